#include "error_metrics.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace internal
}  // namespace vhacd
