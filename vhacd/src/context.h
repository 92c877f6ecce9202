// Shared run state: thread count, cancellation, progress and log forwarding.
#ifndef VHACD_SRC_CONTEXT_H_
#define VHACD_SRC_CONTEXT_H_

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

#include "vhacd/vhacd.h"

namespace vhacd {
namespace internal {

// The worker threads for a requested count: the count itself, or one per hardware thread for 0.
int ThreadCount(uint32_t requested);

// Seconds between laps of a steady clock, for the per-stage times of a report.
struct Clock {
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  double Lap() {
    const auto t = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(t - t0).count();
    t0 = t;
    return s;
  }
};

class Context {
 public:
  Context(Observer* observer, int num_threads) : observer_(observer), num_threads_(num_threads) {}

  int num_threads() const { return num_threads_; }

  // True once the observer asked to stop. Cheap: the observer is polled at most every ~0.5 ms.
  bool Cancelled();

  // Stage bookkeeping: `stage_begin`/`stage_end` are overall percentages of this stage.
  void BeginStage(const char* name, double overall_begin, double overall_end);
  void Progress(double operation_percent, const char* operation);
  void Log(const std::string& message);

 private:
  Observer* observer_;
  int num_threads_;
  std::atomic<bool> cancelled_{false};
  std::atomic<int64_t> last_poll_ns_{0};
  std::mutex mutex_;
  const char* stage_ = "";
  double stage_begin_ = 0.0, stage_end_ = 0.0;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_CONTEXT_H_
