#include "mesh/convex_hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>

namespace hullpack {
namespace {

// Each directed edge of a closed mesh appears once, and its reverse once.
bool Closed(const Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) ++edges[{m.indices[t * 3 + k], m.indices[t * 3 + (k + 1) % 3]}];
  for (const auto& [e, count] : edges) {
    auto reverse = edges.find({e.second, e.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) return false;
  }
  return true;
}

// Signed volume (positive when the triangles face outwards).
double Volume(const Mesh& m) {
  double v = 0;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const float* a = &m.positions[m.indices[t * 3] * 3];
    const float* b = &m.positions[m.indices[t * 3 + 1] * 3];
    const float* c = &m.positions[m.indices[t * 3 + 2] * 3];
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
          a[2] * (b[0] * c[1] - b[1] * c[0])) /
         6.0;
  }
  return v;
}

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
  EXPECT_TRUE(Closed(hull));
  EXPECT_NEAR(Volume(hull), 1.0, 1e-6);
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
  EXPECT_TRUE(Closed(hull));
  EXPECT_GT(Volume(hull), 0.9 * 4.0 / 3.0 * M_PI);
  EXPECT_LT(Volume(hull), 4.0 / 3.0 * M_PI);
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
  EXPECT_NEAR(Volume(hull), 0.0, 1e-9);
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
