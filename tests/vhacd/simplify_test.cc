// Tests of vhacd::Simplify (include/vhacd/simplify.h), on meshes generated in code.
#include "vhacd/simplify.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>

#include "common/test_shapes.h"
#include "test_meshes.h"

namespace {

using vhacd_test::Mesh;
using V = Eigen::Vector3d;

V Point(const vhacd::SimplifyResult& r, uint32_t i) {
  return V(r.points[3 * i], r.points[3 * i + 1], r.points[3 * i + 2]);
}

double Volume(const vhacd::SimplifyResult& r) {
  double v = 0;
  for (size_t t = 0; t < r.triangle_count(); ++t)
    v += Point(r, r.indices[3 * t])
             .dot(Point(r, r.indices[3 * t + 1]).cross(Point(r, r.indices[3 * t + 2])));
  return v / 6.0;
}

double Volume(const Mesh& m) {
  double v = 0;
  auto p = [&](uint32_t i) { return V(m.points[3 * i], m.points[3 * i + 1], m.points[3 * i + 2]); };
  for (size_t t = 0; t < m.triangle_count(); ++t)
    v += p(m.indices[3 * t]).dot(p(m.indices[3 * t + 1]).cross(p(m.indices[3 * t + 2])));
  return v / 6.0;
}

// The shared flat n x n grid (z = 0, facing +z); with `seam`, the vertices of the column x = n / 2
// are duplicated for the triangles on its right (split attributes).
Mesh Grid(int n, bool seam = false) {
  Mesh m = vhacd_test::FromShape(test_shapes::Grid(n, n));
  if (!seam) return m;
  std::map<uint32_t, uint32_t> copy;
  const size_t original = m.point_count();
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    double cx = 0;
    for (int k = 0; k < 3; ++k) cx += m.points[3 * m.indices[3 * t + k]] / 3.0;
    if (cx < n / 2) continue;
    for (int k = 0; k < 3; ++k) {
      uint32_t& v = m.indices[3 * t + k];
      if (v >= original || m.points[3 * v] != n / 2) continue;
      auto it = copy.find(v);
      if (it == copy.end())
        it = copy.emplace(v, m.AddPoint(m.points[3 * v], m.points[3 * v + 1], 0.0)).first;
      v = it->second;
    }
  }
  return m;
}

TEST(SimplifyTest, FlatGridGoesDownToTwoTriangles) {
  const Mesh grid = Grid(16);
  vhacd::SimplifyParameters p;
  p.target_error = 1e-9;
  const vhacd::SimplifyResult r = vhacd::Simplify(grid.View(), p);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.triangle_count(), 2u);
  // The square is kept: its four corners, both triangles facing +z.
  for (size_t t = 0; t < r.triangle_count(); ++t) {
    const V n = (Point(r, r.indices[3 * t + 1]) - Point(r, r.indices[3 * t]))
                    .cross(Point(r, r.indices[3 * t + 2]) - Point(r, r.indices[3 * t]));
    EXPECT_GT(n.z(), 0.0);
  }
  double area = 0;
  for (size_t t = 0; t < r.triangle_count(); ++t)
    area += 0.5 * (Point(r, r.indices[3 * t + 1]) - Point(r, r.indices[3 * t]))
                      .cross(Point(r, r.indices[3 * t + 2]) - Point(r, r.indices[3 * t]))
                      .norm();
  EXPECT_NEAR(area, 256.0, 1e-9);
}

TEST(SimplifyTest, SphereKeepsItsVolumeAtTenPercent) {
  const Mesh sphere = vhacd_test::Sphere(1.0, 96, 48);
  vhacd::SimplifyParameters p;
  p.target_triangles = static_cast<uint32_t>(sphere.triangle_count() / 10);
  const vhacd::SimplifyResult r = vhacd::Simplify(sphere.View(), p);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_LE(r.triangle_count(), p.target_triangles);
  EXPECT_GE(r.triangle_count(), p.target_triangles - 2);
  EXPECT_NEAR(Volume(r) / Volume(sphere), 1.0, 0.01);
  // No triangle flipped: every normal still points away from the centre.
  for (size_t t = 0; t < r.triangle_count(); ++t) {
    const V a = Point(r, r.indices[3 * t]), b = Point(r, r.indices[3 * t + 1]),
            c = Point(r, r.indices[3 * t + 2]);
    EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0.0) << "triangle " << t;
  }
}

TEST(SimplifyTest, LargeSphereDecimatedInSlabsFirst) {
  // 65k triangles: the first phase decimates slabs of the mesh apart, the second the whole.
  const Mesh sphere = vhacd_test::Sphere(1.0, 256, 128);
  ASSERT_GT(sphere.triangle_count(), 60000u);
  for (uint32_t target : {6500u, 650u}) {
    vhacd::SimplifyParameters p;
    p.target_triangles = target;
    const vhacd::SimplifyResult r = vhacd::Simplify(sphere.View(), p);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_LE(r.triangle_count(), target);
    EXPECT_GE(r.triangle_count(), target - 2);
    EXPECT_NEAR(Volume(r) / Volume(sphere), 1.0, target > 1000 ? 0.002 : 0.01);
    for (size_t t = 0; t < r.triangle_count(); ++t) {
      const V a = Point(r, r.indices[3 * t]), b = Point(r, r.indices[3 * t + 1]),
              c = Point(r, r.indices[3 * t + 2]);
      EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0.0) << "triangle " << t;
    }
  }
}

