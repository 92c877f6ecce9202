// Recursive clipping of the voxel set into parts of low concavity (hierarchical, level by level).
#ifndef VHACD_SRC_CLIPPING_H_
#define VHACD_SRC_CLIPPING_H_

#include <vector>

#include "context.h"
#include "distance_field.h"
#include "plane_search.h"
#include "primitive_set.h"

namespace vhacd {
namespace internal {

struct ClipParams {
  int depth = 20;
  double concavity = 0.0025;
  int plane_downsampling = 4;
  int convexhull_downsampling = 4;
  double alpha = 0.05, beta = 0.05;
  // A part is also split while its voxel hull sticks out of the solid by more than max_depth
  // voxels (measured on `field`; disabled when field is null or max_depth <= 0).
  const class DistanceField* field = nullptr;
  double max_depth = 0.0;
  // When set, a part is also split while its hull (BuildPartHull on `index`) sticks out of the
  // exact surface by more than max_stick grid units, and SplitToCount cuts the parts sticking out
  // farthest by that measure first.
  const class StickOutMeter* meter = nullptr;
  const class TriangleIndex* index = nullptr;
  const class SolidCorners* corners = nullptr;  // passed to BuildPartHull
  // When set, the part hulls are taken from it (built on `index` with `corners`), which builds the
  // whole set's hull once.
  class PartHulls* part_hulls = nullptr;
  double max_stick = 0.0;
  // Also try planes along each part's own axes (oriented_cuts.h), kept where they give closer
  // hulls on the exact surface (needs meter and index).
  bool oriented_cuts = false;
  // When set, the root is first split into these islands (voxel_islands.h): no part spans two.
  const class VoxelIslands* islands = nullptr;
};

struct ClipOutput {
  std::vector<Part> parts;
  std::vector<double> concavity;  // of each part, as measured before it became a leaf (-1: not)
  std::vector<double> depth;      // how far each part's hull sticks out (voxels; 0: not measured)
  std::vector<double> stick;      // the same on the exact surface (grid units; 0: not measured)
  double volume0 = 0.0;           // volume of the hull of the whole voxel set (voxel units)
  int levels = 0;
};

// Splits `root` level by level: at each level every part whose concavity exceeds the threshold is
// cut by its best plane (coarse search every plane_downsampling slices with downsampled hulls, then
// an exact search around the best coarse plane). Parts are processed in a fixed order and each
// cost is computed by one task, so the result does not depend on the thread count.
// Returns false when cancelled.
bool ClipRecursively(Part root, const ClipParams& params, Context* ctx, ClipOutput* out);

// Cuts the leaves of `out` further until there are at least `count` (or no leaf can be cut): each
// round cuts the leaves whose hulls stick out farthest (then the most concave), as many as are
// missing but at most `per_round` (0: no limit), by the same plane search. Deterministic. Returns
// false when cancelled.
bool SplitToCount(size_t count, const ClipParams& params, Context* ctx, ClipOutput* out,
                  size_t per_round = 0);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_CLIPPING_H_
