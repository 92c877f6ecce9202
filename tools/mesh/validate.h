// Structural checks a mesh must pass before any other stage touches it.
#ifndef HULLPACK_TOOLS_MESH_VALIDATE_H_
#define HULLPACK_TOOLS_MESH_VALIDATE_H_

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

// Returns kInvalidMesh when the mesh cannot be trusted as an indexed triangle mesh:
//  - positions not a multiple of 3, indices not a multiple of 3;
//  - an attribute array (normals, tangents, each UV set, colors, joints, weights) that is
//    neither empty nor exactly one entry per vertex; joints without weights or the reverse;
//    material_ids neither empty nor one per triangle;
//  - an index >= vertex_count();
//  - a NaN or infinite value in positions, normals, tangents, UVs, colors or weights.
// The message names the first offender (vertex or triangle index) and how many there are,
// e.g. "positions: 3 non-finite values, first at vertex 17 (y = nan)".
// Every later stage (AnalyzeTopology, RepairMesh) assumes this returned ok.
Status ValidateMesh(const Mesh& mesh);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_VALIDATE_H_
