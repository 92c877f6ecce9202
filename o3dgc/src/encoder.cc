// Top-level encoder: validation, position welding, and the sequence of payload parts
// (see payload_header.h for the layout; decoder.cc mirrors every step).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "arithmetic_coder.h"
#include "ascii_stream.h"
#include "attribute_coder.h"
#include "connectivity_encoder.h"
#include "decision_log.h"
#include "degenerate_triangles.h"
#include "entropy.h"
#include "key_table.h"
#include "o3dgc/o3dgc.h"
#include "payload_header.h"
#include "predictors.h"
#include "stream_header.h"

namespace o3dgc {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;
constexpr size_t kMaxCount = size_t(1) << 28;
constexpr double kAutoFastDecodeCost = 1.025;  // see EncodeParams::auto_fast_decode
constexpr double kAutoFastDecodeTry = 1.05;    // estimated bits from which the id order loses

Prediction ResolveFloat(Prediction p, Semantic s) {
  if (p != Prediction::kDefault) return p;
  return s == Semantic::kColor ? Prediction::kDifferential : Prediction::kParallelogram;
}

// Copies `count` vectors of `dim` elements at `stride` bytes into a dense array.
template <typename T>
std::vector<T> Gather(const T* data, size_t stride, uint32_t dim, size_t count) {
  if (stride == 0) stride = dim * sizeof(T);
  std::vector<T> out(count * dim);
  for (size_t i = 0; i < count; ++i) {
    std::memcpy(&out[i * dim], reinterpret_cast<const char*>(data) + i * stride, dim * sizeof(T));
  }
  return out;
}

bool AllFinite(const std::vector<float>& v) {
  for (float f : v) {
    if (!std::isfinite(f)) return false;
  }
  return true;
}

std::vector<float> Reorder(const std::vector<float>& v, uint32_t dim,
                           const std::vector<uint32_t>& old_of_new) {
  std::vector<float> out(old_of_new.size() * dim);
  for (size_t i = 0; i < old_of_new.size(); ++i) {
    std::memcpy(&out[i * dim], &v[size_t(old_of_new[i]) * dim], dim * sizeof(float));
  }
  return out;
}

}  // namespace

// What every position grid shares: the stages up to the positions (validation, welding,
// connectivity, seams, the order tables), their coded decisions recorded, and the positions'
// wedges. The stages follow the payload's parts (payload_header.h); decoder.cc mirrors each.
struct GridEncoder::Prepared {
  Prepared(const MeshView& m, const EncodeParams& p)
      : mesh(m), params(p), nv(m.num_vertices), nt(m.num_triangles) {}
  MeshView mesh;  // the caller's, or `kept`'s view of it
  const EncodeParams params;
  size_t nv, nt;
  KeptMesh kept;    // the input without its degenerate triangles, when it has any
  PayloadHeader h;  // the position quantizer is each grid's
  // The input's values, dense: `positions` points at the caller's array when it is dense, else
  // at own_positions.
  const float* positions = nullptr;
  std::vector<float> own_positions, normals;
  std::vector<std::vector<float>> floats;
  std::vector<std::vector<int32_t>> ints;
  // Welding: input vertex -> welded vertex (kNone if unreferenced), the triangles over them.
  std::vector<uint32_t> weld;
  uint32_t num_welded = 0;
  // Empty when welding changes no index (every vertex referenced, no two equal): the connectivity
  // then reads mesh.indices itself.
  std::vector<uint32_t> welded_tris;
  // The connectivity's, seams' and order tables' decisions, coded after each grid's header.
  DecisionLog log;
  // Connectivity: the decoder's numbering of welded vertices, the input vertex at each decoded
  // corner, the rotation of each decoded triangle.
  ConnectivityEncoding conn;
  uint32_t nc = 0;
  std::vector<uint32_t> welded_new, corner_vertex;
  std::vector<uint8_t> rotation;
  std::unique_ptr<SideModels> sm{new SideModels};
  // Seams: new (decoded) vertex id of each input vertex and back, the position vertex of each,
  // an input vertex for each position vertex.
  std::vector<uint32_t> orig_new, old_of_orig, welded_of_orig, rep_of_welded;
  uint32_t nw = 0;
  bool has_seams = false;
  // The positions' wedges (parallelogram prediction), the same for every grid.
  WedgeTable wedges;
};

