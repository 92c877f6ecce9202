// A triangle as its vertex set and winding, for finding repeated triangles: the rotations of a
// triangle give the same key, its other winding the same set with `flipped` toggled.
#ifndef HULLPACK_TOOLS_MESH_TRIANGLE_KEY_H_
#define HULLPACK_TOOLS_MESH_TRIANGLE_KEY_H_

#include <algorithm>
#include <array>
#include <cstdint>

namespace hullpack {

struct TriangleKey {
  std::array<uint32_t, 3> sorted;
  bool flipped;  // the winding visits the two larger vertices in decreasing order

  // Rotated so that the smallest vertex comes first (which keeps the winding).
  static TriangleKey Of(const uint32_t v[3]) {
    const int m = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    const uint32_t next = v[(m + 1) % 3], prev = v[(m + 2) % 3];
    return {{v[m], std::min(next, prev), std::max(next, prev)}, next > prev};
  }
  bool operator<(const TriangleKey& o) const {
    return sorted != o.sorted ? sorted < o.sorted : flipped < o.flipped;
  }
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_TRIANGLE_KEY_H_
