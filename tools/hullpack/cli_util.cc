#include "hullpack/cli_util.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>

#include "common/file_util.h"
#include "o3dgc/o3dgc.h"

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

std::string FormatVersionText() {
  return std::string("writes o3dgc stream format ") + std::to_string(o3dgc::kFormatMajor) +
         ".1, or " + o3dgc::FormatVersionString() + " where modelled low bits pay," +
         " in glTF 2.0 binary (GLB version 2); reads o3dgc stream formats " +
         std::to_string(o3dgc::kFormatMajor) + ".0 to " + o3dgc::FormatVersionString() +
         " and original Open3DGC (2013) streams";
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
