// "Per mesh: decompose and encode": the pipeline stage after leaving out the unused. Each mesh gets
// its render stream (the smallest within the position error budget, error_budget.h) and, when the
// collision policy gives it hulls, its decomposition (collision.h) as quantized plain accessors
// (hull_quantize.h). The render streams and decompositions of all meshes are independent tasks run
// on the pipeline's threads, largest first; each writes only its own mesh's result, so the output
// does not depend on the thread count.
#ifndef HULLPACK_TOOLS_PIPELINE_PACK_MESH_H_
#define HULLPACK_TOOLS_PIPELINE_PACK_MESH_H_

#include <string>
#include <vector>

#include "common/status.h"
#include "pipeline/mesh_codec.h"
#include "pipeline/pack_options.h"
#include "scene/scene.h"

namespace hullpack {

struct PackedMesh {
  MeshPackReport report;
  // The render stream, or one per part (PackOptions::part_triangles).
  std::vector<EncodedMesh> streams;
  // What a decoder reads back from each stream (DecodeRenderMeshes fills it): with the mesh's
  // name, collides, morph weights and target names; material ids = the stream's groups.
  std::vector<Mesh> decoded;
  bool grouped = false;  // the streams have triangle groups (the mesh had material ids)
  bool collides = true;
  std::vector<float> morph_weights;
  std::vector<std::string> target_names;
  bool has_hulls = false;
  std::vector<HullGrid> hull_grids;  // per hull: what the writer stores
  std::vector<Mesh> hulls;           // per hull: the positions an engine computes, MESH_hull_h
};

// Packs every mesh of `scene`. `observer` (may be null) sees progress as fractions between `from`
// and `to` and can cancel. Errors name the mesh.
Result<std::vector<PackedMesh>> PackMeshes(const Scene& scene, const PackOptions& options,
                                           PackObserver* observer, double from, double to);

// Decodes the render streams of `packed` into their `decoded` meshes, on `threads` threads, and
// sets each report's seconds_decode. A separate step so that the caller can free the source
// meshes first: the decoded copies and the sources are then never held together.
Status DecodeRenderMeshes(std::vector<PackedMesh>& packed, int threads);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_PACK_MESH_H_
