// Shapes generated in code for every test suite (no data files): a torus, a box, a UV sphere and a
// grid, in double precision with documented vertex and triangle order, so that a test can derive
// its own attributes (UVs, colours, joints) from a vertex's place in the shape. Plain arrays in,
// nothing else needed: the vhacd and o3dgc tests use them as well as the tools tests.
#ifndef HULLPACK_TESTS_COMMON_TEST_SHAPES_H_
#define HULLPACK_TESTS_COMMON_TEST_SHAPES_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace test_shapes {

struct Shape {
  std::vector<double> positions;    // xyz per vertex
  std::vector<double> normals;      // unit xyz per vertex; empty when the shape defines none
  std::vector<uint32_t> triangles;  // 3 per triangle, counter-clockwise seen from outside

  size_t vertex_count() const { return positions.size() / 3; }
  size_t triangle_count() const { return triangles.size() / 3; }
};

// Ring torus around the z axis, centred at (cx, 0, 0): vertex i * sides + j is at ring angle
// 2 pi i / rings and tube angle 2 pi j / sides, with its unit normal. Quad (i, j) is the triangles
// (a, b, c), (a, c, d) with a = (i, j), b = (i + 1, j), c = (i + 1, j + 1), d = (i, j + 1).
// Closed, manifold, genus 1.
Shape Torus(double major, double minor, int rings, int sides, double cx = 0);

// Axis-aligned box: corner k (0..7) has x from bit 0, y from bit 1, z from bit 2. The faces, each
// two triangles sharing the diagonal from its first corner, come in the order -z, +z, -y, +y, -x,
// +x; `with_top` false leaves the +z face out (an open box). No normals (the corners are shared).
Shape Box(double x0, double y0, double z0, double x1, double y1, double z1, bool with_top = true);

// UV sphere around the origin: vertex 0 is the south pole (0, 0, -radius), then stacks - 1 rings
// of `slices` vertices from south to north (ring r, vertex s at polar angle pi r / stacks from the
// south, azimuth 2 pi s / slices), then the north pole. Per slice the south cap triangle, then the
// north one; then the quads ring by ring. `skip(row, slice)`, when given, leaves out the triangles
// of row 1..stacks (row 1 the south cap, row `stacks` the north cap) at that slice: an open scan.
// Unit normals. Closed (without skip), genus 0.
Shape Sphere(double radius, int slices, int stacks,
             const std::function<bool(int row, int slice)>& skip = nullptr);

// Flat grid of (nx + 1) x (ny + 1) vertices at integer coordinates: vertex y * (nx + 1) + x is at
// (x, y, 0). Cell (x, y) is the triangles (a, b, d), (a, d, c) with a = (x, y), b = (x + 1, y),
// c = (x, y + 1), d = (x + 1, y + 1). Normals (0, 0, 1). Open (one boundary loop), genus 0.
Shape Grid(int nx, int ny);

// Appends `shape` to a mesh with float `positions`, `normals` and uint32 `indices` members (the
// project's hullpack::Mesh, the o3dgc tests' TestMesh), offsetting its indices; its normals too
// when `with_normals` and the shape has them.
template <typename FloatMesh>
void AppendTo(const Shape& shape, FloatMesh* mesh, bool with_normals = true) {
  const uint32_t base = static_cast<uint32_t>(mesh->positions.size() / 3);
  for (double v : shape.positions) mesh->positions.push_back(static_cast<float>(v));
  if (with_normals) {
    for (double v : shape.normals) mesh->normals.push_back(static_cast<float>(v));
  }
  for (uint32_t i : shape.triangles) mesh->indices.push_back(base + i);
}

// The same for a mesh with double `points` and uint32 `indices` (the vhacd tests' Mesh, the
// stability cases' Soup).
template <typename DoubleMesh>
void AppendPointsTo(const Shape& shape, DoubleMesh* mesh) {
  const uint32_t base = static_cast<uint32_t>(mesh->points.size() / 3);
  mesh->points.insert(mesh->points.end(), shape.positions.begin(), shape.positions.end());
  for (uint32_t i : shape.triangles) mesh->indices.push_back(base + i);
}

}  // namespace test_shapes

#endif  // HULLPACK_TESTS_COMMON_TEST_SHAPES_H_
