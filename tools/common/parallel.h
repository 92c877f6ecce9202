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

namespace parallel_internal {

// task(0) .. task(count - 1) on `threads` threads (the calling one included), each taking the next
// index; each thread calls idle() once no index is left to take.
template <typename Idle>
void Run(size_t count, size_t threads, const std::function<void(size_t)>& task, Idle idle) {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i; (i = next.fetch_add(1)) < count;) task(i);
    idle();
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
}

}  // namespace parallel_internal

// Calls task(0) .. task(count - 1) on up to `threads` threads (the calling one included) and
// returns when all have returned. Tasks must not throw.
inline void ParallelFor(size_t count, int threads, const std::function<void(size_t)>& task) {
  const size_t n = std::min<size_t>(count, static_cast<size_t>(std::max(1, threads)));
  if (n <= 1) {
    for (size_t i = 0; i < count; ++i) task(i);
    return;
  }
  parallel_internal::Run(count, n, task, [] {});
}

// Cores lent by workers that ran out of work to loops that can use more threads: a stage that
// finishes early (a decomposition beside an encode of the same mesh) leaves its core to the
// other. Never blocks.
class CoreLender {
 public:
  void Lend() { free_.fetch_add(1); }
  bool TryBorrow() {
    for (int f = free_.load(); f > 0;)
      if (free_.compare_exchange_weak(f, f - 1)) return true;
    return false;
  }

 private:
  std::atomic<int> free_{0};
};

// Threads for a parallel loop: `base` always, and up to `extra` more while `lender` has cores free.
struct ThreadBudget {
  ThreadBudget(int threads = 1) : base(threads) {}  // NOLINT: a plain count converts
  int base;
  int extra = 0;
  CoreLender* lender = nullptr;
};

// ParallelFor on budget.base threads; before it takes each task, the calling thread starts a
// helper on a core borrowed from budget.lender (up to budget.extra of them) while tasks remain.
// A helper gives its core back when no task is left.
inline void ParallelFor(size_t count, const ThreadBudget& budget,
                        const std::function<void(size_t)>& task) {
  if (budget.lender == nullptr || budget.extra <= 0) {
    ParallelFor(count, budget.base, task);
    return;
  }
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i; (i = next.fetch_add(1)) < count;) task(i);
  };
  std::vector<std::thread> pool;
  const size_t n = std::min<size_t>(count, static_cast<size_t>(std::max(1, budget.base)));
  for (size_t t = 1; t < n; ++t) pool.emplace_back(worker);
  int borrowed = 0;
  for (size_t i; (i = next.fetch_add(1)) < count;) {
    while (borrowed < budget.extra && next.load() < count && budget.lender->TryBorrow()) {
      ++borrowed;
      pool.emplace_back([&] {
        worker();
        budget.lender->Lend();
      });
    }
    task(i);
  }
  for (std::thread& t : pool) t.join();
}

// ParallelFor whose threads each lend their core to `lender` once no task is left to take.
inline void ParallelForLendingIdle(size_t count, int threads, CoreLender* lender,
                                   const std::function<void(size_t)>& task) {
  const size_t all = static_cast<size_t>(std::max(1, threads));
  const size_t n = std::max<size_t>(1, std::min(count, all));
  for (size_t t = n; t < all; ++t) lender->Lend();  // threads that would get no task
  parallel_internal::Run(count, n, task, [lender] { lender->Lend(); });
}

// std::sort of [first, last) with parts sorted on up to `threads` threads, then merged. `less` must
// be a strict total order (no two elements equivalent, e.g. ties broken by an index): then the
// result is the one std::sort gives, whatever the thread count.
template <typename Iterator, typename Less>
void ParallelSort(Iterator first, Iterator last, Less less, int threads) {
  const size_t n = static_cast<size_t>(last - first);
  size_t parts = std::min<size_t>(static_cast<size_t>(std::max(1, threads)), n / 4096 + 1);
  if (parts <= 1) {
    std::sort(first, last, less);
    return;
  }
  std::vector<size_t> bounds(parts + 1);
  for (size_t k = 0; k <= parts; ++k) bounds[k] = n * k / parts;
  ParallelFor(parts, threads, [&](size_t k) {
    std::sort(first + static_cast<ptrdiff_t>(bounds[k]),
              first + static_cast<ptrdiff_t>(bounds[k + 1]), less);
  });
  // Merge neighbouring runs until one is left, the merges of a round in parallel.
  for (size_t width = 1; width < parts; width *= 2) {
    const size_t merges = (parts + 2 * width - 1) / (2 * width);
    ParallelFor(merges, threads, [&](size_t m) {
      const size_t lo = m * 2 * width, mid = std::min(lo + width, parts),
                   hi = std::min(lo + 2 * width, parts);
      if (mid >= hi) return;
      std::inplace_merge(first + static_cast<ptrdiff_t>(bounds[lo]),
                         first + static_cast<ptrdiff_t>(bounds[mid]),
                         first + static_cast<ptrdiff_t>(bounds[hi]), less);
    });
  }
}

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_PARALLEL_H_
