// The byte header of an o3dgc stream and its checksum.
//
// Binary stream layout:
//   bytes 0..3   magic "O3DG"
//   byte  4      format major version (kFormatMajor)
//   byte  5      format minor version (kFormatMinor)
//   byte  6      flags (bit 0: keep_order; bit 1: fast_decode; bit 2, from format 1.2 on:
//                modelled low bits; bit 3, from format 1.3 on: adaptive low bits in sections of
//                every size; other bits must be 0)
//   bytes 7..10  CRC32 (IEEE, little endian) of every other byte of the stream (bytes 0..6, then
//                every byte after this field)
//   varint      payload length in bytes (LEB128, at most 5 bytes)
//   payload     one arithmetic-coded bit stream (see encoder.cc for its content)
#ifndef O3DGC_SRC_STREAM_HEADER_H_
#define O3DGC_SRC_STREAM_HEADER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace o3dgc {

constexpr uint8_t kMagic[4] = {'O', '3', 'D', 'G'};
constexpr size_t kVersionOffset = 4;
constexpr size_t kFlagsOffset = 6;
constexpr size_t kCrcOffset = 7;
constexpr size_t kCrcSize = 4;

struct StreamHeader {
  uint32_t major = kFormatMajor;
  uint32_t minor = kFormatMinor;
  bool keep_order = false;
  bool fast_decode = false;   // parallelogram-predicted values coded in vertex id order
  bool low_bits = false;      // 1.2: sections of adaptively coded values say if they model low bits
  bool all_adaptive = false;  // 1.3: no section codes its low bits raw (see RawLowBits)
  size_t payload_offset = 0;
  size_t payload_size = 0;
  uint32_t crc = 0;
};

uint32_t Crc32(const uint8_t* data, size_t size, uint32_t crc = 0);

// The CRC a binary stream of `size` bytes (at least kCrcOffset + kCrcSize) carries: over every
// byte but the CRC field, so that the version and flags are covered too.
uint32_t StreamCrc(const uint8_t* data, size_t size);

// The first format minor version with modelled low bits (the flag `low_bits`).
constexpr uint32_t kLowBitsMinor = 2;
// The first format minor version with adaptive low bits in large sections (`all_adaptive`).
constexpr uint32_t kAllAdaptiveMinor = 3;

// Appends the header for a payload of `payload_size` bytes; the CRC field is left zero and filled
// by FinalizeCrc once the payload is appended. The minor version written is the lowest that has
// the stream's features: kAllAdaptiveMinor with `all_adaptive`, kLowBitsMinor with `low_bits`,
// else 1 (older decoders read the stream).
void WriteHeader(bool keep_order, bool fast_decode, bool low_bits, bool all_adaptive,
                 size_t payload_size, std::vector<uint8_t>* out);
inline uint32_t WrittenMinor(bool low_bits, bool all_adaptive) {
  return all_adaptive ? kAllAdaptiveMinor : (low_bits ? kLowBitsMinor : 1);
}
void FinalizeCrc(std::vector<uint8_t>* stream);

// Parses and checks the header of a binary stream of `size` bytes; the payload must end exactly at
// the end of the stream. A stream of another major version, or of a minor version above
// kFormatMinor, is kBadVersion.
Status ParseHeader(const uint8_t* data, size_t size, StreamHeader* header);

}  // namespace o3dgc

#endif  // O3DGC_SRC_STREAM_HEADER_H_