namespace {

using Prepared = GridEncoder::Prepared;

// One grid's stream.
struct GridState {
  GridState(const Prepared& p, int bits, RangeMode range)
      : pre(p),
        h(p.h),
        fast_decode(p.params.fast_decode),
        order(CodingOrder::ForStream(p.params.fast_decode)) {
    h.position.bits = bits;
    h.position.range = range;
    // Only where a section could code its low bits raw: a smaller stream stays readable by 1.2.
    all_adaptive = p.params.max_compression && (p.nw >= kRawLowBitsMesh || p.nv >= kRawLowBitsMesh);
  }
  const Prepared& pre;
  PayloadHeader h;
  std::vector<uint8_t> payload;
  ArithmeticEncoder enc{&payload};
  StreamInfo si;
  bool fast_decode;  // the stream's flag (EncodeParams::fast_decode or auto_fast_decode)
  CodingOrder::Kind order;
  std::unique_ptr<SideModels> sm{new SideModels};
  std::vector<int32_t> qpos;  // quantized positions per position vertex
  bool low_bits = false;      // format 1.2's modelled low bits (decided by the positions)
  bool all_adaptive = false;  // format 1.3: no raw low bits (EncodeParams::max_compression)
};

// Bytes of one section of quantized values coded alone (the choice of LowBits).
size_t SectionBytes(const WedgeTable* wedges, const std::vector<int32_t>& q, int dim, int bits,
                    Prediction mode, CodingOrder::Kind order, const std::vector<double>* geometry,
                    LowBits low_bits, bool all_adaptive) {
  std::vector<uint8_t> scratch;
  ArithmeticEncoder e(&scratch);
  EncodeQuantized(&e, wedges, q, dim, bits, mode, order, geometry, low_bits, true, all_adaptive);
  e.Finish();
  return scratch.size();
}

// Modelled low bits pay on meshes built on a design grid, whose residuals recur; elsewhere the
// trees learn slower than the plain models. They cost decoding time (a decision per low bit, the
// trees' set-up), so the stream takes them (format 1.2) only when the positions, coded alone, get
// smaller by kLowBitsMinGain bytes (which covers the section bits of the other attributes) and by
// 1 / kLowBitsMinShare of their bytes; the other sections then choose on their own.
constexpr size_t kLowBitsMinGain = 2;
constexpr size_t kLowBitsMinShare = 32;

// Frees a working array whose last stage is done: the encoder's peak memory is the sum of the
// arrays alive at once.
template <typename T>
void Release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

// The working arrays the stages after connectivity and seams no longer read.
void ReleaseConnectivityWork(Prepared& st) {
  Release(st.welded_tris);
  Release(st.weld);
  Release(st.welded_new);
  Release(st.rotation);
  Release(st.conn.old_of_new);
  if (!st.h.has_groups) Release(st.conn.source);
  if (!st.h.has_normals && st.h.floats.empty()) Release(st.corner_vertex);
}

// The checks that need no copy of the input.
// (The position bits are checked per grid: ValidGrid.)
Status Validate(const MeshView& mesh, const EncodeParams& params) {
  const size_t nv = mesh.num_vertices, nt = mesh.num_triangles;
  if (nv > kMaxCount || nt > kMaxCount) return Status::kInvalidArgument;
  if ((nv > 0 && !mesh.positions) || (nt > 0 && !mesh.indices)) return Status::kInvalidArgument;
  if (params.normal_bits < 1 || params.normal_bits > 30) return Status::kInvalidArgument;
  if (params.position_prediction == Prediction::kSurfaceNormal) return Status::kInvalidArgument;
  if (params.max_compression && params.fast_decode) return Status::kInvalidArgument;
  for (size_t i = 0; i < 3 * nt; ++i) {
    if (mesh.indices[i] >= nv) return Status::kInvalidArgument;
  }
  return Status::kOk;
}

bool ValidGrid(int position_bits) { return position_bits >= 1 && position_bits <= 30; }

bool AllFinite(const float* v, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

// Whether the box is finite and holds each of the `n` positions.
bool InsideBox(const std::array<float, 6>& box, const float* positions, size_t n) {
  if (!AllFinite(box.data(), box.size())) return false;
  for (size_t i = 0; i < 3 * n; ++i) {
    const size_t k = i % 3;
    if (!(positions[i] >= box[k] && positions[i] <= box[3 + k])) return false;
  }
  return true;
}

// Attribute descriptors and quantizers (but the positions', which is each grid's); the input's
// values copied densely where they are not (and checked).
Status Describe(Prepared& st) {
  const MeshView& mesh = st.mesh;
  const EncodeParams& params = st.params;
  const size_t nv = st.nv;
  const size_t nt = st.nt;
  PayloadHeader& h = st.h;
  std::vector<float>& normals = st.normals;
  std::vector<std::vector<float>>& floats = st.floats;
  std::vector<std::vector<int32_t>>& ints = st.ints;
  // Descriptors.
  h.num_vertices = nv;
  h.num_triangles = nt;
  h.has_normals = mesh.normals != nullptr;
  h.has_groups = mesh.triangle_groups != nullptr;
  h.position.semantic = Semantic::kPosition;
  h.position.dimension = 3;
  h.position.prediction = params.position_prediction == Prediction::kDefault
                              ? Prediction::kParallelogram
                              : params.position_prediction;
  if (mesh.position_stride == 0 || mesh.position_stride == 3 * sizeof(float)) {
    st.positions = mesh.positions;
  } else {
    st.own_positions = Gather(mesh.positions, mesh.position_stride, 3, nv);
    st.positions = st.own_positions.data();
  }
  if (nv > 0 && !AllFinite(st.positions, 3 * nv)) return Status::kInvalidArgument;
  if (params.position_box && !InsideBox(*params.position_box, st.positions, nv))
    return Status::kInvalidArgument;
  if (h.has_normals) {
    h.normal.semantic = Semantic::kNormal;
    h.normal.dimension = 3;
    h.normal.bits = params.normal_bits;
    h.normal.prediction = params.normal_prediction == Prediction::kDefault
                              ? Prediction::kSurfaceNormal
                              : params.normal_prediction;
    h.normal.range = RangeMode::kPerAxis;
    normals = Gather(mesh.normals, mesh.normal_stride, 3, nv);
    if (!AllFinite(normals)) return Status::kInvalidArgument;
  }
  for (const FloatAttributeView& a : mesh.float_attributes) {
    if (a.dimension < 1 || a.dimension > 4 || a.bits < 1 || a.bits > 30) {
      return Status::kInvalidArgument;
    }
    if ((nv > 0 && !a.data) || uint8_t(a.semantic) > uint8_t(Semantic::kJointId)) {
      return Status::kInvalidArgument;
    }
    AttributeDesc d;
    d.semantic = a.semantic;
    d.dimension = a.dimension;
    d.bits = a.bits;
    d.prediction = ResolveFloat(a.prediction, a.semantic);
    if (d.prediction == Prediction::kSurfaceNormal) return Status::kInvalidArgument;
    d.range = a.range;
    h.floats.push_back(d);
    floats.push_back(nv ? Gather(a.data, a.stride, a.dimension, nv) : std::vector<float>());
    if (!AllFinite(floats.back())) return Status::kInvalidArgument;
  }
  for (const IntAttributeView& a : mesh.int_attributes) {
    if (a.dimension < 1 || a.dimension > 4 || (nv > 0 && !a.data) ||
        uint8_t(a.semantic) > uint8_t(Semantic::kJointId)) {
      return Status::kInvalidArgument;
    }
    AttributeDesc d;
    d.semantic = a.semantic;
    d.dimension = a.dimension;
    d.prediction = a.prediction == Prediction::kDefault ? Prediction::kDifferential : a.prediction;
    if (d.prediction != Prediction::kNone && d.prediction != Prediction::kDifferential) {
      return Status::kInvalidArgument;
    }
    h.ints.push_back(d);
    ints.push_back(nv ? Gather(a.data, a.stride, a.dimension, nv) : std::vector<int32_t>());
  }
  if (h.floats.size() > 64 || h.ints.size() > 64) return Status::kInvalidArgument;

  // Quantizers.
  auto fit = [&](AttributeDesc* d, const std::vector<float>& v) {
    d->quant.dimension = d->dimension;
    d->quant.bits = d->bits;
    d->quant.mode = d->range;
    d->quant.Fit(v.data(), d->dimension * sizeof(float), nv);
  };
  if (h.has_normals && h.normal.prediction != Prediction::kSurfaceNormal) fit(&h.normal, normals);
  for (size_t i = 0; i < h.floats.size(); ++i) fit(&h.floats[i], floats[i]);
  // Values near FLT_MAX can give a range whose end overflows: not representable in a stream.
  if (h.has_normals && h.normal.prediction != Prediction::kSurfaceNormal &&
      !h.normal.quant.Valid()) {
    return Status::kUnsupported;
  }
  for (const AttributeDesc& d : h.floats) {
    if (!d.quant.Valid()) return Status::kUnsupported;
  }

  return Status::kOk;
}

void Weld(Prepared& st) {
  const MeshView& mesh = st.mesh;
  const size_t nv = st.nv;
  const size_t nt = st.nt;
  const float* positions = st.positions;
  std::vector<uint32_t>& weld = st.weld;
  uint32_t& num_welded = st.num_welded;
  std::vector<uint32_t>& welded_tris = st.welded_tris;
  // Weld referenced vertices with bitwise equal positions.
  weld.assign(nv, kNone);
  num_welded = 0;
  {
    std::vector<uint8_t> referenced(nv, 0);
    for (size_t i = 0; i < 3 * nt; ++i) referenced[mesh.indices[i]] = 1;
    KeyTable table(positions, nv);
    for (uint32_t v = 0; v < nv; ++v) {
      if (!referenced[v]) continue;
      const uint32_t first = table.FindOrInsert(v);
      weld[v] = first == v ? num_welded++ : weld[first];
    }
  }
  bool identity = num_welded == nv;
  for (uint32_t v = 0; v < nv && identity; ++v) identity = weld[v] == v;
  if (identity) return;
  welded_tris.resize(3 * nt);
  for (size_t i = 0; i < 3 * nt; ++i) welded_tris[i] = weld[mesh.indices[i]];
}

void EncodeTriangles(Prepared& st) {
  const MeshView& mesh = st.mesh;
  const size_t nt = st.nt;
  PayloadHeader& h = st.h;
  std::vector<uint32_t>& weld = st.weld;
  uint32_t& num_welded = st.num_welded;
  std::vector<uint32_t>& welded_tris = st.welded_tris;
  DecisionLog& enc = st.log;
  ConnectivityEncoding& conn = st.conn;
  uint32_t& nc = st.nc;
  std::vector<uint32_t>& welded_new = st.welded_new;
  std::vector<uint32_t>& corner_vertex = st.corner_vertex;
  std::vector<uint8_t>& rotation = st.rotation;
  // Connectivity over welded vertices.
  // The neighbour triangles themselves are needed only by parallelogram-predicted attributes
  // besides positions (across seams; positions use the opposite vertices).
  bool attribute_wedges = h.has_normals && h.normal.prediction == Prediction::kParallelogram;
  for (const AttributeDesc& d : h.floats)
    attribute_wedges |= d.prediction == Prediction::kParallelogram;
  const uint32_t* tris = welded_tris.empty() ? mesh.indices : welded_tris.data();
  EncodeConnectivity(tris, nt, num_welded, &enc, &conn, attribute_wedges, kFormatMinor);
  nc = uint32_t(conn.old_of_new.size());
  welded_new.assign(num_welded, kNone);
  for (uint32_t i = 0; i < nc; ++i) welded_new[conn.old_of_new[i]] = i;
  // Original corner of every decoded corner, and the rotation of every decoded triangle.
  corner_vertex.resize(3 * nt);
  rotation.assign(nt, 0);
  for (size_t j = 0; j < nt; ++j) {
    const uint32_t s = conn.source[j];
    const uint32_t* o = &mesh.indices[3 * size_t(s)];
    const uint32_t* d = &conn.triangles[3 * j];
    const uint32_t n0 = welded_new[weld[o[0]]], n1 = welded_new[weld[o[1]]],
                   n2 = welded_new[weld[o[2]]];
    if (n0 == n1 || n1 == n2 || n0 == n2) {
      for (int k = 0; k < 3; ++k) corner_vertex[3 * j + k] = o[k];
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const int m = d[k] == n0 ? 0 : (d[k] == n1 ? 1 : 2);
      corner_vertex[3 * j + k] = o[m];
      if (m == 0) rotation[j] = uint8_t(k);
    }
  }
}

void EncodeSeams(Prepared& st) {
  const size_t nv = st.nv;
  const size_t nt = st.nt;
  std::vector<uint32_t>& weld = st.weld;
  DecisionLog& enc = st.log;
  uint32_t& nc = st.nc;
  std::vector<uint32_t>& welded_new = st.welded_new;
  std::vector<uint32_t>& corner_vertex = st.corner_vertex;
  SideModels* const sm = st.sm.get();
  std::vector<uint32_t>& orig_new = st.orig_new;
  std::vector<uint32_t>& old_of_orig = st.old_of_orig;
  std::vector<uint32_t>& welded_of_orig = st.welded_of_orig;
  std::vector<uint32_t>& rep_of_welded = st.rep_of_welded;
  uint32_t& nw = st.nw;
  // Seams: attribute vertices per welded vertex, and which one each corner uses.
  std::vector<uint32_t> split_count(nc, 0);
  for (size_t v = 0; v < nv; ++v) {
    if (weld[v] != kNone) ++split_count[welded_new[weld[v]]];
  }
  bool has_seams = false;
  for (uint32_t w = 0; w < nc && !has_seams; ++w) has_seams = split_count[w] > 1;
  enc.EncodeBits(has_seams ? 1 : 0, 1);
  st.has_seams = has_seams;
  if (has_seams) {
    for (uint32_t w = 0; w < nc; ++w) EncodeEG(enc, sm->seam_count, split_count[w] - 1);
  }
  orig_new.assign(nv, kNone);
  std::vector<uint32_t> split_index(nv, kNone);
  std::vector<uint32_t> seen(nc, 0), last(nc, 0);
  old_of_orig.reserve(nv);
  for (size_t i = 0; i < 3 * nt; ++i) {
    const uint32_t o = corner_vertex[i];
    const uint32_t w = welded_new[weld[o]];
    const uint32_t s = split_index[o];
    if (split_count[w] > 1 && seen[w] > 0) {
      enc.Encode(s == last[w], sm->seam_same);
      if (s != last[w]) {
        if (seen[w] < split_count[w]) enc.Encode(s == kNone, sm->seam_new);
        if (s != kNone) enc.EncodeBits(s < last[w] ? s : s - 1, BitsFor(seen[w] - 1));
      }
    }
    if (s == kNone) {
      split_index[o] = seen[w]++;
      orig_new[o] = uint32_t(old_of_orig.size());
      old_of_orig.push_back(o);
    }
    last[w] = split_index[o];
  }
  // Unreferenced vertices follow, each its own welded vertex.
  welded_of_orig.resize(nv);
  for (uint32_t i = 0; i < old_of_orig.size(); ++i) {
    welded_of_orig[i] = welded_new[weld[old_of_orig[i]]];
  }
  rep_of_welded.assign(nc, kNone);
  for (uint32_t i = 0; i < old_of_orig.size(); ++i) {
    if (rep_of_welded[welded_of_orig[i]] == kNone)
      rep_of_welded[welded_of_orig[i]] = old_of_orig[i];
  }
  nw = nc;
  for (size_t v = 0; v < nv; ++v) {
    if (weld[v] != kNone) continue;
    orig_new[v] = uint32_t(old_of_orig.size());
    welded_of_orig[old_of_orig.size()] = nw++;
    old_of_orig.push_back(uint32_t(v));
    rep_of_welded.push_back(uint32_t(v));
  }
}

// The input order (keep_order): vertex and triangle permutations, corner rotations.
void EncodeExactOrder(Prepared& st) {
  const size_t nv = st.nv;
  const size_t nt = st.nt;
  DecisionLog& enc = st.log;
  ConnectivityEncoding& conn = st.conn;
  std::vector<uint8_t>& rotation = st.rotation;
  SideModels* const sm = st.sm.get();
  std::vector<uint32_t>& old_of_orig = st.old_of_orig;
  int64_t prev = -1;
  for (uint32_t i = 0; i < nv; ++i) {
    EncodeEG(enc, sm->perm_vertex, ZigZag(int64_t(old_of_orig[i]) - (prev + 1)));
    prev = old_of_orig[i];
  }
  prev = -1;
  for (size_t j = 0; j < nt; ++j) {
    EncodeEG(enc, sm->perm_triangle, ZigZag(int64_t(conn.source[j]) - (prev + 1)));
    prev = conn.source[j];
    enc.Encode(rotation[j] != 0, sm->rotation[0]);
    if (rotation[j] != 0) enc.Encode(rotation[j] == 2, sm->rotation[1]);
  }
}

// After the seams: the working arrays no grid needs, and the positions' wedges built.
void FinishPrepare(Prepared& st) {
  ReleaseConnectivityWork(st);
  st.log.ShrinkToFit();
  ConnectivityEncoding& conn = st.conn;
  if (st.h.position.prediction == Prediction::kParallelogram) {
    st.wedges.BuildFromOppositeVertices(conn.triangles, st.nw, conn.opposite_vertices,
                                        &conn.vertex_triangles, &conn.component_ends);
  }
  Release(conn.triangles);
  Release(conn.opposite_vertices);
  Release(conn.vertex_triangles);
  if (!st.h.has_normals && st.h.floats.empty() && st.h.ints.empty()) {
    // Only the attributes read the attribute vertices.
    Release(st.orig_new);
    Release(st.old_of_orig);
    Release(st.welded_of_orig);
  }
}

// Positions, per position (welded) vertex.
void EncodePositions(GridState& st) {
  const Prepared& pre = st.pre;
  const EncodeParams& params = pre.params;
  bool& fast_decode = st.fast_decode;
  CodingOrder::Kind& order = st.order;
  PayloadHeader& h = st.h;
  const float* positions = pre.positions;
  ArithmeticEncoder& enc = st.enc;
  const std::vector<uint32_t>& rep_of_welded = pre.rep_of_welded;
  const uint32_t nw = pre.nw;
  std::vector<int32_t>& qpos = st.qpos;
  qpos.resize(size_t(nw) * 3);
  for (uint32_t w = 0; w < nw; ++w) {
    for (uint32_t k = 0; k < 3; ++k) {
      qpos[3 * size_t(w) + k] =
          h.position.quant.Quantize(positions[3 * size_t(rep_of_welded[w]) + k], k);
    }
  }
  bool coded = false;  // the positions are in the stream already (auto_fast_decode)
  const WedgeTable& wedges = pre.wedges;
  // Whether each order uses the parallelogram selection, when its estimate tells (see
  // EncodeQuantized's expect_selection).
  bool selects[2] = {true, true};
  if (st.all_adaptive && h.position.prediction != Prediction::kNone) {
    // max_compression: the positions alone in the greedy order with every residual coded
    // adaptively (plain or with trees), against the raw coding of the default stream in either
    // order; the smallest sets the stream's flag and order, so that the option never makes a
    // stream larger (rocker_arm, whose residuals are large, gains nothing from adaptive low bits
    // and loses its class shifts).
    auto bytes = [&](CodingOrder::Kind kind, LowBits low_bits, bool all) {
      return SectionBytes(&wedges, qpos, 3, h.position.bits, h.position.prediction, kind, nullptr,
                          low_bits, all);
    };
    const size_t adaptive = std::min(bytes(CodingOrder::kGreedy, LowBits::kNoFlag, true),
                                     bytes(CodingOrder::kGreedy, LowBits::kModelled, true));
    const size_t raw_greedy = bytes(CodingOrder::kGreedy, LowBits::kNoFlag, false);
    const bool id_order = h.position.prediction == Prediction::kParallelogram;
    const size_t raw_id = id_order ? bytes(CodingOrder::kVertexId, LowBits::kNoFlag, false) : 0;
    if (std::min(raw_greedy, id_order ? raw_id : raw_greedy) < adaptive) {
      st.all_adaptive = false;
      if (id_order && raw_id < raw_greedy) {
        fast_decode = true;
        order = CodingOrder::kVertexId;
      }
    }
  }
  if (!fast_decode && params.auto_fast_decode && !params.max_compression &&
      h.position.prediction == Prediction::kParallelogram && RawLowBits(nw)) {
    // The bytes of the positions alone in each order (see EncodeParams::auto_fast_decode). The
    // estimates (a pass without coding) rule out the meshes where the id order is clearly
    // larger (CAD parts: 1.7-2.5x, igea 1.10x); they are too coarse to decide the close ones
    // (bunny: +0.7 % estimated, +4 % coded; a noisy scan: +0.6 %, +2.4 %).
    auto bits_in = [&](CodingOrder::Kind kind) {
      return EstimatePositionBits(wedges, qpos, h.position.bits, kind, &selects[kind]);
    };
    auto size_in = [&](CodingOrder::Kind kind) {
      std::vector<uint8_t> scratch;
      ArithmeticEncoder e(&scratch);
      EncodeQuantized(&e, &wedges, qpos, 3, h.position.bits, h.position.prediction, kind, nullptr,
                      LowBits::kNoFlag, selects[kind]);
      e.Finish();
      return double(scratch.size());
    };
    if (bits_in(CodingOrder::kVertexId) <= kAutoFastDecodeTry * bits_in(CodingOrder::kGreedy)) {
      // The id order is coded into the stream itself and the greedy order aside; if the id
      // order loses, the stream is rolled back and the greedy order coded again. Two codings
      // instead of three when the id order wins (the scans), the same three when it loses.
      const ArithmeticEncoder saved = enc;
      const size_t saved_size = st.payload.size();
      const size_t start = enc.BytesSoFar();
      EncodeQuantized(&enc, &wedges, qpos, 3, h.position.bits, h.position.prediction,
                      CodingOrder::kVertexId, nullptr, LowBits::kNoFlag,
                      selects[CodingOrder::kVertexId]);
      const double id_bytes = double(enc.BytesSoFar() - start);
      if (id_bytes <= kAutoFastDecodeCost * size_in(CodingOrder::kGreedy)) {
        fast_decode = true;
        order = CodingOrder::kVertexId;
        coded = true;
      } else {
        enc = saved;
        st.payload.resize(saved_size);
      }
    }
  }
  if (!coded) {
    const bool all = st.all_adaptive;
    if (HasLowBitsChoice(h.position.prediction, nw, 3, false, all)) {
      const size_t plain = SectionBytes(&wedges, qpos, 3, h.position.bits, h.position.prediction,
                                        order, nullptr, LowBits::kNoFlag, all);
      const size_t modelled = SectionBytes(&wedges, qpos, 3, h.position.bits, h.position.prediction,
                                           order, nullptr, LowBits::kModelled, all);
      st.low_bits =
          modelled + kLowBitsMinGain <= plain && (plain - modelled) * kLowBitsMinShare >= plain;
    }
    EncodeQuantized(&enc, &wedges, qpos, 3, h.position.bits, h.position.prediction, order, nullptr,
                    st.low_bits ? LowBits::kModelled : LowBits::kNoFlag, selects[order], all);
  }
}

// Normals, float and int attributes, over the attribute vertices.
// The mesh an attribute is coded over (see decoder.cc): the attribute vertices, or (format 1.1,
// with seams) those left once the ones equal to the first attribute vertex of their position
// vertex are merged into it; `input_of` maps its vertices to input vertices.
struct AttributeMesh {
  const std::vector<uint32_t>* tris = nullptr;
  uint32_t n = 0;
  const uint32_t* position_of = nullptr;
  const std::vector<uint32_t>* input_of = nullptr;
  std::vector<uint32_t> own_tris, own_position_of, own_input_of;
  MeshAdjacency adj;
  bool adj_built = false;
  WedgeTable wedges;
  bool wedges_built = false;
  std::vector<double> geometry;
};

// Format 1.1, with seams: codes which attribute vertices merge into the first attribute vertex of
// their position vertex (those holding bit for bit its value) and returns the mesh to code over.
// Why: UV seams split vertices whose normals, skin weights and joints are continuous across the
// seam (smooth shading, scans, DCC exports); coded per attribute vertex, each copy was coded
// again and its normal predicted from half a fan.
template <typename T>
AttributeMesh* CodeMerges(GridState& st, const std::vector<uint32_t>& attr_tris,
                          const std::vector<uint32_t>& first, const T* values, uint32_t dim,
                          AttributeMesh* attr, AttributeMesh* merged) {
  const Prepared& pre = st.pre;
  const size_t nv = pre.nv;
  std::vector<uint8_t> merge(nv, 0);
  bool any = false;
  for (uint32_t i = 0; i < nv; ++i) {
    const uint32_t f = first[pre.welded_of_orig[i]];
    if (f == i) continue;
    merge[i] = std::memcmp(values + size_t(pre.old_of_orig[i]) * dim,
                           values + size_t(pre.old_of_orig[f]) * dim, dim * sizeof(T)) == 0;
    any |= merge[i] != 0;
  }
  st.enc.EncodeBits(any ? 1 : 0, 1);
  if (!any) return attr;
  BitModel model;
  std::vector<uint32_t> of_vertex(nv);
  merged->own_position_of.clear();
  merged->own_input_of.clear();
  uint32_t n = 0;
  for (uint32_t i = 0; i < nv; ++i) {
    const uint32_t f = first[pre.welded_of_orig[i]];
    if (f != i) st.enc.Encode(merge[i], model);
    if (merge[i]) {
      of_vertex[i] = of_vertex[f];
    } else {
      of_vertex[i] = n++;
      merged->own_position_of.push_back(pre.welded_of_orig[i]);
      merged->own_input_of.push_back(pre.old_of_orig[i]);
    }
  }
  merged->own_tris.resize(attr_tris.size());
  for (size_t i = 0; i < attr_tris.size(); ++i) merged->own_tris[i] = of_vertex[attr_tris[i]];
  merged->tris = &merged->own_tris;
  merged->n = n;
  merged->position_of = merged->own_position_of.data();
  merged->input_of = &merged->own_input_of;
  merged->adj_built = merged->wedges_built = false;
  merged->geometry.clear();
  return merged;
}

void EncodeAttributes(GridState& st) {
  const Prepared& pre = st.pre;
  const size_t nv = pre.nv;
  const size_t nt = pre.nt;
  CodingOrder::Kind& order = st.order;
  PayloadHeader& h = st.h;
  const std::vector<float>& normals = pre.normals;
  const std::vector<std::vector<float>>& floats = pre.floats;
  const std::vector<std::vector<int32_t>>& ints = pre.ints;
  ArithmeticEncoder& enc = st.enc;
  StreamInfo& si = st.si;
  const ConnectivityEncoding& conn = pre.conn;
  const std::vector<uint32_t>& corner_vertex = pre.corner_vertex;
  const std::vector<uint32_t>& orig_new = pre.orig_new;
  std::vector<int32_t>& qpos = st.qpos;
  std::vector<uint32_t> attr_tris;  // only normals and float attributes need it (not ints)
  if (h.has_normals || !h.floats.empty()) {
    attr_tris.resize(3 * nt);
    for (size_t i = 0; i < 3 * nt; ++i) attr_tris[i] = orig_new[corner_vertex[i]];
  }
  AttributeMesh attr, merged;
  attr.tris = &attr_tris;
  attr.n = uint32_t(nv);
  attr.position_of = pre.welded_of_orig.data();
  attr.input_of = &pre.old_of_orig;
  const bool any = h.has_normals || !h.floats.empty() || !h.ints.empty();
  const bool may_merge = kFormatMinor >= 1 && pre.has_seams && any;
  std::vector<uint32_t> first;  // the first (smallest) attribute vertex of each position vertex
  if (may_merge) {
    first.assign(pre.nw, kNone);
    for (uint32_t i = uint32_t(nv); i-- > 0;) first[pre.welded_of_orig[i]] = i;
  }
  NormalGeometry geo;
  geo.positions = qpos.data();
  for (int k = 0; k < 3; ++k) {
    geo.scale[k] = double(h.position.quant.range[k]) / double(h.position.quant.max_q());
  }
  auto mesh_for = [&](const auto* values, uint32_t dim) {
    return may_merge ? CodeMerges(st, attr_tris, first, values, dim, &attr, &merged) : &attr;
  };
  auto code_float = [&](const AttributeDesc& d, const std::vector<float>& values) {
    AttributeMesh& mesh = *mesh_for(values.data(), d.dimension);
    const std::vector<float> v = Reorder(values, d.dimension, *mesh.input_of);
    std::vector<int32_t> q(v.size());
    for (size_t i = 0; i < v.size(); ++i) q[i] = d.quant.Quantize(v[i], uint32_t(i % d.dimension));
    const bool texcoord = d.semantic == Semantic::kTexCoord && d.dimension == 2 &&
                          d.prediction == Prediction::kParallelogram;
    geo.position_of = mesh.position_of;
    if (texcoord && mesh.geometry.empty()) mesh.geometry = AttributeGeometry(geo, mesh.n);
    if (d.prediction == Prediction::kParallelogram && !mesh.wedges_built) {
      mesh.wedges.Build(*mesh.tris, mesh.n, conn.opposite, true);
      mesh.wedges_built = true;
    }
    const std::vector<double>* geometry = texcoord ? &mesh.geometry : nullptr;
    const bool all = st.all_adaptive;
    LowBits low_bits = st.low_bits ? LowBits::kPlain : LowBits::kNoFlag;
    if (st.low_bits && HasLowBitsChoice(d.prediction, mesh.n, int(d.dimension), geometry, all)) {
      const size_t plain = SectionBytes(&mesh.wedges, q, int(d.dimension), d.bits, d.prediction,
                                        order, geometry, LowBits::kPlain, all);
      const size_t modelled = SectionBytes(&mesh.wedges, q, int(d.dimension), d.bits, d.prediction,
                                           order, geometry, LowBits::kModelled, all);
      if (modelled < plain && (plain - modelled) * kLowBitsMinShare >= plain) {
        low_bits = LowBits::kModelled;
      }
    }
    EncodeQuantized(&enc, &mesh.wedges, q, int(d.dimension), d.bits, d.prediction, order, geometry,
                    low_bits, true, all);
  };
  size_t mark = enc.BytesSoFar();
  if (h.has_normals) {
    if (h.normal.prediction == Prediction::kSurfaceNormal) {
      AttributeMesh& mesh = *mesh_for(normals.data(), 3);
      if (!mesh.adj_built) {
        mesh.adj.Build(*mesh.tris, mesh.n);
        mesh.adj_built = true;
      }
      geo.position_of = mesh.position_of;
      EncodeOctNormals(&enc, mesh.adj, geo, Reorder(normals, 3, *mesh.input_of), h.normal.bits);
    } else {
      code_float(h.normal, normals);
    }
  }
  si.normals = enc.BytesSoFar() - mark;
  for (size_t i = 0; i < h.floats.size(); ++i) {
    mark = enc.BytesSoFar();
    code_float(h.floats[i], floats[i]);
    si.float_attributes.push_back(enc.BytesSoFar() - mark);
  }
  for (size_t i = 0; i < h.ints.size(); ++i) {
    mark = enc.BytesSoFar();
    const uint32_t dim = h.ints[i].dimension;
    const AttributeMesh& mesh = *mesh_for(ints[i].data(), dim);
    std::vector<int32_t> v(size_t(mesh.n) * dim);
    for (size_t j = 0; j < mesh.n; ++j) {
      std::memcpy(&v[j * dim], &ints[i][size_t((*mesh.input_of)[j]) * dim], dim * sizeof(int32_t));
    }
    EncodeInts(&enc, v, int(dim), h.ints[i].prediction);
    si.int_attributes.push_back(enc.BytesSoFar() - mark);
  }
}

void EncodeGroups(GridState& st) {
  const MeshView& mesh = st.pre.mesh;
  const size_t nt = st.pre.nt;
  PayloadHeader& h = st.h;
  ArithmeticEncoder& enc = st.enc;
  const ConnectivityEncoding& conn = st.pre.conn;
  SideModels* const sm = st.sm.get();
  if (h.has_groups) {
    uint32_t prev = 0;
    for (size_t j = 0; j < nt; ++j) {
      const uint32_t g = mesh.triangle_groups[conn.source[j]];
      enc.Encode(g == prev, sm->group_same);
      if (g != prev) EncodeEG(enc, sm->group_value, g);
      prev = g;
    }
  }
}

// The stages up to the positions, for every grid.
Status PrepareStages(Prepared& st, const std::function<bool(float)>& progress) {
  Status s = Validate(st.mesh, st.params);
  if (s != Status::kOk) return s;
  if (!st.params.keep_order && !st.params.keep_degenerate_triangles &&
      LeaveOutDegenerateTriangles(st.mesh, &st.kept)) {
    st.mesh = st.kept.view;
    st.nv = st.mesh.num_vertices;
    st.nt = st.mesh.num_triangles;
  }
  if ((s = Describe(st)) != Status::kOk) return s;
  Weld(st);
  EncodeTriangles(st);
  if (!progress(0.2f)) return Status::kCancelled;
  EncodeSeams(st);
  if (st.params.keep_order) EncodeExactOrder(st);
  FinishPrepare(st);
  if (!progress(0.4f)) return Status::kCancelled;
  return Status::kOk;
}

// One grid's stream from the prepared stages. `release` (may be null: then `pre` is shared with
// other grids) is `pre` itself when this is its only grid: its arrays are freed once done.
Status EncodeGrid(const Prepared& pre, Prepared* release, int position_bits,
                  RangeMode position_range, const std::function<bool(float)>& progress,
                  std::vector<uint8_t>* out, StreamInfo* info) {
  if (!out || !ValidGrid(position_bits)) return Status::kInvalidArgument;
  std::unique_ptr<GridState> state(new GridState(pre, position_bits, position_range));
  GridState& st = *state;
  AttributeDesc& position = st.h.position;
  position.quant.dimension = 3;
  position.quant.bits = position.bits;
  position.quant.mode = position.range;
  if (pre.params.position_box) {
    // The grid depends on the positions' per-axis extremes alone: fitted on the box's corners it
    // is the grid of any positions whose extremes are those corners.
    position.quant.Fit(pre.params.position_box->data(), 3 * sizeof(float), 2);
  } else {
    position.quant.Fit(pre.positions, 3 * sizeof(float), pre.nv);
  }
  // Values near FLT_MAX can give a range whose end overflows: not representable in a stream.
  if (!position.quant.Valid()) return Status::kUnsupported;
  ArithmeticEncoder& enc = st.enc;
  StreamInfo& si = st.si;
  EncodePayloadHeader(&enc, st.h);
  si.header = enc.BytesSoFar();
  pre.log.ReplayInto(&enc);
  si.connectivity = enc.BytesSoFar() - si.header;
  size_t mark = enc.BytesSoFar();
  EncodePositions(st);
  si.positions = enc.BytesSoFar() - mark;
  if (release) {
    release->wedges = WedgeTable();
    Release(release->rep_of_welded);
  }
  if (!progress(0.6f)) return Status::kCancelled;
  EncodeAttributes(st);
  if (!progress(0.9f)) return Status::kCancelled;
  mark = enc.BytesSoFar();
  EncodeGroups(st);
  // Pad so that the decoder's size check holds (only pathological meshes need it).
  const PayloadHeader& h = st.h;
  const uint64_t budget = h.Budget();
  const uint64_t min_payload = (budget + kElementsPerByte - 1) / kElementsPerByte;
  enc.Finish(min_payload > kBudgetSlackBytes ? size_t(min_payload - kBudgetSlackBytes) : 0);
  AddTailBytes(h, st.payload.size() > mark ? st.payload.size() - mark : 0, &si);
  const EncodeParams& params = pre.params;
  out->clear();
  WriteHeader(params.keep_order, st.fast_decode, st.low_bits, st.all_adaptive, st.payload.size(),
              out);
  const size_t byte_header = out->size();
  out->insert(out->end(), st.payload.begin(), st.payload.end());
  Release(st.payload);
  FinalizeCrc(out);
  si.header += byte_header;
  si.stream_type = params.stream_type;
  si.version_major = kFormatMajor;
  si.version_minor = WrittenMinor(st.low_bits, st.all_adaptive);
  si.keep_order = params.keep_order;
  si.fast_decode = st.fast_decode;
  si.low_bits = st.low_bits;
  si.all_adaptive = st.all_adaptive;
  si.num_vertices = pre.nv;
  si.num_triangles = pre.nt;
  if (params.stream_type == StreamType::kAscii) *out = PackAscii(*out);
  si.total = out->size();
  if (info) *info = si;
  if (!progress(1.0f)) return Status::kCancelled;
  return Status::kOk;
}

std::function<bool(float)> Checked(const ProgressFn& fn) {
  return [fn](float f) { return !fn || fn(f); };
}

}  // namespace

GridEncoder::GridEncoder() = default;
GridEncoder::~GridEncoder() = default;

Status GridEncoder::Prepare(const MeshView& mesh, const EncodeParams& params) {
  prepared_.reset(new Prepared(mesh, params));
  const Status s = PrepareStages(*prepared_, Checked(params.progress));
  if (s != Status::kOk) prepared_.reset();
  return s;
}

Status GridEncoder::Encode(int position_bits, RangeMode position_range, std::vector<uint8_t>* out,
                           StreamInfo* info, const ProgressFn& progress) const {
  if (!prepared_) return Status::kInvalidArgument;
  return EncodeGrid(*prepared_, nullptr, position_bits, position_range, Checked(progress), out,
                    info);
}

Status Encode(const MeshView& mesh, const EncodeParams& params, std::vector<uint8_t>* out,
              StreamInfo* info) {
  if (!out || !ValidGrid(params.position_bits)) return Status::kInvalidArgument;
  const std::function<bool(float)> progress = Checked(params.progress);
  std::unique_ptr<Prepared> pre(new Prepared(mesh, params));
  const Status s = PrepareStages(*pre, progress);
  if (s != Status::kOk) return s;
  return EncodeGrid(*pre, pre.get(), params.position_bits, params.position_range, progress, out,
                    info);
}

}  // namespace o3dgc
