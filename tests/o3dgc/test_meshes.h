// Meshes generated in code for the o3dgc tests, and round-trip comparison helpers.
#ifndef O3DGC_TESTS_TEST_MESHES_H_
#define O3DGC_TESTS_TEST_MESHES_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "common/test_shapes.h"
#include "o3dgc/o3dgc.h"

namespace o3dgc_test {

struct TestMesh {
  std::vector<float> positions;
  std::vector<uint32_t> indices;
  std::vector<float> normals;
  std::vector<float> uvs;
  std::vector<float> colors;
  std::vector<int32_t> joints;
  std::vector<uint32_t> groups;
  size_t nv() const { return positions.size() / 3; }
  size_t nt() const { return indices.size() / 3; }
  o3dgc::MeshView View(int uv_bits = 12) const {
    o3dgc::MeshView v;
    v.positions = positions.data();
    v.num_vertices = nv();
    v.indices = indices.data();
    v.num_triangles = nt();
    if (!normals.empty()) v.normals = normals.data();
    if (!uvs.empty()) {
      o3dgc::FloatAttributeView a;
      a.data = uvs.data();
      a.dimension = 2;
      a.semantic = o3dgc::Semantic::kTexCoord;
      a.bits = uv_bits;
      v.float_attributes.push_back(a);
    }
    if (!colors.empty()) {
      o3dgc::FloatAttributeView a;
      a.data = colors.data();
      a.dimension = 4;
      a.semantic = o3dgc::Semantic::kColor;
      a.bits = 10;
      v.float_attributes.push_back(a);
    }
    if (!joints.empty()) {
      o3dgc::IntAttributeView a;
      a.data = joints.data();
      a.dimension = 4;
      v.int_attributes.push_back(a);
    }
    if (!groups.empty()) v.triangle_groups = groups.data();
    return v;
  }
};

// A model built on a design grid, like a low-poly game building: nx x ny closed boxes (8
// vertices, 12 triangles each) whose corners lie on a grid of 0.7 units with heights from a
// short list, and texture coordinates on a grid of 1/8. Its residuals recur (format 1.2's
// modelled low bits).
inline TestMesh GridBlocks(int nx, int ny) {
  TestMesh t;
  const int heights[5] = {2, 3, 5, 3, 7};
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const uint32_t base = uint32_t(t.nv());
      const float x0 = 0.7f * float(3 * i), x1 = 0.7f * float(3 * i + 2);
      const float y0 = 0.7f * float(3 * j), y1 = 0.7f * float(3 * j + 2);
      const float z1 = 0.7f * float(heights[(i + 2 * j) % 5]);
      for (int c = 0; c < 8; ++c) {
        t.positions.insert(t.positions.end(),
                           {c & 1 ? x1 : x0, c & 2 ? y1 : y0, c & 4 ? z1 : 0.0f});
        t.uvs.insert(t.uvs.end(), {float(((c & 1) + (c >> 2)) % 4) / 8,
                                   float(((c >> 1) & 1) * 3 + (i + j) % 3) / 8});
      }
      const uint32_t faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                                     {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                                     {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
      for (const auto& f : faces) {
        t.indices.insert(t.indices.end(), {base + f[0], base + f[1], base + f[2]});
      }
    }
  }
  return t;
}

// (n+1) x (m+1) vertex grid in the unit square (test_shapes::Grid), z = small bump; uv = xy.
inline TestMesh Grid(int n, int m) {
  const test_shapes::Shape grid = test_shapes::Grid(n, m);
  TestMesh t;
  t.indices = grid.triangles;
  for (size_t v = 0; v < grid.vertex_count(); ++v) {
    const float x = float(grid.positions[3 * v]) / n, y = float(grid.positions[3 * v + 1]) / m;
    t.positions.insert(t.positions.end(), {x, y, 0.1f * std::sin(3 * x) * std::cos(2 * y)});
    t.uvs.insert(t.uvs.end(), {x, y});
    t.normals.insert(t.normals.end(), {0, 0, 1});
  }
  return t;
}

// Unit UV sphere with poles (closed, genus 0) and exact unit normals (test_shapes::Sphere).
inline TestMesh Sphere(int slices, int stacks) {
  TestMesh t;
  test_shapes::AppendTo(test_shapes::Sphere(1, slices, stacks), &t);
  return t;
}

// Torus (genus 1, test_shapes::Torus) with colours and joint ids.
inline TestMesh Torus(int n, int m) {
  TestMesh t;
  test_shapes::AppendTo(test_shapes::Torus(2, 0.5, n, m), &t, /*with_normals=*/false);
  for (int i = 0; i < n; ++i) {  // vertex i * m + j
    for (int j = 0; j < m; ++j) {
      t.colors.insert(t.colors.end(), {float(i) / n, float(j) / m, 0.5f, 1.0f});
      t.joints.insert(t.joints.end(), {i % 3, j % 5, 1000 + i, -7});
    }
  }
  return t;
}

// A mix of awkward cases: a fan of three triangles on one edge (non-manifold), a flipped triangle,
// a duplicated triangle (both windings), a degenerate triangle, a separate component, isolated
// vertices and a seam (two vertices at the same position).
inline TestMesh Awkward() {
  TestMesh t;
  t.positions = {0, 0, 0, 1,  0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 1, 1, 1,  // 0..5
                 5, 5, 5, 6,  5, 5, 5, 6, 5,                              // 6..8 component
                 9, 9, 9, -3, 2, 1,                                       // 9, 10 isolated
                 1, 0, 0};                                                // 11 = seam of 1
  t.indices = {0,  1, 2, 1, 0, 3, 0, 1, 4,  // three triangles on edge 0-1
               1,  2, 5, 2, 1, 5,           // same vertex set, both windings
               0,  2, 4, 0, 2, 4,           // exact duplicate
               2,  2, 5,                    // degenerate
               6,  7, 8,                    // component
               11, 5, 4};                   // uses the seam vertex
  t.uvs.resize(t.nv() * 2);
  for (size_t i = 0; i < t.nv(); ++i) {
    t.uvs[2 * i] = float(i) / 16;
    t.uvs[2 * i + 1] = 1 - float(i) / 16;
  }
  t.groups = {0, 0, 1, 1, 2, 2, 2, 3, 7, 7};
  return t;
}

// A closed CAD-like part tessellated as an STL exporter does (planar faces without inner
// vertices, welded): an nx x ny plate of 4 x 4 cells, 1 thick, each with an octagonal opening,
// a through hole or (every other cell) a pocket 0.5 deep whose floor is a fan from one vertex. The
// top face of a cell is a strip of slivers between its square and its octagon. Every coordinate is
// a multiple of 0.5 (exact on every platform).
inline TestMesh PocketPlate(int nx, int ny) {
  TestMesh t;
  std::map<std::array<float, 3>, uint32_t> ids;
  auto vertex = [&](double x, double y, double z) {
    const std::array<float, 3> key = {float(x), float(y), float(z)};
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    const uint32_t id = uint32_t(t.nv());
    t.positions.insert(t.positions.end(), key.begin(), key.end());
    ids.emplace(key, id);
    return id;
  };
  // The octagon, counter-clockwise, around a cell's centre (2, 2); p[2s], p[2s+1] face side s.
  const double oct[8][2] = {{2.5, 1}, {3, 1.5}, {3, 2.5}, {2.5, 3},
                            {1.5, 3}, {1, 2.5}, {1, 1.5}, {1.5, 1}};
  const double sq[4][2] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  std::vector<std::array<double, 6>> top;     // top-face triangles as (x, y) corners
  std::vector<std::array<double, 2>> floors;  // cell origins of the pockets
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double ox = 4.0 * i, oy = 4.0 * j;
      auto c = [&](int k) { return std::array<double, 2>{ox + sq[k & 3][0], oy + sq[k & 3][1]}; };
      auto p = [&](int k) {
        return std::array<double, 2>{ox + oct[(k + 8) % 8][0], oy + oct[(k + 8) % 8][1]};
      };
      auto tri = [&](std::array<double, 2> a, std::array<double, 2> b, std::array<double, 2> d) {
        top.push_back({a[0], a[1], b[0], b[1], d[0], d[1]});
      };
      for (int s = 0; s < 4; ++s) {
        tri(c(s + 1), p(2 * s + 1), p(2 * s));  // fan at the corner
        tri(c(s), c(s + 1), p(2 * s));          // the side
        tri(c(s), p(2 * s), p(2 * s - 1));
      }
      if ((i + j) % 2) floors.push_back({ox, oy});
    }
  }
  // Directed edges of the top face; an edge without its reverse is on a boundary (outer or hole).
  std::map<std::array<double, 4>, int> edges;
  for (const auto& x : top) {
    for (int k = 0; k < 3; ++k)
      ++edges[{x[2 * k], x[2 * k + 1], x[(2 * k + 2) % 6], x[(2 * k + 3) % 6]}];
  }
  auto in_pocket = [&](double x, double y) {
    for (const auto& f : floors) {
      if (x > f[0] && x < f[0] + 4 && y > f[1] && y < f[1] + 4) return true;
    }
    return false;
  };
  for (const auto& x : top) {
    t.indices.insert(t.indices.end(),
                     {vertex(x[0], x[1], 1), vertex(x[2], x[3], 1), vertex(x[4], x[5], 1)});
    for (int k = 0; k < 3; ++k) {
      const double ax = x[2 * k], ay = x[2 * k + 1], bx = x[(2 * k + 2) % 6],
                   by = x[(2 * k + 3) % 6];
      if (edges.count({bx, by, ax, ay})) continue;
      // A hole edge lies inside its cell; the plate's outline does not.
      const bool inner = in_pocket((ax + bx) / 2, (ay + by) / 2);
      const double z0 = inner ? 0.5 : 0;
      t.indices.insert(t.indices.end(),
                       {vertex(ax, ay, z0), vertex(bx, by, z0), vertex(bx, by, 1)});
      t.indices.insert(t.indices.end(), {vertex(ax, ay, z0), vertex(bx, by, 1), vertex(ax, ay, 1)});
    }
    // The bottom face mirrors the top, except under pockets (there a whole square, below).
    if (!in_pocket((x[0] + x[2] + x[4]) / 3, (x[1] + x[3] + x[5]) / 3)) {
      t.indices.insert(t.indices.end(),
                       {vertex(x[0], x[1], 0), vertex(x[4], x[5], 0), vertex(x[2], x[3], 0)});
    }
  }
  for (const auto& f : floors) {
    const uint32_t c0 = vertex(f[0], f[1], 0), c1 = vertex(f[0] + 4, f[1], 0),
                   c2 = vertex(f[0] + 4, f[1] + 4, 0), c3 = vertex(f[0], f[1] + 4, 0);
    t.indices.insert(t.indices.end(), {c0, c2, c1, c0, c3, c2});
    for (int k = 1; k + 1 < 8; ++k) {
      t.indices.insert(t.indices.end(), {vertex(f[0] + oct[0][0], f[1] + oct[0][1], 0.5),
                                         vertex(f[0] + oct[k][0], f[1] + oct[k][1], 0.5),
                                         vertex(f[0] + oct[k + 1][0], f[1] + oct[k + 1][1], 0.5)});
    }
  }
  return t;
}

