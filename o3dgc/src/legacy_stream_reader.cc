// Fields and header of original Open3DGC streams (see legacy_stream_reader.h).
#include "legacy_stream_reader.h"

#include <cmath>
#include <cstring>

namespace o3dgc {
namespace {

constexpr uint8_t kBinaryStart[4] = {0xF1, 0x01, 0x00, 0x00};
constexpr uint8_t kAsciiStart[5] = {0x71, 0x03, 0x00, 0x00, 0x00};
constexpr uint64_t kMax32 = 0xFFFFFFFFu;

// Reads `dimension` (min, max) pairs; both must be finite (NaN or infinite ranges would produce
// non-finite output).
bool ReadRanges(LegacyReader* r, LegacyArrayDesc* d) {
  for (uint32_t j = 0; j < d->dimension; ++j) {
    d->min[j] = r->ReadFloat32();
    d->max[j] = r->ReadFloat32();
    if (!std::isfinite(d->min[j]) || !std::isfinite(d->max[j])) return false;
  }
  return true;
}

}  // namespace

bool IsLegacyStream(const uint8_t* data, size_t size, LegacyEncoding* encoding) {
  if (!data) return false;
  if (size >= 4 && std::memcmp(data, kBinaryStart, 4) == 0) {
    if (encoding) *encoding = LegacyEncoding::kBinary;
    return true;
  }
  if (size >= 5 && std::memcmp(data, kAsciiStart, 5) == 0) {
    if (encoding) *encoding = LegacyEncoding::kAscii;
    return true;
  }
  return false;
}

uint64_t LegacyReader::ReadUInt32() {
  uint64_t v = 0;
  if (encoding_ == LegacyEncoding::kBinary) {
    for (int i = 0; i < 4; ++i) v |= uint64_t(ReadByte()) << (8 * i);
  } else {
    for (int i = 0; i < 5; ++i) v |= uint64_t(ReadByte()) << (7 * i);
  }
  return v;
}

float LegacyReader::ReadFloat32() {
  const uint32_t bits = uint32_t(ReadUInt32() & kMax32);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

uint64_t LegacyReader::ReadAsciiUInt() {
  uint64_t v = ReadByte();
  if (v != 127) return v;
  // 7 groups of 6 bits reach 2^42, far above any 32-bit value the encoder writes.
  for (int shift = 0; shift <= 36; shift += 6) {
    const uint8_t x = ReadByte();
    v += uint64_t(x >> 1) << shift;
    if (!(x & 1)) return v;
  }
  failed_ = true;
  return 0;
}

int64_t LegacyReader::ReadAsciiInt() { return LegacyUnsignedToSigned(ReadAsciiUInt()); }

Status ParseLegacyHeader(const uint8_t* data, size_t size, LegacyHeader* h) {
  LegacyEncoding encoding;
  if (!IsLegacyStream(data, size, &encoding)) return Status::kBadMagic;
  *h = LegacyHeader();
  h->encoding = encoding;
  LegacyReader r(data, size, encoding);
  r.ReadUInt32();  // start code
  h->stream_size = r.ReadUInt32();
  h->encode_mode = r.ReadUChar();
  r.ReadFloat32();  // crease angle: not used by the decoder
  r.ReadUChar();    // ccw / solid / convex / triangular flags: not used by the decoder
  const uint64_t num_coords = r.ReadUInt32();
  const uint64_t num_normals = r.ReadUInt32();
  const uint64_t num_floats = r.ReadUInt32();
  const uint64_t num_ints = r.ReadUInt32();
  if (r.failed()) return Status::kTruncated;
  if (h->stream_size > size) return Status::kTruncated;
  if (h->encode_mode != 2) return Status::kUnsupported;
  if (num_coords > kMax32 || num_normals > kMax32) return Status::kCorrupt;
  if (num_floats > kLegacyMaxAttributes || num_ints > kLegacyMaxAttributes) return Status::kCorrupt;
  h->coord.count = num_coords;
  h->coord.dimension = 3;
  h->coord.type = uint8_t(LegacyFloatType::kPosition);
  if (num_coords > 0) {
    h->num_triangles = r.ReadUInt32();
    if (!ReadRanges(&r, &h->coord)) return r.failed() ? Status::kTruncated : Status::kCorrupt;
    h->coord.bits = r.ReadUChar();
  }
  h->normal.count = num_normals;
  h->normal.dimension = 3;
  h->normal.type = uint8_t(LegacyFloatType::kNormal);
  if (num_normals > 0) {
    r.ReadUInt32();  // normal index count: the encoder writes 0 (normals share the coord index)
    if (!ReadRanges(&r, &h->normal)) return r.failed() ? Status::kTruncated : Status::kCorrupt;
    r.ReadUChar();  // per-vertex flag: always 1
    h->normal.bits = r.ReadUChar();
  }
  h->floats.resize(size_t(num_floats));
  for (LegacyArrayDesc& d : h->floats) {
    d.count = r.ReadUInt32();
    if (d.count > kMax32) return r.failed() ? Status::kTruncated : Status::kCorrupt;
    if (d.count == 0) continue;
    r.ReadUInt32();  // index count: 0
    d.dimension = r.ReadUChar();
    if (r.failed()) return Status::kTruncated;
    if (d.dimension < 1 || d.dimension > kLegacyMaxDimension) return Status::kCorrupt;
    if (!ReadRanges(&r, &d)) return r.failed() ? Status::kTruncated : Status::kCorrupt;
    r.ReadUChar();  // per-vertex flag: always 1
    d.type = r.ReadUChar();
    d.bits = r.ReadUChar();
  }
  h->ints.resize(size_t(num_ints));
  for (LegacyArrayDesc& d : h->ints) {
    d.count = r.ReadUInt32();
    if (d.count > kMax32) return r.failed() ? Status::kTruncated : Status::kCorrupt;
    if (d.count == 0) continue;
    r.ReadUInt32();  // index count: 0
    d.dimension = r.ReadUChar();
    r.ReadUChar();  // per-vertex flag: always 1
    d.type = r.ReadUChar();
    if (r.failed()) return Status::kTruncated;
    if (d.dimension < 1 || d.dimension > kLegacyMaxDimension) return Status::kCorrupt;
  }
  if (r.failed()) return Status::kTruncated;
  if (h->num_triangles > kMax32) return Status::kCorrupt;
  h->header_bytes = r.pos();
  if (h->header_bytes > h->stream_size) return Status::kCorrupt;
  return Status::kOk;
}

}  // namespace o3dgc
