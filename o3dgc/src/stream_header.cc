// Stream header and CRC32 (see stream_header.h).
#include "stream_header.h"

#include <cstring>

namespace o3dgc {
namespace {

// Slicing by 8: table t[k][b] is the CRC of byte b followed by k zero bytes, so eight bytes take
// eight independent lookups. Built on first use rather than at compile time: 8 KB of CRC values
// do not compress, and the WebAssembly decoder's download would carry them. The constructor is
// deliberately not constexpr: a constant-evaluable initializer would be folded back into data.
struct CrcTables {
  uint32_t t[8][256];
  CrcTables() {
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[0][i] = c;
    }
    for (uint32_t i = 0; i < 256; ++i) {
      for (int k = 1; k < 8; ++k) t[k][i] = t[0][t[k - 1][i] & 0xFF] ^ (t[k - 1][i] >> 8);
    }
  }
};

const CrcTables& Tables() {
  static const CrcTables tables;  // initialised once, thread-safely (C++11 function-local static)
  return tables;
}

}  // namespace

uint32_t Crc32(const uint8_t* data, size_t size, uint32_t crc) {
  const auto& t = Tables().t;
  crc = ~crc;
  size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    const uint32_t lo = crc ^ (uint32_t(data[i]) | uint32_t(data[i + 1]) << 8 |
                               uint32_t(data[i + 2]) << 16 | uint32_t(data[i + 3]) << 24);
    const uint32_t hi = uint32_t(data[i + 4]) | uint32_t(data[i + 5]) << 8 |
                        uint32_t(data[i + 6]) << 16 | uint32_t(data[i + 7]) << 24;
    crc = t[7][lo & 0xFF] ^ t[6][(lo >> 8) & 0xFF] ^ t[5][(lo >> 16) & 0xFF] ^ t[4][lo >> 24] ^
          t[3][hi & 0xFF] ^ t[2][(hi >> 8) & 0xFF] ^ t[1][(hi >> 16) & 0xFF] ^ t[0][hi >> 24];
  }
  for (; i < size; ++i) crc = t[0][(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

void WriteHeader(bool keep_order, bool fast_decode, bool low_bits, bool all_adaptive,
                 size_t payload_size, std::vector<uint8_t>* out) {
  out->insert(out->end(), kMagic, kMagic + 4);
  out->push_back(uint8_t(kFormatMajor));
  out->push_back(uint8_t(WrittenMinor(low_bits, all_adaptive)));
  out->push_back(uint8_t((keep_order ? 1 : 0) | (fast_decode ? 2 : 0) | (low_bits ? 4 : 0) |
                         (all_adaptive ? 8 : 0)));
  for (size_t i = 0; i < kCrcSize; ++i) out->push_back(0);
  uint64_t v = payload_size;
  do {
    uint8_t byte = uint8_t(v & 0x7F);
    v >>= 7;
    if (v) byte |= 0x80;
    out->push_back(byte);
  } while (v);
}

uint32_t StreamCrc(const uint8_t* data, size_t size) {
  const size_t after = kCrcOffset + kCrcSize;
  return Crc32(data + after, size - after, Crc32(data, kCrcOffset));
}

void FinalizeCrc(std::vector<uint8_t>* stream) {
  const uint32_t crc = StreamCrc(stream->data(), stream->size());
  for (size_t i = 0; i < 4; ++i) (*stream)[kCrcOffset + i] = uint8_t(crc >> (8 * i));
}

Status ParseHeader(const uint8_t* data, size_t size, StreamHeader* header) {
  if (size < 4 || std::memcmp(data, kMagic, 4) != 0) return Status::kBadMagic;
  if (size < kCrcOffset + kCrcSize + 1) return Status::kTruncated;
  header->major = data[kVersionOffset];
  header->minor = data[kVersionOffset + 1];
  if (header->major != kFormatMajor || header->minor > kFormatMinor) return Status::kBadVersion;
  const uint8_t flags = data[kFlagsOffset];
  const unsigned known =
      header->minor >= kAllAdaptiveMinor ? 15u : (header->minor >= kLowBitsMinor ? 7u : 3u);
  if (flags & ~known) return Status::kCorrupt;
  header->keep_order = (flags & 1) != 0;
  header->fast_decode = (flags & 2) != 0;
  header->low_bits = (flags & 4) != 0;
  header->all_adaptive = (flags & 8) != 0;
  const uint8_t* c = data + kCrcOffset;
  header->crc = uint32_t(c[0]) | uint32_t(c[1]) << 8 | uint32_t(c[2]) << 16 | uint32_t(c[3]) << 24;
  uint64_t v = 0;
  size_t pos = kCrcOffset + kCrcSize;
  for (int i = 0;; ++i) {
    if (pos >= size) return Status::kTruncated;
    if (i >= 5) return Status::kCorrupt;
    const uint8_t byte = data[pos++];
    v |= uint64_t(byte & 0x7F) << (7 * i);
    if (!(byte & 0x80)) break;
  }
  header->payload_offset = pos;
  if (v > size - pos) return Status::kTruncated;
  if (v < size - pos) return Status::kCorrupt;
  header->payload_size = size_t(v);
  return Status::kOk;
}

}  // namespace o3dgc
