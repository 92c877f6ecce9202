// A scene as one mesh, in world space: the one place where a scene becomes a single mesh (the
// codec's command line test_o3dgc, testVHACD, the benchmarks).
#ifndef HULLPACK_TOOLS_MESH_FLATTEN_H_
#define HULLPACK_TOOLS_MESH_FLATTEN_H_

#include <vector>

#include "scene/scene.h"

namespace hullpack {

// World transform of every node (its ancestors' local transforms times its own; column-major as
// Node::local_transform). A malformed parent chain (a cycle) is cut where it repeats.
std::vector<Matrix4> WorldTransforms(const Scene& scene);

// Every mesh instance as one mesh: for each node in order, each mesh it shows with the node's world
// transform applied (positions; normals by the inverse transpose, renormalized; a mirroring
// transform also reverses the winding so that triangles keep facing out); then every mesh no node
// shows, once, untransformed. Indices are offset by the vertices before them. A vertex attribute
// (normals, the first UV set, colors, the skin's joints and weights) is kept only when every
// instance has it; tangents are not kept; material ids are kept when any instance has them, 0 for
// the triangles of meshes without.
Mesh FlattenScene(const Scene& scene);
// The same, taking the meshes over: a scene of one mesh shown at most once and as stored (a file
// of one mesh) becomes that mesh without a copy.
Mesh FlattenScene(Scene&& scene);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_FLATTEN_H_
