#include "common/parallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace hullpack {
namespace {

using std::chrono::milliseconds;

TEST(ParallelFor, RunsEveryTaskOnce) {
  for (int threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> runs(100);
    ParallelFor(runs.size(), threads, [&](size_t i) { ++runs[i]; });
    for (const std::atomic<int>& r : runs) EXPECT_EQ(r.load(), 1) << threads << " threads";
  }
}

TEST(ParallelSort, GivesStdSortsOrder) {
  std::vector<int> v(50000);
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<int>((i * 7919) % 10007);
  std::vector<int> expected = v;
  std::sort(expected.begin(), expected.end());
  ParallelSort(v.begin(), v.end(), std::less<int>(), 3);
  EXPECT_EQ(v, expected);
}

// The threads that ran `count` tasks of `pause` each under `budget`.
std::set<std::thread::id> ThreadsUsed(size_t count, const ThreadBudget& budget,
                                      milliseconds pause) {
  std::mutex mutex;
  std::set<std::thread::id> ids;
  ParallelFor(count, budget, [&](size_t) {
    std::this_thread::sleep_for(pause);
    std::lock_guard<std::mutex> lock(mutex);
    ids.insert(std::this_thread::get_id());
  });
  return ids;
}

TEST(ThreadBudget, WithoutAFreeCoreTheLoopRunsOnItsBaseThreads) {
  CoreLender lender;
  ThreadBudget budget(1);
  budget.extra = 1;
  budget.lender = &lender;
  EXPECT_EQ(ThreadsUsed(6, budget, milliseconds(1)).size(), 1u);
  EXPECT_FALSE(lender.TryBorrow());
}

TEST(ThreadBudget, ALoopBorrowsAFreeCoreAndGivesItBack) {
  CoreLender lender;
  lender.Lend();
  ThreadBudget budget(1);
  budget.extra = 2;  // only one is free
  budget.lender = &lender;
  EXPECT_EQ(ThreadsUsed(6, budget, milliseconds(20)).size(), 2u);
  EXPECT_TRUE(lender.TryBorrow());
  EXPECT_FALSE(lender.TryBorrow());
}

// A decomposition that ends early leaves its core to the encode beside it.
TEST(ParallelForLendingIdle, AWorkerWithNoTaskLeftLendsItsCoreToALoopStillRunning) {
  CoreLender lender;
  std::set<std::thread::id> inner;
  ParallelForLendingIdle(2, 2, &lender, [&](size_t task) {
    if (task == 0) return;  // done at once: its thread lends its core
    ThreadBudget budget(1);
    budget.extra = 1;
    budget.lender = &lender;
    inner = ThreadsUsed(20, budget, milliseconds(20));
  });
  EXPECT_EQ(inner.size(), 2u);
}

TEST(ParallelForLendingIdle, ThreadsWithoutATaskLendTheirCoresAtOnce) {
  CoreLender lender;
  ParallelForLendingIdle(1, 3, &lender, [](size_t) {});
  int free = 0;
  while (lender.TryBorrow()) ++free;
  EXPECT_EQ(free, 3);  // two never had a task, the third lent its core when done
}

}  // namespace
}  // namespace hullpack
