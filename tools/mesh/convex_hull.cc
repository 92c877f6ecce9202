#include "mesh/convex_hull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>

namespace hullpack {
namespace {

struct V3 {
  double x = 0, y = 0, z = 0;
};
V3 Sub(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 Cross(const V3& a, const V3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double Dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double Length(const V3& a) { return std::sqrt(Dot(a, a)); }
V3 Scale(const V3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }

struct Face {
  int v[3];
  V3 normal;  // unit (zero for a degenerate sliver, which then never sees a point)
  double offset = 0;
  bool alive = true;
};

Face MakeFace(const std::vector<V3>& p, int a, int b, int c) {
  Face f{{a, b, c}, {}, 0, true};
  const V3 n = Cross(Sub(p[b], p[a]), Sub(p[c], p[a]));
  const double len = Length(n);
  if (len > 0) f.normal = Scale(n, 1.0 / len);
  f.offset = Dot(f.normal, p[a]);
  return f;
}

double Distance(const Face& f, const V3& q) { return Dot(f.normal, q) - f.offset; }

// Keeps the points the triangles use, in order of first use, and renumbers the triangles.
Mesh Compact(const std::vector<V3>& p, const std::vector<int>& triangles) {
  Mesh out;
  std::vector<int> remap(p.size(), -1);
  for (int i : triangles) {
    if (remap[i] < 0) {
      remap[i] = static_cast<int>(out.positions.size() / 3);
      out.positions.insert(
          out.positions.end(),
          {static_cast<float>(p[i].x), static_cast<float>(p[i].y), static_cast<float>(p[i].z)});
    }
    out.indices.push_back(static_cast<uint32_t>(remap[i]));
  }
  return out;
}

// All points lie on the plane through p[i0] with unit normal n: their convex polygon, fanned on
// both sides.
Mesh FlatHull(const std::vector<V3>& p, int i0, int i1, const V3& n, double eps) {
  const V3 u = Scale(Sub(p[i1], p[i0]), 1.0 / Length(Sub(p[i1], p[i0])));
  const V3 w = Cross(n, u);
  std::vector<std::pair<std::pair<double, double>, int>> q;
  for (size_t i = 0; i < p.size(); ++i) {
    const V3 d = Sub(p[i], p[i0]);
    q.push_back({{Dot(d, u), Dot(d, w)}, static_cast<int>(i)});
  }
  std::sort(q.begin(), q.end());
  auto turn = [&](int o, int a, int b) {  // > eps: counter-clockwise around n
    const auto& O = q[o].first;
    const auto& A = q[a].first;
    const auto& B = q[b].first;
    return (A.first - O.first) * (B.second - O.second) -
           (A.second - O.second) * (B.first - O.first);
  };
  // Andrew's monotone chain; a turn within eps * extent counts as straight.
  std::vector<int> hull(2 * q.size());
  size_t k = 0;
  for (size_t i = 0; i < q.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], static_cast<int>(i)) <= eps) --k;
    hull[k++] = static_cast<int>(i);
  }
  for (size_t i = q.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], static_cast<int>(i)) <= eps) --k;
    hull[k++] = static_cast<int>(i);
  }
  hull.resize(k > 0 ? k - 1 : 0);
  std::vector<int> triangles;
  for (size_t t = 1; t + 1 < hull.size(); ++t) {
    const int a = q[hull[0]].second, b = q[hull[t]].second, c = q[hull[t + 1]].second;
    triangles.insert(triangles.end(), {a, b, c, a, c, b});
  }
  return Compact(p, triangles);
}

}  // namespace

