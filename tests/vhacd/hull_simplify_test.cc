#include "hull_simplify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vhacd {
namespace internal {
namespace {

HullMesh SphereHull(int n) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) pts.push_back(Vec3(g(rng), g(rng), g(rng)).normalized());
  HullMesh h;
  EXPECT_EQ(ComputeConvexHull(pts, -1.0, &h), HullStatus::kOk);
  return h;
}

TEST(HullSimplifyTest, KeepsAtMostMaxVerticesAndMostOfTheVolume) {
  const HullMesh h = SphereHull(1000);
  const HullMesh s = SimplifyHull(h, 64, 0.0);
  EXPECT_LE(s.vertices.size(), 64u);
  EXPECT_GE(s.vertices.size(), 60u);
  EXPECT_GT(s.Volume(), 0.85 * h.Volume());
  EXPECT_LE(s.Volume(), h.Volume() + 1e-12);
  EXPECT_LE(s.MaxConvexityViolation(), 1e-9);
  // Every kept vertex is an input vertex.
  for (const Vec3& p : s.vertices) {
    bool found = false;
    for (const Vec3& q : h.vertices) found = found || p == q;
    EXPECT_TRUE(found);
  }
}

TEST(HullSimplifyTest, MinVolumeStopsEarlyAndSmallHullsAreUnchanged) {
  const HullMesh h = SphereHull(1000);
  const HullMesh coarse = SimplifyHull(h, 1024, 0.01 * h.Volume());
  EXPECT_LT(coarse.vertices.size(), 64u);
  EXPECT_GE(coarse.vertices.size(), 4u);
  const HullMesh few = SphereHull(20);
  const HullMesh same = SimplifyHull(few, 64, 0.0);
  EXPECT_EQ(same.vertices.size(), few.vertices.size());
  const HullMesh four = SimplifyHull(h, 4, 0.0);
  EXPECT_EQ(four.vertices.size(), 4u);
  EXPECT_GT(four.Volume(), 0.0);
}

TEST(HullSimplifyTest, MinDistanceKeepsFarVerticesOfThinHulls) {
  // A thin slab with one corner pulled out: the corner adds little volume but lies far out.
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1 ? 10 : 0, i & 2 ? 10 : 0, i & 4 ? 0.2 : 0);
  // Mid-edge, so the initial tetrahedron (farthest points) does not pick it.
  pts.emplace_back(5.0, 10.8, 0.1);  // adds about 2.7 % of the volume, 0.8 from the slab
  HullMesh h;
  ASSERT_EQ(ComputeConvexHull(pts, -1.0, &h), HullStatus::kOk);
  const HullMesh by_volume = SimplifyHull(h, 64, 0.05 * h.Volume());
  const HullMesh by_distance = SimplifyHull(h, 64, 0.05 * h.Volume(), 0.5);
  auto has = [](const HullMesh& m, const Vec3& p) {
    for (const Vec3& q : m.vertices)
      if (q == p) return true;
    return false;
  };
  EXPECT_FALSE(has(by_volume, Vec3(5.0, 10.8, 0.1)));
  EXPECT_TRUE(has(by_distance, Vec3(5.0, 10.8, 0.1)));
  EXPECT_LE(by_distance.MaxConvexityViolation(), 1e-9);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
