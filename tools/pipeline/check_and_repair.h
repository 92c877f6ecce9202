// "Checks and repairs": the pipeline stage between loading and leaving out the unused. Every mesh
// must pass ValidateMesh (otherwise the stage fails, naming the mesh); then each is repaired in
// place: skin weights whose sum is not 1 are scaled (glTF requires the sum), joint indices that
// carry no weight become 0, and RepairMesh welds exact duplicates and drops degenerate and
// duplicate triangles and unused vertices. Meshes are independent: they are repaired in parallel.
#ifndef HULLPACK_TOOLS_PIPELINE_CHECK_AND_REPAIR_H_
#define HULLPACK_TOOLS_PIPELINE_CHECK_AND_REPAIR_H_

#include <string>
#include <vector>

#include "common/status.h"
#include "mesh/repair.h"
#include "scene/scene.h"

namespace hullpack {

struct CheckRepairOptions {
  bool normalize_skin_weights = true;
  bool clear_unweighted_joints = true;  // they do nothing; validators warn; zeros code smaller
  RepairOptions repairs;
};

struct CheckRepairReport {
  size_t skin_weights_normalized = 0;    // vertices
  size_t unweighted_joints_cleared = 0;  // joint indices
  RepairReport repairs;                  // summed over meshes
  std::vector<std::string> lines;        // human-readable, one per kind of change
};

// Adds `r` to `total`.
void AddRepairs(RepairReport& total, const RepairReport& r);

// Checks and repairs every mesh of `scene` on up to `threads` threads (the result does not depend
// on it). Errors name the mesh ("mesh 3: positions: ...").
Result<CheckRepairReport> CheckAndRepair(Scene& scene, const CheckRepairOptions& options = {},
                                         int threads = 1);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_CHECK_AND_REPAIR_H_
