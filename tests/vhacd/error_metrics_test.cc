#include "error_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_grid_mesh.h"
#include "test_meshes.h"

namespace vhacd {
namespace internal {
namespace {

TEST(ErrorMetricsTest, TriangleLocatorMatchesBruteForce) {
  const vhacd_test::Mesh t = vhacd_test::Torus(10.0, 3.0, 32, 16);
  const GridMesh g = vhacd_test::ToGridMesh(t, 1.0, Vec3(20, 20, 5));
  TriangleLocator loc(g, 4.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-10, 50);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng) * 0.3);
    double brute = 1e300;
    for (const auto& tr : g.triangles)
      brute = std::min(brute,
                       PointTriangleDistance(p, g.points[tr[0]], g.points[tr[1]], g.points[tr[2]]));
    EXPECT_NEAR(loc.Distance(p), brute, 1e-9);
  }
}

// Triangles whose boxes span many cells are bucketed only where they may reach: a tilted disc
// fanned from its centre into slivers, and one large triangle beside it, give the distances of a
// brute-force search, near the surface and away from it.
TEST(ErrorMetricsTest, TriangleLocatorMatchesBruteForceOnSliversAndLargeTriangles) {
  GridMesh g;
  std::vector<Vec3> points;
  const Vec3 centre(30, 30, 20), axis_u = Vec3(1, 0.2, 0.4).normalized();
  const Vec3 axis_v = axis_u.cross(Vec3(0.1, 1, -0.3)).normalized();
  points.push_back(centre);
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979 * i / n;
    points.push_back(centre + 25 * (std::cos(a) * axis_u + std::sin(a) * axis_v));
  }
  for (int i = 0; i < n; ++i)
    g.triangles.push_back({0, uint32_t(1 + i), uint32_t(1 + (i + 1) % n)});
  points.push_back(Vec3(0, 0, 0));
  points.push_back(Vec3(60, 5, 45));
  points.push_back(Vec3(10, 55, 50));
  g.triangles.push_back({uint32_t(n + 1), uint32_t(n + 2), uint32_t(n + 3)});
  g.points = GridPoints(points);
  TriangleLocator loc(g, 2.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-5, 65), near(-0.5, 0.5);
  std::uniform_int_distribution<uint32_t> pick(0, uint32_t(g.points.size() - 1));
  for (int i = 0; i < 600; ++i) {
    const Vec3 p = i % 2 ? Vec3(u(rng), u(rng), u(rng))
                         : Vec3(g.points[pick(rng)] + Vec3(near(rng), near(rng), near(rng)));
    double brute = 1e300;
    for (const auto& tr : g.triangles)
      brute = std::min(brute,
                       PointTriangleDistance(p, g.points[tr[0]], g.points[tr[1]], g.points[tr[2]]));
    uint32_t nearest = 0;
    ASSERT_NEAR(loc.Distance(p, &nearest), brute, 1e-9) << "point " << i;
    ASSERT_LT(nearest, g.triangles.size());
    const auto& t = g.triangles[nearest];
    EXPECT_NEAR(PointTriangleDistance(p, g.points[t[0]], g.points[t[1]], g.points[t[2]]), brute,
                1e-9);
  }
}

// DistanceUnlessWithin gives the exact distance and a nearest triangle whenever that distance is
// above `enough`, and otherwise a triangle within `enough` and its own distance: on a fan of
// slivers, where the search would otherwise measure most of the fan near its centre.
TEST(ErrorMetricsTest, DistanceUnlessWithinIsExactAboveItsThreshold) {
  GridMesh g;
  std::vector<Vec3> points;
  const Vec3 centre(20, 20, 10);
  points.push_back(centre);
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979 * i / n;
    points.push_back(centre + Vec3(15 * std::cos(a), 15 * std::sin(a), 0));
  }
  for (int i = 0; i < n; ++i)
    g.triangles.push_back({0, uint32_t(1 + i), uint32_t(1 + (i + 1) % n)});
  g.points = GridPoints(points);
  TriangleLocator loc(g, 2.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-3, 3), height(-1.5, 1.5), enough(0, 1.5);
  int exact = 0, stopped = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p = centre + Vec3(5 * u(rng), 5 * u(rng), height(rng));
    const double e = enough(rng);
    uint32_t nearest = 0, found = 0;
    const double d = loc.Distance(p, &nearest);
    const double within = loc.DistanceUnlessWithin(p, e, &found);
    ASSERT_LT(found, g.triangles.size());
    const auto& t = g.triangles[found];
    const double of_found =
        PointTriangleDistance(p, g.points[t[0]], g.points[t[1]], g.points[t[2]]);
    EXPECT_EQ(within, of_found) << "point " << i;
    if (d > e) {
      ++exact;
      EXPECT_EQ(within, d) << "point " << i;
      EXPECT_EQ(found, nearest) << "point " << i;
    } else {
      ++stopped;
      EXPECT_LE(within, e) << "point " << i;
      EXPECT_GE(within, d) << "point " << i;
    }
  }
  EXPECT_GT(exact, 100);
  EXPECT_GT(stopped, 100);
}

// The report measures with the locator it is given (the stick-out measure's, of another cell
// size) exactly as with the one it builds.
TEST(ErrorMetricsTest, ReportIsTheSameWithAGivenLocator) {
  const vhacd_test::Mesh t = vhacd_test::Torus(10.0, 3.0, 32, 16);
  const GridMesh g = vhacd_test::ToGridMesh(t, 1.0, Vec3(15, 15, 5));
  const int dims[3] = {30, 30, 10};
  Context ctx(nullptr, 2);
  VoxelGrid grid;
  ASSERT_TRUE(Voxelize(g, dims, &ctx, &grid));
  // Two hulls: the halves of the torus on either side of x = 15.
  std::vector<HullMesh> hulls(2);
  for (int side = 0; side < 2; ++side) {
    std::vector<Vec3> pts;
    for (size_t i = 0; i < g.points.size(); ++i)
      if ((g.points[i][0] < 15) == (side == 0)) pts.push_back(g.points[i]);
    ASSERT_EQ(ComputeConvexHull(pts, -1.0, &hulls[side]), HullStatus::kOk);
  }
  MetricsInput in;
  in.mesh = &g;
  in.grid = &grid;
  in.hulls = &hulls;
  in.diagonal = 30;
  in.volume0 = 500;
  in.closed = true;
  Report own, given;
  ASSERT_TRUE(ComputeErrorReport(in, &ctx, &own));
  const TriangleLocator locator(g, 2.0);
  in.locator = &locator;
  ASSERT_TRUE(ComputeErrorReport(in, &ctx, &given));
  EXPECT_GT(own.hausdorff_hulls_to_mesh, 0.0);
  EXPECT_EQ(given.hausdorff_hulls_to_mesh, own.hausdorff_hulls_to_mesh);
  EXPECT_EQ(given.hausdorff_mesh_to_hulls, own.hausdorff_mesh_to_hulls);
  EXPECT_EQ(given.concavity, own.concavity);
  EXPECT_EQ(given.volume_iou, own.volume_iou);
  ASSERT_EQ(given.hulls.size(), own.hulls.size());
  for (size_t h = 0; h < own.hulls.size(); ++h)
    EXPECT_EQ(given.hulls[h].distance, own.hulls[h].distance);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
