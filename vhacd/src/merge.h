// Merge stage: greedily merges the pair of hulls whose merged hull adds the least volume.
#ifndef VHACD_SRC_MERGE_H_
#define VHACD_SRC_MERGE_H_

#include <vector>

#include "context.h"
#include "convex_hull.h"
#include "distance_field.h"

namespace vhacd {
namespace internal {

struct MergeParams {
  double gamma = 0.00125;  // merge while the cost is below this
  uint32_t max_hulls = 0;  // then keep merging while more hulls remain (0 = no budget)
  uint32_t min_hulls = 0;  // merges under gamma stop at this many hulls
  double volume0 = 1.0;    // cost normalization
  double adjacency = 1.0;  // pairs whose boxes are farther apart than this are not merged
                           // under gamma (they still are to meet max_hulls)
  // When set, a merge under gamma also needs the merged hull to stick out of the solid by at most
  // max_depth voxels; over the budget, the pair with the smallest depth is merged.
  const DistanceField* field = nullptr;
  double max_depth = 0.0;
  // When set, the same on the exact surface: a merge under gamma also needs the merged hull to
  // stick out by at most max_stick grid units, and over the budget the pair whose merged hull
  // sticks out least is merged.
  const class StickOutMeter* meter = nullptr;
  double max_stick = 0.0;
  // When set, one group per hull (its voxel island; as many as hulls): hulls of different groups
  // are merged only to meet max_hulls, never under gamma.
  const std::vector<uint32_t>* groups = nullptr;
};

// cost(i, j) = max(0, |CH(Hi u Hj)| - |Hi| - |Hj|) / volume0; among the pairs with cost < gamma
// (and depth <= max_depth) the cheapest is merged first. Ties go to the lowest (i, j).
// Returns false when cancelled.
bool MergeHulls(std::vector<HullMesh>* hulls, const MergeParams& params, Context* ctx);

// Convex hull of the union of two hulls' vertices (tolerant mode).
HullMesh MergedHull(const HullMesh& a, const HullMesh& b);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_MERGE_H_
