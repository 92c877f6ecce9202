// "Leave out what the scene does not need": the pipeline stage between checks and repairs
// (check_and_repair.h) and the per-mesh work (pack_mesh.h). Every removal is counted and described
// so the user sees what was left out and why.
#ifndef HULLPACK_TOOLS_PIPELINE_PRUNE_H_
#define HULLPACK_TOOLS_PIPELINE_PRUNE_H_

#include <string>
#include <vector>

#include "mesh/repair.h"
#include "scene/scene.h"

namespace hullpack {

struct PruneOptions {
  bool unused_uv_sets = true;       // UV sets no texture of the mesh's materials samples
  bool unused_tangents = true;      // tangents when no material of the mesh has a normal map
  bool constant_colors = true;      // one colour on every vertex: folded into the material
  bool unused_skin_data = true;     // joints/weights of a mesh no skinned node shows
  bool empty_meshes = true;         // meshes the repairs left without a triangle
  bool unreferenced_meshes = true;  // meshes no node shows (when the scene has nodes)
  bool unreferenced_materials = true;
  bool unreferenced_images = true;
  bool still_animation_tracks = true;  // animation channels that do not move (still_tracks.h)
  // A mesh that lost a vertex attribute may now hold vertices equal in every attribute left: they
  // are welded again (RepairMesh with these options), as if the attribute had never been there.
  RepairOptions reweld;
};

struct PruneReport {
  size_t uv_sets_removed = 0;
  size_t tangent_sets_removed = 0;
  size_t constant_color_sets_folded = 0;
  size_t skin_data_removed = 0;
  size_t empty_meshes_removed = 0;
  size_t meshes_removed = 0;  // unreferenced
  size_t materials_removed = 0;
  size_t images_removed = 0;
  size_t animation_tracks_removed = 0;    // held their node at rest
  size_t animation_tracks_collapsed = 0;  // held another value: one key
  size_t weight_tracks_removed = 0;       // morph weights of meshes left out
  RepairReport repairs;                   // the welds after removals, summed over meshes
  std::vector<std::string> lines;         // human-readable, one per kind of removal (not the welds)
};

// Prunes `scene` in place. Precondition: every mesh passed ValidateMesh (CheckAndRepair).
PruneReport LeaveOutUnused(Scene& scene, const PruneOptions& options = {});

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_PRUNE_H_