TEST(SimplifyTest, TorusNeverFlipsATriangle) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 96, 48);
  for (uint32_t target : {2000u, 400u}) {
    vhacd::SimplifyParameters p;
    p.target_triangles = target;
    const vhacd::SimplifyResult r = vhacd::Simplify(torus.View(), p);
    ASSERT_TRUE(r.ok()) << r.message;
    for (size_t t = 0; t < r.triangle_count(); ++t) {
      const V a = Point(r, r.indices[3 * t]), b = Point(r, r.indices[3 * t + 1]),
              c = Point(r, r.indices[3 * t + 2]);
      const V centre = (a + b + c) / 3.0;
      const V ring = V(centre.x(), centre.y(), 0.0).normalized();  // the tube's axis point
      EXPECT_GT((b - a).cross(c - a).dot(centre - ring), 0.0) << "target " << target;
    }
    EXPECT_GT(Volume(r), 0.0);
  }
}

TEST(SimplifyTest, OpenBorderIsKept) {
  const Mesh cyl = vhacd_test::OpenBottomCylinder(1.0, 2.0, 48, 16);
  vhacd::SimplifyParameters p;
  p.target_triangles = static_cast<uint32_t>(cyl.triangle_count() / 4);
  const vhacd::SimplifyResult r = vhacd::Simplify(cyl.View(), p);
  ASSERT_TRUE(r.ok()) << r.message;
  // Border edges (used once) all lie on the base circle, and the circle is not shrunk.
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (size_t t = 0; t < r.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      uint32_t a = r.indices[3 * t + k], b = r.indices[3 * t + (k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  int border = 0;
  for (const auto& [e, n] : uses) {
    if (n != 1) continue;
    ++border;
    for (uint32_t v : {e.first, e.second}) {
      EXPECT_EQ(Point(r, v).z(), 0.0);
      EXPECT_NEAR(V(Point(r, v).x(), Point(r, v).y(), 0).norm(), 1.0, 1e-12);
    }
  }
  EXPECT_GE(border, 8);
}

TEST(SimplifyTest, AttributeSeamIsKept) {
  const Mesh grid = Grid(16, /*seam=*/true);
  ASSERT_EQ(grid.point_count(), 17u * 17u + 17u);  // the seam column is split
  vhacd::SimplifyParameters p;
  p.target_triangles = 40;
  const vhacd::SimplifyResult r = vhacd::Simplify(grid.View(), p);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_LE(r.triangle_count(), 40u);
  // Output points on the seam stay on it; the seam still separates the triangles: no triangle
  // has a corner on each side.
  for (size_t i = 0; i < r.points.size() / 3; ++i) {
    const uint32_t src = r.point_source[i];
    ASSERT_LT(src, grid.point_count());
    EXPECT_EQ(Point(r, static_cast<uint32_t>(i)).x(), grid.points[3 * src]);
  }
  for (size_t t = 0; t < r.triangle_count(); ++t) {
    bool left = false, right = false;
    for (int k = 0; k < 3; ++k) {
      const double x = Point(r, r.indices[3 * t + k]).x();
      left = left || x < 8.0;
      right = right || x > 8.0;
    }
    EXPECT_FALSE(left && right) << "triangle " << t << " crosses the seam";
  }
}

TEST(SimplifyTest, DeterministicAndErrorsAsValues) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 48, 24);
  vhacd::SimplifyParameters p;
  p.target_triangles = 300;
  const vhacd::SimplifyResult a = vhacd::Simplify(torus.View(), p);
  const vhacd::SimplifyResult b = vhacd::Simplify(torus.View(), p);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.indices, b.indices);
  ASSERT_EQ(a.triangle_source.size(), a.triangle_count());
  for (uint32_t t : a.triangle_source) EXPECT_LT(t, torus.triangle_count());
  EXPECT_GT(a.error, 0.0);
  EXPECT_LT(a.error, 0.05);

  vhacd::SimplifyParameters none;
  const vhacd::SimplifyResult r = vhacd::Simplify(torus.View(), none);
  EXPECT_EQ(r.status, vhacd::Status::kInvalidParameter);
  EXPECT_NE(r.message.find("target"), std::string::npos);
  none.target_error = -1;
  EXPECT_EQ(vhacd::Simplify(torus.View(), none).status, vhacd::Status::kInvalidParameter);
  vhacd::MeshView empty;
  EXPECT_EQ(vhacd::Simplify(empty, p).status, vhacd::Status::kEmptyMesh);
  Mesh bad = torus;
  bad.indices[0] = 1u << 30;
  EXPECT_EQ(vhacd::Simplify(bad.View(), p).status, vhacd::Status::kIndexOutOfRange);
}

}  // namespace
