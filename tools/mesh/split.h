// Splitting a large mesh into spatially compact parts, each coded as a stream of its own: the
// encoder's memory then follows the part, not the mesh.
#ifndef HULLPACK_TOOLS_MESH_SPLIT_H_
#define HULLPACK_TOOLS_MESH_SPLIT_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace hullpack {

// Whether SplitTriangles can split `mesh`: it has no skin and no morph targets (a part would need
// the skin's or the targets' every user to follow it).
bool CanSplitMesh(const Mesh& mesh);

// The triangles of `mesh` in parts of at most `max_triangles` (>= 1), as ascending triangle ids:
// as few parts as that allows, of about equal size, each cut at a quantile of the triangles'
// centroids along the longest side of their box, recursively, so that a part is a compact piece
// of the surface. A mesh of at most `max_triangles` triangles, or that CanSplitMesh refuses, is
// one part. Deterministic.
std::vector<std::vector<uint32_t>> SplitTriangles(const Mesh& mesh, size_t max_triangles);

// The mesh of `triangles` (ascending ids of `mesh`): the triangles keep their order and corners,
// the vertices they use their order, and every per-vertex attribute and material id goes along.
// A vertex used by several parts is copied into each.
Mesh MeshPart(const Mesh& mesh, const std::vector<uint32_t>& triangles);

// The box of the positions of `mesh` (min x, y, z, then max x, y, z); zeros when it has none.
std::array<float, 6> PositionBox(const Mesh& mesh);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_SPLIT_H_
