// SHA-256 (FIPS 180-4): the content hash that names cache entries.
#ifndef HULLPACK_TOOLS_BATCH_SHA256_H_
#define HULLPACK_TOOLS_BATCH_SHA256_H_

#include <cstddef>
#include <cstdint>
#include <string>

namespace hullpack {

class Sha256 {
 public:
  Sha256();
  void Update(const void* data, size_t size);
  void Update(const std::string& text) { Update(text.data(), text.size()); }
  // A length-prefixed field, so that ("ab", "c") and ("a", "bc") hash differently.
  void UpdateField(const std::string& text);
  // 64 lower-case hex digits. The object is spent afterwards.
  std::string HexDigest();

 private:
  void Block(const uint8_t* block);
  uint32_t state_[8];
  uint8_t buffer_[64];
  size_t buffered_ = 0;
  uint64_t total_bytes_ = 0;
};

// SHA-256 of `size` bytes, in hex.
std::string Sha256Hex(const void* data, size_t size);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BATCH_SHA256_H_
