// Small generated meshes with known topology, shared by the mesh tests.
#ifndef HULLPACK_TESTS_TOOLS_MESH_TEST_MESHES_H_
#define HULLPACK_TESTS_TOOLS_MESH_TEST_MESHES_H_

#include <cmath>
#include <cstdint>
#include <initializer_list>

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

// Axis-aligned cube with 8 shared vertices and outward winding; `faces` < 6 leaves the last
// faces out (5 = a box open at the top).
inline void AddCube(Mesh& mesh, float x0, float y0, float z0, float size = 1, int faces = 6) {
  const uint32_t base = static_cast<uint32_t>(mesh.vertex_count());
  for (uint32_t id = 0; id < 8; ++id) {
    AddVertex(mesh, x0 + size * (id & 1), y0 + size * ((id >> 1) & 1), z0 + size * ((id >> 2) & 1));
  }
  for (int f = 0; f < faces; ++f) {
    const uint32_t* q = kCubeFaces[f];
    AddQuad(mesh, base + q[0], base + q[1], base + q[2], base + q[3]);
  }
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

// Ring torus around the z axis (major radius R, minor r), outward winding, genus 1.
inline void AddTorus(Mesh& mesh, float cx, float R, float r, int rings = 48, int sides = 24) {
  const double kPi = 3.14159265358979323846;
  const uint32_t base = static_cast<uint32_t>(mesh.vertex_count());
  for (int i = 0; i < rings; ++i) {
    const double u = 2 * kPi * i / rings;
    for (int j = 0; j < sides; ++j) {
      const double v = 2 * kPi * j / sides;
      const double d = R + r * std::cos(v);
      AddVertex(mesh, static_cast<float>(cx + d * std::cos(u)), static_cast<float>(d * std::sin(u)),
                static_cast<float>(r * std::sin(v)));
    }
  }
  auto at = [&](int i, int j) {
    return base + static_cast<uint32_t>((i % rings) * sides + (j % sides));
  };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j)
      AddQuad(mesh, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  }
}

}  // namespace testing_meshes
}  // namespace hullpack

#endif  // HULLPACK_TESTS_TOOLS_MESH_TEST_MESHES_H_
