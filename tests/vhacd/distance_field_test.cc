#include "distance_field.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vhacd {
namespace internal {
namespace {

TEST(DistanceFieldTest, ExactEuclideanDistanceToSolidVoxels) {
  VoxelGrid g;
  g.dims[0] = 9;
  g.dims[1] = 7;
  g.dims[2] = 5;
  g.cell.assign(9 * 7 * 5, kCellOutside);
  g.cell[g.Index(4, 3, 2)] = kCellSurface;
  Context ctx(nullptr, 2);
  DistanceField f;
  ASSERT_TRUE(f.Build(g, &ctx));
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 7; ++y)
      for (int x = 0; x < 9; ++x)
        EXPECT_NEAR(f.At(g.Index(x, y, z)),
                    std::sqrt((x - 4.0) * (x - 4) + (y - 3.0) * (y - 3) + (z - 2.0) * (z - 2)),
                    1e-5);
  // Depth of a hull covering voxels x in [0, 9): the farthest outside centre inside it.
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1 ? 9 : 0, i & 2 ? 4 : 3, i & 4 ? 3 : 2);
  HullMesh h;
  ASSERT_EQ(ComputeConvexHull(pts, 0.0, &h), HullStatus::kOk);
  EXPECT_NEAR(f.HullDepth(h), 4.0, 1e-5);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
