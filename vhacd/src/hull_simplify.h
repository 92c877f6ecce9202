// Hull simplification: keeps at most `max_vertices` of a hull's vertices, chosen greedily by the
// volume each one adds to the hull of the points already kept.
#ifndef VHACD_SRC_HULL_SIMPLIFY_H_
#define VHACD_SRC_HULL_SIMPLIFY_H_

#include "convex_hull.h"

namespace vhacd {
namespace internal {

// Starts from the largest tetrahedron found by extreme points, then repeatedly adds the vertex
// with the largest volume increment; stops at `max_vertices` (>= 4) or when the best increment is
// below `min_volume` (adaptive sampling: small, flat details cost no vertices). The result is the
// hull of the kept vertices, so it is inside the input hull. A hull that already satisfies both
// limits is returned unchanged. With min_distance > 0, a vertex farther than min_distance from
// the hull of the kept ones is kept whatever volume it adds (the result is then within
// min_distance of the input hull unless max_vertices stops it first), and vertices within a
// millionth of the hull's size of that hull are dropped (no sliver faces).
HullMesh SimplifyHull(const HullMesh& hull, uint32_t max_vertices, double min_volume,
                      double min_distance = 0.0);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_HULL_SIMPLIFY_H_
