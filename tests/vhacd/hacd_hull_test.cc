// Tests of a HACD cluster's hull (src/hacd_hull.h).
#include "hacd_hull.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace vhacd {
namespace internal {
namespace {

// Smallest sine of a corner angle over the hull's faces (0 for a face with collinear corners).
double SmallestFaceSine(const HullMesh& h) {
  double smallest = 1.0;
  for (const auto& t : h.triangles) {
    const Vec3 &a = h.vertices[t[0]], &b = h.vertices[t[1]], &c = h.vertices[t[2]];
    const double longest =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    smallest = std::min(smallest, (b - a).cross(c - a).norm() / longest);
  }
  return smallest;
}

TEST(HacdHullTest, NoFaceWithCollinearCorners) {
  // From a perforated plate's cluster (gen_bench_meshes' cad_sheet_perf_30x20): three points on a
  // line and one off it. The hull of these alone is flat, so it is given its thickness; quickhull
  // then kept the middle point of the line on a hull edge, a zero-area face whose normal is noise.
  const std::vector<Vec3> pts = {{200.3268970847196, -530.23241974993357, -0.12424883688539801},
                                 {311.26584401310765, -530.23241975197379, -0.12424883754755944},
                                 {422.20479094176864, -530.23241975127507, -0.12424883729490133},
                                 {574.23203396141412, -548.9274238826373, 2.958371962081884}};
  const HullMesh h = ClusterHull(pts, 0.2, 100);
  ASSERT_FALSE(h.empty());
  EXPECT_GT(h.Volume(), 0.0);
  EXPECT_GT(SmallestFaceSine(h), 1e-8);
  EXPECT_LE(h.MaxConvexityViolation(), 1e-9);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
