#include "common/file_util.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
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

TEST(RandomAccessFile, ReadsAnyRangeFromSeveralThreads) {
  std::vector<uint8_t> bytes(1 << 20);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<uint8_t>(i * 131 + i / 977);
  const std::string path = TempPath("random_access");
  ASSERT_TRUE(WriteFileAtomically(path, bytes).ok());
  Result<RandomAccessFile> file = RandomAccessFile::Open(path);
  ASSERT_TRUE(file.ok()) << file.status().message();
  EXPECT_EQ(file->size(), bytes.size());
  std::vector<std::thread> threads;
  std::vector<int> same(4, 0);
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      const size_t offset = 1000 + 250000 * size_t(t), length = 200003;
      std::vector<char> part(length);
      same[t] = file->ReadAt(offset, length, part.data()).ok() &&
                std::equal(part.begin(), part.end(), bytes.begin() + offset,
                           [](char a, uint8_t b) { return static_cast<uint8_t>(a) == b; });
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(same, std::vector<int>(4, 1));
  // Past the end: an error naming the file, not a short read.
  char tail[16];
  Status past = file->ReadAt(bytes.size() - 8, sizeof(tail), tail);
  EXPECT_FALSE(past.ok());
  EXPECT_NE(past.message().find(path), std::string::npos) << past.message();
  std::remove(path.c_str());
}

TEST(RandomAccessFile, RefusesWhatIsNotARegularFile) {
  Result<RandomAccessFile> folder = RandomAccessFile::Open(::testing::TempDir());
  ASSERT_FALSE(folder.ok());
  EXPECT_NE(folder.status().message().find("directory"), std::string::npos);
  Result<RandomAccessFile> missing = RandomAccessFile::Open(TempPath("missing"));
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("missing"), std::string::npos);
  // A pipe is refused without being opened (opening it would wait for a writer).
  const std::string fifo = TempPath("fifo_refused");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  Result<RandomAccessFile> pipe = RandomAccessFile::Open(fifo);
  EXPECT_FALSE(pipe.ok());
  std::remove(fifo.c_str());
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

// Names in `folder` that start with `prefix`.
std::vector<std::string> NamesStartingWith(const std::string& folder, const std::string& prefix) {
  std::vector<std::string> names;
  if (DIR* d = opendir(folder.c_str())) {
    while (dirent* e = readdir(d))
      if (std::string(e->d_name).rfind(prefix, 0) == 0) names.push_back(e->d_name);
    closedir(d);
  }
  return names;
}

TEST(AtomicFileWriter, WritesThePiecesInOrderOnCommit) {
  const std::string path = TempPath("pieces");
  ASSERT_TRUE(WriteFileAtomically(path, std::vector<uint8_t>{9, 9}).ok());
  Result<AtomicFileWriter> file = AtomicFileWriter::Create(path);
  ASSERT_TRUE(file.ok()) << file.status().message();
  std::vector<uint8_t> expected;
  for (int piece = 0; piece < 100; ++piece) {
    std::vector<uint8_t> bytes(static_cast<size_t>(piece) * 37);
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<uint8_t>(piece + i);
    file->Write(bytes.data(), bytes.size());
    expected.insert(expected.end(), bytes.begin(), bytes.end());
  }
  // The previous file stays whole until the commit.
  EXPECT_EQ(ReadFileBytes(path).value(), (std::vector<uint8_t>{9, 9}));
  ASSERT_TRUE(file->Commit().ok());
  EXPECT_EQ(ReadFileBytes(path).value(), expected);
  std::remove(path.c_str());
}

TEST(AtomicFileWriter, WithoutCommitLeavesTheTargetAndNoTemporaryFile) {
  const std::string path = TempPath("abandoned");
  ASSERT_TRUE(WriteFileAtomically(path, std::vector<uint8_t>{1, 2, 3}).ok());
  {
    Result<AtomicFileWriter> file = AtomicFileWriter::Create(path);
    ASSERT_TRUE(file.ok());
    const uint8_t bytes[4] = {4, 5, 6, 7};
    file->Write(bytes, sizeof(bytes));
  }
  EXPECT_EQ(ReadFileBytes(path).value(), (std::vector<uint8_t>{1, 2, 3}));
  const std::string name = path.substr(path.find_last_of('/') + 1);
  EXPECT_EQ(NamesStartingWith(::testing::TempDir(), name + ".tmp"), std::vector<std::string>());
  std::remove(path.c_str());
}

TEST(AtomicFileWriter, AFolderThatCannotHoldTheFileIsAnErrorNamingThePath) {
  const std::string path = TempPath("no_such_folder") + "/out.bin";
  Result<AtomicFileWriter> file = AtomicFileWriter::Create(path);
  ASSERT_FALSE(file.ok());
  EXPECT_NE(file.status().message().find(path), std::string::npos);
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

TEST(FolderOf, IsThePathUpToItsLastSlash) {
  EXPECT_EQ(FolderOf("a/b/c.obj"), "a/b");
  EXPECT_EQ(FolderOf("c.obj"), ".");
  EXPECT_EQ(FolderOf("/c.obj"), "/");
  EXPECT_EQ(FolderOf("a/"), "a");
}

}  // namespace
}  // namespace hullpack
