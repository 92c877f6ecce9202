// The collision stage: which meshes get convex hulls, and the decomposition itself.
#ifndef HULLPACK_TOOLS_PIPELINE_COLLISION_H_
#define HULLPACK_TOOLS_PIPELINE_COLLISION_H_

#include <string>
#include <vector>

#include "common/status.h"
#include "scene/scene.h"
#include "vhacd/hacd.h"
#include "vhacd/vhacd.h"

namespace hullpack {

enum class HullPolicy {
  kAll,   // every mesh
  kNone,  // no hulls
  kAuto,  // every mesh except those marked or named non-colliding, and skinned ones unless asked
};

// The decomposition `hullpack pack` runs by default: V-HACD 2.0's defaults (same voxels, same
// splitting, same 3 % stick-out bound max_distance) with
//  - merging driven by that bound: hulls are merged while the merged hull sticks out of the mesh by
//    no more than max_distance and adds at most 2 % of the whole hull volume (gamma 0.02 instead of
//    0.00125), so a shape gets the fewest hulls that stay within the stick-out bound;
//  - at most 24 vertices per hull (instead of 64): what physics engines handle fastest, and plenty
//    for parts whose stick-out is bounded anyway.
vhacd::Parameters PackCollisionParameters();

// The decomposer `hullpack pack --method` picks per run.
enum class DecompositionMethod {
  kVhacd,  // V-HACD 2.0 (voxels): vhacd::Decompose with `parameters`
  kHacd,   // HACD (surface clustering): vhacd::DecomposeHacd with `hacd_parameters`
};

// HACD as `hullpack pack --method hacd` runs it: the original tool's recommended line
// `2 100 0 1 1 30 2000`, at most 24 vertices per hull (as for V-HACD).
vhacd::HacdParameters PackHacdParameters();

struct CollisionSettings {
  HullPolicy policy = HullPolicy::kAuto;
  bool skinned_meshes = false;  // under kAuto: decompose skinned meshes (in their bind pose) too
  DecompositionMethod method = DecompositionMethod::kVhacd;
  vhacd::Parameters parameters = PackCollisionParameters();
  vhacd::HacdParameters hacd_parameters = PackHacdParameters();
};

// Why a mesh gets no hulls ("" when it gets them): "--hulls none", "marked non-colliding", ...
std::string WhyNoHulls(const Mesh& mesh, const CollisionSettings& settings);

// True for names that conventionally mark render-only geometry: they contain "nocol", "no_col",
// "no-col", "nocollision" or "-noimp" (case-insensitive).
bool NameMarksNonColliding(const std::string& name);

struct HullSet {
  std::vector<Mesh> hulls;  // closed convex meshes, in the source mesh's coordinates
  vhacd::Report report;
};

// Decomposes `mesh` with the settings' parameters. `observer` (may be null) gets progress and
// can cancel.
Result<HullSet> DecomposeMesh(const Mesh& mesh, const vhacd::Parameters& parameters,
                              vhacd::Observer* observer);
// The same with the settings' method and its parameters.
Result<HullSet> DecomposeMesh(const Mesh& mesh, const CollisionSettings& settings,
                              vhacd::Observer* observer);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_COLLISION_H_
