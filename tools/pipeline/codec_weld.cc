#include "pipeline/codec_weld.h"

#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace hullpack {
namespace {

// The bytes of vertex `v` in `values` (`per_vertex` values each), or none when empty.
template <typename T>
std::pair<const char*, size_t> BytesOf(const std::vector<T>& values, size_t per_vertex, size_t v) {
  if (values.empty()) return {nullptr, 0};
  return {reinterpret_cast<const char*>(&values[v * per_vertex]), per_vertex * sizeof(T)};
}

// Every attribute of vertex `v` but its normal, as byte ranges.
std::vector<std::pair<const char*, size_t>> AttributesOf(const Mesh& m, size_t v) {
  std::vector<std::pair<const char*, size_t>> out = {BytesOf(m.positions, 3, v),
                                                     BytesOf(m.tangents, 4, v)};
  for (const std::vector<float>& uv : m.uv_sets) out.push_back(BytesOf(uv, 2, v));
  out.push_back(BytesOf(m.colors, 4, v));
  out.push_back(BytesOf(m.joints, 4, v));
  out.push_back(BytesOf(m.weights, 4, v));
  for (const MorphTarget& t : m.morph_targets) {
    out.push_back(BytesOf(t.positions, 3, v));
    out.push_back(BytesOf(t.normals, 3, v));
  }
  return out;
}

uint64_t Mix(uint64_t h, const char* data, size_t size) {
  for (size_t i = 0; i < size; ++i) h = (h ^ uint8_t(data[i])) * 0x100000001b3ull;
  return h;
}

bool SameAttributes(const Mesh& m, size_t a, size_t b) {
  const auto x = AttributesOf(m, a), y = AttributesOf(m, b);
  for (size_t i = 0; i < x.size(); ++i) {
    if (x[i].second && std::memcmp(x[i].first, y[i].first, x[i].second) != 0) return false;
  }
  return true;
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
  // Vertices sorted by a hash of their normal key and other attributes; within a run of equal
  // hashes each takes the first (smallest) vertex that is equal in full.
  std::vector<uint64_t> normal_key(n);
  std::vector<std::pair<uint64_t, uint32_t>> order(n);
  for (size_t v = 0; v < n; ++v) {
    normal_key[v] = o3dgc::OctahedralNormalKey(&mesh.normals[3 * v], normal_bits);
    uint64_t h = Mix(0xcbf29ce484222325ull, reinterpret_cast<const char*>(&normal_key[v]), 8);
    for (const auto& bytes : AttributesOf(mesh, v)) h = Mix(h, bytes.first, bytes.second);
    order[v] = {h, uint32_t(v)};
  }
  std::sort(order.begin(), order.end());
  std::vector<uint32_t> rep(n);
  bool any = false;
  for (size_t i = 0; i < n;) {
    size_t j = i;
    while (j < n && order[j].first == order[i].first) ++j;
    for (size_t a = i; a < j; ++a) {
      const uint32_t v = order[a].second;
      rep[v] = v;
      for (size_t b = i; b < a; ++b) {
        const uint32_t u = order[b].second;
        if (rep[u] == u && normal_key[u] == normal_key[v] && SameAttributes(mesh, u, v)) {
          rep[v] = u;
          break;
        }
      }
      any |= rep[v] != v;
    }
    i = j;
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
  for (MorphTarget& t : out.morph_targets) {
    Compact(t.positions, 3, kept);
    Compact(t.normals, 3, kept);
  }
  return out;
}

}  // namespace hullpack
