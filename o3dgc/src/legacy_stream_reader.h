// Reading the fields of a stream written by the original Open3DGC SC3DMC encoder (2013), and its
// header. The format is described in docs/open3dgc-legacy-format.md.
//
// The original stream has two encodings of the same fields, chosen by the encoder:
//  - binary: 32-bit fields little endian (the byte order of the x86 machines that wrote them),
//    bytes as they are, float32 as its IEEE bits;
//  - ASCII: every byte < 128. 32-bit fields (and float bits) as five 7-bit groups, least
//    significant first; bytes as they are; variable-length numbers as one byte < 127, or 127
//    followed by 6-bit groups (least significant first) each shifted left by one with a
//    "more follows" flag in bit 0.
// The reader never reads outside [data, data + size); a read past the end returns zeros and marks
// the reader failed, so callers check failed() once after a group of reads.
#ifndef O3DGC_SRC_LEGACY_STREAM_READER_H_
#define O3DGC_SRC_LEGACY_STREAM_READER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace o3dgc {

enum class LegacyEncoding : uint8_t { kBinary, kAscii };

// The start code of an SC3DMC stream (the first 32-bit field, in either encoding).
constexpr uint32_t kLegacyStartCode = 0x1F1;

// True if the stream starts with the SC3DMC start code; *encoding (if not null) says which.
bool IsLegacyStream(const uint8_t* data, size_t size, LegacyEncoding* encoding = nullptr);

class LegacyReader {
 public:
  LegacyReader(const uint8_t* data, size_t size, LegacyEncoding encoding)
      : data_(data), size_(size), encoding_(encoding) {}

  LegacyEncoding encoding() const { return encoding_; }
  const uint8_t* data() const { return data_; }
  size_t size() const { return size_; }
  size_t pos() const { return pos_; }
  size_t remaining() const { return pos_ < size_ ? size_ - pos_ : 0; }
  bool failed() const { return failed_; }
  void Seek(size_t pos) {
    if (pos > size_) failed_ = true;
    pos_ = pos > size_ ? size_ : pos;
  }

  uint8_t ReadByte() {
    if (pos_ >= size_) {
      failed_ = true;
      return 0;
    }
    return data_[pos_++];
  }
  // A 32-bit field in the stream's encoding. In ASCII the five 7-bit groups can hold 35 bits; the
  // full value is returned so that counts above 2^32 - 1 can be rejected.
  uint64_t ReadUInt32();
  // The 32-bit field as float bits (ASCII: the low 32 bits, as the original decoder kept them).
  float ReadFloat32();
  // A one-byte field (the same in both encodings).
  uint8_t ReadUChar() { return ReadByte(); }
  // ASCII variable-length numbers; more than 7 continuation groups mark the reader failed.
  uint64_t ReadAsciiUInt();
  int64_t ReadAsciiInt();

 private:
  const uint8_t* data_;
  size_t size_;
  LegacyEncoding encoding_;
  size_t pos_ = 0;
  bool failed_ = false;
};

// The original's signed <-> unsigned mapping: 0, -1, 1, -2, ... <-> 0, 1, 2, 3, ...
inline int64_t LegacyUnsignedToSigned(uint64_t u) {
  return (u & 1) ? -int64_t((u >> 1) + 1) : int64_t(u >> 1);
}

// The original's float attribute types and what they mean here.
enum class LegacyFloatType : uint8_t {
  kUnknown = 0,
  kPosition = 1,
  kNormal = 2,
  kColor = 3,
  kTexCoord = 4,
  kWeight = 5,
};
enum class LegacyIntType : uint8_t { kUnknown = 0, kIndex = 1, kJointId = 2, kIndexBufferId = 3 };

// Bounds the original decoder also has (fixed-size tables).
constexpr uint32_t kLegacyMaxAttributes = 256;
constexpr uint32_t kLegacyMaxDimension = 31;

struct LegacyArrayDesc {
  uint64_t count = 0;  // elements (vertices) in the array
  uint32_t dimension = 0;
  uint8_t type = 0;  // LegacyFloatType / LegacyIntType
  int bits = 0;      // quantization bits (float arrays)
  float min[kLegacyMaxDimension] = {};
  float max[kLegacyMaxDimension] = {};
};

struct LegacyHeader {
  LegacyEncoding encoding = LegacyEncoding::kBinary;
  uint64_t stream_size = 0;  // bytes of the whole SC3DMC stream, start code included
  uint8_t encode_mode = 0;   // 2 = TFAN, the only mode the original decoder implements
  uint64_t num_triangles = 0;
  LegacyArrayDesc coord;   // dimension 3
  LegacyArrayDesc normal;  // dimension 3
  std::vector<LegacyArrayDesc> floats;
  std::vector<LegacyArrayDesc> ints;
  size_t header_bytes = 0;  // where the payload starts
};

// Parses the header. kBadMagic if there is no start code, kTruncated if the stream ends inside the
// header or before its declared size, kCorrupt for out-of-range fields (counts over 2^32 - 1,
// more than 256 attributes, dimensions outside 1..31, non-finite ranges), kUnsupported for an
// encoding mode other than TFAN.
Status ParseLegacyHeader(const uint8_t* data, size_t size, LegacyHeader* header);

}  // namespace o3dgc

#endif  // O3DGC_SRC_LEGACY_STREAM_READER_H_
