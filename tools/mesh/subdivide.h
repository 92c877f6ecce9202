// Midpoint subdivision: dense test meshes of a known shape, for benchmarks of large inputs.
#ifndef HULLPACK_TOOLS_MESH_SUBDIVIDE_H_
#define HULLPACK_TOOLS_MESH_SUBDIVIDE_H_

#include "scene/scene.h"

namespace hullpack {

// Positions and triangles of `mesh` (other attributes are not kept), with bitwise-equal positions
// welded first so that triangles sharing an edge share its midpoint; then `levels` rounds that
// split every triangle in 4 at its edge midpoints (a closed mesh stays closed; the shape does not
// change). Each round multiplies the triangles by 4 and about the vertices too.
Mesh SubdivideMidpoint(const Mesh& mesh, int levels);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_SUBDIVIDE_H_
