// The working frame of the decomposers: inputs moved into a unit box on the way in, hulls moved
// back to input coordinates on the way out. Shared by Decompose and DecomposeHacd.
#ifndef VHACD_SRC_WORKING_FRAME_H_
#define VHACD_SRC_WORKING_FRAME_H_

#include <cmath>
#include <functional>
#include <vector>

#include "convex_hull.h"
#include "vhacd/vhacd.h"

namespace vhacd {
namespace internal {

// Rounds x to a multiple of 2^-40 (to nearest, ties to even) for |x| <= 1: the normalized mesh
// then does not depend on the input's position and scale. Inline and without a library call:
// a decomposition that reads a large input in place maps every point on each read.
inline double QuantizeUnit(double x) {
  constexpr double kSteps = 1099511627776.0;     // 2^40
  constexpr double kRound = 6755399441055744.0;  // 1.5 x 2^52: adding it drops the fraction
  return ((x * kSteps + kRound) - kRound) / kSteps;
}

// The map of a decomposer from input coordinates into its unit box: Unit(p) is (p - center) /
// scale, quantized (QuantizeUnit), then turned onto the principal axes when `rotate`.
struct UnitFrame {
  Vec3 center = Vec3::Zero();
  double scale = 1.0;  // the bounding box's largest side
  bool rotate = false;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // rows: the principal axes

  Vec3 Unit(const Vec3& p) const {
    const Vec3 q = (p - center) / scale;
    const Vec3 u(QuantizeUnit(q[0]), QuantizeUnit(q[1]), QuantizeUnit(q[2]));
    if (!rotate) return u;
    return rotation * u;
  }
};

// Sets frame->center and frame->scale from the bounding box of the `count` points point(i).
// False when the box is degenerate or overflows.
template <typename PointFn>
bool FitUnitBox(size_t count, const PointFn& point, UnitFrame* frame) {
  if (count == 0) return false;
  Vec3 lo = point(0), hi = lo;
  for (size_t i = 1; i < count; ++i) {
    const Vec3 p = point(i);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  frame->center = 0.5 * (lo + hi);
  frame->scale = (hi - lo).maxCoeff();
  return frame->scale > 0 && std::isfinite(frame->scale) && frame->center.allFinite();
}

// Replaces every point p with UnitFrame::Unit(p) of the frame fitted to them (in place: a mesh's
// points are its largest array); *center is the centre of the bounding box, *scale its largest
// side. Returns false, with the points unchanged, when the box is degenerate or overflows.
bool NormalizeToUnitBox(std::vector<Vec3>* points, Vec3* center, double* scale);

// Fills *out from a working-frame hull: points and centroid through to_world, the volume times
// volume_scale (clamped to the double range, never Inf). Returns false on a non-finite value.
bool ToOutputHull(const HullMesh& hull, const std::function<Vec3(const Vec3&)>& to_world,
                  double volume_scale, ConvexHull* out);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_WORKING_FRAME_H_
