#include "io/obj_writer.h"

#include "io/text_writer.h"

namespace hullpack {

std::string EncodeObj(const Scene& scene) {
  TextWriter w;
  w << "# written by hullpack\n";
  uint64_t base = 1;  // OBJ indices are global and 1-based
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    const Mesh& m = scene.meshes[mi];
    w << "o " << (m.name.empty() ? "mesh_" + std::to_string(mi) : m.name) << '\n';
    const size_t n = m.vertex_count();
    const bool colors = m.colors.size() == n * 4 && n > 0;
    const bool uvs = !m.uv_sets.empty() && m.uv_sets[0].size() == n * 2 && n > 0;
    const bool normals = m.normals.size() == n * 3 && n > 0;
    for (size_t i = 0; i < n; ++i) {
      w << "v " << m.positions[i * 3] << ' ' << m.positions[i * 3 + 1] << ' '
        << m.positions[i * 3 + 2];
      if (colors)
        w << ' ' << m.colors[i * 4] << ' ' << m.colors[i * 4 + 1] << ' ' << m.colors[i * 4 + 2];
      w << '\n';
    }
    if (uvs) {
      for (size_t i = 0; i < n; ++i)
        w << "vt " << m.uv_sets[0][i * 2] << ' ' << (1.0f - m.uv_sets[0][i * 2 + 1]) << '\n';
    }
    if (normals) {
      for (size_t i = 0; i < n; ++i) {
        w << "vn " << m.normals[i * 3] << ' ' << m.normals[i * 3 + 1] << ' ' << m.normals[i * 3 + 2]
          << '\n';
      }
    }
    const bool materials = m.material_ids.size() == m.triangle_count();
    uint32_t current = 0xFFFFFFFFu;
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      if (materials && m.material_ids[t] != current) {
        current = m.material_ids[t];
        w << "usemtl "
          << (current < scene.materials.size() && !scene.materials[current].name.empty()
                  ? scene.materials[current].name
                  : "material_" + std::to_string(current))
          << '\n';
      }
      w << 'f';
      for (int k = 0; k < 3; ++k) {
        const uint64_t i = base + m.indices[t * 3 + k];
        w << ' ' << i;
        if (uvs || normals) {
          w << '/';
          if (uvs) w << i;
          if (normals) w << '/' << i;
        }
      }
      w << '\n';
    }
    base += n;
  }
  return std::move(w.str());
}

}  // namespace hullpack
