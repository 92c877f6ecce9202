#include "mesh/subdivide.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <unordered_map>

namespace hullpack {
namespace {

struct PositionHash {
  size_t operator()(const std::array<uint32_t, 3>& p) const {
    uint64_t h = p[0] * 0x9E3779B97F4A7C15ull;
    h ^= (p[1] + 0x7F4A7C15ull) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= (p[2] + 0x27D4EB4Full) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};

}  // namespace

Mesh SubdivideMidpoint(const Mesh& mesh, int levels) {
  Mesh out;
  out.name = mesh.name;
  // Weld by bit pattern (so +0 and -0 stay apart, as a file would keep them).
  std::unordered_map<std::array<uint32_t, 3>, uint32_t, PositionHash> at;
  std::vector<uint32_t> remap(mesh.vertex_count());
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    std::array<uint32_t, 3> bits;
    std::memcpy(bits.data(), &mesh.positions[v * 3], 12);
    auto it = at.emplace(bits, static_cast<uint32_t>(out.vertex_count()));
    if (it.second)
      out.positions.insert(out.positions.end(), &mesh.positions[v * 3], &mesh.positions[v * 3] + 3);
    remap[v] = it.first->second;
  }
  out.indices.reserve(mesh.indices.size());
  for (uint32_t i : mesh.indices) out.indices.push_back(remap[i]);
  for (int level = 0; level < levels; ++level) {
    // Edge (low, high) -> midpoint vertex; edges sorted once instead of hashed.
    std::vector<std::array<uint32_t, 3>> edges;  // low, high, corner slot (triangle * 3 + k)
    edges.reserve(out.indices.size());
    for (size_t t = 0; t < out.triangle_count(); ++t) {
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = out.indices[t * 3 + k], b = out.indices[t * 3 + (k + 1) % 3];
        edges.push_back({std::min(a, b), std::max(a, b), static_cast<uint32_t>(t * 3 + k)});
      }
    }
    std::sort(edges.begin(), edges.end());
    std::vector<uint32_t> midpoint(out.indices.size());  // per corner slot: its edge's midpoint
    for (size_t e = 0; e < edges.size(); ++e) {
      if (e == 0 || edges[e][0] != edges[e - 1][0] || edges[e][1] != edges[e - 1][1]) {
        float mid[3];  // computed before the push_back that may move the array
        for (int c = 0; c < 3; ++c)
          mid[c] = 0.5f * (out.positions[size_t(edges[e][0]) * 3 + c] +
                           out.positions[size_t(edges[e][1]) * 3 + c]);
        out.positions.insert(out.positions.end(), mid, mid + 3);
      }
      midpoint[edges[e][2]] = static_cast<uint32_t>(out.vertex_count() - 1);
    }
    std::vector<uint32_t> next;
    next.reserve(out.indices.size() * 4);
    for (size_t t = 0; t < out.triangle_count(); ++t) {
      const uint32_t* v = &out.indices[t * 3];
      const uint32_t ab = midpoint[t * 3], bc = midpoint[t * 3 + 1], ca = midpoint[t * 3 + 2];
      for (uint32_t i : {v[0], ab, ca, ab, v[1], bc, ca, bc, v[2], ab, bc, ca}) next.push_back(i);
    }
    out.indices.swap(next);
  }
  return out;
}

}  // namespace hullpack
