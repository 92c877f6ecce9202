#include "context.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace vhacd {
namespace internal {
namespace {

class Rec : public Observer {
 public:
  std::vector<double> overall;
  std::string last_stage, log;
  void OnProgress(double o, double, double, const char* stage, const char*) override {
    overall.push_back(o);
    last_stage = stage;
  }
  void OnLog(const char* m) override { log += m; }
};

TEST(ContextTest, MapsStageProgressToOverall) {
  Rec rec;
  Context ctx(&rec, 1);
  ctx.BeginStage("Clipping", 20, 60);
  ctx.Progress(50, "op");
  ctx.Progress(250, "op");  // clamped
  ASSERT_EQ(rec.overall.size(), 3u);
  EXPECT_DOUBLE_EQ(rec.overall[0], 20);
  EXPECT_DOUBLE_EQ(rec.overall[1], 40);
  EXPECT_DOUBLE_EQ(rec.overall[2], 60);
  EXPECT_EQ(rec.last_stage, "Clipping");
  ctx.Log("hello");
  EXPECT_EQ(rec.log, "hello");
  EXPECT_FALSE(ctx.Cancelled());
  Context quiet(nullptr, 1);
  quiet.Progress(10, "x");  // no observer: no crash
  EXPECT_FALSE(quiet.Cancelled());
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
