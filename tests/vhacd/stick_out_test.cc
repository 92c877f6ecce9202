#include "stick_out.h"

#include <gtest/gtest.h>

#include "context.h"
#include "test_grid_mesh.h"
#include "test_hulls.h"
#include "test_meshes.h"

namespace vhacd {
namespace internal {
namespace {

using vhacd_test::ToGridMesh;

TEST(StickOutTest, MeasuresBelowAVoxelOnTheExactSurface) {
  const GridMesh mesh = ToGridMesh(vhacd_test::Box(2.3, 2.3, 2.3, 12.7, 12.7, 12.7));
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
  GridMesh mesh = ToGridMesh(box);
  const int dims[3] = {16, 16, 16};
  Context ctx(nullptr, 2);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(mesh, dims, &ctx, &grid, nullptr, 0.0));
  const StickOutMeter meter(mesh, grid, false);
  EXPECT_LT(meter.Measure(BoxHull(4, 4, 4, 10, 10, 10)), 1e-9);
  EXPECT_GT(meter.Measure(BoxHull(2.3, 2.3, 2.3, 12.7, 12.7, 15.2)), 1.5);
}

TEST(StickOutTest, FillCapsAreMeasuredFromTheSolid) {
  // A box without its top, filled by the parity rule alone: the fill closes the top. A hull 2.5
  // voxels above that cap is within a few voxels of the solid the decomposition works on, though
  // its corners are 8 voxels from the nearest wall: splits and merges must not chase the cap.
  const vhacd_test::Mesh box = vhacd_test::Box(2.3, 2.3, 2.3, 28.7, 28.7, 28.7);
  GridMesh closed = ToGridMesh(box), mesh;
  mesh.points = closed.points;
  for (const auto& t : closed.triangles)
    if (closed.points[t[0]].z() < 28.0 || closed.points[t[1]].z() < 28.0 ||
        closed.points[t[2]].z() < 28.0)
      mesh.triangles.push_back(t);
  ASSERT_EQ(mesh.triangles.size(), closed.triangles.size() - 2);
  const int dims[3] = {32, 32, 32};
  Context ctx(nullptr, 2);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(mesh, dims, &ctx, &grid, nullptr, 0.0));
  DistanceField field;
  ASSERT_TRUE(field.Build(grid, &ctx));
  const StickOutMeter meter(mesh, grid, false, &field);
  const double above_cap = meter.Measure(BoxHull(10, 10, 10, 20, 20, 31.2));
  EXPECT_GT(above_cap, 1.5);
  EXPECT_LT(above_cap, 5.0);
  // Beside a wall the surface is the nearer: measured from it as before.
  EXPECT_NEAR(meter.Measure(BoxHull(2.3, 2.3, 2.3, 28.7, 28.7 + 2.5, 20)), 2.5, 1e-9);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
