// Runs independent tasks on a few threads. Each task writes only its own result, so what the
// tasks compute does not depend on the thread count or on the order they run in.
#ifndef HULLPACK_TOOLS_COMMON_PARALLEL_H_
#define HULLPACK_TOOLS_COMMON_PARALLEL_H_

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>
#include <vector>

namespace hullpack {

// Threads to use for `requested` (0 = every core), at least 1.
inline int ThreadCount(int requested) {
  if (requested > 0) return requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Calls task(0) .. task(count - 1) on up to `threads` threads (the calling one included) and
// returns when all have returned. Tasks must not throw.
inline void ParallelFor(size_t count, int threads, const std::function<void(size_t)>& task) {
  const size_t n = std::min<size_t>(count, static_cast<size_t>(std::max(1, threads)));
  if (n <= 1) {
    for (size_t i = 0; i < count; ++i) task(i);
    return;
  }
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i; (i = next.fetch_add(1)) < count;) task(i);
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
}

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_PARALLEL_H_
