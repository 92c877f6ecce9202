#include "mesh/merge.h"

namespace hullpack {

Mesh MergeMeshes(const Scene& scene) {
  Mesh all;
  bool normals = !scene.meshes.empty(), uvs = normals, colors = normals, skin = normals,
       materials = false;
  for (const Mesh& m : scene.meshes) {
    normals = normals && !m.normals.empty();
    uvs = uvs && !m.uv_sets.empty();
    colors = colors && !m.colors.empty();
    skin = skin && m.has_skin();
    materials = materials || !m.material_ids.empty();
  }
  all.uv_sets.resize(uvs ? 1 : 0);
  for (const Mesh& m : scene.meshes) {
    const uint32_t base = uint32_t(all.vertex_count());
    all.positions.insert(all.positions.end(), m.positions.begin(), m.positions.end());
    for (uint32_t i : m.indices) all.indices.push_back(base + i);
    if (normals) all.normals.insert(all.normals.end(), m.normals.begin(), m.normals.end());
    if (uvs) all.uv_sets[0].insert(all.uv_sets[0].end(), m.uv_sets[0].begin(), m.uv_sets[0].end());
    if (colors) all.colors.insert(all.colors.end(), m.colors.begin(), m.colors.end());
    if (skin) {
      all.joints.insert(all.joints.end(), m.joints.begin(), m.joints.end());
      all.weights.insert(all.weights.end(), m.weights.begin(), m.weights.end());
    }
    if (materials) {
      for (size_t t = 0; t < m.triangle_count(); ++t) {
        all.material_ids.push_back(m.material_ids.empty() ? 0 : m.material_ids[t]);
      }
    }
  }
  return all;
}

}  // namespace hullpack
