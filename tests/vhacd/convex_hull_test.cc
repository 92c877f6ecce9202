#include "convex_hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

namespace vhacd {
namespace internal {
namespace {

void ExpectValid(const HullMesh& h, double tol) {
  ASSERT_FALSE(h.empty());
  // Closed: each directed edge appears once and its reverse once.
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (const auto& t : h.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& e : edges) {
    EXPECT_EQ(e.second, 1);
    EXPECT_EQ(edges.count({e.first.second, e.first.first}), 1u);
  }
  EXPECT_LE(h.MaxConvexityViolation(), tol);
  EXPECT_GT(h.Volume(), 0.0);
  EXPECT_EQ(h.vertices.size() - (h.triangles.size() * 3) / 2 + h.triangles.size(), 2u);  // Euler
}

TEST(ConvexHullTest, CubeWithInteriorAndDuplicatePoints) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  for (int i = 0; i < 8; ++i) pts.push_back(pts[i]);  // duplicates
  pts.emplace_back(0.5, 0.5, 0.5);
  pts.emplace_back(0.5, 0.5, 0.0);  // on a face
  pts.emplace_back(0.5, 0.0, 0.0);  // on an edge
  HullMesh h;
  ASSERT_EQ(ComputeConvexHull(pts, -1.0, &h), HullStatus::kOk);
  ExpectValid(h, 1e-12);
  EXPECT_EQ(h.vertices.size(), 8u);
  EXPECT_NEAR(h.Volume(), 1.0, 1e-12);
  const Vec3 c = h.Centroid();
  EXPECT_NEAR((c - Vec3(0.5, 0.5, 0.5)).norm(), 0.0, 1e-12);
}

TEST(ConvexHullTest, ExactModeOnIntegerGridWithManyCoplanarPoints) {
  std::vector<Vec3> pts;
  for (int x = 0; x <= 6; ++x)
    for (int y = 0; y <= 5; ++y)
      for (int z = 0; z <= 4; ++z) pts.emplace_back(x, y, z);
  HullMesh h;
  ASSERT_EQ(ComputeConvexHull(pts, 0.0, &h), HullStatus::kOk);
  ExpectValid(h, 0.0);
  EXPECT_EQ(h.vertices.size(), 8u);
  EXPECT_DOUBLE_EQ(h.Volume(), 6.0 * 5.0 * 4.0);
}

TEST(ConvexHullTest, RandomPointsOnAndInSphere) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  std::vector<Vec3> pts;
  for (int i = 0; i < 3000; ++i) {
    Vec3 p(g(rng), g(rng), g(rng));
    p.normalize();
    pts.push_back(i % 3 == 0 ? 0.5 * p : p);
  }
  HullMesh h;
  ASSERT_EQ(ComputeConvexHull(pts, -1.0, &h), HullStatus::kOk);
  ExpectValid(h, 1e-9);
  EXPECT_EQ(h.vertices.size(), 2000u);  // every sphere point is extreme
  EXPECT_NEAR(h.Volume(), 4.0 / 3.0 * M_PI, 0.05);
}

TEST(ConvexHullTest, DegenerateInputs) {
  HullMesh h;
  EXPECT_EQ(ComputeConvexHull({}, -1.0, &h), HullStatus::kTooFewPoints);
  EXPECT_EQ(ComputeConvexHull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, -1.0, &h),
            HullStatus::kTooFewPoints);
  std::vector<Vec3> same(10, Vec3(1, 2, 3));
  EXPECT_EQ(ComputeConvexHull(same, -1.0, &h), HullStatus::kCollinear);
  std::vector<Vec3> line;
  for (int i = 0; i < 10; ++i) line.emplace_back(i, 2 * i, 3 * i);
  EXPECT_EQ(ComputeConvexHull(line, -1.0, &h), HullStatus::kCollinear);
  EXPECT_EQ(ComputeConvexHull(line, 0.0, &h), HullStatus::kCollinear);
  std::vector<Vec3> plane;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) plane.emplace_back(i, j, 0.5 * i + 0.25 * j);
  EXPECT_EQ(ComputeConvexHull(plane, -1.0, &h), HullStatus::kCoplanar);
  std::vector<Vec3> nan = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, NAN)};
  EXPECT_EQ(ComputeConvexHull(nan, -1.0, &h), HullStatus::kNonFinite);
  EXPECT_TRUE(h.empty());
}

TEST(ConvexHullTest, NearlyCoplanarAndTinyScales) {
  for (double scale : {1e-6, 1.0, 1e6}) {
    std::vector<Vec3> pts;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 500; ++i) pts.push_back(scale * Vec3(u(rng), u(rng), 1e-9 * u(rng)));
    pts.push_back(scale * Vec3(0, 0, 1));
    pts.push_back(scale * Vec3(0, 0, -1));
    HullMesh h;
    ASSERT_EQ(ComputeConvexHull(pts, -1.0, &h), HullStatus::kOk) << scale;
    ExpectValid(h, 1e-9 * scale);
  }
}

TEST(ConvexHullTest, PointTriangleDistance) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_NEAR(PointTriangleDistance(Vec3(0.2, 0.2, 3), a, b, c), 3.0, 1e-12);
  EXPECT_NEAR(PointTriangleDistance(Vec3(-1, 0, 0), a, b, c), 1.0, 1e-12);
  EXPECT_NEAR(PointTriangleDistance(Vec3(1, 1, 0), a, b, c), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(PointTriangleDistance(Vec3(0.5, -2, 0), a, b, c), 2.0, 1e-12);
}

TEST(ConvexHullTest, HalfSpacesClassifyPoints) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(2 * (i & 1), 2 * ((i >> 1) & 1), 2 * ((i >> 2) & 1));
  HullMesh h;
  ASSERT_EQ(ComputeConvexHull(pts, -1.0, &h), HullStatus::kOk);
  HullPlanes hp(h);
  EXPECT_LT(hp.SignedDistanceBound(Vec3(1, 1, 1)), 0.0);
  EXPECT_NEAR(hp.SignedDistanceBound(Vec3(1, 1, 3)), 1.0, 1e-12);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
