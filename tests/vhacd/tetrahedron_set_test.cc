#include "tetrahedron_set.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_grid_mesh.h"
#include "test_meshes.h"

namespace vhacd {
namespace internal {
namespace {

double VolumeOfTet(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return std::fabs((b - a).dot((c - a).cross(d - a))) / 6.0;
}

Vec3 Corner(int k) { return Vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1); }

TEST(TetrahedronSetTest, FiveTetrahedraTileTheCube) {
  double total = 0.0;
  for (const auto& t : kCubeTetrahedra) {
    const double v = VolumeOfTet(Corner(t[0]), Corner(t[1]), Corner(t[2]), Corner(t[3]));
    EXPECT_GT(v, 0.1);
    total += v;
  }
  EXPECT_NEAR(total, 1.0, 1e-15);
  const SurfaceCell full = FullCell(3, 4, 5);
  EXPECT_EQ(full.point_count, 8);
  EXPECT_EQ(full.tetrahedra, 5);
  EXPECT_EQ(full.volume, 1.0f);
}

TEST(TetrahedronSetTest, ClippedTetrahedronVolumes) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1);  // volume 1/6
  int count = 0;
  std::vector<std::array<Vec3, 4>> pieces;
  // Whole, nothing, one vertex in (a corner of scale t: t^3), three vertices in (1 - (1-t)^3).
  EXPECT_NEAR(ClipTetrahedron(a, b, c, d, Vec3(1, 0, 0), 2.0, &count), 1.0 / 6, 1e-15);
  EXPECT_EQ(count, 1);
  EXPECT_EQ(ClipTetrahedron(a, b, c, d, Vec3(1, 0, 0), -1.0, &count), 0.0);
  EXPECT_EQ(count, 0);
  const Vec3 diag = Vec3(1, 1, 1).normalized();
  const double t = 0.4;
  EXPECT_NEAR(ClipTetrahedron(a, b, c, d, diag, t / std::sqrt(3.0), &count), t * t * t / 6, 1e-15);
  EXPECT_EQ(count, 1);
  // Vertex a out, b, c, d in: the tetrahedron minus its corner at a.
  EXPECT_NEAR(ClipTetrahedron(a, b, c, d, -diag, -t / std::sqrt(3.0), &count, &pieces),
              (1 - t * t * t) / 6, 1e-15);
  EXPECT_EQ(count, 3);
  EXPECT_EQ(pieces.size(), 3u);
  // Two in, two out (a wedge): x <= 0.5 keeps everything but the corner at b... of scale 1/2,
  // that is 1 - 1/8 of the volume; z + x <= 0.5 leaves a, c in and b, d out.
  EXPECT_NEAR(ClipTetrahedron(a, b, c, d, Vec3(1, 0, 0), 0.5, &count), (1 - 0.125) / 6, 1e-15);
  pieces.clear();
  const Vec3 nxz = Vec3(1, 0, 1).normalized();
  const double v2 = ClipTetrahedron(a, b, c, d, nxz, 0.5 / std::sqrt(2.0), &count, &pieces);
  double sum = 0.0;
  for (const auto& q : pieces) {
    sum += VolumeOfTet(q[0], q[1], q[2], q[3]);
    for (const Vec3& p : q) EXPECT_LE(nxz.dot(p), 0.5 / std::sqrt(2.0) + 1e-12);
  }
  EXPECT_EQ(count, 3);
  EXPECT_NEAR(sum, v2, 1e-15);
  // The complement has the rest of the volume.
  const double rest = ClipTetrahedron(a, b, c, d, -nxz, -0.5 / std::sqrt(2.0), &count);
  EXPECT_NEAR(v2 + rest, 1.0 / 6, 1e-15);
}

