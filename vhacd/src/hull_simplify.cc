#include "hull_simplify.h"

#include <algorithm>
#include <cmath>

namespace vhacd {
namespace internal {

HullMesh SimplifyHull(const HullMesh& hull, uint32_t max_vertices, double min_volume,
                      double min_distance) {
  const size_t n = hull.vertices.size();
  max_vertices = std::max<uint32_t>(4, max_vertices);
  const bool by_distance = min_distance > 0.0;
  if (n <= 4 || (n <= max_vertices && min_volume <= 0.0 && !by_distance)) return hull;
  const std::vector<Vec3>& p = hull.vertices;
  // Distance mode: a vertex this close to the hull of the kept ones would only add a sliver face
  // (whose plane rounding to a few digits in a file can flip).
  double tol = -1.0;
  if (by_distance) {
    Vec3 lo = p[0], hi = p[0];
    for (const Vec3& q : p) {
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    tol = 1e-6 * (hi - lo).norm();
  }
  // Initial tetrahedron: farthest pair, farthest from their line, farthest from their plane.
  size_t i0 = 0, i1 = 0;
  for (size_t i = 0; i < n; ++i)
    if ((p[i] - p[0]).squaredNorm() > (p[i1] - p[0]).squaredNorm()) i1 = i;
  for (size_t i = 0; i < n; ++i)
    if ((p[i] - p[i1]).squaredNorm() > (p[i0] - p[i1]).squaredNorm()) i0 = i;
  const Vec3 dir = p[i1] - p[i0];
  size_t i2 = i0;
  for (size_t i = 0; i < n; ++i)
    if ((p[i] - p[i0]).cross(dir).squaredNorm() > (p[i2] - p[i0]).cross(dir).squaredNorm()) i2 = i;
  const Vec3 nrm = dir.cross(p[i2] - p[i0]);
  size_t i3 = i0;
  for (size_t i = 0; i < n; ++i)
    if (std::fabs(nrm.dot(p[i] - p[i0])) > std::fabs(nrm.dot(p[i3] - p[i0]))) i3 = i;
  std::vector<char> used(n, 0);
  std::vector<Vec3> kept;
  for (size_t i : {i0, i1, i2, i3})
    if (!used[i]) {
      used[i] = 1;
      kept.push_back(p[i]);
    }
  HullMesh cur;
  if (kept.size() < 4 || ComputeConvexHull(kept, -1.0, &cur) != HullStatus::kOk) return hull;
  while (kept.size() < max_vertices) {
    // Volume increment of adding point i = sum over visible faces of the tetrahedron volume.
    // Distance of point i above the hull of the kept ones = the largest height above a face.
    std::vector<Vec3> fn(cur.triangles.size());
    std::vector<double> flen(cur.triangles.size());
    for (size_t f = 0; f < cur.triangles.size(); ++f) {
      const auto& t = cur.triangles[f];
      fn[f] =
          (cur.vertices[t[1]] - cur.vertices[t[0]]).cross(cur.vertices[t[2]] - cur.vertices[t[0]]);
      flen[f] = fn[f].norm();
    }
    double best = 0.0, farthest = 0.0;
    size_t best_i = n, far_i = n;
    for (size_t i = 0; i < n; ++i) {
      if (used[i]) continue;
      double inc = 0.0, height = 0.0;
      for (size_t f = 0; f < fn.size(); ++f) {
        const double d = fn[f].dot(p[i] - cur.vertices[cur.triangles[f][0]]);
        if (d > 0) {
          inc += d;
          if (flen[f] > 0) height = std::max(height, d / flen[f]);
        }
      }
      inc /= 6.0;
      if (by_distance && height <= tol) continue;
      if (inc > best) {
        best = inc;
        best_i = i;
      }
      if (height > farthest) {
        farthest = height;
        far_i = i;
      }
    }
    if (best_i == n) break;
    if (best < min_volume) {
      // Adaptive sampling by volume alone would drop it: keep it when it lies farther than
      // min_distance (a thin part's corner adds little volume but sticks out far).
      if (!by_distance || farthest <= min_distance) break;
      best_i = far_i;
    }
    used[best_i] = 1;
    kept.push_back(p[best_i]);
    HullMesh next;
    if (ComputeConvexHull(kept, -1.0, &next) != HullStatus::kOk) break;
    cur = std::move(next);
  }
  return cur;
}

}  // namespace internal
}  // namespace vhacd
