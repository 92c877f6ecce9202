// Edge-topology figures of a triangle mesh: is it closed, manifold, consistently oriented,
// how many pieces, what genus, how much area and volume.
#ifndef HULLPACK_TOOLS_MESH_TOPOLOGY_H_
#define HULLPACK_TOOLS_MESH_TOPOLOGY_H_

#include <array>
#include <cstddef>
#include <cstdint>

#include "scene/scene.h"

namespace hullpack {

// How triangles are taken to be connected.
enum class Connectivity {
  // Vertices whose positions compare equal (bit-identical floats, with -0 treated as +0) are
  // one point, so a mesh split at UV or normal seams is still closed. The default: it is what a
  // physics engine sees.
  kWeldedPositions,
  // Vertex indices as stored: two vertices at the same place are different points. Useful to
  // see the seams a file carries (the Utah teapot's patches are only stitched by position).
  kVertexIndices,
};

struct TopologyOptions {
  Connectivity connectivity = Connectivity::kWeldedPositions;
};

// Every figure is computed on the connectivity the options choose; "point" below means a
// welded position (or a vertex index under kVertexIndices).
//
// Degenerate triangles (two corners on the same welded point) are counted and then left out
// of every other figure: they have no area and no proper edges.
struct TopologyReport {
  size_t vertices = 0;              // vertex_count(): entries in Mesh::positions / 3
  size_t referenced_vertices = 0;   // vertex indices used by at least one triangle
  size_t unique_positions = 0;      // distinct positions among the referenced vertices
  size_t triangles = 0;             // triangle_count()
  size_t degenerate_triangles = 0;  // two or three corners on the same welded point
  // Extra copies of a triangle with the same three points in the same cyclic order
  // (a triangle present k times adds k - 1).
  size_t duplicate_triangles = 0;
  // Triangle pairs with the same three points in opposite winding: a two-sided face.
  // Each such pair makes its three edges non-manifold or inconsistent; counted here so the
  // cause is visible.
  size_t opposite_triangle_pairs = 0;

  size_t edges = 0;               // distinct undirected edges between welded points
  size_t boundary_edges = 0;      // used by exactly one triangle (open edges)
  size_t non_manifold_edges = 0;  // used by more than two triangles
  // Vertices whose incident triangles do not form a single fan (disk or half-disk) when
  // triangles are joined across the vertex's manifold edges only: bow-ties, cone tips touching,
  // every vertex on a non-manifold edge.
  size_t non_manifold_vertices = 0;
  // Edges used by exactly two triangles that both traverse it in the same direction.
  size_t inconsistent_edges = 0;
  bool consistently_oriented = true;  // inconsistent_edges == 0

  // Connected components of non-degenerate triangles. By edges: triangles sharing an edge
  // (including non-manifold edges) are connected. By vertices: sharing a welded point is enough,
  // so a bow-tie is one vertex component but two edge components.
  size_t components = 0;                  // by shared edges
  size_t components_by_vertex = 0;        // by shared points
  size_t closed_components = 0;           // edge components with no boundary or non-manifold edge
  size_t closed_manifold_components = 0;  // ... and no non-manifold vertex

  bool closed = false;  // no boundary edges and no non-manifold edges (and at least one triangle)
  // Sum over edge components of g = (2 - chi) / 2 with chi = V - E + F of the component.
  // -1 (unknown) unless every component is a closed manifold.
  int genus = -1;

  double area = 0;  // total area of the non-degenerate triangles
  // Signed volume (divergence theorem) summed over the closed components only; positive for
  // outward-facing (counter-clockwise seen from outside) winding. 0 when none is closed.
  double volume = 0;
  // Axis-aligned bounds of the referenced vertices; all zero when no triangle references any.
  std::array<float, 3> bbox_min = {0, 0, 0};
  std::array<float, 3> bbox_max = {0, 0, 0};
};

// O(n log n) in the triangle count (a sort welds the positions; edges, duplicates and fans are
// found among the entries that share a point), memory O(n).
// Expects a mesh that passed ValidateMesh (indices in range, finite positions).
TopologyReport AnalyzeTopology(const Mesh& mesh, const TopologyOptions& options = {});

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_TOPOLOGY_H_
