// Top-level decoder: the mirror of encoder.cc. Every count is checked against what the stream can
// hold before anything is allocated, every value against its valid range.
#include <algorithm>
#include <cstring>
#include <memory>
#include <type_traits>

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

// What the stages of one decode share. The stages follow the payload's parts (payload_header.h),
// each the mirror of the encoder's.
struct DecodeState {
  StreamHeader sh;
  PayloadHeader h;
  ArithmeticDecoder dec{nullptr, 0};
  StreamInfo si;
  CodingOrder::Kind order = CodingOrder::kGreedy;
  uint32_t nv = 0;
  size_t nt = 0;
  std::unique_ptr<SideModels> sm{new SideModels};
  // Connectivity, over position vertices.
  std::vector<uint32_t> tris, opposite, opposite_vertices, vertex_triangles, component_ends;
  uint32_t nc = 0;
  // Seams: the position vertex of each attribute vertex, the attribute mesh when it differs.
  bool has_seams = false;
  std::vector<uint32_t> welded_of, seam_tris;
  uint32_t nw = 0;
  const std::vector<uint32_t>& attr_tris() const { return has_seams ? seam_tris : tris; }
  // Exact order (keep_order).
  std::vector<uint32_t> vertex_perm, triangle_perm;
  std::vector<uint8_t> rotation;
  // Quantized positions per position vertex.
  std::vector<int32_t> qpos;
};

// The stream header, the checksum, the counts and descriptors, checked against the limits and
// against what the payload can hold before anything is allocated.
O3DGC_WASM_MINSIZE Status DecodeHeaders(const uint8_t* data, size_t size,
                                        const DecodeOptions& options, DecodeState& st) {
  Status s = ParseHeader(data, size, &st.sh);
  if (s != Status::kOk) return s;
  if (options.verify_checksum && StreamCrc(data, size) != st.sh.crc) {
    return Status::kChecksumMismatch;
  }
  const StreamHeader& sh = st.sh;
  st.dec = ArithmeticDecoder(data + sh.payload_offset, sh.payload_size);
  st.si.version_major = sh.major;
  st.si.version_minor = sh.minor;
  st.si.keep_order = sh.keep_order;
  st.si.fast_decode = sh.fast_decode;
  st.si.low_bits = sh.low_bits;
  st.si.all_adaptive = sh.all_adaptive;
  st.order = CodingOrder::ForStream(sh.fast_decode);
  PayloadHeader& h = st.h;
  if ((s = DecodePayloadHeader(&st.dec, &h)) != Status::kOk) return s;
  if (h.num_vertices > options.max_vertices || h.num_triangles > options.max_triangles) {
    return Status::kLimitExceeded;
  }
  if (h.num_vertices > (uint64_t(1) << 32) - 2 || h.num_triangles > (uint64_t(1) << 32) / 3) {
    return Status::kLimitExceeded;
  }
  if (h.Budget() > kElementsPerByte * (sh.payload_size + kBudgetSlackBytes)) {
    return Status::kLimitExceeded;
  }
  st.nv = uint32_t(h.num_vertices);
  st.nt = size_t(h.num_triangles);
  st.si.num_vertices = st.nv;
  st.si.num_triangles = st.nt;
  st.si.header = sh.payload_offset + st.dec.BytesConsumed();
  return Status::kOk;
}

Status DecodeTriangles(DecodeState& st) {
  const PayloadHeader& h = st.h;
  // The neighbour triangles themselves are needed only by parallelogram-predicted attributes
  // (across seams); positions use the opposite vertices.
  bool attribute_wedges = h.has_normals && h.normal.prediction == Prediction::kParallelogram;
  for (const AttributeDesc& d : h.floats)
    attribute_wedges |= d.prediction == Prediction::kParallelogram;
  return DecodeConnectivity(&st.dec, st.nt, st.nv, &st.tris, &st.nc,
                            attribute_wedges ? &st.opposite : nullptr, &st.opposite_vertices,
                            &st.vertex_triangles, st.sh.minor, st.nt >= kCompactFrontTriangles,
                            &st.component_ends);
}

