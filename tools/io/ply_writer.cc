#include "io/ply_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace hullpack {
namespace {

template <typename T>
void Put(std::vector<uint8_t>& out,
         T value) {  // PLY binary_little_endian; this host is little-endian
  uint8_t bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

uint8_t ToByte(float v) {
  const float c = std::isfinite(v) ? std::min(1.0f, std::max(0.0f, v)) : 0.0f;
  return static_cast<uint8_t>(std::lround(c * 255.0f));
}

}  // namespace

std::vector<uint8_t> EncodePly(const Scene& scene) {
  size_t nv = 0, nf = 0;
  bool normals = !scene.meshes.empty(), uvs = normals, colors = normals;
  for (const Mesh& m : scene.meshes) {
    nv += m.vertex_count();
    nf += m.triangle_count();
    normals = normals && m.normals.size() == m.vertex_count() * 3;
    uvs = uvs && !m.uv_sets.empty() && m.uv_sets[0].size() == m.vertex_count() * 2;
    colors = colors && m.colors.size() == m.vertex_count() * 4;
  }
  std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment written by hullpack\nelement vertex " +
      std::to_string(nv) + "\nproperty float x\nproperty float y\nproperty float z\n";
  if (normals) header += "property float nx\nproperty float ny\nproperty float nz\n";
  if (uvs) header += "property float s\nproperty float t\n";
  if (colors)
    header +=
        "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n";
  header += "element face " + std::to_string(nf) +
            "\nproperty list uchar int vertex_indices\nend_header\n";
  std::vector<uint8_t> out(header.begin(), header.end());
  for (const Mesh& m : scene.meshes) {
    for (size_t i = 0; i < m.vertex_count(); ++i) {
      for (int k = 0; k < 3; ++k) Put(out, m.positions[i * 3 + k]);
      if (normals) {
        for (int k = 0; k < 3; ++k) Put(out, m.normals[i * 3 + k]);
      }
      if (uvs) {
        Put(out, m.uv_sets[0][i * 2]);
        Put(out, 1.0f - m.uv_sets[0][i * 2 + 1]);
      }
      if (colors) {
        for (int k = 0; k < 4; ++k) Put(out, ToByte(m.colors[i * 4 + k]));
      }
    }
  }
  uint32_t base = 0;
  for (const Mesh& m : scene.meshes) {
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      Put(out, static_cast<uint8_t>(3));
      for (int k = 0; k < 3; ++k) Put(out, static_cast<int32_t>(base + m.indices[t * 3 + k]));
    }
    base += static_cast<uint32_t>(m.vertex_count());
  }
  return out;
}

}  // namespace hullpack
