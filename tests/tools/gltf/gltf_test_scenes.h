// Generated scenes for the glTF tests, and an exact comparison of two scenes.
#ifndef HULLPACK_TESTS_TOOLS_GLTF_GLTF_TEST_SCENES_H_
#define HULLPACK_TESTS_TOOLS_GLTF_GLTF_TEST_SCENES_H_

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace hullpack {
namespace testing_gltf {

// A valid 1x1 RGBA PNG (70 bytes).
const std::vector<uint8_t>& TinyPng();

// A grid of (nx+1) x (ny+1) vertices in the z=0 plane with unit normals, tangents, `uv_sets` UV
// sets and RGBA colours; 2*nx*ny triangles.
Mesh MakeGrid(int nx, int ny, int uv_sets, float z);

// Everything the writer supports at once: 3 meshes (skinned with two morph targets + two materials
// with non-decreasing material ids, 2 UV sets, colours; a non-colliding mesh; a plain one), 2
// materials with textures, an embedded PNG and an external image, a skin with inverse bind
// matrices, and a node hierarchy with transforms and a node holding two meshes.
Scene MakeRichScene();

// One mesh with more than 65535 vertices.
Scene MakeLargeScene();

// Compares every field; float arrays must match bit for bit.
void ExpectScenesEqual(const Scene& expected, const Scene& actual);

}  // namespace testing_gltf
}  // namespace hullpack

#endif  // HULLPACK_TESTS_TOOLS_GLTF_GLTF_TEST_SCENES_H_
