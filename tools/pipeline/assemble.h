// "Write": the last stage of the pipeline. The packed meshes (pack_mesh.h) and what the scene keeps
// besides them (materials, images, skins, nodes) become one packed GLB (packed_glb_writer.h):
// render meshes keep their indices, so nodes stay valid, and every mesh's hulls follow them.
#ifndef HULLPACK_TOOLS_PIPELINE_ASSEMBLE_H_
#define HULLPACK_TOOLS_PIPELINE_ASSEMBLE_H_

#include <cstdint>
#include <vector>

#include "common/status.h"
#include "packed/packed_glb_writer.h"
#include "pipeline/pack_mesh.h"
#include "scene/scene.h"

namespace hullpack {

// `scene` gives everything but the meshes (consumed); `packed` holds one entry per scene mesh
// (consumed). `stats` (may be null): see WritePackedGlb.
Result<std::vector<uint8_t>> AssemblePackedGlb(Scene scene, std::vector<PackedMesh> packed,
                                               const PackedGlbOptions& options,
                                               PackedGlbStats* stats = nullptr);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_ASSEMBLE_H_
