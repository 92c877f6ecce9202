#include "context.h"

#include <algorithm>
#include <thread>

namespace vhacd {
namespace internal {

int ThreadCount(uint32_t requested) {
  return requested > 0 ? static_cast<int>(requested)
                       : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

namespace {
int64_t NowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

bool Context::Cancelled() {
  if (cancelled_.load(std::memory_order_relaxed)) return true;
  if (observer_ == nullptr) return false;
  const int64_t now = NowNs();
  int64_t last = last_poll_ns_.load(std::memory_order_relaxed);
  if (now - last < 500000) return false;
  if (!last_poll_ns_.compare_exchange_strong(last, now)) return false;  // another thread polls
  std::lock_guard<std::mutex> lock(mutex_);
  if (observer_->IsCancelled()) cancelled_.store(true);
  return cancelled_.load();
}

void Context::BeginStage(const char* name, double overall_begin, double overall_end) {
  stage_ = name;
  stage_begin_ = overall_begin;
  stage_end_ = overall_end;
  Progress(0.0, name);
}

void Context::Progress(double operation_percent, const char* operation) {
  if (observer_ == nullptr) return;
  const double op = std::clamp(operation_percent, 0.0, 100.0);
  const double overall = stage_begin_ + (stage_end_ - stage_begin_) * op / 100.0;
  std::lock_guard<std::mutex> lock(mutex_);
  observer_->OnProgress(overall, op, op, stage_, operation);
}

void Context::Log(const std::string& message) {
  if (observer_ == nullptr) return;
  std::lock_guard<std::mutex> lock(mutex_);
  observer_->OnLog(message.c_str());
}

}  // namespace internal
}  // namespace vhacd
