// Distance from every voxel outside the solid to the nearest solid (surface or inside) voxel, in
// voxel units (exact Euclidean distance transform between voxel centres). It measures how far a
// hull sticks out of the input: the "depth" of a hull is the largest distance over the outside
// voxel centres it contains.
#ifndef VHACD_SRC_DISTANCE_FIELD_H_
#define VHACD_SRC_DISTANCE_FIELD_H_

#include <vector>

#include "context.h"
#include "convex_hull.h"
#include "voxelizer.h"

namespace vhacd {
namespace internal {

// Squared Euclidean distance transform in place: every cell gets the squared distance (in cells)
// to the nearest cell holding 0 (cells hold 0 or +infinity on entry). False when cancelled.
bool SquaredDistanceTransform(const int dims[3], Context* ctx, std::vector<float>* sq);

class DistanceField {
 public:
  // False when cancelled.
  bool Build(const VoxelGrid& grid, Context* ctx);
  float At(size_t index) const { return d_[index]; }

  // Largest distance over the outside voxel centres strictly inside the hull (0 when none). Stops
  // early, returning a value > limit, as soon as the depth is known to exceed `limit`.
  double HullDepth(const HullPlanes& hull, double limit = 1e30) const;
  double HullDepth(const HullMesh& hull, double limit = 1e30) const;
  // The field interpolated (trilinearly between voxel centres) at points spread over the hull's
  // surface about a voxel apart: catches protrusions thinner than a voxel, which hold no voxel
  // centre. Early exit as above.
  double SurfaceDepth(const HullMesh& hull, double limit = 1e30) const;
  double Interpolate(const Vec3& p) const;

 private:
  int dims_[3] = {0, 0, 0};
  std::vector<float> d_;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_DISTANCE_FIELD_H_
