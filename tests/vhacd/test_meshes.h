// Meshes generated in code for the vhacd tests (no data files needed).
#ifndef HULLPACK_TESTS_VHACD_TEST_MESHES_H_
#define HULLPACK_TESTS_VHACD_TEST_MESHES_H_

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/test_shapes.h"
#include "vhacd/vhacd.h"

namespace vhacd_test {

struct Mesh {
  std::vector<double> points;     // xyz
  std::vector<uint32_t> indices;  // 3 per triangle

  size_t point_count() const { return points.size() / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
  vhacd::MeshView View() const {
    return vhacd::MeshView::FromDouble(points.data(), point_count(), indices.data(),
                                       triangle_count());
  }
  uint32_t AddPoint(double x, double y, double z) {
    points.insert(points.end(), {x, y, z});
    return static_cast<uint32_t>(point_count() - 1);
  }
  void AddTriangle(uint32_t a, uint32_t b, uint32_t c) { indices.insert(indices.end(), {a, b, c}); }
  void AddQuad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    AddTriangle(a, b, c);
    AddTriangle(a, c, d);
  }
  void Append(const Mesh& other) {
    const uint32_t base = static_cast<uint32_t>(point_count());
    points.insert(points.end(), other.points.begin(), other.points.end());
    for (uint32_t i : other.indices) indices.push_back(base + i);
  }
  Mesh Scaled(double s) const {
    Mesh m = *this;
    for (double& v : m.points) v *= s;
    return m;
  }
};

// Shapes shared with the other suites (tests/common/test_shapes.h) as vhacd test meshes.
inline Mesh FromShape(const test_shapes::Shape& shape) {
  Mesh m;
  test_shapes::AppendPointsTo(shape, &m);
  return m;
}

// Axis-aligned box [lo, hi], outward-facing.
inline Mesh Box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return FromShape(test_shapes::Box(x0, y0, z0, x1, y1, z1));
}

// Closed L-shaped block: [0,2]x[0,1]x[0,1] union [0,1]x[1,2]x[0,1], as a prism of the L outline.
inline Mesh LBlock() {
  const double outline[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  Mesh m;
  for (int z = 0; z < 2; ++z)
    for (const auto& p : outline) m.AddPoint(p[0], p[1], z);
  // Bottom (z=0, facing -z) and top (z=1) as fans from the reflex vertex 3.
  const int fan[4][2] = {{4, 5}, {5, 0}, {0, 1}, {1, 2}};
  for (const auto& f : fan) {
    m.AddTriangle(3, f[1], f[0]);
    m.AddTriangle(6 + 3, 6 + f[0], 6 + f[1]);
  }
  for (uint32_t i = 0; i < 6; ++i) {
    const uint32_t j = (i + 1) % 6;
    m.AddQuad(i, j, 6 + j, 6 + i);
  }
  return m;
}

inline bool InsideLBlock(double x, double y, double z) {
  if (z < 0 || z > 1 || x < 0 || y < 0) return false;
  return (x <= 2 && y <= 1) || (x <= 1 && y <= 2);
}

// Torus around the z axis: major radius R, minor radius r.
inline Mesh Torus(double R, double r, int nu = 48, int nv = 24) {
  return FromShape(test_shapes::Torus(R, r, nu, nv));
}

// UV sphere; when `holes` is set, removes a few small patches of triangles (an open scan).
inline Mesh Sphere(double radius, int nu = 48, int nv = 24, bool holes = false) {
  if (!holes) return FromShape(test_shapes::Sphere(radius, nu, nv));
  // Five small holes plus a larger opening at the bottom rows.
  return FromShape(test_shapes::Sphere(radius, nu, nv, [](int j, int i) {
    if (j <= 2) return true;
    const int centers[5][2] = {{8, 3}, {12, 17}, {16, 30}, {10, 40}, {18, 9}};
    for (const auto& c : centers)
      if (j == c[0] && (i == c[1] || i == c[1] + 1)) return true;
    return false;
  }));
}

// Closed thick bowl: a solid of revolution about z whose profile is a U of wall thickness t.
// Outer radius R, height H, bottom thickness t; the cavity is r < R - t, z > t.
inline Mesh ThickBowl(double R, double H, double t, int n = 48) {
  // Profile (r, z) going around the wall cross-section, counter-clockwise in the (r, z) plane.
  const double prof[][2] = {{0, 0}, {R, 0}, {R, H}, {R - t, H}, {R - t, t}, {0, t}};
  const int np = 6;
  Mesh m;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    for (int k = 0; k < np; ++k)
      m.AddPoint(prof[k][0] * std::cos(a), prof[k][0] * std::sin(a), prof[k][1]);
  }
  for (int i = 0; i < n; ++i) {
    const int i2 = (i + 1) % n;
    for (int k = 0; k + 1 < np; ++k) {
      const uint32_t a = i * np + k, b = i * np + k + 1, c = i2 * np + k + 1, d = i2 * np + k;
      m.AddQuad(a, d, c, b);
    }
  }
  return m;  // the axis points (r = 0) are repeated per slice; welding makes the mesh closed
}

// A cylinder about z (radius R, height H) with its top disc and, at its base, an annulus around a
// hole of radius `hole` (hole >= R: no bottom at all, an upside-down pot): open at its base like a
// scan standing on a table.
inline Mesh OpenBottomCylinder(double R, double H, int n = 48, int rows = 8, double hole = 1e30) {
  Mesh m;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      m.AddPoint(R * std::cos(a), R * std::sin(a), H * j / rows);
    }
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = j * n + i, b = j * n + (i + 1) % n;
      m.AddQuad(a, b, b + n, a + n);
    }
  const uint32_t top = m.AddPoint(0, 0, H);
  for (int i = 0; i < n; ++i) m.AddTriangle(rows * n + i, rows * n + (i + 1) % n, top);
  if (hole < R) {
    const uint32_t inner = static_cast<uint32_t>(m.point_count());
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      m.AddPoint(hole * std::cos(a), hole * std::sin(a), 0);
    }
    for (int i = 0; i < n; ++i) {
      const uint32_t a = i, b = (i + 1) % n;
      m.AddQuad(inner + a, inner + b, b, a);
    }
  }
  return m;
}

inline bool InsideHull(const vhacd::ConvexHull& h, double x, double y, double z, double tol) {
  for (size_t t = 0; t < h.triangle_count(); ++t) {
    const double* a = &h.points[3 * h.triangles[3 * t]];
    const double* b = &h.points[3 * h.triangles[3 * t + 1]];
    const double* c = &h.points[3 * h.triangles[3 * t + 2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                 v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0)) continue;
    if ((n[0] * (x - a[0]) + n[1] * (y - a[1]) + n[2] * (z - a[2])) / len > tol) return false;
  }
  return true;
}

inline bool InsideAnyHull(const std::vector<vhacd::ConvexHull>& hulls, double x, double y, double z,
                          double tol) {
  for (const auto& h : hulls)
    if (InsideHull(h, x, y, z, tol)) return true;
  return false;
}

// Checks that every hull is closed (each directed edge has its reverse), finite, outward-facing
// and convex within tol. Returns an empty string when valid, else what is wrong.
std::string CheckHulls(const std::vector<vhacd::ConvexHull>& hulls, double tol);

}  // namespace vhacd_test

#endif  // HULLPACK_TESTS_VHACD_TEST_MESHES_H_
