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

// The closeness `hullpack pack` asks of its hulls by default, in --max-concavity's units (the
// larger one-sided Hausdorff distance between the surface and the hulls, as a fraction of the
// bounding-box diagonal): chosen from the corpus' size and closeness curve (docs/packed-gltf.md,
// "Sizes") as the closest hulls whose whole file stays within the size of the same meshes
// Draco-compressed without hulls.
inline constexpr double kPackMaxConcavity = 0.08;

// The decomposition `hullpack pack` runs by default: V-HACD 2.0's voxels and splitting with
//  - the target error max_concavity = kPackMaxConcavity: parts are split until every hull lies
//    within it and merged while the merged hull stays within it, so a shape gets the fewest hulls
//    that keep that closeness (V-HACD 2.0's volume criteria, concavity and gamma, are off);
//  - at most 24 vertices per hull (instead of 64): what physics engines handle fastest.
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
