// Splitting a large mesh into spatially compact parts, each coded as a stream of its own: the
// encoder's memory then follows the part, not the mesh.
#ifndef HULLPACK_TOOLS_MESH_SPLIT_H_
#define HULLPACK_TOOLS_MESH_SPLIT_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

// Whether SplitTriangles can split `mesh`: it has no skin and no morph targets (a part would need
// the skin's or the targets' every user to follow it).
bool CanSplitMesh(const Mesh& mesh);

// The part of each triangle of a mesh (SplitTriangles), one byte per triangle when there are at
// most 256 parts: the split of a large mesh is held while its parts are coded, beside its
// decomposition, and triangle ids would take four bytes each.
class TriangleParts {
 public:
  // Every triangle in part 0 (count() == 1).
  TriangleParts() = default;
  // part_of[t] < part_count for every t.
  TriangleParts(size_t part_count, const std::vector<uint32_t>& part_of);

  size_t count() const { return count_; }
  uint32_t Of(size_t t) const {
    if (count_ == 1) return 0;
    return small_.empty() ? large_[t] : small_[t];
  }
  // The triangles of part p, ascending, among the mesh's `triangle_count`.
  std::vector<uint32_t> Triangles(size_t p, size_t triangle_count) const;

 private:
  size_t count_ = 1;
  std::vector<uint8_t> small_;   // count_ <= 256
  std::vector<uint32_t> large_;  // otherwise
};

// The triangles of `mesh` in parts of at most `max_triangles` (>= 1): as few parts as that allows,
// of about equal size, each cut at a quantile of the triangles' centroids along the longest side
// of their box, recursively, so that a part is a compact piece of the surface. A mesh of at most
// `max_triangles` triangles, or that CanSplitMesh refuses, is one part. Deterministic.
TriangleParts SplitTriangles(const Mesh& mesh, size_t max_triangles);

// The mesh of `triangles` (ascending ids of `mesh`): the triangles keep their order and corners,
// the vertices they use their order, and every per-vertex attribute and material id goes along.
// A vertex used by several parts is copied into each.
Mesh MeshPart(const Mesh& mesh, const std::vector<uint32_t>& triangles);

// The box of the positions of `mesh` (min x, y, z, then max x, y, z); zeros when it has none.
std::array<float, 6> PositionBox(const Mesh& mesh);

// One part of a mesh to code (ForEachPart).
struct PartToCode {
  size_t index = 0;  // from 0
  size_t count = 1;  // the mesh's parts
  const Mesh& mesh;  // the part, or the whole mesh when it is one part
  // The entries of the caller's groups for the part's triangles (empty when those are).
  const std::vector<uint32_t>& groups;
  // The whole mesh's PositionBox when it has several parts (coded on it, a vertex two parts share
  // decodes alike in both), else nothing.
  std::optional<std::array<float, 6>> box;
};

// Visits the parts of `mesh` for coding, in order: SplitTriangles with `max_triangles`, or the
// whole mesh when that is 0. `groups`: one entry per triangle, or empty. Only one part's mesh is
// held at a time. Stops at the first error `visit` returns, and returns it.
Status ForEachPart(const Mesh& mesh, const std::vector<uint32_t>& groups, size_t max_triangles,
                   const std::function<Status(const PartToCode&)>& visit);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_SPLIT_H_
