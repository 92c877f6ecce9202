// Top-level decoder: the mirror of encoder.cc. Every count is checked against what the stream can
// hold before anything is allocated, every value against its valid range.
#include <cstring>
#include <memory>

#include "arithmetic_coder.h"
#include "ascii_stream.h"
#include "attribute_coder.h"
#include "connectivity_decoder.h"
#include "entropy.h"
#include "legacy_decoder.h"
#include "o3dgc/o3dgc.h"
#include "payload_header.h"
#include "predictors.h"
#include "stream_header.h"

namespace o3dgc {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;

Status DecodeBinary(const uint8_t* data, size_t size, const DecodeOptions& options,
                    DecodedMesh* out, StreamInfo* info) {
  StreamHeader sh;
  Status s = ParseHeader(data, size, &sh);
  if (s != Status::kOk) return s;
  if (options.verify_checksum && StreamCrc(data, size) != sh.crc) {
    return Status::kChecksumMismatch;
  }
  auto progress = [&](float f) { return !options.progress || options.progress(f); };
  ArithmeticDecoder dec(data + sh.payload_offset, sh.payload_size);
  StreamInfo si;
  si.version_major = sh.major;
  si.version_minor = sh.minor;
  si.keep_order = sh.keep_order;
  si.fast_decode = sh.fast_decode;
  const CodingOrder::Kind order = CodingOrder::ForStream(sh.fast_decode);
  PayloadHeader h;
  if ((s = DecodePayloadHeader(&dec, &h)) != Status::kOk) return s;
  if (h.num_vertices > options.max_vertices || h.num_triangles > options.max_triangles) {
    return Status::kLimitExceeded;
  }
  if (h.num_vertices > (uint64_t(1) << 32) - 2 || h.num_triangles > (uint64_t(1) << 32) / 3) {
    return Status::kLimitExceeded;
  }
  if (h.Budget() > kElementsPerByte * (sh.payload_size + kBudgetSlackBytes)) {
    return Status::kLimitExceeded;
  }
  const uint32_t nv = uint32_t(h.num_vertices);
  const size_t nt = size_t(h.num_triangles);
  si.num_vertices = nv;
  si.num_triangles = nt;
  si.header = sh.payload_offset + dec.BytesConsumed();
  size_t mark = dec.BytesConsumed();

  // Connectivity.
  std::vector<uint32_t> tris, opposite, opposite_vertices, vertex_triangles;
  uint32_t nc = 0;
  // The neighbour triangles themselves are needed only by parallelogram-predicted attributes
  // (across seams); positions use the opposite vertices.
  bool attribute_wedges = h.has_normals && h.normal.prediction == Prediction::kParallelogram;
  for (const AttributeDesc& d : h.floats)
    attribute_wedges |= d.prediction == Prediction::kParallelogram;
  if ((s = DecodeConnectivity(&dec, nt, nv, &tris, &nc, attribute_wedges ? &opposite : nullptr,
                              &opposite_vertices, &vertex_triangles)) != Status::kOk) {
    return s;
  }

  // Seams.
  std::unique_ptr<SideModels> sm(new SideModels);
  const bool has_seams = dec.DecodeBits(1) != 0;
  std::vector<uint32_t> welded_of(nv);
  std::vector<uint32_t> seam_tris;  // the attribute mesh, when seams make it differ
  uint32_t nw = nc;
  if (!has_seams) {
    // One attribute vertex per welded vertex. Both numberings follow first use in the triangle
    // list, so the attribute mesh is the welded one; unreferenced vertices follow in order.
    for (uint32_t v = 0; v < nv; ++v) welded_of[v] = v;
    nw = nv;
  } else {
    std::vector<uint32_t> split_count(nc), split_base(size_t(nc) + 1, 0);
    for (uint32_t w = 0; w < nc; ++w) {
      const uint64_t k = DecodeEG(dec, sm->seam_count) + 1;
      if (k > nv || split_base[w] + k > nv) return Status::kCorrupt;
      split_count[w] = uint32_t(k);
      split_base[w + 1] = split_base[w] + uint32_t(k);
      if (dec.failed()) return Status::kTruncated;
    }
    const uint32_t referenced = split_base[nc];
    std::vector<uint32_t> split_vertex(referenced, kNone);
    std::vector<uint32_t> seen(nc, 0), last(nc, 0);
    uint32_t next_vertex = 0;
    seam_tris.resize(3 * nt);
    for (size_t i = 0; i < 3 * nt; ++i) {
      const uint32_t w = tris[i];
      uint32_t sidx;
      if (seen[w] == 0) {
        sidx = kNone;
      } else if (split_count[w] == 1 || dec.Decode(sm->seam_same)) {
        sidx = last[w];
      } else if (seen[w] < split_count[w] && dec.Decode(sm->seam_new)) {
        sidx = kNone;
      } else {
        if (seen[w] < 2) return Status::kCorrupt;
        const uint32_t idx = dec.DecodeBits(BitsFor(seen[w] - 1));
        if (idx >= seen[w] - 1) return Status::kCorrupt;
        sidx = idx < last[w] ? idx : idx + 1;
      }
      if (sidx == kNone) {
        sidx = seen[w]++;
        split_vertex[split_base[w] + sidx] = next_vertex;
        welded_of[next_vertex] = w;
        ++next_vertex;
      }
      last[w] = sidx;
      seam_tris[i] = split_vertex[split_base[w] + sidx];
      if ((i & 4095) == 0 && dec.failed()) return Status::kTruncated;
    }
    if (next_vertex != referenced) return Status::kCorrupt;
    for (uint32_t v = referenced; v < nv; ++v) welded_of[v] = nw++;
  }
  const std::vector<uint32_t>& attr_tris = has_seams ? seam_tris : tris;

  // Exact order.
  std::vector<uint32_t> vertex_perm, triangle_perm;
  std::vector<uint8_t> rotation;
  if (sh.keep_order) {
    vertex_perm.resize(nv);
    std::vector<uint8_t> used(nv, 0);
    int64_t prev = -1;
    for (uint32_t i = 0; i < nv; ++i) {
      const int64_t v = prev + 1 + UnZigZag(DecodeEG(dec, sm->perm_vertex));
      if (v < 0 || v >= int64_t(nv) || used[size_t(v)]) return Status::kCorrupt;
      used[size_t(v)] = 1;
      vertex_perm[i] = uint32_t(v);
      prev = v;
      if ((i & 1023) == 0 && dec.failed()) return Status::kTruncated;
    }
    triangle_perm.resize(nt);
    rotation.resize(nt);
    std::vector<uint8_t> tused(nt, 0);
    prev = -1;
    for (size_t j = 0; j < nt; ++j) {
      const int64_t t = prev + 1 + UnZigZag(DecodeEG(dec, sm->perm_triangle));
      if (t < 0 || t >= int64_t(nt) || tused[size_t(t)]) return Status::kCorrupt;
      tused[size_t(t)] = 1;
      triangle_perm[j] = uint32_t(t);
      prev = t;
      rotation[j] = 0;
      if (dec.Decode(sm->rotation[0])) rotation[j] = dec.Decode(sm->rotation[1]) ? 2 : 1;
      if ((j & 1023) == 0 && dec.failed()) return Status::kTruncated;
    }
  }
  if (dec.failed()) return Status::kTruncated;
  si.connectivity = dec.BytesConsumed() - mark;
  if (!progress(0.4f)) return Status::kCancelled;

  // Positions.
  mark = dec.BytesConsumed();
  std::vector<int32_t> qpos;
  {
    WedgeTable wedges;
    if (h.position.prediction == Prediction::kParallelogram) {
      wedges.BuildFromOppositeVertices(tris, nw, opposite_vertices, &vertex_triangles);
    }
    if ((s = DecodeQuantized(&dec, &wedges, nw, 3, h.position.bits, h.position.prediction, order,
                             &qpos)) != Status::kOk) {
      return s;
    }
  }
  si.positions = dec.BytesConsumed() - mark;
  if (!progress(0.6f)) return Status::kCancelled;

  DecodedMesh m;
  m.positions.resize(size_t(nv) * 3);
  h.position.quant.DequantizeAll(qpos.data(), has_seams ? welded_of.data() : nullptr, nv,
                                 m.positions.data());
  MeshAdjacency attr_adj;
  if (h.has_normals && h.normal.prediction == Prediction::kSurfaceNormal)
    attr_adj.Build(attr_tris, nv);
  WedgeTable attr_wedges;
  bool attr_wedges_built = false;
  NormalGeometry geo;
  geo.positions = qpos.data();
  for (int k = 0; k < 3; ++k) {
    geo.scale[k] = double(h.position.quant.range[k]) / double(h.position.quant.max_q());
  }
  geo.position_of = welded_of.data();
  std::vector<double> attr_geometry;
  auto decode_float = [&](const AttributeDesc& d, std::vector<float>* values) {
    std::vector<int32_t> q;
    const bool texcoord = d.semantic == Semantic::kTexCoord && d.dimension == 2 &&
                          d.prediction == Prediction::kParallelogram;
    if (texcoord && attr_geometry.empty()) attr_geometry = AttributeGeometry(geo, nv);
    if (d.prediction == Prediction::kParallelogram && !attr_wedges_built) {
      attr_wedges.Build(attr_tris, nv, opposite, has_seams);
      attr_wedges_built = true;
    }
    const Status st = DecodeQuantized(&dec, &attr_wedges, nv, int(d.dimension), d.bits,
                                      d.prediction, order, &q, texcoord ? &attr_geometry : nullptr);
    if (st != Status::kOk) return st;
    values->resize(q.size());
    d.quant.DequantizeAll(q.data(), nullptr, nv, values->data());
    return Status::kOk;
  };
  mark = dec.BytesConsumed();
  if (h.has_normals) {
    if (h.normal.prediction == Prediction::kSurfaceNormal) {
      s = DecodeOctNormals(&dec, attr_adj, geo, nv, h.normal.bits, &m.normals);
    } else {
      s = decode_float(h.normal, &m.normals);
    }
    if (s != Status::kOk) return s;
  }
  si.normals = dec.BytesConsumed() - mark;
  for (const AttributeDesc& d : h.floats) {
    mark = dec.BytesConsumed();
    DecodedFloatAttribute a;
    a.semantic = d.semantic;
    a.dimension = d.dimension;
    if ((s = decode_float(d, &a.values)) != Status::kOk) return s;
    m.float_attributes.push_back(std::move(a));
    si.float_attributes.push_back(dec.BytesConsumed() - mark);
  }
  for (const AttributeDesc& d : h.ints) {
    mark = dec.BytesConsumed();
    DecodedIntAttribute a;
    a.semantic = d.semantic;
    a.dimension = d.dimension;
    if ((s = DecodeInts(&dec, nv, int(d.dimension), d.prediction, &a.values)) != Status::kOk) {
      return s;
    }
    m.int_attributes.push_back(std::move(a));
    si.int_attributes.push_back(dec.BytesConsumed() - mark);
  }
  if (!progress(0.9f)) return Status::kCancelled;

  mark = dec.BytesConsumed();
  if (h.has_groups) {
    m.triangle_groups.resize(nt);
    uint32_t prev = 0;
    for (size_t j = 0; j < nt; ++j) {
      if (!dec.Decode(sm->group_same)) {
        const uint64_t g = DecodeEG(dec, sm->group_value);
        if (g > 0xFFFFFFFFu) return Status::kCorrupt;
        prev = uint32_t(g);
      }
      m.triangle_groups[j] = prev;
      if ((j & 1023) == 0 && dec.failed()) return Status::kTruncated;
    }
  }
  if (dec.failed()) return Status::kTruncated;
  AddTailBytes(h, sh.payload_size > mark ? sh.payload_size - mark : 0, &si);
  m.indices = has_seams ? std::move(seam_tris) : std::move(tris);

  if (sh.keep_order) {
    // New vertex i is input vertex vertex_perm[i]; decoded triangle j is input triangle
    // triangle_perm[j] starting at corner rotation[j].
    DecodedMesh o;
    auto permute_f = [&](const std::vector<float>& v, uint32_t dim) {
      std::vector<float> r(v.size());
      for (uint32_t i = 0; i < nv; ++i) {
        std::memcpy(&r[size_t(vertex_perm[i]) * dim], &v[size_t(i) * dim], dim * sizeof(float));
      }
      return r;
    };
    o.positions = permute_f(m.positions, 3);
    if (!m.normals.empty()) o.normals = permute_f(m.normals, 3);
    for (auto& a : m.float_attributes) {
      a.values = permute_f(a.values, a.dimension);
    }
    for (auto& a : m.int_attributes) {
      std::vector<int32_t> r(a.values.size());
      for (uint32_t i = 0; i < nv; ++i) {
        std::memcpy(&r[size_t(vertex_perm[i]) * a.dimension], &a.values[size_t(i) * a.dimension],
                    a.dimension * sizeof(int32_t));
      }
      a.values = std::move(r);
    }
    o.float_attributes = std::move(m.float_attributes);
    o.int_attributes = std::move(m.int_attributes);
    o.indices.resize(3 * nt);
    if (h.has_groups) o.triangle_groups.resize(nt);
    for (size_t j = 0; j < nt; ++j) {
      const uint32_t t = triangle_perm[j];
      for (int k = 0; k < 3; ++k) {
        o.indices[3 * size_t(t) + k] = vertex_perm[m.indices[3 * j + (rotation[j] + k) % 3]];
      }
      if (h.has_groups) o.triangle_groups[t] = m.triangle_groups[j];
    }
    m = std::move(o);
  }
  *out = std::move(m);
  si.total = size;
  if (info) *info = si;
  if (!progress(1.0f)) return Status::kCancelled;
  return Status::kOk;
}

}  // namespace