Mesh ConvexHullOfPoints(const std::vector<float>& points) {
  const size_t n = points.size() / 3;
  std::vector<V3> p(n);
  V3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (size_t i = 0; i < n; ++i) {
    p[i] = {points[i * 3], points[i * 3 + 1], points[i * 3 + 2]};
    lo = {std::min(lo.x, p[i].x), std::min(lo.y, p[i].y), std::min(lo.z, p[i].z)};
    hi = {std::max(hi.x, p[i].x), std::max(hi.y, p[i].y), std::max(hi.z, p[i].z)};
  }
  Mesh points_only;
  points_only.positions.assign(points.begin(), points.begin() + n * 3);
  if (n < 3) return points_only;
  const double extent = Length(Sub(hi, lo));
  const double eps = 1e-9 * extent;
  if (!(extent > 0) || !std::isfinite(extent)) return points_only;

  // A first tetrahedron from extreme points.
  int i0 = 0;
  for (size_t i = 1; i < n; ++i) {
    if (p[i].x < p[i0].x) i0 = static_cast<int>(i);
  }
  int i1 = -1, i2 = -1, i3 = -1;
  double best = eps;
  for (size_t i = 0; i < n; ++i) {
    const double d = Length(Sub(p[i], p[i0]));
    if (d > best) best = d, i1 = static_cast<int>(i);
  }
  if (i1 < 0) return points_only;
  const V3 axis = Sub(p[i1], p[i0]);
  best = eps * Length(axis);
  for (size_t i = 0; i < n; ++i) {
    const double d = Length(Cross(axis, Sub(p[i], p[i0])));
    if (d > best) best = d, i2 = static_cast<int>(i);
  }
  if (i2 < 0) return points_only;  // collinear
  const Face base = MakeFace(p, i0, i1, i2);
  best = eps;
  for (size_t i = 0; i < n; ++i) {
    const double d = std::fabs(Distance(base, p[i]));
    if (d > best) best = d, i3 = static_cast<int>(i);
  }
  if (i3 < 0) return FlatHull(p, i0, i1, base.normal, eps * extent);

  std::vector<Face> faces;
  const V3 inside =
      Scale({p[i0].x + p[i1].x + p[i2].x + p[i3].x, p[i0].y + p[i1].y + p[i2].y + p[i3].y,
             p[i0].z + p[i1].z + p[i2].z + p[i3].z},
            0.25);
  for (const auto& t : {std::array<int, 3>{i0, i1, i2}, std::array<int, 3>{i0, i1, i3},
                        std::array<int, 3>{i1, i2, i3}, std::array<int, 3>{i2, i0, i3}}) {
    Face f = MakeFace(p, t[0], t[1], t[2]);
    if (Distance(f, inside) > 0) f = MakeFace(p, t[0], t[2], t[1]);
    faces.push_back(f);
  }

  std::set<std::pair<int, int>> edges;
  std::vector<size_t> visible;
  size_t dead = 0;
  for (size_t i = 0; i < n; ++i) {
    const int pi = static_cast<int>(i);
    if (pi == i0 || pi == i1 || pi == i2 || pi == i3) continue;
    visible.clear();
    for (size_t f = 0; f < faces.size(); ++f) {
      if (faces[f].alive && Distance(faces[f], p[i]) > eps) visible.push_back(f);
    }
    if (visible.empty()) continue;  // inside (or on) the hull so far
    edges.clear();
    for (size_t f : visible) {
      for (int k = 0; k < 3; ++k) edges.insert({faces[f].v[k], faces[f].v[(k + 1) % 3]});
    }
    for (size_t f : visible) {
      faces[f].alive = false;
      for (int k = 0; k < 3; ++k) {
        const int a = faces[f].v[k], b = faces[f].v[(k + 1) % 3];
        if (!edges.count({b, a})) faces.push_back(MakeFace(p, a, b, pi));  // a horizon edge
      }
    }
    dead += visible.size();
    if (dead * 2 > faces.size()) {  // drop the dead faces once they are half the list
      faces.erase(
          std::remove_if(faces.begin(), faces.end(), [](const Face& f) { return !f.alive; }),
          faces.end());
      dead = 0;
    }
  }
  std::vector<int> triangles;
  for (const Face& f : faces) {
    if (f.alive) triangles.insert(triangles.end(), {f.v[0], f.v[1], f.v[2]});
  }
  return Compact(p, triangles);
}

}  // namespace hullpack
