// Runs one measured step in a forked child process, so that its peak memory can be read on its own
// (getrusage/wait4 ru_maxrss of the child, which starts at the parent's resident size at the fork),
// so that a crash or a hang of one step does not end a whole benchmark, and so that the CPU time
// of the step (user + system, all of its threads) is known.
//
// POSIX only. Call it from a process that has no other threads running: the child only runs the
// given function and then _exit()s.
#ifndef HULLPACK_TOOLS_BENCH_CHILD_PROCESS_H_
#define HULLPACK_TOOLS_BENCH_CHILD_PROCESS_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace hullpack {

struct ChildResult {
  bool ok = false;               // the child ran `work` to the end and exited with status 0
  std::string error;             // why not: "killed by signal 11", "timed out after 900 s", ...
  std::vector<uint8_t> payload;  // what `work` returned
  double base_rss_mb = 0;   // resident size of the child when it started (the parent's at the fork)
  double peak_rss_mb = 0;   // ru_maxrss of the child
  double cpu_seconds = 0;   // user + system time of the child
  double wall_seconds = 0;  // from fork to exit
};

// Forks, runs `work` in the child and sends its result back through a pipe. The child is killed
// when it runs longer than `timeout_seconds` (<= 0: no limit).
ChildResult RunInChild(const std::function<std::vector<uint8_t>()>& work, double timeout_seconds);

// The resident set size of this process now, in MB (VmRSS of /proc/self/status; 0 if unknown).
double CurrentRssMb();

// Little helpers to pass numbers and byte strings through a payload.
class PayloadWriter {
 public:
  void Double(double v);
  void U64(uint64_t v);
  void Bytes(const void* data, size_t size);
  std::vector<uint8_t> Take() { return std::move(bytes_); }

 private:
  std::vector<uint8_t> bytes_;
};

class PayloadReader {
 public:
  explicit PayloadReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
  // Each returns false, and leaves the reader failed, when the payload is too short.
  bool Double(double* v);
  bool U64(uint64_t* v);
  bool Bytes(void* data, size_t size);
  bool ok() const { return ok_; }

 private:
  const std::vector<uint8_t>& bytes_;
  size_t at_ = 0;
  bool ok_ = true;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_CHILD_PROCESS_H_
