// The byte header of an o3dgc stream and its checksum.
//
// Binary stream layout:
//   bytes 0..3  magic "O3DG"
//   byte  4     format version (kStreamVersion)
//   byte  5     flags (bit 0: keep_order; bit 1: fast_decode; other bits must be 0)
//   bytes 6..9  CRC32 (IEEE, little endian) of every byte after this field
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
constexpr size_t kCrcOffset = 6;
constexpr size_t kCrcSize = 4;

struct StreamHeader {
  uint32_t version = kStreamVersion;
  bool keep_order = false;
  bool fast_decode = false;  // parallelogram-predicted values coded in vertex id order
  size_t payload_offset = 0;
  size_t payload_size = 0;
  uint32_t crc = 0;
};

uint32_t Crc32(const uint8_t* data, size_t size, uint32_t crc = 0);

// Appends the header for a payload of `payload_size` bytes; the CRC field is left zero and filled
// by FinalizeCrc once the payload is appended.
void WriteHeader(bool keep_order, bool fast_decode, size_t payload_size, std::vector<uint8_t>* out);
void FinalizeCrc(std::vector<uint8_t>* stream);

// Parses and checks the header of a binary stream of `size` bytes; the payload must end exactly at
// the end of the stream.
Status ParseHeader(const uint8_t* data, size_t size, StreamHeader* header);

}  // namespace o3dgc

#endif  // O3DGC_SRC_STREAM_HEADER_H_
