// tools/bench/hull_metrics: the benchmark's error measure, independent of vhacd/.
#include "hull_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/test_shapes.h"

namespace hullpack {
namespace bench {
namespace {

Soup FromShape(const test_shapes::Shape& shape) {
  Soup s;
  for (size_t i = 0; i < shape.positions.size(); i += 3)
    s.points.emplace_back(shape.positions[i], shape.positions[i + 1], shape.positions[i + 2]);
  for (size_t i = 0; i < shape.triangles.size(); i += 3)
    s.triangles.push_back({shape.triangles[i], shape.triangles[i + 1], shape.triangles[i + 2]});
  return s;
}

Soup Box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return FromShape(test_shapes::Box(x0, y0, z0, x1, y1, z1));
}

Soup Sphere(double r, int nu, int nv) { return FromShape(test_shapes::Sphere(r, nu, nv)); }

MetricsOptions Small() {
  MetricsOptions o;
  o.mesh_samples = o.hull_samples = 20000;
  o.solid_points = 40000;
  o.threads = 2;
  return o;
}

TEST(HullMetricsTest, PointTriangleDistance) {
  const V3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_DOUBLE_EQ(PointTriangleDistance(V3(0.2, 0.2, 3), a, b, c), 3.0);           // face
  EXPECT_DOUBLE_EQ(PointTriangleDistance(V3(-1, -1, 0), a, b, c), std::sqrt(2.0));  // vertex
  EXPECT_DOUBLE_EQ(PointTriangleDistance(V3(0.5, -2, 0), a, b, c), 2.0);            // edge
  EXPECT_NEAR(PointTriangleDistance(V3(1, 1, 0), a, b, c), std::sqrt(0.5), 1e-15);  // hypotenuse
  // Degenerate triangles measure to their segment.
  EXPECT_DOUBLE_EQ(PointTriangleDistance(V3(0.5, 1, 0), a, b, V3(2, 0, 0)), 1.0);
}

TEST(HullMetricsTest, BvhDistanceAndWindingMatchBruteForce) {
  const Soup sphere = Sphere(1.0, 40, 20);
  const TriangleBvh bvh(sphere);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int k = 0; k < 300; ++k) {
    const V3 p(u(rng), u(rng), u(rng));
    double brute = 1e300;
    for (const auto& t : sphere.triangles)
      brute = std::min(brute, PointTriangleDistance(p, sphere.points[t[0]], sphere.points[t[1]],
                                                    sphere.points[t[2]]));
    EXPECT_NEAR(bvh.Distance(p), brute, 1e-12);
    const double exact = WindingNumberExact(sphere, p);
    EXPECT_NEAR(bvh.Winding(p), exact, 0.05);  // far clusters as dipoles: close, not exact
    // Inside the (polygonal) sphere the winding number is 1, outside 0.
    if (p.norm() < 0.95) {
      EXPECT_NEAR(exact, 1.0, 1e-9);
    }
    if (p.norm() > 1.01) {
      EXPECT_NEAR(exact, 0.0, 1e-9);
    }
  }
}

TEST(HullMetricsTest, CheckHullFindsEachProblem) {
  Soup cube = Box(0, 0, 0, 1, 1, 1);
  EXPECT_EQ(CheckHull(cube, 1e-9), "");
  EXPECT_NEAR(SignedVolume(cube), 1.0, 1e-15);
  Soup flipped = cube;
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  EXPECT_NE(CheckHull(flipped, 1e-9).find("outward"), std::string::npos);
  Soup dented = cube;
  dented.points[7] = V3(0.9, 0.9, 0.9);  // a corner pushed in: no longer convex
  EXPECT_NE(CheckHull(dented, 1e-6).find("convex"), std::string::npos);
  Soup open = cube;
  open.triangles.pop_back();
  EXPECT_EQ(CheckHull(open, 1e-9), "not closed");
  Soup nan = cube;
  nan.points[0][0] = std::nan("");
  EXPECT_EQ(CheckHull(nan, 1e-9), "non-finite coordinate");
}

TEST(HullMetricsTest, ExactHullsScoreZeroAndAnInflatedHullItsOffset) {
  const MeshMeasure m(Box(0, 0, 0, 1, 1, 1), Small());
  EXPECT_TRUE(m.closed());
  EXPECT_NEAR(m.diagonal(), std::sqrt(3.0), 1e-15);
  HullMetrics same = m.Measure({Box(0, 0, 0, 1, 1, 1)});
  EXPECT_EQ(same.invalid_hulls, 0u);
  EXPECT_LT(same.concavity, 1e-9);
  EXPECT_GT(same.iou, 0.999);
  EXPECT_GT(same.coverage, 0.999);
  // Two halves sharing a face: the shared face is inside the union, not boundary.
  const HullMetrics halves = m.Measure({Box(0, 0, 0, 0.5, 1, 1), Box(0.5, 0, 0, 1, 1, 1)});
  EXPECT_LT(halves.concavity, 1e-9);
  // A crack narrower than the gap tolerance is not boundary (only its mouth on the surface is
  // missed, by half its width); a wide one is: its faces lie up to 0.25 inside the solid.
  const HullMetrics narrow = m.Measure({Box(0, 0, 0, 0.4995, 1, 1), Box(0.5, 0, 0, 1, 1, 1)});
  EXPECT_LT(narrow.hulls_to_mesh, 1e-9);
  EXPECT_NEAR(narrow.mesh_to_hulls, 0.00025 / std::sqrt(3.0), 3e-5);
  const HullMetrics cracked = m.Measure({Box(0, 0, 0, 0.25, 1, 1), Box(0.75, 0, 0, 1, 1, 1)});
  EXPECT_NEAR(cracked.hulls_to_mesh, 0.25 / std::sqrt(3.0), 1e-3);
  EXPECT_NEAR(cracked.mesh_to_hulls, 0.25 / std::sqrt(3.0), 1e-3);  // the middle of the faces
  EXPECT_NEAR(cracked.iou, 0.5, 0.01);
  EXPECT_EQ(cracked.solid_iou, cracked.iou);  // the same ratio for a closed mesh
  // Inflated by 0.1 on every side: its corners are 0.1 * sqrt(3) away, a tenth of the diagonal.
  const HullMetrics big = m.Measure({Box(-0.1, -0.1, -0.1, 1.1, 1.1, 1.1)});
  EXPECT_NEAR(big.hulls_to_mesh, 0.1, 1e-9);
  EXPECT_EQ(big.mesh_to_hulls, 0.0);
  EXPECT_NEAR(big.iou, 1.0 / (1.2 * 1.2 * 1.2), 0.01);
  EXPECT_GT(big.coverage, 0.999);
}

TEST(HullMetricsTest, OpenMeshSolidByWindingNumber) {
  // A box without its top: the generalized winding number still calls most of it solid (no IoU,
  // which is for closed meshes only).
  Soup open = Box(0, 0, 0, 1, 1, 1);
  open.triangles.erase(open.triangles.begin() + 2, open.triangles.begin() + 4);  // the z = 1 face
  const MeshMeasure m(open, Small());
  EXPECT_FALSE(m.closed());
  const HullMetrics r = m.Measure({Box(0, 0, 0, 1, 1, 1)});
  EXPECT_LT(r.iou, 0.0);
  EXPECT_GT(r.coverage, 0.999);
  // Against the winding-number solid (the box closed over its missing face): nearly all of it.
  EXPECT_GT(r.solid_iou, 0.75);
  EXPECT_GT(m.solid_point_count(), 40000u * 3 / 4);
  // Only the lower half covered: about half of the solid.
  EXPECT_NEAR(m.Measure({Box(0, 0, 0, 1, 1, 0.5)}).coverage,
              0.5 / (static_cast<double>(m.solid_point_count()) / 40000), 0.05);
}

}  // namespace
}  // namespace bench
}  // namespace hullpack
