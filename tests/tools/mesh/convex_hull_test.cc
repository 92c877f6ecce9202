#include "mesh/convex_hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_meshes.h"

namespace hullpack {
namespace {

using testing_meshes::IsClosed;
using testing_meshes::SignedVolume;

TEST(ConvexHullOfPoints, CubeCornersWithInnerPointsGiveTheCube) {
  std::vector<float> points;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.01f, 0.99f);
  for (int i = 0; i < 200; ++i) points.insert(points.end(), {unit(rng), unit(rng), unit(rng)});
  for (int c = 0; c < 8; ++c) {
    points.insert(points.end(), {float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1)});
  }
  // A point on a face and one on an edge do not become vertices.
  points.insert(points.end(), {0.5f, 0.5f, 1.0f, 1.0f, 0.5f, 0.0f});
  const Mesh hull = ConvexHullOfPoints(points);
  EXPECT_EQ(hull.vertex_count(), 8u);
  EXPECT_EQ(hull.triangle_count(), 12u);
  EXPECT_TRUE(IsClosed(hull));
  EXPECT_NEAR(SignedVolume(hull), 1.0, 1e-6);
}

TEST(ConvexHullOfPoints, EveryPointOfASphereIsAVertex) {
  std::vector<float> points;
  const int n = 300;
  for (int i = 0; i < n; ++i) {  // Fibonacci sphere
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
    points.insert(points.end(), {float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)});
  }
  const Mesh hull = ConvexHullOfPoints(points);
  EXPECT_EQ(hull.vertex_count(), size_t(n));
  EXPECT_EQ(hull.triangle_count(), size_t(2 * n - 4));  // Euler, every vertex on the hull
  EXPECT_TRUE(IsClosed(hull));
  EXPECT_GT(SignedVolume(hull), 0.9 * 4.0 / 3.0 * M_PI);
  EXPECT_LT(SignedVolume(hull), 4.0 / 3.0 * M_PI);
}

TEST(ConvexHullOfPoints, FlatSetsGiveTheirPolygonOnBothSides) {
  // A square with its centre, in the plane z = 2.
  const std::vector<float> square = {0, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 2, 0.5f, 0.5f, 2};
  const Mesh hull = ConvexHullOfPoints(square);
  EXPECT_EQ(hull.vertex_count(), 4u);
  ASSERT_EQ(hull.triangle_count(), 4u);  // two triangles, each side
  // (a, b, c) then its back (a, c, b)
  EXPECT_EQ(hull.indices[3], hull.indices[0]);
  EXPECT_EQ(hull.indices[4], hull.indices[2]);
  EXPECT_EQ(hull.indices[5], hull.indices[1]);
  EXPECT_NEAR(SignedVolume(hull), 0.0, 1e-9);
}

TEST(ConvexHullOfPoints, FewerThanThreeNonCollinearPointsGiveNoTriangles) {
  EXPECT_EQ(ConvexHullOfPoints({}).triangle_count(), 0u);
  EXPECT_EQ(ConvexHullOfPoints({1, 2, 3, 1, 2, 3, 1, 2, 3}).triangle_count(), 0u);
  const Mesh line = ConvexHullOfPoints({0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3});
  EXPECT_EQ(line.triangle_count(), 0u);
  EXPECT_EQ(line.vertex_count(), 4u);
}

}  // namespace
}  // namespace hullpack
