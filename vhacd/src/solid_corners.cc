#include "solid_corners.h"

#include <cmath>

#include "thread_pool.h"

namespace vhacd {
namespace internal {

namespace {
// The nearest point is inside its triangle when the plane distance equals the triangle distance.
constexpr double kOnFaceTolerance = 1e-7;
// Corners closer than this to the surface (grid units) add nothing the surface does not give.
constexpr double kMinDepth = 1e-6;
}  // namespace

bool SolidCorners::Build(const GridMesh& mesh, const VoxelGrid& grid,
                         const TriangleLocator& locator, Context* ctx) {
  for (int a = 0; a < 3; ++a) dims_[a] = grid.dims[a];
  mask_.assign(grid.size(), 0);
  auto solid = [&](int x, int y, int z) {
    if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) return false;
    return grid.cell[grid.Index(x, y, z)] != kCellOutside;
  };
  auto inside = [&](int cx, int cy, int cz) {
    for (int k = 0; k < 8; ++k)
      if (!solid(cx - 1 + (k & 1), cy - 1 + ((k >> 1) & 1), cz - 1 + ((k >> 2) & 1))) return false;
    const Vec3 p(cx, cy, cz);
    uint32_t tri = 0;
    const double d = locator.Distance(p, &tri);
    if (tri >= mesh.triangles.size() || d < kMinDepth) return false;
    const auto& t = mesh.triangles[tri];
    const Vec3 a = mesh.points[t[0]];
    const Vec3 n = (mesh.points[t[1]] - a).cross(mesh.points[t[2]] - a);
    const double len = n.norm();
    if (!(len > 0)) return false;
    const double plane = n.dot(p - a) / len;
    return plane < 0 && -plane >= d * (1.0 - kOnFaceTolerance);
  };
  const int nx = dims_[0], ny = dims_[1];
  return ParallelFor(ctx, static_cast<size_t>(dims_[2]), [&](size_t zi) {
    const int z = static_cast<int>(zi);
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const size_t i = grid.Index(x, y, z);
        if (grid.cell[i] != kCellSurface) continue;
        uint8_t m = 0;
        for (int k = 0; k < 8; ++k)
          if (inside(x + (k & 1), y + ((k >> 1) & 1), z + ((k >> 2) & 1))) m |= 1u << k;
        mask_[i] = m;
      }
  });
}

}  // namespace internal
}  // namespace vhacd
