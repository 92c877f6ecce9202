#include "thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace vhacd {
namespace internal {
namespace {

TEST(ThreadPoolTest, RunsEveryIndexOnce) {
  for (int threads : {1, 2, 7}) {
    Context ctx(nullptr, threads);
    std::vector<std::atomic<int>> hits(1000);
    for (auto& h : hits) h = 0;
    ASSERT_TRUE(ParallelFor(&ctx, hits.size(), [&](size_t i) { ++hits[i]; }));
    for (auto& h : hits) EXPECT_EQ(h.load(), 1);
  }
  EXPECT_TRUE(ParallelFor(nullptr, 3, [](size_t) {}));
}

TEST(ThreadPoolTest, ExceptionsReachTheCaller) {
  Context ctx(nullptr, 3);
  EXPECT_THROW(ParallelFor(&ctx, 1000,
                           [](size_t i) {
                             if (i == 500) throw std::runtime_error("boom");
                           }),
               std::runtime_error);
}

class StopNow : public Observer {
 public:
  bool IsCancelled() override { return true; }
};

TEST(ThreadPoolTest, StopsWhenCancelled) {
  StopNow stop;
  Context ctx(&stop, 2);
  std::atomic<int> ran{0};
  EXPECT_FALSE(ParallelFor(&ctx, 100000, [&](size_t) { ++ran; }));
  EXPECT_LT(ran.load(), 100000);
  EXPECT_TRUE(ctx.Cancelled());
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