// The meshes side by side in one mesh, each part's vertex ids after the previous part's;
// `ends` (optional) receives one past each part's last id.
inline TestMesh Concatenated(const std::vector<TestMesh>& parts,
                             std::vector<uint32_t>* ends = nullptr) {
  TestMesh t;
  for (const TestMesh& part : parts) {
    const uint32_t base = uint32_t(t.nv());
    for (size_t i = 0; i < part.positions.size(); ++i) {
      t.positions.push_back(part.positions[i] + (i % 3 == 0 ? 3.0f * float(base) : 0.0f));
    }
    for (const uint32_t v : part.indices) t.indices.push_back(base + v);
    if (ends) ends->push_back(uint32_t(t.nv()));
  }
  return t;
}

// Sorted multiset of triangles up to rotation (winding kept), over vertex positions.
inline std::vector<std::array<float, 9>> TriangleSet(const std::vector<float>& p,
                                                     const std::vector<uint32_t>& idx) {
  std::vector<std::array<float, 9>> out;
  for (size_t t = 0; t < idx.size() / 3; ++t) {
    std::array<std::array<float, 3>, 3> c;
    for (int k = 0; k < 3; ++k) {
      for (int d = 0; d < 3; ++d) c[k][d] = p[3 * size_t(idx[3 * t + k]) + d];
    }
    // Rotate so the smallest corner comes first.
    int best = 0;
    for (int k = 1; k < 3; ++k) {
      if (c[k] < c[best]) best = k;
    }
    std::array<float, 9> r;
    for (int k = 0; k < 3; ++k) {
      for (int d = 0; d < 3; ++d) r[3 * k + d] = c[(best + k) % 3][d];
    }
    out.push_back(r);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Neighbour corners of a triangle list (triangle * 3 + slot, or 0xFFFFFFFF), for a wedge table.
inline std::vector<uint32_t> OppositeCorners(const std::vector<uint32_t>& tris) {
  std::map<std::pair<uint32_t, uint32_t>, uint32_t>
      edge_corner;  // directed edge -> opposite corner
  for (uint32_t c = 0; c < tris.size(); ++c) {
    const uint32_t t = c / 3, k = c % 3;
    edge_corner[{tris[3 * t + (k + 1) % 3], tris[3 * t + (k + 2) % 3]}] = c;
  }
  std::vector<uint32_t> opposite(tris.size(), 0xFFFFFFFFu);
  for (uint32_t c = 0; c < tris.size(); ++c) {
    const uint32_t t = c / 3, k = c % 3;
    const auto it = edge_corner.find({tris[3 * t + (k + 2) % 3], tris[3 * t + (k + 1) % 3]});
    if (it != edge_corner.end()) opposite[c] = it->second;
  }
  return opposite;
}

}  // namespace o3dgc_test

#endif  // O3DGC_TESTS_TEST_MESHES_H_
