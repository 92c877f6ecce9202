#include "common/file_util.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <utility>

namespace hullpack {

Result<std::vector<uint8_t>> ReadFileBytes(const std::string& path) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) {
    return Status(StatusCode::kIoError, path + ": " + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) return Status(StatusCode::kIoError, path + ": is a directory");
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return Status(StatusCode::kIoError, path + ": " + std::strerror(errno));
  // Read straight into a buffer of the file's size: grown chunk by chunk, a large mesh file was
  // copied as the buffer doubled and held at up to twice its size. Whatever stat could not size
  // (a pipe, a file that grew meanwhile) follows in chunks.
  std::vector<uint8_t> bytes(S_ISREG(st.st_mode) ? static_cast<size_t>(st.st_size) : 0);
  size_t size = 0, n;
  while (size < bytes.size() &&
         (n = std::fread(bytes.data() + size, 1, bytes.size() - size, f)) > 0)
    size += n;
  bytes.resize(size);
  uint8_t chunk[1 << 16];
  while ((n = std::fread(chunk, 1, sizeof(chunk), f)) > 0)
    bytes.insert(bytes.end(), chunk, chunk + n);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) return Status(StatusCode::kIoError, path + ": read error");
  return bytes;
}

Result<RandomAccessFile> RandomAccessFile::Open(const std::string& path) {
  // Checked before opening: opening a pipe would wait for a writer, and closing it again would
  // lose what the writer sent.
  struct stat st;
  if (stat(path.c_str(), &st) != 0)
    return Status(StatusCode::kIoError, path + ": " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) {
    return Status(StatusCode::kIoError,
                  path + (S_ISDIR(st.st_mode) ? ": is a directory" : ": not a regular file"));
  }
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Status(StatusCode::kIoError, path + ": " + std::strerror(errno));
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {  // replaced meanwhile
    close(fd);
    return Status(StatusCode::kIoError, path + ": not a regular file");
  }
  return RandomAccessFile(fd, static_cast<size_t>(st.st_size), path);
}

RandomAccessFile::RandomAccessFile(RandomAccessFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), size_(other.size_), path_(std::move(other.path_)) {}

RandomAccessFile& RandomAccessFile::operator=(RandomAccessFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    size_ = other.size_;
    path_ = std::move(other.path_);
  }
  return *this;
}

RandomAccessFile::~RandomAccessFile() {
  if (fd_ >= 0) close(fd_);
}

Status RandomAccessFile::ReadAt(size_t offset, size_t length, char* out) const {
  while (length > 0) {
    const ssize_t n = pread(fd_, out, length, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return Status(StatusCode::kIoError, path_ + ": read error: " + std::strerror(errno));
    if (n == 0)
      return Status(StatusCode::kIoError,
                    path_ + ": ended early (did it change while being read?)");
    out += n;
    offset += static_cast<size_t>(n);
    length -= static_cast<size_t>(n);
  }
  return Status::Ok();
}

Result<AtomicFileWriter> AtomicFileWriter::Create(const std::string& path) {
  std::random_device rd;
  std::string tmp =
      path + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(rd() % 1000000);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return Status(StatusCode::kIoError, path + ": cannot create: " + std::strerror(errno));
  return AtomicFileWriter(f, path, std::move(tmp));
}

AtomicFileWriter::AtomicFileWriter(AtomicFileWriter&& other) noexcept
    : file_(std::exchange(other.file_, nullptr)),
      path_(std::move(other.path_)),
      tmp_(std::move(other.tmp_)),
      failed_(other.failed_),
      error_(other.error_) {}

AtomicFileWriter::~AtomicFileWriter() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  std::remove(tmp_.c_str());
}

void AtomicFileWriter::Write(const void* data, size_t size) {
  if (failed_ || file_ == nullptr || size == 0) return;
  if (std::fwrite(data, 1, size, file_) != size) {
    failed_ = true;
    error_ = errno;
  }
}

Status AtomicFileWriter::Commit() {
  if (file_ == nullptr) return Status(StatusCode::kIoError, path_ + ": already written");
  int error = failed_ ? (error_ != 0 ? error_ : EIO) : 0;  // the first error
  if (std::fflush(file_) != 0 && error == 0) error = errno;
  if (fsync(fileno(file_)) != 0 && errno != EINVAL && error == 0) error = errno;
  if (std::fclose(std::exchange(file_, nullptr)) != 0 && error == 0) error = errno;
  if (error != 0) {
    std::remove(tmp_.c_str());
    return Status(StatusCode::kIoError, path_ + ": write failed: " + std::strerror(error));
  }
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp_.c_str());
    return Status(StatusCode::kIoError, path_ + ": cannot rename into place: " + why);
  }
  return Status::Ok();
}

Status WriteFileAtomically(const std::string& path, const void* data, size_t size) {
  Result<AtomicFileWriter> file = AtomicFileWriter::Create(path);
  if (!file.ok()) return file.status();
  file->Write(data, size);
  return file->Commit();
}

Status MakeDirectories(const std::string& path) {
  for (size_t end = path.find('/', 1);; end = path.find('/', end + 1)) {
    const std::string prefix = end == std::string::npos ? path : path.substr(0, end);
    if (!prefix.empty() && mkdir(prefix.c_str(), 0777) != 0 && errno != EEXIST)
      return Status(StatusCode::kIoError,
                    prefix + ": cannot create folder: " + std::strerror(errno));
    if (end == std::string::npos) break;
  }
  struct stat st;
  if (stat(path.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    return Status(StatusCode::kIoError, path + ": is not a folder");
  return Status::Ok();
}

bool SameFile(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  if (stat(a.c_str(), &sa) != 0 || stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::string FolderOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string LowerExtension(const std::string& path) {
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace hullpack
