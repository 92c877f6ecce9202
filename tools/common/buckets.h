// Grouping ids by a small integer key (a counting sort): the mesh stages find duplicate triangles,
// edges and fans among the few entries that share a point, and the OBJ reader orders the corners
// of a position, at 4 bytes per entry, instead of in one sort of every entry's whole key.
#ifndef HULLPACK_TOOLS_COMMON_BUCKETS_H_
#define HULLPACK_TOOLS_COMMON_BUCKETS_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hullpack {

// A key_of result that leaves the id out.
constexpr uint32_t kNoBucket = UINT32_MAX;

// Group k is ids[start[k], start[k + 1]), its ids ascending.
struct Buckets {
  std::vector<uint32_t> start, ids;
};

// The ids 0..n-1 grouped by key_of(id), a key below key_count or kNoBucket.
template <typename KeyOf>
Buckets BucketBy(size_t n, size_t key_count, KeyOf key_of) {
  Buckets b;
  b.start.assign(key_count + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t k = key_of(i);
    if (k != kNoBucket) ++b.start[size_t(k) + 1];
  }
  for (size_t k = 0; k < key_count; ++k) b.start[k + 1] += b.start[k];
  b.ids.resize(b.start[key_count]);
  std::vector<uint32_t> fill(b.start.begin(), b.start.end() - 1);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t k = key_of(i);
    if (k != kNoBucket) b.ids[fill[k]++] = static_cast<uint32_t>(i);
  }
  return b;
}

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_BUCKETS_H_
