#include "hacd_orient.h"

#include <algorithm>
#include <tuple>

namespace vhacd {
namespace internal {

size_t OrientConsistently(const std::vector<Vec3>& points,
                          std::vector<std::array<uint32_t, 3>>* triangles) {
  auto& tris = *triangles;
  const uint32_t n = static_cast<uint32_t>(tris.size());
  struct Use {
    uint64_t key;
    uint32_t tri;
    bool forward;  // the triangle walks the edge from its smaller to its larger vertex
  };
  std::vector<Use> uses;
  uses.reserve(size_t{n} * 3);
  for (uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = tris[t][k], b = tris[t][(k + 1) % 3];
      uses.push_back({(uint64_t{std::min(a, b)} << 32) | std::max(a, b), t, a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return std::tie(x.key, x.tri) < std::tie(y.key, y.tri);
  });
  // Manifold neighbours: (other triangle, same direction?) per triangle.
  std::vector<std::vector<std::pair<uint32_t, bool>>> nbr(n);
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 2) {
      const bool same = uses[i].forward == uses[i + 1].forward;
      nbr[uses[i].tri].push_back({uses[i + 1].tri, same});
      nbr[uses[i + 1].tri].push_back({uses[i].tri, same});
    }
    i = j;
  }
  std::vector<int8_t> flip(n, -1);
  std::vector<uint32_t> piece, queue;
  size_t flipped = 0;
  for (uint32_t seed = 0; seed < n; ++seed) {
    if (flip[seed] >= 0) continue;
    piece.clear();
    queue.assign(1, seed);
    flip[seed] = 0;
    for (size_t q = 0; q < queue.size(); ++q) {
      const uint32_t t = queue[q];
      piece.push_back(t);
      for (const auto& [o, same] : nbr[t]) {
        if (flip[o] >= 0) continue;
        flip[o] = static_cast<int8_t>(flip[t] ^ (same ? 1 : 0));
        queue.push_back(o);
      }
    }
    auto corner = [&](uint32_t t, int k) {
      const auto& tri = tris[t];
      return points[tri[flip[t] ? 2 - k : k]];
    };
    Vec3 c = Vec3::Zero();
    for (uint32_t t : piece) c += (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0;
    c /= static_cast<double>(piece.size());
    double vol = 0.0;
    for (uint32_t t : piece)
      vol += (corner(t, 0) - c).dot((corner(t, 1) - c).cross(corner(t, 2) - c));
    const int8_t turn = vol < 0 ? 1 : 0;
    for (uint32_t t : piece) {
      if ((flip[t] ^ turn) == 0) continue;
      std::swap(tris[t][1], tris[t][2]);
      ++flipped;
    }
  }
  return flipped;
}

}  // namespace internal
}  // namespace vhacd
