// An open-addressing hash table of entries keyed by 12 bytes (three 32-bit words), used by the
// encoder to weld equal positions in linear time. The keys stay in the caller's array; a slot keeps
// a 32-bit hash tag and the entry's index (8 bytes: half of a slot holding the key, so that large
// meshes touch half the memory), and keys are compared only when the tags match.
#ifndef O3DGC_SRC_KEY_TABLE_H_
#define O3DGC_SRC_KEY_TABLE_H_

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace o3dgc {

class KeyTable {
 public:
  // `keys`: 12 bytes per entry; at most `expected` entries are inserted.
  KeyTable(const void* keys, size_t expected) : keys_(static_cast<const uint8_t*>(keys)) {
    size_t cap = 16;
    while (cap < expected * 2) cap <<= 1;
    slots_.assign(cap, Slot{0, kEmpty});
    mask_ = cap - 1;
  }
  // The first inserted entry whose key equals entry i's; inserts i (and returns it) if none does.
  uint32_t FindOrInsert(uint32_t i) {
    const uint8_t* key = keys_ + 12 * size_t(i);
    uint32_t k[3];
    std::memcpy(k, key, 12);
    uint64_t h = (uint64_t(k[0]) * 0x9E3779B97F4A7C15ull) ^
                 (uint64_t(k[1]) * 0xC2B2AE3D27D4EB4Full) ^
                 (uint64_t(k[2]) * 0x165667B19E3779F9ull);
    h ^= h >> 29;
    const uint32_t tag = uint32_t(h >> 32);
    for (size_t j = size_t(h) & mask_;; j = (j + 1) & mask_) {
      Slot& s = slots_[j];
      if (s.index == kEmpty) {
        s = Slot{tag, i};
        return i;
      }
      if (s.tag == tag && std::memcmp(keys_ + 12 * size_t(s.index), key, 12) == 0) return s.index;
    }
  }

 private:
  static constexpr uint32_t kEmpty = 0xFFFFFFFFu;
  struct Slot {
    uint32_t tag, index;
  };
  const uint8_t* keys_;
  std::vector<Slot> slots_;
  size_t mask_ = 0;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_KEY_TABLE_H_
