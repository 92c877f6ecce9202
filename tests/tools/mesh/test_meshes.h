// Small generated meshes with known topology, shared by the mesh tests.
#ifndef HULLPACK_TESTS_TOOLS_MESH_TEST_MESHES_H_
#define HULLPACK_TESTS_TOOLS_MESH_TEST_MESHES_H_

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <utility>

#include "common/test_shapes.h"
#include "scene/scene.h"

namespace hullpack {
namespace testing_meshes {

inline uint32_t AddVertex(Mesh& mesh, float x, float y, float z) {
  mesh.positions.insert(mesh.positions.end(), {x, y, z});
  return static_cast<uint32_t>(mesh.vertex_count() - 1);
}

inline void AddTriangle(Mesh& mesh, uint32_t a, uint32_t b, uint32_t c) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// Counter-clockwise quad a-b-c-d as two triangles sharing the a-c diagonal.
inline void AddQuad(Mesh& mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  AddTriangle(mesh, a, b, c);
  AddTriangle(mesh, a, c, d);
}

// The six faces of the unit cube as corner ids (x + 2y + 4z), counter-clockwise seen from
// outside; the last one is the top (z = 1).
constexpr uint32_t kCubeFaces[6][4] = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3},
                                       {0, 4, 6, 2}, {1, 3, 7, 5}, {4, 5, 7, 6}};

// Axis-aligned cube with 8 shared vertices and outward winding (test_shapes::Box); `faces` 5
// leaves the top out (a box open at the top).
inline void AddCube(Mesh& mesh, float x0, float y0, float z0, float size = 1, int faces = 6) {
  test_shapes::AppendTo(
      test_shapes::Box(x0, y0, z0, x0 + size, y0 + size, z0 + size, /*with_top=*/faces == 6),
      &mesh);
}

inline Mesh UnitCube() {
  Mesh mesh;
  AddCube(mesh, 0, 0, 0);
  return mesh;
}

// The unit cube with its own 4 vertices per face, as a file split at normal seams stores it:
// closed by position, six separate squares by index.
inline Mesh SplitCube() {
  Mesh mesh;
  for (const auto& q : kCubeFaces) {
    uint32_t v[4];
    for (int k = 0; k < 4; ++k) {
      v[k] = AddVertex(mesh, static_cast<float>(q[k] & 1), static_cast<float>((q[k] >> 1) & 1),
                       static_cast<float>((q[k] >> 2) & 1));
    }
    AddQuad(mesh, v[0], v[1], v[2], v[3]);
  }
  return mesh;
}

// Ring torus around the z axis (major radius R, minor r), outward winding, genus 1
// (test_shapes::Torus).
inline void AddTorus(Mesh& mesh, float cx, float R, float r, int rings = 48, int sides = 24) {
  test_shapes::AppendTo(test_shapes::Torus(R, r, rings, sides, cx), &mesh, /*with_normals=*/false);
}

// Each directed edge of a closed mesh appears once, and its reverse once.
inline bool IsClosed(const Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) ++edges[{m.indices[t * 3 + k], m.indices[t * 3 + (k + 1) % 3]}];
  for (const auto& [e, count] : edges) {
    auto reverse = edges.find({e.second, e.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) return false;
  }
  return true;
}

// Signed volume (positive when the triangles face outwards).
inline double SignedVolume(const Mesh& m) {
  double v = 0;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const float* a = &m.positions[m.indices[t * 3] * 3];
    const float* b = &m.positions[m.indices[t * 3 + 1] * 3];
    const float* c = &m.positions[m.indices[t * 3 + 2] * 3];
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
          a[2] * (b[0] * c[1] - b[1] * c[0])) /
         6.0;
  }
  return v;
}

}  // namespace testing_meshes
}  // namespace hullpack

#endif  // HULLPACK_TESTS_TOOLS_MESH_TEST_MESHES_H_
