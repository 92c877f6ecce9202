#include "voxelizer.h"

#include <gtest/gtest.h>

#include "test_grid_mesh.h"
#include "test_meshes.h"

namespace vhacd {
namespace internal {
namespace {

using vhacd_test::ToGridMesh;

TEST(VoxelizerTest, TriangleBoxOverlap) {
  const Vec3 c(0.5, 0.5, 0.5);
  EXPECT_TRUE(TriangleBoxOverlap(c, 0.5, Vec3(-1, -1, 0.5), Vec3(3, -1, 0.5),
                                 Vec3(-1, 3, 0.5)));  // slices it
  EXPECT_FALSE(
      TriangleBoxOverlap(c, 0.5, Vec3(-1, -1, 1.5), Vec3(3, -1, 1.5), Vec3(-1, 3, 1.5)));  // above
  EXPECT_TRUE(TriangleBoxOverlap(c, 0.5, Vec3(0.2, 0.2, 0.2), Vec3(0.3, 0.2, 0.2),
                                 Vec3(0.2, 0.3, 0.2)));  // inside
  // Beyond the box corner edge: only the triangle plane separates them.
  EXPECT_FALSE(TriangleBoxOverlap(c, 0.5, Vec3(2.1, 0, 0), Vec3(0, 2.1, 0), Vec3(0, 2.1, 1)));
  EXPECT_TRUE(TriangleBoxOverlap(c, 0.5, Vec3(1.9, 0, 0), Vec3(0, 1.9, 0), Vec3(0, 1.9, 1)));
}

TEST(VoxelizerTest, ChooseGridGivesAboutTheResolution) {
  const GridPlacement g = ChooseGrid(Vec3(-0.5, -0.25, -0.1), Vec3(0.5, 0.25, 0.1), 100000);
  const double n = (g.dims[0] - 2.0) * (g.dims[1] - 2.0) * (g.dims[2] - 2.0);
  EXPECT_GT(n, 80000);
  EXPECT_LT(n, 130000);
  const GridPlacement flat = ChooseGrid(Vec3(0, 0, 0), Vec3(1, 1, 0), 10000);
  EXPECT_EQ(flat.dims[2], 3);
  EXPECT_GT(flat.dims[0], 50);
  // Padding included, a flat box stays within twice the resolution.
  const GridPlacement big = ChooseGrid(Vec3(0, 0, 0), Vec3(1, 1, 0), 64000000);
  EXPECT_LE(static_cast<double>(big.dims[0]) * big.dims[1] * big.dims[2], 2.0 * 64000000);
  const GridPlacement line = ChooseGrid(Vec3(0, 0, 0), Vec3(1, 0, 0), 64000000);
  EXPECT_LE(line.dims[0], 30002);
  EXPECT_LE(static_cast<double>(line.dims[0]) * line.dims[1] * line.dims[2], 2.0 * 64000000);
}

TEST(VoxelizerTest, ClosedBoxIsFilled) {
  // A box covering voxels [2, 12) x [2, 10) x [2, 8) with faces at voxel boundaries.
  const vhacd_test::Mesh box = vhacd_test::Box(2, 2, 2, 12, 10, 8);
  const GridMesh g = ToGridMesh(box, 1.0, Vec3::Zero());
  const int dims[3] = {15, 13, 11};
  Context ctx(nullptr, 2);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(g, dims, &ctx, &grid));
  int inside = 0, surface = 0;
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) {
        const size_t i = grid.Index(x, y, z);
        const bool in_box = x >= 2 && x < 12 && y >= 2 && y < 10 && z >= 2 && z < 8;
        EXPECT_EQ(grid.CenterInside(i), in_box) << x << " " << y << " " << z;
        inside += grid.cell[i] == kCellInside;
        surface += grid.cell[i] == kCellSurface;
      }
  EXPECT_EQ(inside, 8 * 6 * 4);  // the strict interior (faces touch the boundary layer)
  EXPECT_GT(surface, 0);
}

TEST(VoxelizerTest, SphereWithHolesIsSolidButThinSheetIsNot) {
  const vhacd_test::Mesh s = vhacd_test::Sphere(10.0, 48, 24, true);
  const GridMesh g = ToGridMesh(s, 1.0, Vec3(12.3, 12.3, 12.3));
  const int dims[3] = {25, 25, 25};
  Context ctx(nullptr, 1);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(g, dims, &ctx, &grid));
  EXPECT_EQ(grid.cell[grid.Index(12, 12, 12)], kCellInside);
  EXPECT_EQ(grid.cell[grid.Index(12, 12, 5)], kCellInside);
  EXPECT_EQ(grid.cell[grid.Index(1, 1, 1)], kCellOutside);
  EXPECT_EQ(grid.cell[grid.Index(12, 12, 24)], kCellOutside);
  int inside = 0, expected = 0;
  for (int z = 0; z < 25; ++z)
    for (int y = 0; y < 25; ++y)
      for (int x = 0; x < 25; ++x) {
        const Vec3 c(x + 0.5 - 12.3, y + 0.5 - 12.3, z + 0.5 - 12.3);
        if (c.norm() < 8.5 && c.z() > -8) {
          ++expected;
          inside += grid.cell[grid.Index(x, y, z)] != kCellOutside;
        }
      }
  EXPECT_GE(inside, expected * 95 / 100);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
