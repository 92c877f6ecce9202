#include "stick_out.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace vhacd {
namespace internal {

namespace {
// Triangle buckets about this many voxels wide.
constexpr double kLocatorCell = 2.0;
// Sample spacing on the hull's faces, voxels.
constexpr double kSpacing = 0.5;
// ... or this fraction of the largest distance found so far, when larger.
constexpr double kRelativeSpacing = 0.2;
}  // namespace

// A point of a voxel that meets the surface is within the voxel's diagonal of it; an outside
// voxel's centre is within its field value plus half a diagonal of a solid voxel's centre.
constexpr double kVoxelDiagonal = 1.7320508075688772;
// Any point is within a voxel's diagonal of the surface in the nearest surface voxel; farther
// than that (plus the field's interpolation error) from the surface than from the solid voxels, the
// nearest solid is a fill cap.
constexpr double kCapMargin = kVoxelDiagonal + 0.5;

StickOutMeter::StickOutMeter(const GridMesh& mesh, const VoxelGrid& grid, bool closed,
                             const DistanceField* field)
    : mesh_(mesh), grid_(grid), closed_(closed), field_(field), locator_(mesh, kLocatorCell) {}

double StickOutMeter::OutsideDistance(const Vec3& p, double best) const {
  // Only a distance above best matters: the search may stop at any triangle within best.
  uint32_t tri = 0;
  auto distance = [&]() { return locator_.DistanceUnlessWithin(p, best, &tri); };
  int c[3];
  bool in_grid = true;
  for (int a = 0; a < 3; ++a) {
    c[a] = static_cast<int>(std::floor(p[a]));
    in_grid = in_grid && c[a] >= 0 && c[a] < grid_.dims[a];
  }
  if (in_grid) {
    const size_t index = grid_.Index(c[0], c[1], c[2]);
    const uint8_t cell = grid_.cell[index];
    if (cell == kCellInside) return 0.0;
    if (cell == kCellSurface && best >= kVoxelDiagonal) return 0.0;
    if (cell == kCellOutside && field_ != nullptr && field_->At(index) + kVoxelDiagonal <= best)
      return 0.0;
    if (cell == kCellOutside && field_ != nullptr) {
      // Farther from the surface than from the solid voxels by more than a voxel's diagonal:
      // the nearest solid voxel is a fill cap (an opening the fill rule closed), not the
      // surface. Measure from the solid the decomposition works on there.
      const double to_solid = std::max(0.0, field_->Interpolate(p) - 0.5);
      const double d = distance();
      return d > to_solid + kCapMargin ? to_solid : d;
    }
    if (cell == kCellSurface) {
      // An open surface has no side: trust the voxel centre's parity vote for the whole voxel.
      if (!closed_) return grid_.CenterInside(grid_.Index(c[0], c[1], c[2])) ? 0.0 : distance();
      const double d = distance();
      if (tri >= mesh_.triangles.size()) return d;
      // A closed surface: the side of the nearest triangle's plane (exact away from its edges;
      // near an edge only points within that distance of the surface are misjudged).
      const auto& t = mesh_.triangles[tri];
      const Vec3 a = mesh_.points[t[0]];
      const Vec3 n = (mesh_.points[t[1]] - a).cross(mesh_.points[t[2]] - a);
      return n.dot(p - a) > 0 ? d : 0.0;
    }
  }
  return distance();
}

double StickOutMeter::SampleFaces(const HullMesh& hull, const std::vector<char>* skip, double best,
                                  double limit) const {
  std::vector<Vec3> pts;
  for (size_t f = 0; f < hull.triangles.size(); ++f) {
    if (skip != nullptr && (*skip)[f]) continue;
    const auto& t = hull.triangles[f];
    pts.clear();
    // The distance is 1-Lipschitz: once the maximum is large, coarser samples rank as well.
    const double spacing = std::max(kSpacing, kRelativeSpacing * best);
    SampleTriangle(hull.vertices[t[0]], hull.vertices[t[1]], hull.vertices[t[2]], spacing, &pts);
    for (const Vec3& p : pts) {
      best = std::max(best, OutsideDistance(p, best));
      if (best > limit) return best;
    }
  }
  return best;
}

double StickOutMeter::Measure(const HullMesh& hull, double limit) const {
  double best = 0.0;
  for (const Vec3& v : hull.vertices) {
    best = std::max(best, OutsideDistance(v, best));
    if (best > limit) return best;
  }
  return SampleFaces(hull, nullptr, best, limit);
}

double StickOutMeter::MeasureMerged(const HullMesh& merged, const HullMesh& a, double stick_a,
                                    const HullMesh& b, double stick_b, double limit) const {
  const double best = std::max(stick_a, stick_b);
  if (best > limit) return best;
  // A face is old when its three corners are the corners of one face of a or of b.
  using Key = std::array<double, 9>;
  auto key = [](const HullMesh& h, const std::array<uint32_t, 3>& t) {
    std::array<std::array<double, 3>, 3> c;
    for (int k = 0; k < 3; ++k)
      c[k] = {h.vertices[t[k]][0], h.vertices[t[k]][1], h.vertices[t[k]][2]};
    std::sort(c.begin(), c.end());
    Key out;
    for (int k = 0; k < 9; ++k) out[k] = c[k / 3][k % 3];
    return out;
  };
  std::vector<Key> old;
  old.reserve(a.triangles.size() + b.triangles.size());
  for (const auto& t : a.triangles) old.push_back(key(a, t));
  for (const auto& t : b.triangles) old.push_back(key(b, t));
  std::sort(old.begin(), old.end());
  std::vector<char> skip(merged.triangles.size(), 0);
  for (size_t f = 0; f < merged.triangles.size(); ++f)
    skip[f] = std::binary_search(old.begin(), old.end(), key(merged, merged.triangles[f]));
  return SampleFaces(merged, &skip, best, limit);
}

}  // namespace internal
}  // namespace vhacd