TEST(TetrahedronSetTest, TrimmedCellsFollowThePlane) {
  // x <= 10.3 in voxel (10, 0, 0): a slab 0.3 thick with the 8 points of its box.
  const SurfaceCell slab = TrimmedCell(10, 0, 0, Vec3(1, 0, 0), 10.3);
  EXPECT_NEAR(slab.volume, 0.3, 1e-6);
  EXPECT_EQ(slab.point_count, 8);
  for (int i = 0; i < slab.point_count; ++i) EXPECT_LE(slab.p[i][0], 10.3f + 1e-5f);
  // Through the cube's centre, perpendicular to its diagonal: half the cube, a hexagonal cut.
  const Vec3 n = Vec3(1, 1, 1).normalized();
  const SurfaceCell half = TrimmedCell(0, 0, 0, n, n.dot(Vec3(0.5, 0.5, 0.5)));
  EXPECT_NEAR(half.volume, 0.5, 1e-6);
  EXPECT_EQ(half.point_count, 4 + 6);
  // A plane beyond the cube keeps it whole.
  const SurfaceCell whole = TrimmedCell(0, 0, 0, n, 10.0);
  EXPECT_EQ(whole.volume, 1.0f);
  EXPECT_EQ(whole.tetrahedra, 5);
}

TEST(TetrahedronSetTest, ConvexCornerAndConcaveEdge) {
  // Corner of the solid x <= 0.5, y <= 0.5, z <= 0.5 in voxel (0, 0, 0): an eighth of the cube.
  const HalfSpace corner[3] = {{Vec3(1, 0, 0), 0.5}, {Vec3(0, 1, 0), 0.5}, {Vec3(0, 0, 1), 0.5}};
  const SurfaceCell c = TrimmedCell(0, 0, 0, corner, 3, false);
  EXPECT_NEAR(c.volume, 0.125, 1e-6);
  EXPECT_EQ(c.point_count, 8);
  // Concave edge: x <= 0.5 or y <= 0.5, three quarters of the cube, vertices of both pieces.
  const SurfaceCell e = TrimmedCell(0, 0, 0, corner, 2, true);
  EXPECT_NEAR(e.volume, 0.75, 1e-6);
  EXPECT_GE(e.point_count, 10);
  for (int i = 0; i < e.point_count; ++i) EXPECT_TRUE(e.p[i][0] <= 0.5f || e.p[i][1] <= 0.5f);
}

TEST(TetrahedronSetTest, SurfaceCellsTrimABoxToItsVolume) {
  // A box whose faces lie inside voxels (grid units): the trimmed cells add up to its volume,
  // while whole surface voxels overestimate it.
  const vhacd_test::Mesh box = vhacd_test::Box(1.3, 1.3, 1.3, 8.6, 7.7, 6.4);
  const GridMesh mesh = vhacd_test::ToGridMesh(box);
  const int dims[3] = {10, 9, 8};
  Context one(nullptr, 1);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(mesh, dims, &one, &grid));
  std::vector<SurfaceCell> cells;
  ASSERT_TRUE(BuildSurfaceCells(mesh, grid, &one, &cells));
  size_t surface = 0, inside = 0;
  for (size_t i = 0; i < grid.size(); ++i) {
    surface += grid.cell[i] == kCellSurface;
    inside += grid.cell[i] == kCellInside;
  }
  ASSERT_EQ(cells.size(), surface);
  double volume = static_cast<double>(inside);
  int trimmed = 0;
  for (const SurfaceCell& c : cells) {
    volume += c.volume;
    trimmed += c.volume < 1.0f;
    EXPECT_EQ(grid.cell[grid.Index(c.c[0], c.c[1], c.c[2])], kCellSurface);
  }
  const double exact = 7.3 * 6.4 * 5.1;
  EXPECT_GT(trimmed, static_cast<int>(surface / 2));
  // Edges and corners are trimmed by their two or three faces.
  EXPECT_NEAR(volume, exact, 0.01 * exact);
  EXPECT_GT(static_cast<double>(inside + surface) - exact, 2 * (volume - exact));
  // Deterministic with any number of threads.
  Context ctx(nullptr, 3);
  std::vector<SurfaceCell> again;
  ASSERT_TRUE(BuildSurfaceCells(mesh, grid, &ctx, &again));
  ASSERT_EQ(again.size(), cells.size());
  for (size_t i = 0; i < cells.size(); ++i) {
    EXPECT_EQ(again[i].volume, cells[i].volume);
    EXPECT_EQ(again[i].point_count, cells[i].point_count);
  }
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
