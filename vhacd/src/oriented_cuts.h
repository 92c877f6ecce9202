// Cut planes that are not axis-aligned: a slanted arm, a chamfer or a rotated part is cut cleanly
// only by a plane along its own axes, which the voxel slices cannot express.
//
// A part's candidate directions are its principal axes (covariance of its voxel centres) and the
// bisectors of each pair of them (for an L the principal axes bisect the arms, the bisectors run
// along them). Directions within a few degrees of a grid axis are left to the axis-aligned search.
// An oriented plane n.x = d puts a voxel on the left when n.centre < d, so each line of voxels
// along the axis where |n| is largest splits at one coordinate: the side hulls are then built from
// the line ends as for slices, and the cost is the one of plane_search.h.
#ifndef VHACD_SRC_ORIENTED_CUTS_H_
#define VHACD_SRC_ORIENTED_CUTS_H_

#include <vector>

#include "plane_search.h"
#include "primitive_set.h"

namespace vhacd {
namespace internal {

// A direction to cut along: unit normal n with n[axis] > 0 where |n[axis]| is largest, and the
// range of n.centre over the part's voxel centres.
struct CutDirection {
  Vec3 n = Vec3::UnitX();
  int axis = 0;
  double lo = 0.0, hi = 0.0;
};

// The part's oriented candidate directions (none for a part of fewer than two voxels).
std::vector<CutDirection> OrientedCutDirections(const Part& part);

// Whether any of the parts is bounded by an oriented cut (else they are the voxel slices' parts).
bool HasOrientedCut(const std::vector<Part>& parts);

// Offsets d of the planes to try along `dir`: every `step` from lo, both sides non-empty.
std::vector<double> OrientedCandidateOffsets(const CutDirection& dir, double step);

// The first coordinate along dir.axis that is on the right of plane (dir.n, d) for the line of
// voxels at (u, v) on the two other axes.
int OrientedSplit(const CutDirection& dir, double d, int u, int v);

// True when voxel (or cell) c lies on the left of the plane.
inline bool OrientedLeft(const CutDirection& dir, double d, const uint16_t c[3]) {
  const int a = dir.axis;
  return c[a] < OrientedSplit(dir, d, c[(a + 1) % 3], c[(a + 2) % 3]);
}

// CutCost (plane_search.h) of the plane (dir.n, d); `lines` (and `tetra` in mode 1) must be built
// on dir.axis.
double OrientedCutCost(const Part& part, const AxisLines& lines, const CutDirection& dir, double d,
                       int hull_downsample, const CutWeights& w, const RevolutionHint& hint,
                       double part_concavity, const TetraAxis* tetra = nullptr);

// Appends the polygon `poly` clipped to the half-spaces of `cuts` to *out.
void ClipPolygonToCuts(const std::vector<Vec3>& poly, const std::vector<CutPlane>& cuts,
                       std::vector<Vec3>* out);

// The hull cut down to the half-spaces of `cuts` (empty when nothing solid is left).
HullMesh ClipHullToCuts(const HullMesh& hull, const std::vector<CutPlane>& cuts);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_ORIENTED_CUTS_H_
