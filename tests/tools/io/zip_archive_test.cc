#include "io/zip_archive.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "zip_test_util.h"

namespace hullpack {
namespace {

using testing::MakeZip;
using testing::PutLe;

std::string Text(const std::vector<uint8_t>& bytes) {
  return std::string(bytes.begin(), bytes.end());
}

// Where the first central directory header starts.
size_t CentralDirectoryOffset(const std::vector<uint8_t>& zip) {
  const size_t end = zip.size() - 22;
  return zip[end + 16] | zip[end + 17] << 8 | zip[end + 18] << 16 | size_t{zip[end + 19]} << 24;
}

TEST(ZipArchive, ReadsStoredAndDeflatedEntries) {
  const std::string long_text(100000, 'x');
  const std::vector<uint8_t> zip =
      MakeZip({{"a.txt", "stored bytes", false}, {"Dir/B.model", long_text, true}, {"empty", ""}});
  Result<ZipArchive> archive = ZipArchive::Open(zip.data(), zip.size(), "t.zip");
  ASSERT_TRUE(archive.ok()) << archive.status().message();
  ASSERT_EQ(archive->entries().size(), 3u);
  // Part names compare without case and without a leading '/'.
  const ZipEntry* b = archive->Find("/dir/b.MODEL");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->method, 8);
  Result<std::vector<uint8_t>> bytes = archive->Read(*b);
  ASSERT_TRUE(bytes.ok()) << bytes.status().message();
  EXPECT_EQ(Text(bytes.value()), long_text);
  EXPECT_EQ(Text(archive->Read(*archive->Find("a.txt")).value()), "stored bytes");
  EXPECT_TRUE(archive->Read(*archive->Find("empty")).value().empty());
  EXPECT_EQ(archive->Find("missing"), nullptr);
}

TEST(ZipArchive, ReadsZip64SizesAndOffsets) {
  std::vector<uint8_t> zip = MakeZip({{"a", "sixty-four", false}});
  // Mark the central header's sizes and offset as 0xFFFFFFFF and give them in a ZIP64 extra.
  const size_t header = CentralDirectoryOffset(zip);
  for (size_t field : {20, 24, 42}) {
    for (int i = 0; i < 4; ++i) zip[header + field + i] = 0xFF;
  }
  std::vector<uint8_t> extra;
  PutLe(&extra, 1, 2);
  PutLe(&extra, 24, 2);
  PutLe(&extra, 10, 8);  // uncompressed
  PutLe(&extra, 10, 8);  // compressed
  PutLe(&extra, 0, 8);   // local header offset
  zip[header + 30] = static_cast<uint8_t>(extra.size());
  const size_t name_end = header + 46 + 1;
  zip.insert(zip.begin() + static_cast<long>(name_end), extra.begin(), extra.end());
  const size_t end = zip.size() - 22;
  zip[end + 12] = static_cast<uint8_t>(zip[end + 12] + extra.size());  // directory size
  Result<ZipArchive> archive = ZipArchive::Open(zip.data(), zip.size(), "t.zip");
  ASSERT_TRUE(archive.ok()) << archive.status().message();
  EXPECT_EQ(archive->entries()[0].uncompressed_size, 10u);
  EXPECT_EQ(Text(archive->Read(archive->entries()[0]).value()), "sixty-four");
}

TEST(ZipArchive, DamagedEntriesAreErrorsThatNameThem) {
  const std::string data(5000, 'q');
  std::vector<uint8_t> zip = MakeZip({{"part.model", data, true}});
  const size_t header = CentralDirectoryOffset(zip);

  std::vector<uint8_t> bad_crc = zip;
  bad_crc[header + 16] ^= 1;
  Result<ZipArchive> a = ZipArchive::Open(bad_crc.data(), bad_crc.size(), "t.zip");
  ASSERT_TRUE(a.ok());
  Result<std::vector<uint8_t>> r = a->Read(a->entries()[0]);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("'part.model': CRC-32 mismatch"), std::string::npos);

  // A declared size deflate cannot reach from the compressed bytes is refused before allocating.
  std::vector<uint8_t> bomb = zip;
  for (int i = 0; i < 4; ++i) bomb[header + 24 + i] = 0xFF;
  bomb[header + 27] = 0x7F;
  a = ZipArchive::Open(bomb.data(), bomb.size(), "t.zip");
  ASSERT_TRUE(a.ok());
  r = a->Read(a->entries()[0]);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("declares more bytes"), std::string::npos);

  // Fewer bytes declared than the data inflates to.
  std::vector<uint8_t> short_size = zip;
  short_size[header + 24] = 100;
  short_size[header + 25] = 0;
  a = ZipArchive::Open(short_size.data(), short_size.size(), "t.zip");
  ASSERT_TRUE(a.ok());
  r = a->Read(a->entries()[0]);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("more bytes than declared"), std::string::npos);

  std::vector<uint8_t> encrypted = zip;
  encrypted[header + 8] |= 1;
  a = ZipArchive::Open(encrypted.data(), encrypted.size(), "t.zip");
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.status().code(), StatusCode::kUnsupported);
  EXPECT_NE(a.status().message().find("'part.model' is encrypted"), std::string::npos);

  std::vector<uint8_t> method = zip;
  method[header + 10] = 12;  // bzip2
  a = ZipArchive::Open(method.data(), method.size(), "t.zip");
  ASSERT_TRUE(a.ok());
  r = a->Read(a->entries()[0]);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("compression method 12"), std::string::npos);
}

TEST(ZipArchive, EveryTruncationAndByteFlipIsSafe) {
  const std::vector<uint8_t> zip =
      MakeZip({{"a", std::string(300, 'a'), true}, {"b", "bee", false}});
  Result<ZipArchive> none = ZipArchive::Open(zip.data(), 0, "t.zip");
  EXPECT_FALSE(none.ok());
  for (size_t size = 0; size < zip.size(); ++size) {
    // Copied, so that a read past `size` is a heap overflow the sanitizers see.
    std::vector<uint8_t> prefix(zip.begin(), zip.begin() + static_cast<long>(size));
    Result<ZipArchive> a = ZipArchive::Open(prefix.data(), prefix.size(), "t.zip");
    EXPECT_FALSE(a.ok()) << size;
  }
  size_t readable = 0;
  for (size_t at = 0; at < zip.size(); ++at) {
    std::vector<uint8_t> flipped = zip;
    flipped[at] ^= 0xA5;
    Result<ZipArchive> a = ZipArchive::Open(flipped.data(), flipped.size(), "t.zip");
    if (!a.ok()) continue;
    for (const ZipEntry& e : a->entries()) readable += a->Read(e).ok();
  }
  EXPECT_GT(readable, 0u);
}

TEST(ZipArchive, NotAZipIsAClearError) {
  const std::string text = "solid cube\nendsolid cube\n, and more than twenty-two bytes";
  Result<ZipArchive> a =
      ZipArchive::Open(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "cube.3mf");
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.status().message(),
            "cube.3mf: not a readable ZIP archive: no end of central directory");
}

}  // namespace
}  // namespace hullpack