Status DecodeSeams(DecodeState& st) {
  ArithmeticDecoder& dec = st.dec;
  const uint32_t nv = st.nv, nc = st.nc;
  const size_t nt = st.nt;
  const std::vector<uint32_t>& tris = st.tris;
  std::vector<uint32_t>& welded_of = st.welded_of;
  std::vector<uint32_t>& seam_tris = st.seam_tris;
  uint32_t& nw = st.nw;
  st.has_seams = dec.DecodeBits(1) != 0;
  welded_of.resize(nv);
  nw = nc;
  if (!st.has_seams) {
    // One attribute vertex per welded vertex. Both numberings follow first use in the triangle
    // list, so the attribute mesh is the welded one; unreferenced vertices follow in order.
    for (uint32_t v = 0; v < nv; ++v) welded_of[v] = v;
    nw = nv;
  } else {
    std::vector<uint32_t> split_count(nc), split_base(size_t(nc) + 1, 0);
    for (uint32_t w = 0; w < nc; ++w) {
      const uint64_t k = DecodeEG(dec, st.sm->seam_count) + 1;
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
      } else if (split_count[w] == 1 || dec.Decode(st.sm->seam_same)) {
        sidx = last[w];
      } else if (seen[w] < split_count[w] && dec.Decode(st.sm->seam_new)) {
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
  return Status::kOk;
}

O3DGC_WASM_MINSIZE Status DecodeExactOrder(DecodeState& st) {
  ArithmeticDecoder& dec = st.dec;
  const uint32_t nv = st.nv;
  const size_t nt = st.nt;
  std::vector<uint32_t>& vertex_perm = st.vertex_perm;
  std::vector<uint32_t>& triangle_perm = st.triangle_perm;
  std::vector<uint8_t>& rotation = st.rotation;
  vertex_perm.resize(nv);
  std::vector<uint8_t> used(nv, 0);
  int64_t prev = -1;
  for (uint32_t i = 0; i < nv; ++i) {
    const int64_t v = prev + 1 + UnZigZag(DecodeEG(dec, st.sm->perm_vertex));
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
    const int64_t t = prev + 1 + UnZigZag(DecodeEG(dec, st.sm->perm_triangle));
    if (t < 0 || t >= int64_t(nt) || tused[size_t(t)]) return Status::kCorrupt;
    tused[size_t(t)] = 1;
    triangle_perm[j] = uint32_t(t);
    prev = t;
    rotation[j] = 0;
    if (dec.Decode(st.sm->rotation[0])) rotation[j] = dec.Decode(st.sm->rotation[1]) ? 2 : 1;
    if ((j & 1023) == 0 && dec.failed()) return Status::kTruncated;
  }
  return Status::kOk;
}

Status DecodePositions(DecodeState& st, DecodedMesh* m) {
  const PayloadHeader& h = st.h;
  {
    WedgeTable wedges;
    if (h.position.prediction == Prediction::kParallelogram) {
      wedges.BuildFromOppositeVertices(st.tris, st.nw, st.opposite_vertices, &st.vertex_triangles,
                                       &st.component_ends);
    }
    const Status s =
        DecodeQuantized(&st.dec, &wedges, st.nw, 3, h.position.bits, h.position.prediction,
                        st.order, &st.qpos, nullptr, st.sh.low_bits, st.sh.all_adaptive);
    if (s != Status::kOk) return s;
  }
  m->positions.resize(size_t(st.nv) * 3);
  h.position.quant.DequantizeAll(st.qpos.data(), st.has_seams ? st.welded_of.data() : nullptr,
                                 st.nv, m->positions.data());
  return Status::kOk;
}

// The mesh an attribute is coded over: the attribute vertices, or (format 1.1, with seams) the
// attribute vertices once those that merge into the first attribute vertex of their position
// vertex are left out; what its predictors need, built on first use.
struct AttributeMesh {
  const std::vector<uint32_t>* tris = nullptr;
  uint32_t n = 0;
  const uint32_t* position_of = nullptr;  // vertex -> position vertex
  std::vector<uint32_t> of_vertex;        // attribute vertex -> vertex (empty: the same)
  std::vector<uint32_t> own_tris, own_position_of;
  MeshAdjacency adj;
  bool adj_built = false;
  WedgeTable wedges;
  bool wedges_built = false;
  std::vector<double> geometry;
};

// Format 1.1, with seams: an attribute section's merge flags (section 5.1 of the format).
// Returns kOk with `merged` left unused when nothing merges.
Status DecodeMerges(ArithmeticDecoder& dec, const DecodeState& st,
                    const std::vector<uint32_t>& first, AttributeMesh* merged, bool* any) {
  *any = dec.DecodeBits(1) != 0;
  if (!*any) return Status::kOk;
  const uint32_t nv = st.nv;
  BitModel merge;
  merged->of_vertex.resize(nv);
  merged->own_position_of.clear();
  uint32_t n = 0;
  for (uint32_t v = 0; v < nv; ++v) {
    const uint32_t f = first[st.welded_of[v]];
    if (f != v && dec.Decode(merge)) {
      merged->of_vertex[v] = merged->of_vertex[f];
    } else {
      merged->of_vertex[v] = n++;
      merged->own_position_of.push_back(st.welded_of[v]);
    }
    if ((v & 4095) == 0 && dec.failed()) return Status::kTruncated;
  }
  const std::vector<uint32_t>& at = st.attr_tris();
  merged->own_tris.resize(at.size());
  for (size_t i = 0; i < at.size(); ++i) merged->own_tris[i] = merged->of_vertex[at[i]];
  merged->tris = &merged->own_tris;
  merged->n = n;
  merged->position_of = merged->own_position_of.data();
  merged->adj_built = merged->wedges_built = false;
  merged->geometry.clear();
  return Status::kOk;
}

// Normals, float attributes and int attributes, over the attribute vertices (format 1.1: over
// the merged ones, then copied to each attribute vertex).
Status DecodeAttributes(DecodeState& st, DecodedMesh* m) {
  const PayloadHeader& h = st.h;
  ArithmeticDecoder& dec = st.dec;
  StreamInfo& si = st.si;
  const uint32_t nv = st.nv;
  Status s;
  AttributeMesh attr, merged;
  attr.tris = &st.attr_tris();
  attr.n = nv;
  attr.position_of = st.welded_of.data();
  // Format 1.1: with seams, each attribute says which attribute vertices merge.
  const bool may_merge = st.sh.minor >= 1 && st.has_seams;
  std::vector<uint32_t> first;  // the first (smallest) attribute vertex of each position vertex
  if (may_merge) {
    first.assign(st.nw, kNone);
    for (uint32_t v = nv; v-- > 0;) first[st.welded_of[v]] = v;
  }
  NormalGeometry geo;
  geo.positions = st.qpos.data();
  for (int k = 0; k < 3; ++k) {
    geo.scale[k] = double(h.position.quant.range[k]) / double(h.position.quant.max_q());
  }
  AttributeMesh* mesh = &attr;
  auto read_merges = [&]() {
    mesh = &attr;
    if (!may_merge) return Status::kOk;
    bool any = false;
    const Status r = DecodeMerges(dec, st, first, &merged, &any);
    if (any) mesh = &merged;
    return r;
  };
  // Copies the merged vertices' values to the attribute vertices.
  auto expand = [&](auto* values, uint32_t dim) {
    if (mesh->of_vertex.empty()) return;
    std::remove_reference_t<decltype(*values)> out(size_t(nv) * dim);
    for (uint32_t v = 0; v < nv; ++v) {
      std::copy_n(values->data() + size_t(mesh->of_vertex[v]) * dim, dim,
                  out.data() + size_t(v) * dim);
    }
    *values = std::move(out);
  };
  auto decode_float = [&](const AttributeDesc& d, std::vector<float>* values) {
    std::vector<int32_t> q;
    const bool texcoord = d.semantic == Semantic::kTexCoord && d.dimension == 2 &&
                          d.prediction == Prediction::kParallelogram;
    geo.position_of = mesh->position_of;
    if (texcoord && mesh->geometry.empty()) mesh->geometry = AttributeGeometry(geo, mesh->n);
    if (d.prediction == Prediction::kParallelogram && !mesh->wedges_built) {
      mesh->wedges.Build(*mesh->tris, mesh->n, st.opposite, st.has_seams);
      mesh->wedges_built = true;
    }
    const Status r = DecodeQuantized(
        &dec, &mesh->wedges, mesh->n, int(d.dimension), d.bits, d.prediction, st.order, &q,
        texcoord ? &mesh->geometry : nullptr, st.sh.low_bits, st.sh.all_adaptive);
    if (r != Status::kOk) return r;
    values->resize(q.size());
    d.quant.DequantizeAll(q.data(), nullptr, mesh->n, values->data());
    expand(values, d.dimension);
    return Status::kOk;
  };
  size_t mark = dec.BytesConsumed();
  if (h.has_normals) {
    if ((s = read_merges()) != Status::kOk) return s;
    if (h.normal.prediction == Prediction::kSurfaceNormal) {
      if (!mesh->adj_built) {
        mesh->adj.Build(*mesh->tris, mesh->n);
        mesh->adj_built = true;
      }
      geo.position_of = mesh->position_of;
      s = DecodeOctNormals(&dec, mesh->adj, geo, mesh->n, h.normal.bits, &m->normals);
      if (s == Status::kOk) expand(&m->normals, 3);
    } else {
      s = decode_float(h.normal, &m->normals);
    }
    if (s != Status::kOk) return s;
  }
  si.normals = dec.BytesConsumed() - mark;
  for (const AttributeDesc& d : h.floats) {
    mark = dec.BytesConsumed();
    DecodedFloatAttribute a;
    a.semantic = d.semantic;
    a.dimension = d.dimension;
    if ((s = read_merges()) != Status::kOk) return s;
    if ((s = decode_float(d, &a.values)) != Status::kOk) return s;
    m->float_attributes.push_back(std::move(a));
    si.float_attributes.push_back(dec.BytesConsumed() - mark);
  }
  for (const AttributeDesc& d : h.ints) {
    mark = dec.BytesConsumed();
    DecodedIntAttribute a;
    a.semantic = d.semantic;
    a.dimension = d.dimension;
    if ((s = read_merges()) != Status::kOk) return s;
    if ((s = DecodeInts(&dec, mesh->n, int(d.dimension), d.prediction, &a.values)) != Status::kOk) {
      return s;
    }
    expand(&a.values, d.dimension);
    m->int_attributes.push_back(std::move(a));
    si.int_attributes.push_back(dec.BytesConsumed() - mark);
  }
  return Status::kOk;
}

O3DGC_WASM_MINSIZE Status DecodeGroups(DecodeState& st, DecodedMesh* m) {
  ArithmeticDecoder& dec = st.dec;
  if (!st.h.has_groups) return Status::kOk;
  m->triangle_groups.resize(st.nt);
  uint32_t prev = 0;
  for (size_t j = 0; j < st.nt; ++j) {
    if (!dec.Decode(st.sm->group_same)) {
      const uint64_t g = DecodeEG(dec, st.sm->group_value);
      if (g > 0xFFFFFFFFu) return Status::kCorrupt;
      prev = uint32_t(g);
    }
    m->triangle_groups[j] = prev;
    if ((j & 1023) == 0 && dec.failed()) return Status::kTruncated;
  }
  return Status::kOk;
}

// New vertex i is input vertex vertex_perm[i]; decoded triangle j is input triangle
// triangle_perm[j] starting at corner rotation[j].
O3DGC_WASM_MINSIZE void ApplyExactOrder(const DecodeState& st, DecodedMesh* mesh) {
  const uint32_t nv = st.nv;
  const size_t nt = st.nt;
  const std::vector<uint32_t>& vertex_perm = st.vertex_perm;
  DecodedMesh& m = *mesh;
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
  if (st.h.has_groups) o.triangle_groups.resize(nt);
  for (size_t j = 0; j < nt; ++j) {
    const uint32_t t = st.triangle_perm[j];
    for (int k = 0; k < 3; ++k) {
      o.indices[3 * size_t(t) + k] = vertex_perm[m.indices[3 * j + (st.rotation[j] + k) % 3]];
    }
    if (st.h.has_groups) o.triangle_groups[t] = m.triangle_groups[j];
  }
  m = std::move(o);
}

Status DecodeBinary(const uint8_t* data, size_t size, const DecodeOptions& options,
                    DecodedMesh* out, StreamInfo* info) {
  auto progress = [&](float f) { return !options.progress || options.progress(f); };
  DecodeState st;
  Status s = DecodeHeaders(data, size, options, st);
  if (s != Status::kOk) return s;
  ArithmeticDecoder& dec = st.dec;
  StreamInfo& si = st.si;
  size_t mark = dec.BytesConsumed();
  if ((s = DecodeTriangles(st)) != Status::kOk) return s;
  if ((s = DecodeSeams(st)) != Status::kOk) return s;
  if (st.sh.keep_order && (s = DecodeExactOrder(st)) != Status::kOk) return s;
  if (dec.failed()) return Status::kTruncated;
  si.connectivity = dec.BytesConsumed() - mark;
  if (!progress(0.4f)) return Status::kCancelled;

  DecodedMesh m;
  mark = dec.BytesConsumed();
  if ((s = DecodePositions(st, &m)) != Status::kOk) return s;
  si.positions = dec.BytesConsumed() - mark;
  if (!progress(0.6f)) return Status::kCancelled;

  if ((s = DecodeAttributes(st, &m)) != Status::kOk) return s;
  if (!progress(0.9f)) return Status::kCancelled;

  mark = dec.BytesConsumed();
  if ((s = DecodeGroups(st, &m)) != Status::kOk) return s;
  if (dec.failed()) return Status::kTruncated;
  AddTailBytes(st.h, st.sh.payload_size > mark ? st.sh.payload_size - mark : 0, &si);
  m.indices = st.has_seams ? std::move(st.seam_tris) : std::move(st.tris);
  if (st.sh.keep_order) ApplyExactOrder(st, &m);
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
  if (IsLegacyStream(data, size)) {
#ifdef O3DGC_NO_LEGACY_DECODER  // a build without their decoder (the default WebAssembly one)
    return Status::kUnsupported;
#else
    return DecodeLegacy(data, size, options, out, info);
#endif
  }
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

O3DGC_WASM_MINSIZE Status ReadStreamInfo(const uint8_t* data, size_t size, StreamInfo* info) {
  if (!info || (!data && size > 0)) return Status::kInvalidArgument;
  if (IsLegacyStream(data, size)) {
#ifdef O3DGC_NO_LEGACY_DECODER
    return Status::kUnsupported;
#else
    return ReadLegacyStreamInfo(data, size, info);
#endif
  }
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
  info->low_bits = sh.low_bits;
  info->all_adaptive = sh.all_adaptive;
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
