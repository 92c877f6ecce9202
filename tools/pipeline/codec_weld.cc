#include "pipeline/codec_weld.h"

#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace hullpack {
namespace {

template <typename T>
void AppendBytes(const std::vector<T>& values, size_t per_vertex, size_t v, std::string* key) {
  if (values.empty()) return;
  key->append(reinterpret_cast<const char*>(&values[v * per_vertex]), per_vertex * sizeof(T));
}

template <typename T>
void Compact(std::vector<T>& values, size_t per_vertex, const std::vector<uint32_t>& kept) {
  if (values.empty()) return;
  std::vector<T> out;
  out.reserve(kept.size() * per_vertex);
  for (uint32_t v : kept) {
    out.insert(out.end(), values.begin() + v * per_vertex, values.begin() + (v + 1) * per_vertex);
  }
  values = std::move(out);
}

}  // namespace

std::optional<Mesh> WeldNormalsStoredAlike(const Mesh& mesh, int normal_bits) {
  const size_t n = mesh.vertex_count();
  if (mesh.normals.size() != 3 * n || normal_bits < 1 || normal_bits > 16) return std::nullopt;
  std::unordered_map<std::string, uint32_t> first;
  first.reserve(n);
  std::vector<uint32_t> rep(n);
  bool any = false;
  std::string key;
  for (size_t v = 0; v < n; ++v) {
    key.clear();
    const uint64_t normal = o3dgc::OctahedralNormalKey(&mesh.normals[3 * v], normal_bits);
    key.append(reinterpret_cast<const char*>(&normal), sizeof(normal));
    AppendBytes(mesh.positions, 3, v, &key);
    AppendBytes(mesh.tangents, 4, v, &key);
    for (const std::vector<float>& uv : mesh.uv_sets) AppendBytes(uv, 2, v, &key);
    AppendBytes(mesh.colors, 4, v, &key);
    AppendBytes(mesh.joints, 4, v, &key);
    AppendBytes(mesh.weights, 4, v, &key);
    const auto it = first.emplace(key, uint32_t(v)).first;
    rep[v] = it->second;
    any |= rep[v] != v;
  }
  if (!any) return std::nullopt;
  std::vector<uint32_t> kept, index_of(n);
  for (size_t v = 0; v < n; ++v) {
    if (rep[v] == v) {
      index_of[v] = uint32_t(kept.size());
      kept.push_back(uint32_t(v));
    }
  }
  Mesh out = mesh;
  for (uint32_t& i : out.indices) i = index_of[rep[i]];
  Compact(out.positions, 3, kept);
  Compact(out.normals, 3, kept);
  Compact(out.tangents, 4, kept);
  for (std::vector<float>& uv : out.uv_sets) Compact(uv, 2, kept);
  Compact(out.colors, 4, kept);
  Compact(out.joints, 4, kept);
  Compact(out.weights, 4, kept);
  return out;
}

}  // namespace hullpack
