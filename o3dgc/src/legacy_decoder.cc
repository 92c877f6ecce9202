// Top-level decoder of original Open3DGC streams (see legacy_decoder.h).
#include "legacy_decoder.h"

#include <cmath>

#include "legacy_attribute_decoder.h"
#include "legacy_connectivity_decoder.h"
#include "legacy_stream_reader.h"

namespace o3dgc {
namespace {

Semantic FloatSemantic(uint8_t type) {
  switch (LegacyFloatType(type)) {
    case LegacyFloatType::kNormal:
      return Semantic::kNormal;
    case LegacyFloatType::kColor:
      return Semantic::kColor;
    case LegacyFloatType::kTexCoord:
      return Semantic::kTexCoord;
    case LegacyFloatType::kWeight:
      return Semantic::kWeight;
    default:
      return Semantic::kGeneric;
  }
}

Semantic IntSemantic(uint8_t type) {
  return LegacyIntType(type) == LegacyIntType::kJointId ? Semantic::kJointId : Semantic::kGeneric;
}

void FillInfo(const LegacyHeader& h, size_t size, StreamInfo* info) {
  *info = StreamInfo();
  info->format = StreamFormat::kOpen3dgc2013;
  info->stream_type =
      h.encoding == LegacyEncoding::kAscii ? StreamType::kAscii : StreamType::kBinary;
  info->version_major = 0;
  info->version_minor = 0;
  info->num_vertices = size_t(h.coord.count);
  info->num_triangles = size_t(h.num_triangles);
  info->total = size;
  info->header = h.header_bytes;
}

bool AllFinite(const std::vector<float>& v) {
  for (float f : v) {
    if (!std::isfinite(f)) return false;
  }
  return true;
}

}  // namespace

Status ReadLegacyStreamInfo(const uint8_t* data, size_t size, StreamInfo* info) {
  LegacyHeader h;
  const Status s = ParseLegacyHeader(data, size, &h);
  if (s != Status::kOk) return s;
  FillInfo(h, size, info);
  return Status::kOk;
}

Status DecodeLegacy(const uint8_t* data, size_t size, const DecodeOptions& options,
                    DecodedMesh* out, StreamInfo* info) {
  auto progress = [&](float f) { return !options.progress || options.progress(f); };
  LegacyHeader h;
  Status s = ParseLegacyHeader(data, size, &h);
  if (s != Status::kOk) return s;
  const uint64_t nv = h.coord.count, nt = h.num_triangles;
  if (nv == 0 || nt == 0) return Status::kCorrupt;  // the original encoder needs both
  if (nv > options.max_vertices || nt > options.max_triangles) return Status::kLimitExceeded;
  // Every array is per coordinate in streams of the original tool; DecodedMesh needs that too.
  if (h.normal.count != 0 && h.normal.count != nv) return Status::kUnsupported;
  uint64_t elements = nt + 4 * nv + 3 * h.normal.count;
  for (const LegacyArrayDesc& d : h.floats) {
    if (d.count != 0 && d.count != nv) return Status::kUnsupported;
    elements += d.count * d.dimension;
  }
  for (const LegacyArrayDesc& d : h.ints) {
    if (d.count != 0 && d.count != nv) return Status::kUnsupported;
    elements += d.count * d.dimension;
  }
  if (elements > kLegacyElementsPerByte * uint64_t(h.stream_size)) return Status::kLimitExceeded;

  StreamInfo si;
  FillInfo(h, size, &si);
  // Only the declared stream is read (the original tool wrote nothing after it).
  LegacyReader r(data, size_t(h.stream_size), h.encoding);
  r.Seek(h.header_bytes);
  LegacyConnectivity conn;
  size_t mark = r.pos();
  s = DecodeLegacyConnectivity(&r, uint32_t(nv), uint32_t(nt), &conn);
  if (s != Status::kOk) return s;
  si.connectivity = r.pos() - mark;
  if (!progress(0.4f)) return Status::kCancelled;

  DecodedMesh m;
  LegacyAttributeDecoder attributes(&r, conn.triangles, uint32_t(nv));
  mark = r.pos();
  if ((s = attributes.DecodePositions(h.coord, &m.positions)) != Status::kOk) return s;
  si.positions = r.pos() - mark;
  if (!progress(0.6f)) return Status::kCancelled;
  if (h.normal.count > 0) {
    mark = r.pos();
    if ((s = attributes.DecodeNormals(h.normal, &m.normals)) != Status::kOk) return s;
    si.normals = r.pos() - mark;
  }
  for (const LegacyArrayDesc& d : h.floats) {
    mark = r.pos();
    DecodedFloatAttribute a;
    a.semantic = FloatSemantic(d.type);
    a.dimension = d.dimension;
    if ((s = attributes.DecodeFloats(d, &a.values)) != Status::kOk) return s;
    if (d.count == 0) continue;  // an empty array still has its (empty) section
    m.float_attributes.push_back(std::move(a));
    si.float_attributes.push_back(r.pos() - mark);
  }
  for (const LegacyArrayDesc& d : h.ints) {
    mark = r.pos();
    DecodedIntAttribute a;
    a.semantic = IntSemantic(d.type);
    a.dimension = d.dimension;
    if ((s = attributes.DecodeInts(d, &a.values)) != Status::kOk) return s;
    if (d.count == 0) continue;
    m.int_attributes.push_back(std::move(a));
    si.int_attributes.push_back(r.pos() - mark);
  }
  if (!progress(0.9f)) return Status::kCancelled;
  // Out-of-range quantized values or huge ranges can overflow float.
  if (!AllFinite(m.positions) || !AllFinite(m.normals)) return Status::kCorrupt;
  for (const DecodedFloatAttribute& a : m.float_attributes) {
    if (!AllFinite(a.values)) return Status::kCorrupt;
  }

  if (conn.placement.empty()) {
    m.indices = std::move(conn.triangles);
  } else {
    m.indices.resize(conn.triangles.size());
    for (size_t i = 0; i < conn.placement.size(); ++i) {
      for (size_t k = 0; k < 3; ++k)
        m.indices[3 * size_t(conn.placement[i]) + k] = conn.triangles[3 * i + k];
    }
  }
  *out = std::move(m);
  if (info) *info = si;
  if (!progress(1.0f)) return Status::kCancelled;
  return Status::kOk;
}

}  // namespace o3dgc
