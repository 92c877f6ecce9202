// HACD's dual graph: one node per triangle, an edge per pair of triangles sharing a mesh edge,
// plus "virtual" edges joining connected pieces that come closer than a distance.
#ifndef VHACD_SRC_HACD_GRAPH_H_
#define VHACD_SRC_HACD_GRAPH_H_

#include <array>
#include <cstdint>
#include <vector>

#include "context.h"
#include "convex_hull.h"

namespace vhacd {
namespace internal {

struct DualEdge {
  uint32_t a = 0, b = 0;       // triangle indices, a < b
  double shared_length = 0.0;  // length of the mesh edges the two triangles share (0: virtual)
};

// Edges of the dual graph, sorted by (a, b), without duplicates. Triangles sharing an edge with
// more than one other triangle (non-manifold) are joined to each of them. When connect_distance
// >= 0, each vertex is joined to the nearest vertex of any other connected piece within that
// distance (a triangle of one to a triangle of the other), searched through a uniform grid.
// Returns false when cancelled.
bool BuildDualGraph(const std::vector<Vec3>& points,
                    const std::vector<std::array<uint32_t, 3>>& triangles, double connect_distance,
                    Context* ctx, std::vector<DualEdge>* edges);

// Connected pieces of the triangles through the given edges: a label per triangle, labels
// numbered 0.. in order of their lowest triangle. Returns the number of pieces.
uint32_t LabelPieces(size_t triangle_count, const std::vector<DualEdge>& edges,
                     std::vector<uint32_t>* label);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_HACD_GRAPH_H_