Status Decode(const uint8_t* data, size_t size, const DecodeOptions& options, DecodedMesh* out,
              StreamInfo* info) {
  if (!out || (!data && size > 0)) return Status::kInvalidArgument;
  if (IsLegacyStream(data, size)) return DecodeLegacy(data, size, options, out, info);
  if (IsAsciiStream(data, size)) {
    std::vector<uint8_t> binary;
    const Status s = UnpackAscii(data, size, &binary);
    if (s != Status::kOk) return s;
    const Status d = DecodeBinary(binary.data(), binary.size(), options, out, info);
    if (d == Status::kOk && info) {
      info->stream_type = StreamType::kAscii;
      info->total = size;
    }
    return d;
  }
  return DecodeBinary(data, size, options, out, info);
}

Status ReadStreamInfo(const uint8_t* data, size_t size, StreamInfo* info) {
  if (!info || (!data && size > 0)) return Status::kInvalidArgument;
  if (IsLegacyStream(data, size)) return ReadLegacyStreamInfo(data, size, info);
  std::vector<uint8_t> binary;
  StreamType type = StreamType::kBinary;
  if (IsAsciiStream(data, size)) {
    const Status s = UnpackAscii(data, size, &binary);
    if (s != Status::kOk) return s;
    data = binary.data();
    type = StreamType::kAscii;
  }
  const size_t bsize = type == StreamType::kAscii ? binary.size() : size;
  StreamHeader sh;
  Status s = ParseHeader(data, bsize, &sh);
  if (s != Status::kOk) return s;
  ArithmeticDecoder dec(data + sh.payload_offset, sh.payload_size);
  PayloadHeader h;
  if ((s = DecodePayloadHeader(&dec, &h)) != Status::kOk) return s;
  *info = StreamInfo();
  info->stream_type = type;
  info->version_major = sh.major;
  info->version_minor = sh.minor;
  info->keep_order = sh.keep_order;
  info->fast_decode = sh.fast_decode;
  info->num_vertices = size_t(h.num_vertices);
  info->num_triangles = size_t(h.num_triangles);
  info->total = size;
  info->header = sh.payload_offset + dec.BytesConsumed();
  return Status::kOk;
}

const char* FormatVersionString() {
  static_assert(kFormatMajor < 10 && kFormatMinor < 10, "update the version string");
  static const char kText[] = {char('0' + kFormatMajor), '.', char('0' + kFormatMinor), 0};
  return kText;
}

const char* StatusName(Status status) {
  switch (status) {
    case Status::kOk:
      return "ok";
    case Status::kInvalidArgument:
      return "invalid_argument";
    case Status::kUnsupported:
      return "unsupported";
    case Status::kBadMagic:
      return "bad_magic";
    case Status::kBadVersion:
      return "bad_version";
    case Status::kTruncated:
      return "truncated";
    case Status::kCorrupt:
      return "corrupt";
    case Status::kChecksumMismatch:
      return "checksum_mismatch";
    case Status::kLimitExceeded:
      return "limit_exceeded";
    case Status::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

}  // namespace o3dgc
