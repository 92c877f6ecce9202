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

// The cluster's hull, extended through the solid behind its patch, so that the hulls of the
// patches around a solid meet inside it instead of leaving a hollow between them. Each triangle's
// point behind it starts halfway through the solid. The extension is kept when the middle of the
// extended hull is inside the solid and no ray of the cluster's concavity (from its distance points
// along their normals to the hull, as the clustering measures it on the patch's own hull) runs
// farther *outside the solid* than the patch hull's concavity: the clustering bounds that
// concavity, so an extension bridging a concave part of the patch would otherwise escape the
// Concavity limit unmeasured, while a stretch of hull that stays inside the solid (a pot under its
// lid) reaches out of nothing. Otherwise the behind points at the corners of the faces those rays
// end on go back by an eighth of the depth (all of them when the middle left the solid) and the
// hull is made again: the rest of the patch keeps its full extension, and the hollows next to it
// stay closed.
HullMesh FilledClusterHull(const FillInput& in);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_HACD_HULL_H_
