#include "stick_out.h"

#include <gtest/gtest.h>

#include "context.h"
#include "test_hulls.h"
#include "test_meshes.h"

namespace vhacd {
namespace internal {
namespace {

GridMesh ToGrid(const vhacd_test::Mesh& m) {
  GridMesh g;
  for (size_t i = 0; i < m.point_count(); ++i)
    g.points.emplace_back(m.points[3 * i], m.points[3 * i + 1], m.points[3 * i + 2]);
  for (size_t k = 0; k < m.triangle_count(); ++k)
    g.triangles.push_back({m.indices[3 * k], m.indices[3 * k + 1], m.indices[3 * k + 2]});
  return g;
}

TEST(StickOutTest, MeasuresBelowAVoxelOnTheExactSurface) {
  const GridMesh mesh = ToGrid(vhacd_test::Box(2.3, 2.3, 2.3, 12.7, 12.7, 12.7));
  const int dims[3] = {16, 16, 16};
  Context ctx(nullptr, 2);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(mesh, dims, &ctx, &grid, nullptr, 0.0));
  const StickOutMeter meter(mesh, grid, true);
  // The solid itself, and a hull inside it, stick out by nothing.
  EXPECT_LT(meter.Measure(BoxHull(2.3, 2.3, 2.3, 12.7, 12.7, 12.7)), 1e-9);
  EXPECT_LT(meter.Measure(BoxHull(3, 3, 3, 10, 10, 10)), 1e-9);
  // A hull 0.3 voxel past one face (inside the face's surface voxels): 0.3, not 0 or a voxel.
  EXPECT_NEAR(meter.Measure(BoxHull(2.3, 2.3, 2.3, 13.0, 12.7, 12.7)), 0.3, 1e-9);
  // 2.5 voxels past: the farthest sample, within the half-voxel sample spacing.
  const double far = meter.Measure(BoxHull(2.3, 2.3, 2.3, 12.7, 15.2, 12.7));
  EXPECT_NEAR(far, 2.5, 1e-9);
  // Early exit: any value above the limit.
  EXPECT_GT(meter.Measure(BoxHull(2.3, 2.3, 2.3, 12.7, 15.2, 12.7), 1.0), 1.0);
}

TEST(StickOutTest, OpenSurfacesTrustTheVoxelVote) {
  // An open box (no top): points just inside its walls are not counted as sticking out.
  vhacd_test::Mesh box = vhacd_test::Box(2.3, 2.3, 2.3, 12.7, 12.7, 12.7);
  GridMesh mesh = ToGrid(box);
  const int dims[3] = {16, 16, 16};
  Context ctx(nullptr, 2);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(mesh, dims, &ctx, &grid, nullptr, 0.0));
  const StickOutMeter meter(mesh, grid, false);
  EXPECT_LT(meter.Measure(BoxHull(4, 4, 4, 10, 10, 10)), 1e-9);
  EXPECT_GT(meter.Measure(BoxHull(2.3, 2.3, 2.3, 12.7, 12.7, 15.2)), 1.5);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
