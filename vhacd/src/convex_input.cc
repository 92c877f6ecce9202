#include "convex_input.h"

#include <algorithm>
#include <cmath>

namespace vhacd {
namespace internal {

bool ConvexInputHull(const std::vector<Vec3>& points, const TriangleList& triangles,
                     size_t max_vertices, double tolerance, HullMesh* hull) {
  if (points.size() > kMaxConvexInputPoints || triangles.empty()) return false;
  // The hull of the points in lexicographic order: the same hull whatever order they come in.
  std::vector<Vec3> sorted = points;
  std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  HullMesh h;
  if (ComputeConvexHull(sorted, -1.0, &h) != HullStatus::kOk) return false;
  if (h.vertices.size() > max_vertices) return false;
  // A dent puts a point inside the hull; a self-intersecting surface could still enclose the
  // hull's volume by its signed sum, hence both tests.
  const HullPlanes planes(h);
  for (const Vec3& p : points)
    if (planes.SignedDistanceBound(p) < -tolerance) return false;
  double six_volume = 0.0;
  for (const auto& t : triangles) six_volume += points[t[0]].dot(points[t[1]].cross(points[t[2]]));
  constexpr double kRelativeVolume = 1e-6;
  const double hull_volume = h.Volume();
  if (!(hull_volume > 0) ||
      std::fabs(std::fabs(six_volume / 6.0) - hull_volume) > kRelativeVolume * hull_volume)
    return false;
  *hull = std::move(h);
  return true;
}

}  // namespace internal
}  // namespace vhacd
