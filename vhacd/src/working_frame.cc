#include "working_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vhacd {
namespace internal {

bool NormalizeToUnitBox(std::vector<Vec3>* points, Vec3* center, double* scale) {
  UnitFrame frame;
  if (!FitUnitBox(
          points->size(), [points](size_t i) { return (*points)[i]; }, &frame))
    return false;
  for (Vec3& p : *points) p = frame.Unit(p);
  *center = frame.center;
  *scale = frame.scale;
  return true;
}

bool ToOutputHull(const HullMesh& hull, const std::function<Vec3(const Vec3&)>& to_world,
                  double volume_scale, ConvexHull* out) {
  out->points.reserve(hull.vertices.size() * 3);
  for (const Vec3& g : hull.vertices) {
    const Vec3 w = to_world(g);
    out->points.insert(out->points.end(), {w[0], w[1], w[2]});
  }
  for (const auto& t : hull.triangles)
    out->triangles.insert(out->triangles.end(), {t[0], t[1], t[2]});
  // Volumes of extreme-scale inputs may leave the double range: clamp, never return Inf.
  out->volume = std::min(hull.Volume() * volume_scale, std::numeric_limits<double>::max());
  const Vec3 c = to_world(hull.Centroid());
  for (int k = 0; k < 3; ++k) out->center[k] = c[k];
  bool finite = std::isfinite(out->volume) && c.allFinite();
  for (double v : out->points) finite = finite && std::isfinite(v);
  return finite;
}

}  // namespace internal
}  // namespace vhacd
