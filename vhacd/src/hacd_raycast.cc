#include "hacd_raycast.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vhacd {
namespace internal {

RayCaster::RayCaster(const std::vector<Vec3>& points,
                     const std::vector<std::array<uint32_t, 3>>& triangles)
    : points_(points), triangles_(triangles) {
  order_.resize(triangles.size());
  std::iota(order_.begin(), order_.end(), 0u);
  std::vector<Vec3> centroids(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t)
    centroids[t] =
        (points[triangles[t][0]] + points[triangles[t][1]] + points[triangles[t][2]]) / 3.0;
  if (!triangles.empty()) Build(0, static_cast<uint32_t>(triangles.size()), centroids);
}

uint32_t RayCaster::Build(uint32_t first, uint32_t count, const std::vector<Vec3>& centroids) {
  const uint32_t id = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = -lo, clo = lo, chi = hi;
  for (uint32_t i = first; i < first + count; ++i) {
    for (uint32_t v : triangles_[order_[i]]) {
      lo = lo.cwiseMin(points_[v]);
      hi = hi.cwiseMax(points_[v]);
    }
    clo = clo.cwiseMin(centroids[order_[i]]);
    chi = chi.cwiseMax(centroids[order_[i]]);
  }
  nodes_[id].lo = lo;
  nodes_[id].hi = hi;
  if (count <= 4) {
    nodes_[id].first = first;
    nodes_[id].count = count;
    return id;
  }
  int axis = 0;
  const Vec3 ext = chi - clo;
  if (ext[1] > ext[axis]) axis = 1;
  if (ext[2] > ext[axis]) axis = 2;
  const uint32_t mid = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                   [&](uint32_t a, uint32_t b) {
                     return centroids[a][axis] != centroids[b][axis]
                                ? centroids[a][axis] < centroids[b][axis]
                                : a < b;
                   });
  const uint32_t left = Build(first, mid - first, centroids);
  const uint32_t right = Build(mid, first + count - mid, centroids);
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

bool RayCaster::HitTriangle(uint32_t tri, const Vec3& origin, const Vec3& dir, double* t) const {
  const Vec3& a = points_[triangles_[tri][0]];
  const Vec3 e1 = points_[triangles_[tri][1]] - a, e2 = points_[triangles_[tri][2]] - a;
  const Vec3 pv = dir.cross(e2);
  const double det = e1.dot(pv);
  if (!(std::fabs(det) > 1e-300)) return false;
  const Vec3 tv = origin - a;
  const double u = tv.dot(pv) / det;
  if (u < 0 || u > 1) return false;
  const Vec3 qv = tv.cross(e1);
  const double v = dir.dot(qv) / det;
  if (v < 0 || u + v > 1) return false;
  *t = e2.dot(qv) / det;
  return true;
}

bool RayCaster::Cast(const Vec3& origin, const Vec3& dir, double min_t, uint32_t skip,
                     uint32_t* triangle, double* t_out) const {
  if (nodes_.empty()) return false;
  double best = HUGE_VAL;
  uint32_t best_tri = UINT32_MAX;
  const Vec3 inv(1.0 / dir[0], 1.0 / dir[1], 1.0 / dir[2]);
  auto box_hit = [&](const Node& n) {
    double t0 = min_t, t1 = best;
    for (int k = 0; k < 3; ++k) {
      double a = (n.lo[k] - origin[k]) * inv[k], b = (n.hi[k] - origin[k]) * inv[k];
      if (std::isnan(a) || std::isnan(b)) {  // ray parallel to the slab, origin on its plane
        if (origin[k] < n.lo[k] || origin[k] > n.hi[k]) return false;
        continue;
      }
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
      if (t0 > t1) return false;
    }
    return true;
  };
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& n = nodes_[stack.back()];
    stack.pop_back();
    if (!box_hit(n)) continue;
    if (n.count == 0) {
      stack.push_back(n.left);
      stack.push_back(n.right);
      continue;
    }
    for (uint32_t i = n.first; i < n.first + n.count; ++i) {
      const uint32_t tri = order_[i];
      if (tri == skip) continue;
      double t = 0.0;
      if (!HitTriangle(tri, origin, dir, &t)) continue;
      if (t > min_t && (t < best || (t == best && tri < best_tri))) {
        best = t;
        best_tri = tri;
      }
    }
  }
  if (best_tri == UINT32_MAX) return false;
  *triangle = best_tri;
  *t_out = best;
  return true;
}

int RayCaster::CountHits(const Vec3& origin, const Vec3& dir) const {
  if (nodes_.empty()) return 0;
  int hits = 0;
  const Vec3 inv(1.0 / dir[0], 1.0 / dir[1], 1.0 / dir[2]);
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& n = nodes_[stack.back()];
    stack.pop_back();
    double t0 = 0.0, t1 = HUGE_VAL;
    bool miss = false;
    for (int k = 0; k < 3 && !miss; ++k) {
      double a = (n.lo[k] - origin[k]) * inv[k], b = (n.hi[k] - origin[k]) * inv[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
      miss = !(t0 <= t1);
    }
    if (miss) continue;
    if (n.count == 0) {
      stack.push_back(n.left);
      stack.push_back(n.right);
      continue;
    }
    for (uint32_t i = n.first; i < n.first + n.count; ++i) {
      const uint32_t tri = order_[i];
      double t = 0.0;
      if (!HitTriangle(tri, origin, dir, &t) || !(t > 0)) continue;
      const auto& v = triangles_[tri];
      const Vec3 normal = (points_[v[1]] - points_[v[0]]).cross(points_[v[2]] - points_[v[0]]);
      hits += normal.dot(dir) > 0 ? 1 : -1;
    }
  }
  return hits;
}

bool RayCaster::Inside(const Vec3& p) const {
  static const Vec3 dirs[3] = {Vec3(1.0, 0.1234, 0.0567).normalized(),
                               Vec3(-0.0789, 1.0, 0.1357).normalized(),
                               Vec3(0.1111, -0.0987, -1.0).normalized()};
  int votes = 0;
  for (const Vec3& d : dirs) votes += CountHits(p, d) != 0 ? 1 : 0;
  return votes >= 2;
}

}  // namespace internal
}  // namespace vhacd
