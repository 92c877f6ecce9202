#include "thread_pool.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace vhacd {
namespace internal {

bool ParallelFor(Context* ctx, size_t n, const std::function<void(size_t)>& fn) {
  if (n == 0) return ctx == nullptr || !ctx->Cancelled();
  const size_t threads = std::min<size_t>(
      n, ctx != nullptr ? static_cast<size_t>(std::max(1, ctx->num_threads())) : 1);
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&]() {
    for (;;) {
      if (stop.load(std::memory_order_relaxed)) return;
      if (ctx != nullptr && ctx->Cancelled()) {
        stop.store(true);
        return;
      }
      const size_t i = next.fetch_add(1);
      if (i >= n) return;
      try {
        fn(i);
      } catch (...) {  // e.g. std::bad_alloc: stop everyone and rethrow on the calling thread
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        stop.store(true);
        return;
      }
    }
  };
  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& th : pool) th.join();
  }
  if (error) std::rethrow_exception(error);
  return !(ctx != nullptr && ctx->Cancelled());
}

}  // namespace internal
}  // namespace vhacd
