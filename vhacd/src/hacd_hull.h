// The convex hull of one HACD cluster, extended into the solid behind its surface patch.
#ifndef VHACD_SRC_HACD_HULL_H_
#define VHACD_SRC_HACD_HULL_H_

#include <cstdint>
#include <vector>

#include "convex_hull.h"
#include "hacd_cost.h"
#include "hacd_raycast.h"

namespace vhacd {
namespace internal {

// The hull of a cluster's mesh vertices, given `thickness` when it is flat or thinner than that,
// reduced to `max_vertices`.
HullMesh ClusterHull(const std::vector<Vec3>& points, double thickness, uint32_t max_vertices);

struct FillInput {
  std::vector<Vec3> surface;  // the cluster's mesh vertices
  // Per triangle of the cluster: its centre, inward unit normal and the depth of the solid behind
  // it along that normal (0: unknown).
  std::vector<Vec3> behind, inward;
  std::vector<double> depth;
  // The cluster's distance points and area, for its concavity as the clustering measures it.
  const std::vector<DistPoint>* dist = nullptr;
  const std::vector<uint32_t>* dist_ids = nullptr;
  double area = 0.0;
  const HacdCostParams* cost = nullptr;
  const RayCaster* caster = nullptr;  // the decimated surface (inside test)
  double thickness = 0.0;             // of flat clusters' hulls
  double tolerance = 0.0;             // concavity increase taken as none
  uint32_t max_vertices = 100;
};

// The cluster's hull, extended through the solid behind its patch (halfway, else 3/8, 1/4 or 1/8
// of the depth), so that the hulls of the patches around a solid meet inside it instead of
// leaving a hollow between them. An extension is kept only when the middle of the extended hull
// is inside the solid and the cluster's concavity, measured on the extended hull exactly as the
// clustering measured it on the patch's own hull, does not grow: the clustering bounds the
// concavity of the patch hull, so an extension that reaches out of the solid (a hull face bridging
// a concave part of the patch) would otherwise escape the Concavity limit unmeasured.
HullMesh FilledClusterHull(const FillInput& in);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_HACD_HULL_H_
