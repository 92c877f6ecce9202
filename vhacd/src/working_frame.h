// The working frame of the decomposers: inputs moved into a unit box on the way in, hulls moved
// back to input coordinates on the way out. Shared by Decompose and DecomposeHacd.
#ifndef VHACD_SRC_WORKING_FRAME_H_
#define VHACD_SRC_WORKING_FRAME_H_

#include <functional>
#include <vector>

#include "convex_hull.h"
#include "vhacd/vhacd.h"

namespace vhacd {
namespace internal {

// Replaces every point p with (p - *center) / *scale, quantized to 2^-40 so that the result does
// not depend on the input's position and scale (in place: a mesh's points are its largest array);
// *center is the centre of the bounding box, *scale its largest side. Returns false, with the
// points unchanged, when the box is degenerate or overflows.
bool NormalizeToUnitBox(std::vector<Vec3>* points, Vec3* center, double* scale);

// Fills *out from a working-frame hull: points and centroid through to_world, the volume times
// volume_scale (clamped to the double range, never Inf). Returns false on a non-finite value.
bool ToOutputHull(const HullMesh& hull, const std::function<Vec3(const Vec3&)>& to_world,
                  double volume_scale, ConvexHull* out);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_WORKING_FRAME_H_
