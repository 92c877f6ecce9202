#include "hullpack/cli_util.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>

#include "common/file_util.h"

namespace hullpack {

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled), tty_(isatty(fileno(stderr)) != 0) {}

ProgressLine::~ProgressLine() { Clear(); }

void ProgressLine::Update(const std::string& text) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (tty_) {
    if (now - last_ < std::chrono::milliseconds(100)) return;
    std::fprintf(stderr, "\r%s%*s", text.c_str(),
                 static_cast<int>(last_width_ > text.size() ? last_width_ - text.size() : 0), "");
    last_width_ = text.size();
  } else {
    if (last_width_ != 0 && now - last_ < std::chrono::seconds(2)) return;
    std::fprintf(stderr, "%s\n", text.c_str());
    last_width_ = 1;
  }
  std::fflush(stderr);
  last_ = now;
}

void ProgressLine::Clear() {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (tty_ && last_width_ > 0) std::fprintf(stderr, "\r%*s\r", static_cast<int>(last_width_), "");
  last_width_ = 0;
}

Status CheckOutputPath(const std::string& output, const std::vector<std::string>& inputs,
                       bool force) {
  for (const std::string& input : inputs) {
    if (SameFile(input, output)) {
      return Status(StatusCode::kInvalidArgument,
                    output + ": is an input file; refusing to overwrite it");
    }
  }
  struct stat st;
  if (stat(output.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode))
      return Status(StatusCode::kInvalidArgument, output + ": is a directory");
    if (!force)
      return Status(StatusCode::kInvalidArgument, output + ": exists (use --force to replace it)");
  }
  return Status::Ok();
}

bool ParseDouble(const std::string& flag, const std::string& text, double lo, double hi,
                 double* out) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno != 0 || !(v >= lo && v <= hi)) {
    std::fprintf(stderr, "hullpack: %s takes a number in [%g, %g], not '%s'\n", flag.c_str(), lo,
                 hi, text.c_str());
    return false;
  }
  *out = v;
  return true;
}

bool ParseInt(const std::string& flag, const std::string& text, long lo, long hi, long* out) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < lo || v > hi) {
    std::fprintf(stderr, "hullpack: %s takes a whole number in [%ld, %ld], not '%s'\n",
                 flag.c_str(), lo, hi, text.c_str());
    return false;
  }
  *out = v;
  return true;
}

std::string FileStem(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

bool IsDirectory(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

}  // namespace hullpack
