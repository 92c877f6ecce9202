// The convex hull of a point set as a closed triangle mesh: what a physics engine builds from a
// collider's points, for writers of formats that hold triangles only (hullpack unpack to OBJ, OFF,
// WRL, PLY). Incremental construction in double precision; meant for hull-sized inputs (up to a few
// thousand points: O(n * faces)).
#ifndef HULLPACK_TOOLS_MESH_CONVEX_HULL_H_
#define HULLPACK_TOOLS_MESH_CONVEX_HULL_H_

#include <vector>

#include "scene/scene.h"

namespace hullpack {

// The hull of `points` (x y z triples): positions are the hull's vertices (a subset of the points),
// triangles wound counter-clockwise seen from outside. Points within a relative 1e-9 of the hull's
// extent from a face count as on it. A flat set (all points on one plane) gives its convex polygon
// fanned on both sides; fewer than three non-collinear points give the points and no triangles.
Mesh ConvexHullOfPoints(const std::vector<float>& points);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_CONVEX_HULL_H_
