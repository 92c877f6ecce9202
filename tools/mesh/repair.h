// Clean-ups that change no shape: welding exact duplicates, dropping triangles that add
// nothing, dropping vertices nothing uses. Each one is counted so callers can say what changed.
#ifndef HULLPACK_TOOLS_MESH_REPAIR_H_
#define HULLPACK_TOOLS_MESH_REPAIR_H_

#include <cstddef>
#include <string>

#include "scene/scene.h"

namespace hullpack {

struct RepairOptions {
  // Merge vertices whose every attribute (position, normal, tangent, all UV sets, color,
  // joints, weights) is equal. Vertices that differ in any attribute stay apart, so UV and
  // normal seams survive. Values compare with ==, so -0 and +0 are equal.
  bool weld_duplicate_vertices = true;
  // Remove triangles that use the same vertex index twice (after welding).
  bool remove_degenerate_triangles = true;
  // Also remove triangles whose three positions are collinear (area exactly 0 in double),
  // e.g. two corners at one position but on different sides of a UV seam.
  bool remove_zero_area_triangles = false;
  // Remove extra copies of a triangle: same three vertices in the same cyclic order.
  bool remove_duplicate_triangles = true;
  // A copy with the opposite winding is a two-sided face (a thin wall, a leaf); it is kept and
  // counted unless this is set, in which case only the first triangle of the pair stays.
  bool remove_opposite_duplicates = false;
  // Remove vertices no remaining triangle uses.
  bool remove_unused_vertices = true;
  // Threads for the weld's sort and the degenerate-triangle checks (the result does not depend
  // on it).
  int threads = 1;
};

struct RepairReport {
  size_t welded_vertices = 0;               // vertices merged into an identical earlier one
  size_t degenerate_triangles_removed = 0;  // repeated vertex index
  size_t zero_area_triangles_removed = 0;   // collinear positions (option)
  size_t duplicate_triangles_removed = 0;   // same vertices, same winding
  // Two-sided faces found (same vertices, both windings), counted among the triangles left
  // after same-winding copies are removed.
  size_t opposite_triangle_pairs = 0;
  size_t opposite_triangles_removed = 0;  // ... of which removed (option)
  size_t unused_vertices_removed = 0;     // referenced by no triangle (not counting welded ones)

  // True when the mesh was modified (finding opposite pairs alone changes nothing).
  bool changed() const {
    return welded_vertices + degenerate_triangles_removed + zero_area_triangles_removed +
               duplicate_triangles_removed + opposite_triangles_removed + unused_vertices_removed >
           0;
  }
};

// Repairs `mesh` in place and reports what it did. Triangles and vertices keep their relative
// order; every per-vertex array and material_ids stay consistent with the new indices.
// Precondition: ValidateMesh(mesh) is ok (indices in range, attribute sizes consistent).
// O(n log n) in the vertex and triangle counts.
RepairReport RepairMesh(Mesh& mesh, const RepairOptions& options = {});

// One line for a log: "welded 12 duplicate vertices, removed 3 degenerate triangles, kept 2
// two-sided faces", or "no repairs needed".
std::string DescribeRepairs(const RepairReport& report);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_REPAIR_H_
