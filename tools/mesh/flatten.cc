#include "mesh/flatten.h"

#include <cmath>
#include <utility>

namespace hullpack {
namespace {

Matrix4 Multiply(const Matrix4& a, const Matrix4& b) {
  Matrix4 r{};
  for (int c = 0; c < 4; ++c) {
    for (int row = 0; row < 4; ++row) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[c * 4 + k];
      r[c * 4 + row] = s;
    }
  }
  return r;
}

struct Instance {
  const Mesh* mesh;
  const Matrix4* transform;  // null: as stored
};

// Appends `m` transformed by `t` (null: identity) to `all`.
void Append(const Mesh& m, const Matrix4* t, bool normals, bool uvs, bool colors, bool skin,
            bool materials, Mesh& all) {
  const uint32_t base = static_cast<uint32_t>(all.vertex_count());
  const size_t n = m.vertex_count();
  // Linear part L (row r, column c = t[c * 4 + r]), its cofactor matrix (the inverse transpose
  // up to the determinant's factor) for normals, and the determinant's sign for the winding.
  double l[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, cof[3][3], det = 1;
  if (t) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) l[r][c] = (*t)[c * 4 + r];
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
        cof[r][c] = l[r1][c1] * l[r2][c2] - l[r1][c2] * l[r2][c1];
      }
    }
    det = l[0][0] * cof[0][0] + l[0][1] * cof[0][1] + l[0][2] * cof[0][2];
  }
  const bool mirrored = det < 0;
  auto unit = [](double v[3]) {
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0 && std::isfinite(len))
      for (int k = 0; k < 3; ++k) v[k] /= len;
  };
  for (size_t v = 0; v < n; ++v) {
    const float* p = &m.positions[v * 3];
    for (int r = 0; r < 3; ++r) {
      all.positions.push_back(
          t ? static_cast<float>(l[r][0] * p[0] + l[r][1] * p[1] + l[r][2] * p[2] + (*t)[12 + r])
            : p[r]);
    }
    if (normals) {
      const float* q = &m.normals[v * 3];
      double w[3] = {q[0], q[1], q[2]};
      if (t) {
        for (int r = 0; r < 3; ++r)
          w[r] = (cof[r][0] * q[0] + cof[r][1] * q[1] + cof[r][2] * q[2]) * (mirrored ? -1 : 1);
        unit(w);
      }
      for (int k = 0; k < 3; ++k) all.normals.push_back(static_cast<float>(w[k]));
    }
  }
  for (size_t tri = 0; tri < m.triangle_count(); ++tri) {
    const uint32_t* c = &m.indices[tri * 3];
    all.indices.push_back(base + c[0]);
    all.indices.push_back(base + (mirrored ? c[2] : c[1]));
    all.indices.push_back(base + (mirrored ? c[1] : c[2]));
  }
  if (uvs) all.uv_sets[0].insert(all.uv_sets[0].end(), m.uv_sets[0].begin(), m.uv_sets[0].end());
  if (colors) all.colors.insert(all.colors.end(), m.colors.begin(), m.colors.end());
  if (skin) {
    all.joints.insert(all.joints.end(), m.joints.begin(), m.joints.end());
    all.weights.insert(all.weights.end(), m.weights.begin(), m.weights.end());
  }
  if (materials) {
    for (size_t tri = 0; tri < m.triangle_count(); ++tri)
      all.material_ids.push_back(m.material_ids.empty() ? 0 : m.material_ids[tri]);
  }
}

}  // namespace

std::vector<Matrix4> WorldTransforms(const Scene& scene) {
  const size_t n = scene.nodes.size();
  std::vector<Matrix4> world(n, kIdentity);
  for (size_t i = 0; i < n; ++i) {
    std::vector<int> chain;  // this node, its parent, ... up to a root
    for (int k = static_cast<int>(i); k >= 0 && static_cast<size_t>(k) < n && chain.size() <= n;
         k = scene.nodes[k].parent)
      chain.push_back(k);
    Matrix4 m = kIdentity;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
      m = Multiply(m, scene.nodes[*it].local_transform);
    world[i] = m;
  }
  return world;
}

Mesh FlattenScene(Scene&& scene) {
  if (scene.meshes.size() != 1) return FlattenScene(static_cast<const Scene&>(scene));
  const std::vector<Matrix4> world = WorldTransforms(scene);
  int shown = 0;
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    for (int m : scene.nodes[n].meshes) {
      if (m != 0) continue;
      if (++shown > 1 || !(world[n] == kIdentity))
        return FlattenScene(static_cast<const Scene&>(scene));
    }
  }
  // What Append keeps of one untransformed instance.
  Mesh all = std::move(scene.meshes[0]);
  all.name.clear();
  all.tangents.clear();
  if (all.uv_sets.size() > 1) all.uv_sets.resize(1);
  if (!all.has_skin()) {
    all.joints.clear();
    all.weights.clear();
  }
  all.morph_targets.clear();
  all.morph_weights.clear();
  all.collides = true;
  return all;
}

Mesh FlattenScene(const Scene& scene) {
  const std::vector<Matrix4> world = WorldTransforms(scene);
  std::vector<Instance> instances;
  std::vector<char> shown(scene.meshes.size(), 0);
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    for (int m : scene.nodes[n].meshes) {
      if (m < 0 || static_cast<size_t>(m) >= scene.meshes.size()) continue;
      const bool identity = world[n] == kIdentity;
      instances.push_back({&scene.meshes[m], identity ? nullptr : &world[n]});
      shown[m] = 1;
    }
  }
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (!shown[m]) instances.push_back({&scene.meshes[m], nullptr});

  Mesh all;
  bool normals = !instances.empty(), uvs = normals, colors = normals, skin = normals,
       materials = false;
  for (const Instance& i : instances) {
    const Mesh& m = *i.mesh;
    normals = normals && !m.normals.empty();
    uvs = uvs && !m.uv_sets.empty();
    colors = colors && !m.colors.empty();
    skin = skin && m.has_skin();
    materials = materials || !m.material_ids.empty();
  }
  all.uv_sets.resize(uvs ? 1 : 0);
  for (const Instance& i : instances)
    Append(*i.mesh, i.transform, normals, uvs, colors, skin, materials, all);
  return all;
}

}  // namespace hullpack
