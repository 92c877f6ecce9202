#include "plane_search.h"

#include <gtest/gtest.h>

#include <limits>

namespace vhacd {
namespace internal {
namespace {

Part Block(int nx, int ny, int nz, bool notch) {
  Part p;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        if (notch && x >= nx / 2 && y >= ny / 2) continue;
        Voxel v;
        v.c[0] = static_cast<uint16_t>(x + 1);
        v.c[1] = static_cast<uint16_t>(y + 1);
        v.c[2] = static_cast<uint16_t>(z + 1);
        v.surface = 0;
        p.voxels.push_back(v);
      }
  p.ComputeBounds();
  return p;
}

TEST(PlaneSearchTest, BestCutOfAnLIsAtTheNotch) {
  const Part p = Block(12, 12, 4, true);
  CutWeights w;
  w.volume0 = 12.0 * 12 * 4;
  const RevolutionHint hint = ComputeRevolutionHint(p);
  double best = std::numeric_limits<double>::infinity();
  int best_axis = -1, best_c = -1;
  for (int axis = 0; axis < 2; ++axis) {
    const AxisLines lines = BuildAxisLines(p, axis);
    for (int c : CandidatePlanes(p, axis, 1)) {
      const double cost = CutCost(p, lines, c, 1, w, hint, 0.1);
      if (cost < best) {
        best = cost;
        best_axis = axis;
        best_c = c;
      }
    }
  }
  EXPECT_EQ(best_c, 7);  // between voxel x/y = 6 and 7 (the notch starts at 6 + 1 offset)
  EXPECT_GE(best_axis, 0);
  EXPECT_LT(best, 0.05);
}

TEST(PlaneSearchTest, CandidatesCoverTheRange) {
  const Part p = Block(10, 3, 1, false);
  const std::vector<int> all = CandidatePlanes(p, 0, 1);
  ASSERT_EQ(all.size(), 9u);
  EXPECT_EQ(all.front(), 2);
  EXPECT_EQ(all.back(), 10);
  EXPECT_EQ(CandidatePlanes(p, 0, 4).size(), 3u);
  EXPECT_TRUE(CandidatePlanes(p, 2, 1).empty());
}

TEST(PlaneSearchTest, RevolutionHintOfARodIsItsAxis) {
  const Part p = Block(3, 3, 30, false);
  const RevolutionHint h = ComputeRevolutionHint(p);
  EXPECT_GT(h.weight, 0.9);
  EXPECT_GT(std::fabs(h.axis.z()), 0.99);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
