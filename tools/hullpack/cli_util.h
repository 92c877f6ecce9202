// Pieces every hullpack command shares: a progress line on stderr, output-path rules, the format
// versions --version prints. The command-line convention itself is common/cli_args.h.
#ifndef HULLPACK_TOOLS_HULLPACK_CLI_UTIL_H_
#define HULLPACK_TOOLS_HULLPACK_CLI_UTIL_H_

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "common/cli_args.h"
#include "common/status.h"

namespace hullpack {

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

// The formats hullpack writes and reads, for --version.
std::string FormatVersionText();

// "dir/name.ext" -> "name"
std::string FileStem(const std::string& path);
bool IsDirectory(const std::string& path);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_CLI_UTIL_H_
