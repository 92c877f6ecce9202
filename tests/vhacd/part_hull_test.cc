#include "part_hull.h"

#include <gtest/gtest.h>

#include "context.h"
#include "error_metrics.h"
#include "oriented_cuts.h"
#include "solid_corners.h"
#include "test_grid_mesh.h"
#include "test_meshes.h"

namespace vhacd {
namespace internal {
namespace {

using vhacd_test::VoxelAt;

TEST(PartHullTest, ClipTriangleToBox) {
  std::vector<Vec3> out;
  // Fully inside: unchanged.
  ClipTriangleToBox(Vec3(1, 1, 1), Vec3(2, 1, 1), Vec3(1, 2, 1), Vec3(0, 0, 0), Vec3(3, 3, 3),
                    &out);
  EXPECT_EQ(out.size(), 3u);
  // Outside: nothing.
  out.clear();
  ClipTriangleToBox(Vec3(5, 5, 5), Vec3(6, 5, 5), Vec3(5, 6, 5), Vec3(0, 0, 0), Vec3(3, 3, 3),
                    &out);
  EXPECT_TRUE(out.empty());
  // A big triangle in z = 1 covering the box's section: clipped to the square [0,3]^2.
  out.clear();
  ClipTriangleToBox(Vec3(-10, -10, 1), Vec3(30, -10, 1), Vec3(-10, 30, 1), Vec3(0, 0, 0),
                    Vec3(3, 3, 3), &out);
  ASSERT_EQ(out.size(), 4u);
  for (const Vec3& p : out) {
    EXPECT_TRUE(p.x() == 0 || p.x() == 3);
    EXPECT_TRUE(p.y() == 0 || p.y() == 3);
    EXPECT_EQ(p.z(), 1);
  }
}

TEST(PartHullTest, HullOfAPartHugsTheSurfaceInsideItsBox) {
  // A box mesh [2.3, 7.6] x [2.2, 5.9] x [2.1, 4.8] in grid units; the part holds voxels x < 5.
  const vhacd_test::Mesh box = vhacd_test::Box(2.3, 2.2, 2.1, 7.6, 5.9, 4.8);
  const GridMesh g = vhacd_test::ToGridMesh(box);
  const int dims[3] = {10, 8, 7};
  Part part;
  for (int z = 2; z <= 4; ++z)
    for (int y = 2; y <= 5; ++y)
      for (int x = 2; x <= 4; ++x)
        part.voxels.push_back(VoxelAt(x, y, z, x == 2 || y == 2 || y == 5 || z == 2 || z == 4));
  part.ComputeBounds();
  const TriangleIndex index(g, dims, 4);
  const HullMesh h = BuildPartHull(part, index);
  ASSERT_FALSE(h.empty());
  // The mesh box clipped to x <= 5: [2.3, 5] x [2.2, 5.9] x [2.1, 4.8].
  EXPECT_NEAR(h.Volume(), (5 - 2.3) * (5.9 - 2.2) * (4.8 - 2.1), 1e-9);
}

// Whether p lies in the hull (within tol).
bool HullContains(const HullMesh& h, const Vec3& p, double tol) {
  for (const auto& t : h.triangles) {
    const Vec3& a = h.vertices[t[0]];
    const Vec3 n = (h.vertices[t[1]] - a).cross(h.vertices[t[2]] - a).normalized();
    if (n.dot(p - a) > tol) return false;
  }
  return true;
}

// PartHulls gives BuildPartHull's hull for every part: the whole set's (built once), a half's,
// and that of a part holding every voxel but bounded by a cut, which is not the whole set's.
TEST(PartHullTest, PartHullsGivesEachPartItsOwnHull) {
  const vhacd_test::Mesh box = vhacd_test::Box(2.3, 2.2, 2.1, 7.6, 5.9, 4.8);
  const GridMesh g = vhacd_test::ToGridMesh(box);
  const int dims[3] = {10, 8, 7};
  Part whole, half;
  for (int z = 2; z <= 4; ++z)
    for (int y = 2; y <= 5; ++y)
      for (int x = 2; x <= 7; ++x) {
        const Voxel v = VoxelAt(x, y, z, x == 2 || x == 7 || y == 2 || y == 5 || z == 2 || z == 4);
        whole.voxels.push_back(v);
        if (x <= 4) half.voxels.push_back(v);
      }
  whole.ComputeBounds();
  half.ComputeBounds();
  Part cut = whole;
  cut.cuts.push_back(CutPlane{Vec3(1, 0, 0), 5.5});  // x <= 5.5
  const TriangleIndex index(g, dims, 4);
  PartHulls hulls(whole, index, nullptr);
  for (int round = 0; round < 2; ++round) {
    for (const Part* p : {&whole, &half, &cut}) {
      const HullMesh expected = BuildPartHull(*p, index);
      const HullMesh got = hulls.Of(*p);
      ASSERT_FALSE(got.empty());
      EXPECT_EQ(got.vertices, expected.vertices);
      EXPECT_EQ(got.triangles, expected.triangles);
    }
  }
  EXPECT_NEAR(hulls.Of(whole).Volume(), (7.6 - 2.3) * (5.9 - 2.2) * (4.8 - 2.1), 1e-9);
  EXPECT_LT(hulls.Of(cut).Volume(), hulls.Of(whole).Volume() - 1.0);
}

// A part bounded by oblique cuts gets the hull of the surface clipped to its box and its cuts: the
// triangles inside them all give their vertices once, the others their clipped polygons.
TEST(PartHullTest, APartWithCutsHasTheHullOfItsClippedSurface) {
  const GridMesh g = vhacd_test::ToGridMesh(vhacd_test::Sphere(7.0, 64, 32), 1.0, Vec3(10, 10, 10));
  const int dims[3] = {20, 20, 20};
  Part part;
  for (int z = 2; z <= 17; ++z)
    for (int y = 2; y <= 17; ++y)
      for (int x = 2; x <= 17; ++x) part.voxels.push_back(VoxelAt(x, y, z, true));
  part.ComputeBounds();
  part.cuts.push_back(CutPlane{Vec3(1, 1, 0).normalized(), 15.0});
  part.cuts.push_back(CutPlane{Vec3(0, -1, 1).normalized(), 3.0});
  const TriangleIndex index(g, dims, 4);
  const HullMesh got = BuildPartHull(part, index);
  ASSERT_FALSE(got.empty());
  const Vec3 lo(2, 2, 2), hi(18, 18, 18);
  std::vector<Vec3> clipped, poly;
  for (const auto& t : g.triangles) {
    poly.clear();
    ClipTriangleToBox(g.points[t[0]], g.points[t[1]], g.points[t[2]], lo, hi, &poly);
    if (!poly.empty()) ClipPolygonToCuts(poly, part.cuts, &clipped);
  }
  HullMesh expected;
  ASSERT_EQ(ComputeConvexHull(clipped, -1.0, &expected), HullStatus::kOk);
  EXPECT_NEAR(got.Volume(), expected.Volume(), 1e-9 * expected.Volume());
  EXPECT_EQ(got.vertices.size(), expected.vertices.size());
  for (const Vec3& p : clipped) EXPECT_TRUE(HullContains(got, p, 1e-9));
}

// Mapped on every read (Parameters::points_in_place), the mesh's points are read by index instead
// of copied into a part's points: the same hulls, bit for bit.
// BuildPartHull on `a` and on `b` (the same surface held differently) for a whole box of voxels,
// its half, and the whole under an oriented cut: the hulls must be the same.
void ExpectSamePartHulls(const GridMesh& a, const GridMesh& b) {
  const int dims[3] = {20, 20, 20};
  Part whole, cut, half;
  for (int z = 2; z <= 17; ++z)
    for (int y = 2; y <= 17; ++y)
      for (int x = 2; x <= 17; ++x) {
        whole.voxels.push_back(VoxelAt(x, y, z, true));
        if (x <= 9) half.voxels.push_back(VoxelAt(x, y, z, true));
      }
  whole.ComputeBounds();
  half.ComputeBounds();
  cut = whole;
  cut.cuts.push_back(CutPlane{Vec3(1, 1, 0).normalized(), 15.0});
  const TriangleIndex a_index(a, dims, 4), b_index(b, dims, 4);
  for (const Part* part : {&whole, &half, &cut}) {
    const HullMesh ha = BuildPartHull(*part, a_index);
    const HullMesh hb = BuildPartHull(*part, b_index);
    ASSERT_FALSE(ha.empty());
    EXPECT_EQ(ha.vertices, hb.vertices);
    EXPECT_EQ(ha.triangles, hb.triangles);
  }
}

TEST(PartHullTest, MappedPointsGiveTheSameHullsAsHeldOnes) {
  const vhacd_test::Mesh sphere = vhacd_test::Sphere(7.0, 64, 32);
  std::vector<double> coords;
  for (size_t i = 0; i < sphere.point_count(); ++i)
    for (int a = 0; a < 3; ++a) coords.push_back(sphere.points[3 * i + a] + 10.0);
  PointSource source;
  source.d = coords.data();
  source.count = sphere.point_count();
  GridFrame frame;
  frame.unit.scale = 32.0;
  frame.h = 1.0 / 32.0;
  std::vector<Vec3> held;
  for (size_t i = 0; i < source.size(); ++i) held.push_back(frame.ToGrid(source[i]));
  GridMesh owned = vhacd_test::ToGridMesh(sphere), mapped = vhacd_test::ToGridMesh(sphere);
  owned.points = GridPoints(held);
  mapped.points = GridPoints(source, frame);
  ExpectSamePartHulls(owned, mapped);
}

TEST(PartHullTest, ALargeMeshGivesTheSameHullsReadByIndex) {
  // The same triangles over the same points, once as a small mesh (a part's points are copied)
  // and once padded with unused copies of a point to a size whose parts read points by index.
  const vhacd_test::Mesh sphere = vhacd_test::Sphere(7.0, 64, 32);
  GridMesh small = vhacd_test::ToGridMesh(sphere);
  std::vector<Vec3> points;
  for (size_t i = 0; i < sphere.point_count(); ++i)
    points.emplace_back(sphere.points[3 * i] + 10.0, sphere.points[3 * i + 1] + 10.0,
                        sphere.points[3 * i + 2] + 10.0);
  small.points = GridPoints(points);
  GridMesh large = small;
  points.resize(size_t{1} << 18, points[0]);
  large.points = GridPoints(points);
  ExpectSamePartHulls(small, large);
}

TEST(PartHullTest, InsideCornersOfSurfaceVoxelsReachTheCut) {
  // An L-shaped prism (grid units): a floor x in [0.25, 6.25], y in [0.25, 4.75] and a wall x in
  // [4.75, 6.25] up to y = 10.25, z in [0.5, 9.5]. The part is cut at x = 5, y = 6, z = 3 and z =
  // 7: in its box the wall is a quarter voxel thick and all surface voxels, and no surface crosses
  // the box faces near the corner (5, 6), so surface and interior voxels alone leave that corner of
  // the solid out (its neighbours across the cuts cover it: a crack).
  const double outline[6][2] = {{0.25, 0.25},  {6.25, 0.25}, {6.25, 10.25},
                                {4.75, 10.25}, {4.75, 4.75}, {0.25, 4.75}};
  GridMesh g;
  std::vector<Vec3> points;
  for (double z : {0.5, 9.5})
    for (const auto& p : outline) points.emplace_back(p[0], p[1], z);
  g.points = GridPoints(points);
  const int fan[4][2] = {{5, 0}, {0, 1}, {1, 2}, {2, 3}};  // from the reflex vertex 4
  for (const auto& f : fan) {
    g.triangles.push_back({4, static_cast<uint32_t>(f[1]), static_cast<uint32_t>(f[0])});
    g.triangles.push_back({10, static_cast<uint32_t>(6 + f[0]), static_cast<uint32_t>(6 + f[1])});
  }
  for (uint32_t i = 0; i < 6; ++i) {
    const uint32_t j = (i + 1) % 6;
    g.triangles.push_back({i, j, 6 + j});
    g.triangles.push_back({i, 6 + j, 6 + i});
  }
  const int dims[3] = {8, 12, 11};
  Context ctx(nullptr, 1);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(g, dims, &ctx, &grid));
  Part part;
  for (int z = 3; z <= 6; ++z)
    for (int y = 0; y <= 5; ++y)
      for (int x = 0; x <= 4; ++x) {
        const uint8_t c = grid.cell[grid.Index(x, y, z)];
        if (c != kCellOutside) part.voxels.push_back(VoxelAt(x, y, z, c == kCellSurface));
      }
  part.ComputeBounds();
  const TriangleIndex index(g, dims, 4);
  const TriangleLocator locator(g, 2.0);
  SolidCorners corners;
  ASSERT_TRUE(corners.Build(g, grid, locator, &ctx));
  const Vec3 corner(4.95, 5.95, 5.0);
  EXPECT_FALSE(HullContains(BuildPartHull(part, index), corner, 1e-9));
  const HullMesh h = BuildPartHull(part, index, &corners);
  EXPECT_TRUE(HullContains(h, corner, 1e-9));
  // Only inside corners were added: the hull stays within the part's box and the solid's hull.
  for (const Vec3& v : h.vertices) {
    EXPECT_LE(v.x(), 5.0);
    EXPECT_LE(v.y(), 6.0);
    EXPECT_GE(v.x() + 1e-9, v.y() < 4.75 + 1e-9 ? 0.25 : 4.75) << v.transpose();
  }
}

TEST(PartHullTest, TheSameHullAfterManyPartsOnOneThread) {
  // A part's hull does not depend on the parts built before it on the same thread, also once
  // the per-thread marks of the triangles and vertices seen have wrapped (every few hundred
  // parts).
  const vhacd_test::Mesh box = vhacd_test::Box(1.3, 1.2, 1.1, 6.6, 4.9, 3.8);
  const GridMesh g = vhacd_test::ToGridMesh(box);
  const int dims[3] = {8, 6, 5};
  auto voxel = [](int x, int y, int z) { return VoxelAt(x, y, z, true); };
  Part whole;  // every voxel: the whole mesh lies inside the part's box
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) whole.voxels.push_back(voxel(x, y, z));
  whole.ComputeBounds();
  Part corner;  // one voxel that no triangle reaches
  corner.voxels.push_back(voxel(0, 0, 0));
  corner.ComputeBounds();
  const TriangleIndex index(g, dims, 4);
  const HullMesh first = BuildPartHull(whole, index);
  ASSERT_FALSE(first.empty());
  EXPECT_NEAR(first.Volume(), (6.6 - 1.3) * (4.9 - 1.2) * (3.8 - 1.1), 1e-9);
  for (int others = 0; others < 600; ++others) {
    for (int k = 0; k < others; ++k) BuildPartHull(corner, index);
    const HullMesh again = BuildPartHull(whole, index);
    ASSERT_EQ(again.vertices, first.vertices) << "after " << others << " other parts";
    ASSERT_EQ(again.triangles, first.triangles) << "after " << others << " other parts";
  }
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
