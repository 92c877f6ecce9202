// How far a hull sticks out of the input solid, measured against the exact input surface rather
// than the voxel distance field: the split and merge decisions of the distance targets
// (max_concavity, hull_count) then resolve differences well below a voxel, where the field only
// knows whole voxel centres.
#ifndef VHACD_SRC_STICK_OUT_H_
#define VHACD_SRC_STICK_OUT_H_

#include <vector>

#include "convex_hull.h"
#include "distance_field.h"
#include "error_metrics.h"
#include "voxelizer.h"

namespace vhacd {
namespace internal {

class StickOutMeter {
 public:
  // `mesh` and `grid` (grid units) must outlive the meter. `closed`: the input is a closed
  // surface, so the side of a point near it can be read from the nearest triangle's plane.
  // `field` (optional) bounds the distances from above, so that points that cannot raise the
  // maximum are skipped without a surface query.
  StickOutMeter(const GridMesh& mesh, const VoxelGrid& grid, bool closed,
                const DistanceField* field = nullptr);

  // Largest distance to the input surface over points about half a voxel apart on the hull's
  // surface (its vertices included) that lie outside the solid (grid units; 0 when none). Stops
  // early, returning a value > limit, once the distance is known to exceed `limit`.
  double Measure(const HullMesh& hull, double limit = 1e30) const;
  // The same for the hull of a and b, given how far a and b stick out: only the faces of the
  // merged hull that are not faces of a or b are sampled (the bridges, where a merge adds error).
  double MeasureMerged(const HullMesh& merged, const HullMesh& a, double stick_a, const HullMesh& b,
                       double stick_b, double limit = 1e30) const;

  const TriangleLocator& locator() const { return locator_; }

 private:
  // Distance from p to the surface when p is outside the solid, else 0; any value <= best when
  // it cannot exceed best.
  double OutsideDistance(const Vec3& p, double best) const;
  // Largest OutsideDistance over samples of the faces f with !skip[f], from `best` on.
  double SampleFaces(const HullMesh& hull, const std::vector<char>* skip, double best,
                     double limit) const;

  const GridMesh& mesh_;
  const VoxelGrid& grid_;
  bool closed_;
  const DistanceField* field_;
  TriangleLocator locator_;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_STICK_OUT_H_
