// Merging a scene's meshes into one, for the stages that take a single mesh (the codec's command
// line, the benchmarks).
#ifndef HULLPACK_TOOLS_MESH_MERGE_H_
#define HULLPACK_TOOLS_MESH_MERGE_H_

#include "scene/scene.h"

namespace hullpack {

// Every mesh of the scene as one: positions and indices appended in mesh order (indices offset by
// the vertices before them). A vertex attribute (normals, the first UV set, colors, the skin's
// joints and weights) is kept only when every mesh has it; material ids are kept when any mesh has
// them, 0 for the triangles of meshes without. Node transforms are not applied.
Mesh MergeMeshes(const Scene& scene);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_MERGE_H_
