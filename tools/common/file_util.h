// Whole-file reads, reads at offsets, and atomic writes: outputs go to a temporary file beside the
// target, then rename, so an interrupted run never leaves a half-written file and never destroys
// the previous one.
#ifndef HULLPACK_TOOLS_COMMON_FILE_UTIL_H_
#define HULLPACK_TOOLS_COMMON_FILE_UTIL_H_

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "common/status.h"

namespace hullpack {

// Reads all of `path`. Errors name the path.
Result<std::vector<uint8_t>> ReadFileBytes(const std::string& path);

// A regular file read at offsets, for readers that take a large file part by part instead of
// holding it whole. Reads from several threads at once are safe.
class RandomAccessFile {
 public:
  // Fails (naming the path) when the file cannot be opened or is not a regular file (a pipe,
  // a folder): those are read whole with ReadFileBytes.
  static Result<RandomAccessFile> Open(const std::string& path);
  RandomAccessFile(RandomAccessFile&& other) noexcept;
  RandomAccessFile& operator=(RandomAccessFile&& other) noexcept;
  RandomAccessFile(const RandomAccessFile&) = delete;
  RandomAccessFile& operator=(const RandomAccessFile&) = delete;
  ~RandomAccessFile();

  // The size when opened.
  size_t size() const { return size_; }
  // Reads exactly `length` bytes at `offset` into `out`; an error when the file ends first (it
  // changed while being read) or the read fails.
  Status ReadAt(size_t offset, size_t length, char* out) const;

 private:
  RandomAccessFile(int fd, size_t size, std::string path)
      : fd_(fd), size_(size), path_(std::move(path)) {}
  int fd_ = -1;
  size_t size_ = 0;
  std::string path_;
};

// A file written in pieces through a temporary file in the same folder, renamed to `path` by
// Commit: for outputs too large to build in memory first. Destroyed without Commit (an error on
// the way), it removes the temporary file and leaves `path` as it was.
class AtomicFileWriter {
 public:
  // Fails, naming the path, when the temporary file cannot be created.
  static Result<AtomicFileWriter> Create(const std::string& path);
  AtomicFileWriter(AtomicFileWriter&& other) noexcept;
  AtomicFileWriter& operator=(AtomicFileWriter&&) = delete;
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;
  ~AtomicFileWriter();

  // Appends bytes. After a failed write the later ones are skipped, and Commit reports it.
  void Write(const void* data, size_t size);
  // Flushes the file to disk and renames it into place; errors name the path.
  Status Commit();

 private:
  AtomicFileWriter(std::FILE* file, std::string path, std::string tmp)
      : file_(file), path_(std::move(path)), tmp_(std::move(tmp)) {}
  std::FILE* file_ = nullptr;
  std::string path_, tmp_;
  bool failed_ = false;
  int error_ = 0;
};

// Writes `size` bytes to `path` through a temporary file in the same folder and a rename.
Status WriteFileAtomically(const std::string& path, const void* data, size_t size);
inline Status WriteFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes) {
  return WriteFileAtomically(path, bytes.data(), bytes.size());
}

// Creates `path` and its missing parents (like mkdir -p). Errors name the folder.
Status MakeDirectories(const std::string& path);

// True when both paths name the same existing file (hard links and symlinks included).
bool SameFile(const std::string& a, const std::string& b);

// Lower-case extension without the dot ("obj" for "a/b.OBJ"), or "".
std::string LowerExtension(const std::string& path);

// The folder of `path` without a trailing slash ("a/b" for "a/b/c.obj"), "." when it names none.
std::string FolderOf(const std::string& path);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_FILE_UTIL_H_
