#include "primitive_set.h"

#include <gtest/gtest.h>

namespace vhacd {
namespace internal {
namespace {

// Voxels of an L: [0,8)x[0,4)x[0,3) plus [0,4)x[4,8)x[0,3).
Part LPart() {
  Part p;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x)
        if (y < 4 || x < 4) {
          Voxel v;
          v.c[0] = static_cast<uint16_t>(x + 1);
          v.c[1] = static_cast<uint16_t>(y + 1);
          v.c[2] = static_cast<uint16_t>(z + 1);
          v.surface = (x == 0 || y == 0 || z == 0 || z == 2 || x == 7 || y == 7);
          p.voxels.push_back(v);
        }
  p.ComputeBounds();
  return p;
}

TEST(PrimitiveSetTest, PartHullIsTheExactHullOfTheVoxels) {
  const Part p = LPart();
  EXPECT_EQ(p.volume(), 3 * (32 + 16));
  std::vector<Vec3> pts;
  PartHullPoints(p, false, &pts);
  // Hull of the L outline (8x8 square minus the 4x4 corner triangle half) times 3.
  EXPECT_DOUBLE_EQ(ExactHullVolume(pts), 3.0 * (64 - 8));
  EXPECT_EQ(p.bmin[0], 1);
  EXPECT_EQ(p.bmax[1], 8);
}

TEST(PrimitiveSetTest, SideHullsSplitAtThePlane) {
  const Part p = LPart();
  const AxisLines lines = BuildAxisLines(p, 0);
  EXPECT_EQ(lines.slice_count.size(), 8u);
  EXPECT_EQ(lines.slice_count[0], 24u);
  EXPECT_EQ(lines.slice_count[7], 12u);
  std::vector<Vec3> pts;
  SideHullPoints(lines, 5, true, 1, &pts);  // x < 5: the 4x8x3 block
  EXPECT_DOUBLE_EQ(ExactHullVolume(pts), 4.0 * 8 * 3);
  SideHullPoints(lines, 5, false, 1, &pts);  // x >= 5: 4x4x3
  EXPECT_DOUBLE_EQ(ExactHullVolume(pts), 4.0 * 4 * 3);
  SideHullPoints(lines, 5, false, 2, &pts);  // downsampled: an underestimate
  EXPECT_LE(ExactHullVolume(pts), 4.0 * 4 * 3);
}

TEST(PrimitiveSetTest, SparseWidePartsUseDirectEmission) {
  Part p;
  Voxel a, b;
  a.c[0] = a.c[1] = a.c[2] = 1;
  b.c[0] = b.c[1] = 2000;
  b.c[2] = 1;
  a.surface = b.surface = 1;
  p.voxels = {a, b};
  p.ComputeBounds();
  // Hull of two unit cubes 1999 apart along (1, 1, 0): 1 + sqrt(2) * 1999 * sqrt(2).
  const AxisLines lines = BuildAxisLines(p, 2);
  std::vector<Vec3> pts;
  SideHullPoints(lines, 2, true, 1, &pts);
  EXPECT_DOUBLE_EQ(ExactHullVolume(pts), 3999.0);
  PartHullPoints(p, false, &pts);
  EXPECT_DOUBLE_EQ(ExactHullVolume(pts), 3999.0);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
