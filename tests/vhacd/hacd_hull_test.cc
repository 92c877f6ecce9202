// Tests of a HACD cluster's hull (src/hacd_hull.h).
#include "hacd_hull.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "test_meshes.h"

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

// The caster's copy of a test mesh (the caster keeps references).
struct Surface {
  std::vector<Vec3> points;
  std::vector<std::array<uint32_t, 3>> triangles;
  explicit Surface(const vhacd_test::Mesh& m) {
    for (size_t i = 0; i < m.point_count(); ++i)
      points.emplace_back(m.points[3 * i], m.points[3 * i + 1], m.points[3 * i + 2]);
    for (size_t t = 0; t < m.triangle_count(); ++t)
      triangles.push_back({m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]});
  }
};

TEST(HacdHullTest, InsideCountsOverlappingPiecesOnce) {
  // A closed box inside another (both outward): a point in the inner one crosses two surfaces on
  // its way out, and is inside both.
  vhacd_test::Mesh m = vhacd_test::Box(0, 0, 0, 4, 4, 4);
  m.Append(vhacd_test::Box(1, 1, 1, 3, 3, 3));
  const Surface s(m);
  const RayCaster caster(s.points, s.triangles);
  EXPECT_TRUE(caster.Inside(Vec3(2, 2, 2)));
  EXPECT_TRUE(caster.Inside(Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(caster.Inside(Vec3(5, 2, 2)));
}

TEST(HacdHullTest, ExtensionThatStaysInsideTheSolidIsKept) {
  // The patch is the top of a 4 x 4 x 2 box. One distance point lies under it, inside the solid,
  // its ray pointing down (a surface closing the solid from inside, like a pot's rim under its
  // lid): the extended hull lengthens that ray, but only through the solid, so the extension
  // halfway down is kept.
  const Surface box(vhacd_test::Box(0, 0, 0, 4, 4, 2));
  const RayCaster caster(box.points, box.triangles);
  FillInput in;
  in.surface = {{0, 0, 2}, {4, 0, 2}, {4, 4, 2}, {0, 4, 2}};
  in.behind = {{8.0 / 3, 4.0 / 3, 2}, {4.0 / 3, 8.0 / 3, 2}};
  in.inward = {{0, 0, -1}, {0, 0, -1}};
  in.depth = {2, 2};
  std::vector<DistPoint> dist;
  for (const Vec3& p : in.surface) dist.push_back({p, Vec3(0, 0, 1)});
  dist.push_back({Vec3(2, 2, 1.9), Vec3(0, 0, -1)});
  const std::vector<uint32_t> ids = {0, 1, 2, 3, 4};
  const HacdCostParams cost;
  in.dist = &dist;
  in.dist_ids = &ids;
  in.area = 16;
  in.cost = &cost;
  in.caster = &caster;
  in.thickness = 1e-3;
  in.tolerance = 1e-6;
  const HullMesh h = FilledClusterHull(in);
  ASSERT_FALSE(h.empty());
  double lowest = 2;
  for (const Vec3& p : h.vertices) lowest = std::min(lowest, p[2]);
  EXPECT_NEAR(lowest, 1.0, 1e-9);  // halfway through the solid
  EXPECT_GT(h.Volume(), 1.0);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
