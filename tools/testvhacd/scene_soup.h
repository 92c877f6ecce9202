// Every mesh instance of a scene in world space, as one triangle soup (what testVHACD and
// vhacd_bench decompose).
#ifndef HULLPACK_TOOLS_TESTVHACD_SCENE_SOUP_H_
#define HULLPACK_TOOLS_TESTVHACD_SCENE_SOUP_H_

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace hullpack {

inline Matrix4 MultiplyTransforms(const Matrix4& a, const Matrix4& b) {
  Matrix4 r{};
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + rr] * b[c * 4 + k];
      r[c * 4 + rr] = s;
    }
  return r;
}

// Appends every mesh instance (node transforms applied) to points (xyz) and indices; meshes no
// node instances are added untransformed.
inline void FlattenScene(const Scene& scene, std::vector<double>* points,
                         std::vector<uint32_t>* indices) {
  std::vector<Matrix4> world(scene.nodes.size(), kIdentity);
  for (size_t i = 0; i < scene.nodes.size(); ++i) {
    // Walk up to the root (bounded by the node count, in case of a malformed cycle).
    std::vector<int> chain;
    for (int n = static_cast<int>(i);
         n >= 0 && n < static_cast<int>(scene.nodes.size()) && chain.size() <= scene.nodes.size();
         n = scene.nodes[n].parent)
      chain.push_back(n);
    Matrix4 m = kIdentity;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
      m = MultiplyTransforms(m, scene.nodes[*it].local_transform);
    world[i] = m;
  }
  std::vector<int> instanced(scene.meshes.size(), 0);
  auto add = [&](const Mesh& mesh, const Matrix4& m) {
    const uint32_t base = static_cast<uint32_t>(points->size() / 3);
    for (size_t v = 0; v < mesh.vertex_count(); ++v) {
      const double x = mesh.positions[3 * v], y = mesh.positions[3 * v + 1],
                   z = mesh.positions[3 * v + 2];
      for (int r = 0; r < 3; ++r)
        points->push_back(m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r]);
    }
    for (uint32_t i : mesh.indices) indices->push_back(base + i);
  };
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    for (int mi : scene.nodes[n].meshes)
      if (mi >= 0 && mi < static_cast<int>(scene.meshes.size())) {
        add(scene.meshes[mi], world[n]);
        instanced[mi] = 1;
      }
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi)
    if (!instanced[mi]) add(scene.meshes[mi], kIdentity);
}

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_TESTVHACD_SCENE_SOUP_H_
