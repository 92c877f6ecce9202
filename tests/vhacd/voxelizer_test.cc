#include "voxelizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// The range test never rejects a range holding a voxel the voxel test accepts, and does reject
// ranges well away from the triangle.
TEST(VoxelizerTest, TriangleMayMeetVoxelsIsConservative) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(0.0, 24.0), unit(0.0, 1.0);
  std::uniform_int_distribution<int> start(0, 20), size(0, 6);
  int rejected = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Vec3 a(coord(rng), coord(rng), coord(rng)), b(coord(rng), coord(rng), coord(rng));
    // Every third a sliver: its third corner close to its first edge.
    Vec3 c = trial % 3 == 0 ? a + unit(rng) * (b - a) + Vec3::Constant(0.05 * unit(rng))
                            : Vec3(coord(rng), coord(rng), coord(rng));
    if (trial % 7 == 0) c = Vec3(std::floor(c[0]), std::floor(c[1]), b[2]);  // on voxel faces
    int lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = start(rng);
      hi[k] = lo[k] + size(rng);
    }
    bool any = false;
    for (int z = lo[2]; z <= hi[2] && !any; ++z)
      for (int y = lo[1]; y <= hi[1] && !any; ++y)
        for (int x = lo[0]; x <= hi[0] && !any; ++x)
          any = TriangleBoxOverlap(Vec3(x + 0.5, y + 0.5, z + 0.5), 0.5 + 1e-9, a, b, c);
    const bool may = TriangleMayMeetVoxels(lo, hi, a, b, c);
    if (any) EXPECT_TRUE(may) << "trial " << trial;
    rejected += !may;
  }
  EXPECT_GT(rejected, 500);
}

// A disc fanned from its centre into 300 long slivers, wavy in z so that all three axes see it at
// an angle, on an 82 x 82 x 8 grid.
GridMesh WavyFan() {
  GridMesh fan;
  const int n = 300;
  const Vec3 centre(40.3, 40.7, 3.2);
  std::vector<Vec3> points{centre};
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    points.push_back(centre + Vec3(37 * std::cos(t), 37 * std::sin(t), 1.3 * std::sin(3 * t)));
  }
  fan.points = GridPoints(points);
  for (int i = 0; i < n; ++i)
    fan.triangles.push_back(
        {0, static_cast<uint32_t>(i + 1), static_cast<uint32_t>((i + 1) % n + 1)});
  return fan;
}
constexpr int kWavyFanDims[3] = {82, 82, 8};

bool VoxelizeOnTwoThreads(const GridMesh& mesh, const int dims[3], VoxelGrid* grid) {
  Context ctx(nullptr, 2);
  return Voxelize(mesh, dims, &ctx, grid);
}

// A fan of long slivers (an STL exporter's round face): the surface voxels are exactly those the
// voxel test accepts over each triangle's whole box.
TEST(VoxelizerTest, FanOfSliversMarksTheSameVoxelsAsAFullWalk) {
  const GridMesh fan = WavyFan();
  const int* dims = kWavyFanDims;
  VoxelGrid grid;
  ASSERT_TRUE(VoxelizeOnTwoThreads(fan, dims, &grid));
  std::vector<uint8_t> expected(grid.size(), 0);
  for (const auto& t : fan.triangles) {
    const Vec3 &a = fan.points[t[0]], &b = fan.points[t[1]], &c = fan.points[t[2]];
    for (int z = 0; z < dims[2]; ++z)
      for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x)
          if (TriangleBoxOverlap(Vec3(x + 0.5, y + 0.5, z + 0.5), 0.5 + 1e-9, a, b, c))
            expected[grid.Index(x, y, z)] = 1;
  }
  size_t surface = 0;
  for (size_t i = 0; i < grid.size(); ++i) {
    EXPECT_EQ(grid.cell[i] == kCellSurface, expected[i] == 1) << i;
    surface += expected[i];
  }
  EXPECT_GT(surface, 4000u);
}

// The same fan: the parity votes are those of a walk over every line through voxel centres
// (the lines of a sliver's range that lie outside it are skipped, not miscounted). No line centre
// lies on an edge here, so a closed point-in-triangle test is the reference.
TEST(VoxelizerTest, FanOfSliversVotesAsEveryLineDoes) {
  const GridMesh fan = WavyFan();
  const int* dims = kWavyFanDims;
  VoxelGrid grid;
  ASSERT_TRUE(VoxelizeOnTwoThreads(fan, dims, &grid));
  std::vector<int> expected(grid.size(), 0);
  size_t crossings = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int iv = 0; iv < dims[v]; ++iv)
      for (int iu = 0; iu < dims[u]; ++iu) {
        const double qu = iu + 0.5, qv = iv + 0.5;
        std::vector<double> ts;
        for (const auto& t : fan.triangles) {
          const Vec3 &a = fan.points[t[0]], &b = fan.points[t[1]], &c = fan.points[t[2]];
          auto orient = [&](const Vec3& p, const Vec3& q) {
            return (q[u] - p[u]) * (qv - p[v]) - (q[v] - p[v]) * (qu - p[u]);
          };
          const double wa = orient(b, c), wb = orient(c, a), wc = orient(a, b);
          const bool in = (wa >= 0 && wb >= 0 && wc >= 0) || (wa <= 0 && wb <= 0 && wc <= 0);
          const double sum = wa + wb + wc;
          if (!in || sum == 0) continue;
          ts.push_back((wa * a[axis] + wb * b[axis] + wc * c[axis]) / sum);
        }
        crossings += ts.size();
        int g[3];
        g[u] = iu;
        g[v] = iv;
        for (int k = 0; k < dims[axis]; ++k) {
          size_t below = 0;
          for (double t : ts) below += t < k + 0.5;
          g[axis] = k;
          expected[grid.Index(g[0], g[1], g[2])] +=
              static_cast<int>((below & 1) + ((ts.size() - below) & 1));
        }
      }
  }
  EXPECT_GT(crossings, 4000u);
  for (size_t i = 0; i < grid.size(); ++i) ASSERT_EQ(grid.votes[i], expected[i]) << i;
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
