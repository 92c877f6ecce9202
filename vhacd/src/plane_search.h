// Cost of cutting a voxel part by an axis-aligned plane, and the candidate planes to try.
#ifndef VHACD_SRC_PLANE_SEARCH_H_
#define VHACD_SRC_PLANE_SEARCH_H_

#include <vector>

#include "primitive_set.h"

namespace vhacd {
namespace internal {

struct CutWeights {
  double alpha = 0.05;   // balance
  double beta = 0.05;    // revolution axis
  double volume0 = 1.0;  // normalization: volume of the hull of the whole voxel set
};

// Revolution axis of a part from the eigenvalues of its inertia: `weight` in [0, 1] is 1 when two
// eigenvalues are equal (a solid of revolution about `axis`) and 0 when all differ a lot.
struct RevolutionHint {
  Vec3 axis = Vec3::UnitZ();
  double weight = 0.0;
};
RevolutionHint ComputeRevolutionHint(const Part& part);

// The plane between voxel slices c-1 and c on `lines.axis`.
//   cost = (|CH(left)| - |left| + |CH(right)| - |right|) / volume0      (concavity)
//        + alpha * | |left| - |right| | / volume0                        (balance)
//        + beta * weight * |axis . n| * concavity(part)                  (revolution axis)
// Hulls use every `hull_downsample`-th line of voxels (1 = exact). In mode 1 (`tetra` non-null)
// the exact cost (hull_downsample 1) is taken on the primitives: interior voxels and trimmed cells,
// with their volumes; the downsampled estimate stays on the voxel lines.
double CutCost(const Part& part, const AxisLines& lines, int c, int hull_downsample,
               const CutWeights& w, const RevolutionHint& hint, double part_concavity,
               const TetraAxis* tetra = nullptr);

// Planes c in [bmin+1, bmax] on `axis` every `step` slices (always at least one when the part is
// at least two slices thick).
std::vector<int> CandidatePlanes(const Part& part, int axis, int step);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_PLANE_SEARCH_H_
