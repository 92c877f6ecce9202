// A closed input that is already convex is its own decomposition: its convex hull, exactly, with
// nothing to voxelize, cut or merge. Scenes of many small convex parts (boxes, panels, prisms)
// otherwise pay the whole voxel pipeline for each.
#ifndef VHACD_SRC_CONVEX_INPUT_H_
#define VHACD_SRC_CONVEX_INPUT_H_

#include <cstdint>
#include <vector>

#include "convex_hull.h"
#include "triangle_list.h"

namespace vhacd {
namespace internal {

// Inputs with more points are not checked: their hull would rarely fit a hull's vertex budget, and
// the check would cost more than it saves.
constexpr size_t kMaxConvexInputPoints = 4096;

// True, with *hull set, when the closed mesh (`points` in the unit working frame, `triangles`
// every edge shared by two) is convex: every point lies on its convex hull within `tolerance` and
// the mesh encloses the hull's volume to a relative 1e-6, and the hull has at most
// `max_vertices` vertices. False otherwise, and for more than kMaxConvexInputPoints points.
bool ConvexInputHull(const std::vector<Vec3>& points, const TriangleList& triangles,
                     size_t max_vertices, double tolerance, HullMesh* hull);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_CONVEX_INPUT_H_
