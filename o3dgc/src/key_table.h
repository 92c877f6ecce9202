// A small open-addressing hash table from three 32-bit words to an index, used by the encoder to
// weld equal positions and to find repeated triangles in linear time.
#ifndef O3DGC_SRC_KEY_TABLE_H_
#define O3DGC_SRC_KEY_TABLE_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace o3dgc {

class KeyTable {
 public:
  explicit KeyTable(size_t expected) {
    size_t cap = 16;
    while (cap < expected * 2) cap <<= 1;
    slots_.assign(cap, Slot{0, 0, 0, kEmpty});
    mask_ = cap - 1;
  }
  // Returns the value stored for the key, inserting `value` first if the key is new.
  uint32_t FindOrInsert(uint32_t a, uint32_t b, uint32_t c, uint32_t value) {
    uint64_t h = (uint64_t(a) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(b) * 0xC2B2AE3D27D4EB4Full) ^
                 (uint64_t(c) * 0x165667B19E3779F9ull);
    h ^= h >> 29;
    for (size_t i = size_t(h) & mask_;; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.value == kEmpty) {
        s = Slot{a, b, c, value};
        return value;
      }
      if (s.a == a && s.b == b && s.c == c) return s.value;
    }
  }

 private:
  static constexpr uint32_t kEmpty = 0xFFFFFFFFu;
  struct Slot {
    uint32_t a, b, c, value;
  };
  std::vector<Slot> slots_;
  size_t mask_ = 0;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_KEY_TABLE_H_
