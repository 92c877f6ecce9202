// Which corners of the surface voxels lie inside the input solid.
//
// A part's hull (part_hull.h) is the surface inside the part's box plus its interior voxels'
// corners. Where the solid meets a face of the box inside surface voxels only (a wall thinner than
// a few voxels, a cut next to the surface) neither gives a point there, so the hull stopped up to a
// voxel short of the box face while the neighbour across the cut reached it: a crack inside the
// solid, and the more cuts, the more cracks. The inside corners of those voxels fill it (closed
// surfaces only: the side test needs one).
#ifndef VHACD_SRC_SOLID_CORNERS_H_
#define VHACD_SRC_SOLID_CORNERS_H_

#include <cstdint>
#include <vector>

#include "context.h"
#include "error_metrics.h"
#include "voxelizer.h"

namespace vhacd {
namespace internal {

class SolidCorners {
 public:
  // `locator` must be built on `mesh` (grid units). A corner counts as inside only when none of
  // the eight voxels around it is outside and the nearest point of the surface lies inside a
  // triangle (not on an edge, where the side is ambiguous) whose back it is behind. Returns false
  // from Build when cancelled.
  bool Build(const GridMesh& mesh, const VoxelGrid& grid, const TriangleLocator& locator,
             Context* ctx);

  // Bit k (k = x + 2y + 4z) set: corner (x, y, z) + k's offsets of surface voxel (x, y, z) is
  // inside. 0 for any other voxel.
  uint8_t Mask(int x, int y, int z) const {
    return mask_.empty() ? 0 : mask_[(static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x];
  }

 private:
  int dims_[3] = {0, 0, 0};
  std::vector<uint8_t> mask_;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_SOLID_CORNERS_H_
