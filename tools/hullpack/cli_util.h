// Pieces every hullpack command shares: exit codes, a progress line on stderr, output-path rules.
#ifndef HULLPACK_TOOLS_HULLPACK_CLI_UTIL_H_
#define HULLPACK_TOOLS_HULLPACK_CLI_UTIL_H_

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "common/status.h"

namespace hullpack {

constexpr int kExitUsage = 64;  // sysexits' EX_USAGE: the command line is wrong

// One progress line on stderr: rewritten in place on a terminal, otherwise a new line at most
// every two seconds. Thread-safe; silent when disabled.
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled);
  ~ProgressLine();
  void Update(const std::string& text);
  // Ends the line (so the next message starts on a fresh one).
  void Clear();

 private:
  bool enabled_;
  bool tty_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_;
  size_t last_width_ = 0;
};

// Checks that `output` may be written: not the same file as any input, and not existing unless
// `force`. The message names the file and the rule.
Status CheckOutputPath(const std::string& output, const std::vector<std::string>& inputs,
                       bool force);

// Parses a number option's value; false (and a message on stderr) when it is not one.
bool ParseDouble(const std::string& flag, const std::string& text, double lo, double hi,
                 double* out);
bool ParseInt(const std::string& flag, const std::string& text, long lo, long hi, long* out);

// "dir/name.ext" -> "name"
std::string FileStem(const std::string& path);
bool IsDirectory(const std::string& path);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_CLI_UTIL_H_
