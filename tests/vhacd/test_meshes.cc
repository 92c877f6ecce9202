#include "test_meshes.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>

namespace vhacd_test {

std::string CheckHulls(const std::vector<vhacd::ConvexHull>& hulls, double tol) {
  std::ostringstream err;
  for (size_t h = 0; h < hulls.size(); ++h) {
    const vhacd::ConvexHull& H = hulls[h];
    if (H.vertex_count() < 4 || H.triangle_count() < 4) err << "hull " << h << " too small; ";
    for (double v : H.points)
      if (!std::isfinite(v)) err << "hull " << h << " non-finite; ";
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (size_t t = 0; t < H.triangle_count(); ++t)
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = H.triangles[3 * t + k], b = H.triangles[3 * t + (k + 1) % 3];
        if (a >= H.vertex_count() || b >= H.vertex_count()) err << "hull " << h << " bad index; ";
        ++edges[{a, b}];
      }
    for (const auto& e : edges)
      if (e.second != 1 || edges.count({e.first.second, e.first.first}) != 1) {
        err << "hull " << h << " not closed; ";
        break;
      }
    // Convex and outward: every vertex below every face plane, positive volume.
    double worst = 0.0;
    for (size_t t = 0; t < H.triangle_count(); ++t) {
      const double* a = &H.points[3 * H.triangles[3 * t]];
      const double* b = &H.points[3 * H.triangles[3 * t + 1]];
      const double* c = &H.points[3 * H.triangles[3 * t + 2]];
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                   v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                           u[0] * v[1] - u[1] * v[0]};
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(len > 0)) continue;
      for (size_t p = 0; p < H.vertex_count(); ++p) {
        const double* q = &H.points[3 * p];
        worst = std::max(
            worst, (n[0] * (q[0] - a[0]) + n[1] * (q[1] - a[1]) + n[2] * (q[2] - a[2])) / len);
      }
    }
    if (worst > tol) err << "hull " << h << " not convex (" << worst << "); ";
    if (!(H.volume > 0)) err << "hull " << h << " has volume " << H.volume << "; ";
  }
  return err.str();
}

}  // namespace vhacd_test
