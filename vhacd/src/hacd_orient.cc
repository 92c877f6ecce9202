#include "hacd_orient.h"

#include <algorithm>
#include <array>
#include <tuple>

namespace vhacd {
namespace internal {

size_t OrientConsistently(const std::vector<Vec3>& points,
                          std::vector<std::array<uint32_t, 3>>* triangles) {
  auto& tris = *triangles;
  const uint32_t n = static_cast<uint32_t>(tris.size());
  // Edge uses bucketed by their smaller vertex, each bucket sorted by (larger vertex, triangle):
  // the order of one global sort by (edge, triangle), without sorting 3n entries at once.
  struct Use {
    uint32_t other, tri;
    bool forward;  // the triangle walks the edge from its smaller to its larger vertex
  };
  const size_t nv = points.size();
  std::vector<uint32_t> first(nv + 1, 0);
  for (const auto& tri : tris)
    for (int k = 0; k < 3; ++k) ++first[std::min(tri[k], tri[(k + 1) % 3]) + 1];
  for (size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<Use> uses(first[nv]);
  {
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    for (uint32_t t = 0; t < n; ++t)
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = tris[t][k], b = tris[t][(k + 1) % 3];
        uses[fill[std::min(a, b)]++] = {std::max(a, b), t, a < b};
      }
  }
  // Manifold neighbours (other triangle, same direction?), at most one per edge of a triangle.
  struct Neighbours {
    std::array<std::pair<uint32_t, bool>, 3> of;
    uint8_t count = 0;
  };
  std::vector<Neighbours> nbr(n);
  for (size_t v = 0; v < nv; ++v) {
    const auto begin = uses.begin() + first[v], end = uses.begin() + first[v + 1];
    std::sort(begin, end, [](const Use& x, const Use& y) {
      return std::tie(x.other, x.tri) < std::tie(y.other, y.tri);
    });
    for (auto i = begin; i != end;) {
      auto j = i;
      while (j != end && j->other == i->other) ++j;
      if (j - i == 2) {
        const bool same = i[0].forward == i[1].forward;
        Neighbours& x = nbr[i[0].tri];
        Neighbours& y = nbr[i[1].tri];
        if (x.count < 3) x.of[x.count++] = {i[1].tri, same};
        if (y.count < 3) y.of[y.count++] = {i[0].tri, same};
      }
      i = j;
    }
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
      for (uint8_t k = 0; k < nbr[t].count; ++k) {
        const auto [o, same] = nbr[t].of[k];
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
