// 7-bit packing of binary streams (see ascii_stream.h).
#include "ascii_stream.h"

#include <cstring>

namespace o3dgc {

bool IsAsciiStream(const uint8_t* data, size_t size) {
  return size >= 4 && std::memcmp(data, kAsciiMagic, 4) == 0;
}

std::vector<uint8_t> PackAscii(const std::vector<uint8_t>& binary) {
  std::vector<uint8_t> out(kAsciiMagic, kAsciiMagic + 4);
  out.reserve(4 + (binary.size() * 8 + 6) / 7);
  uint32_t acc = 0;
  int n = 0;
  for (uint8_t byte : binary) {
    acc = (acc << 8) | byte;
    n += 8;
    while (n >= 7) {
      n -= 7;
      out.push_back(uint8_t((acc >> n) & 0x7F));
    }
    acc &= (1u << n) - 1;
  }
  if (n > 0) out.push_back(uint8_t((acc << (7 - n)) & 0x7F));
  return out;
}

Status UnpackAscii(const uint8_t* data, size_t size, std::vector<uint8_t>* binary) {
  if (!IsAsciiStream(data, size)) return Status::kBadMagic;
  binary->clear();
  binary->reserve((size - 4) * 7 / 8);
  uint32_t acc = 0;
  int n = 0;
  for (size_t i = 4; i < size; ++i) {
    if (data[i] >= 128) return Status::kCorrupt;
    acc = (acc << 7) | data[i];
    n += 7;
    if (n >= 8) {
      n -= 8;
      binary->push_back(uint8_t(acc >> n));
      acc &= (1u << n) - 1;
    }
  }
  if (acc != 0) return Status::kCorrupt;
  return Status::kOk;
}

}  // namespace o3dgc
