#include "common/file_util.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace hullpack {
namespace {

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "file_util_test_" + std::to_string(getpid()) + "_" + name;
}

TEST(ReadFileBytes, ReadsEveryByteOfFilesOfEverySize) {
  // Sizes around the chunk the reader falls back to, and a file much larger than one.
  for (size_t size :
       {size_t(0), size_t(1), size_t(65535), size_t(65536), size_t(65537), size_t(3 << 20) + 7}) {
    std::vector<uint8_t> bytes(size);
    for (size_t i = 0; i < size; ++i) bytes[i] = static_cast<uint8_t>(i * 131 + i / 977);
    const std::string path = TempPath("sized");
    ASSERT_TRUE(WriteFileAtomically(path, bytes).ok());
    Result<std::vector<uint8_t>> read = ReadFileBytes(path);
    ASSERT_TRUE(read.ok()) << read.status().message();
    EXPECT_EQ(read.value(), bytes) << size << " bytes";
    std::remove(path.c_str());
  }
}

TEST(ReadFileBytes, ReadsWhatStatCannotSize) {
  // A pipe has no size: everything written into it is read all the same.
  const std::string path = TempPath("fifo");
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  std::vector<uint8_t> bytes(200000);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<uint8_t>(i % 251);
  std::thread writer([&] {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return;
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
  });
  Result<std::vector<uint8_t>> read = ReadFileBytes(path);
  writer.join();
  std::remove(path.c_str());
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read.value(), bytes);
}

TEST(ReadFileBytes, MissingFilesAndFoldersAreErrorsNamingThePath) {
  const std::string missing = TempPath("missing");
  Result<std::vector<uint8_t>> read = ReadFileBytes(missing);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.status().message().find(missing), std::string::npos);
  read = ReadFileBytes(::testing::TempDir());
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.status().message().find("directory"), std::string::npos);
}

}  // namespace
}  // namespace hullpack
