// How far a hull sticks out of the input solid, measured against the exact input surface rather
// than the voxel distance field: the split and merge decisions of the distance targets
// (max_concavity, hull_count) then resolve differences well below a voxel, where the field only
// knows whole voxel centres.
#ifndef VHACD_SRC_STICK_OUT_H_
#define VHACD_SRC_STICK_OUT_H_

#include "convex_hull.h"
#include "error_metrics.h"
#include "voxelizer.h"

namespace vhacd {
namespace internal {

class StickOutMeter {
 public:
  // `mesh` and `grid` (grid units) must outlive the meter. `closed`: the input is a closed
  // surface, so the side of a point near it can be read from the nearest triangle's plane.
  StickOutMeter(const GridMesh& mesh, const VoxelGrid& grid, bool closed);

  // Largest distance to the input surface over points about half a voxel apart on the hull's
  // surface (its vertices included) that lie outside the solid (grid units; 0 when none). Stops
  // early, returning a value > limit, once the distance is known to exceed `limit`.
  double Measure(const HullMesh& hull, double limit = 1e30) const;

 private:
  // Distance from p to the surface when p is outside the solid, else 0.
  double OutsideDistance(const Vec3& p) const;

  const GridMesh& mesh_;
  const VoxelGrid& grid_;
  bool closed_;
  TriangleLocator locator_;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_STICK_OUT_H_
