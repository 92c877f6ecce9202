#include "stick_out.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vhacd {
namespace internal {

namespace {
// Triangle buckets about this many voxels wide.
constexpr double kLocatorCell = 2.0;
// Sample spacing on the hull's faces, voxels.
constexpr double kSpacing = 0.5;
}  // namespace

StickOutMeter::StickOutMeter(const GridMesh& mesh, const VoxelGrid& grid, bool closed)
    : mesh_(mesh), grid_(grid), closed_(closed), locator_(mesh, kLocatorCell) {}

double StickOutMeter::OutsideDistance(const Vec3& p) const {
  int c[3];
  bool in_grid = true;
  for (int a = 0; a < 3; ++a) {
    c[a] = static_cast<int>(std::floor(p[a]));
    in_grid = in_grid && c[a] >= 0 && c[a] < grid_.dims[a];
  }
  if (in_grid) {
    const uint8_t cell = grid_.cell[grid_.Index(c[0], c[1], c[2])];
    if (cell == kCellInside) return 0.0;
    if (cell == kCellSurface) {
      // An open surface has no side: trust the voxel centre's parity vote for the whole voxel.
      if (!closed_)
        return grid_.CenterInside(grid_.Index(c[0], c[1], c[2])) ? 0.0 : locator_.Distance(p);
      uint32_t tri = 0;
      const double d = locator_.Distance(p, &tri);
      if (tri >= mesh_.triangles.size()) return d;
      // A closed surface: the side of the nearest triangle's plane (exact away from its edges;
      // near an edge only points within that distance of the surface are misjudged).
      const auto& t = mesh_.triangles[tri];
      const Vec3& a = mesh_.points[t[0]];
      const Vec3 n = (mesh_.points[t[1]] - a).cross(mesh_.points[t[2]] - a);
      return n.dot(p - a) > 0 ? d : 0.0;
    }
  }
  return locator_.Distance(p);
}

double StickOutMeter::Measure(const HullMesh& hull, double limit) const {
  double best = 0.0;
  auto visit = [&](const Vec3& p) {
    best = std::max(best, OutsideDistance(p));
    return best > limit;
  };
  for (const Vec3& v : hull.vertices)
    if (visit(v)) return best;
  std::vector<Vec3> pts;
  for (const auto& t : hull.triangles) {
    pts.clear();
    SampleTriangle(hull.vertices[t[0]], hull.vertices[t[1]], hull.vertices[t[2]], kSpacing, &pts);
    for (const Vec3& p : pts)
      if (visit(p)) return best;
  }
  return best;
}

}  // namespace internal
}  // namespace vhacd
