// TFAN connectivity decoding for original Open3DGC streams (see legacy_connectivity_decoder.h).
#include "legacy_connectivity_decoder.h"

#include <algorithm>

#include "legacy_arithmetic_decoder.h"

namespace o3dgc {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;

// One of the symbol arrays, read front to back.
struct SymbolArray {
  std::vector<int64_t> v;
  size_t next = 0;
  bool Take(int64_t* out) {
    if (next >= v.size()) return false;
    *out = v[next++];
    return true;
  }
};

// Binary sections: [u32 section bytes][u32 count] then, if count > 0, [u32 offset] (not for bit
// arrays) and the arithmetic-coded bytes. `offset_bias` is subtracted from the stored offset.
enum class BinaryKind { kIntEG, kUInt, kBit };

Status LoadBinary(LegacyReader* r, BinaryKind kind, uint32_t m, size_t limit, SymbolArray* out) {
  const uint64_t section = r->ReadUInt32();
  const uint64_t count = r->ReadUInt32();
  if (r->failed()) return Status::kTruncated;
  if (count == 0) return Status::kOk;  // the section is just the two fields
  if (count > limit) return Status::kCorrupt;
  int64_t offset = 0;
  size_t fields = 8;
  if (kind != BinaryKind::kBit) {
    const uint64_t stored = r->ReadUInt32();
    // Signed arrays store min + (2^31 - 1); unsigned ones the min itself.
    offset = kind == BinaryKind::kIntEG ? int64_t(stored) - 0x7FFFFFFF : int64_t(stored);
    fields = 12;
  }
  if (r->failed()) return Status::kTruncated;
  if (section < fields) return Status::kCorrupt;
  const uint64_t bytes = section - fields;
  if (bytes > r->remaining()) return Status::kTruncated;
  const size_t begin = r->pos(), end = begin + size_t(bytes);
  LegacyArithmeticDecoder dec(r->data(), begin, end, r->size());
  out->v.resize(size_t(count));
  LegacyAdaptiveDataModel values;
  LegacyStaticBitModel eg_bits;
  LegacyAdaptiveBitModel eg_prefix, bit_model;
  if (kind != BinaryKind::kBit && !values.Init(kind == BinaryKind::kIntEG ? m + 2 : m + 1)) {
    return Status::kCorrupt;
  }
  for (size_t i = 0; i < count; ++i) {
    uint64_t s;
    if (kind == BinaryKind::kBit) {
      s = dec.Decode(bit_model);
    } else {
      s = dec.Decode(values);
      if (kind == BinaryKind::kIntEG && s == m) {
        uint32_t extra;
        if (!dec.DecodeExpGolomb(0, eg_bits, eg_prefix, &extra)) return Status::kCorrupt;
        s += extra;
      }
    }
    out->v[i] = int64_t(s) + offset;
    if ((i & 1023) == 0 && dec.failed()) return Status::kCorrupt;
  }
  if (dec.failed()) return Status::kCorrupt;
  r->Seek(end);
  return Status::kOk;
}

// ASCII sections: [u32 section bytes][u32 count] then the values, one variable-length number
// each (kBit: 7 bits per byte, least significant first).
Status LoadAscii(LegacyReader* r, BinaryKind kind, size_t limit, SymbolArray* out) {
  r->ReadUInt32();  // section bytes: not needed to read the values
  const uint64_t count = r->ReadUInt32();
  if (r->failed()) return Status::kTruncated;
  if (count > limit) return Status::kCorrupt;
  const uint64_t bytes = kind == BinaryKind::kBit ? (count + 6) / 7 : count;
  if (bytes > r->remaining()) return Status::kTruncated;  // every value takes a byte at least
  if (kind == BinaryKind::kBit) {
    out->v.resize(size_t(bytes) * 7);
    for (size_t i = 0; i < bytes; ++i) {
      const uint8_t symbol = r->ReadByte();
      for (int h = 0; h < 7; ++h) out->v[7 * i + size_t(h)] = (symbol >> h) & 1;
    }
  } else {
    out->v.resize(size_t(count));
    for (size_t i = 0; i < count; ++i) {
      out->v[i] = kind == BinaryKind::kIntEG ? r->ReadAsciiInt() : int64_t(r->ReadAsciiUInt());
    }
  }
  return r->failed() ? Status::kTruncated : Status::kOk;
}

// Vertex-to-triangle incidence while triangles are being added. Lists are unordered: every use
// (visited sets, predictor candidates, normal sums) depends only on their content.
struct Incidence {
  std::vector<uint32_t> head, count, next, tri;
  uint32_t capacity = 0;
  explicit Incidence(uint32_t nv, uint32_t cap, size_t entries)
      : head(nv, kNone), count(nv, 0), capacity(cap) {
    next.reserve(entries);
    tri.reserve(entries);
  }
  // The original keeps at most `capacity` (the encoder's largest vertex degree) triangles per
  // vertex; a valid stream never needs more.
  bool Add(uint32_t v, uint32_t t) {
    if (count[v] >= capacity) return false;
    ++count[v];
    next.push_back(head[v]);
    tri.push_back(t);
    head[v] = uint32_t(tri.size() - 1);
    return true;
  }
};

class TfanDecoder {
 public:
  TfanDecoder(uint32_t nv, uint32_t nt, uint32_t capacity, SymbolArray* arrays)
      : nv_(nv),
        nt_(nt),
        inc_(nv, capacity, 3 * size_t(nt)),
        fans_(arrays[0]),
        degrees_(arrays[1]),
        configs_(arrays[2]),
        ops_(arrays[3]),
        indices_(arrays[4]) {
    triangles_.reserve(3 * size_t(nt));
  }

  Status Run() {
    for (uint32_t focus = 0; focus < nv_; ++focus) {
      if (focus == vertex_count_) ++vertex_count_;
      GatherVisited(focus);
      const Status s = DecodeFans(focus);
      if (s != Status::kOk) return s;
    }
    return triangles_.size() == 3 * size_t(nt_) ? Status::kOk : Status::kCorrupt;
  }
  std::vector<uint32_t>& triangles() { return triangles_; }

 private:
  // The vertices after `focus` in its decoded triangles, by id, with how often they occur; when
  // there are more than two, those occurring once go first (each group keeps id order).
  void GatherVisited(uint32_t focus) {
    scratch_.clear();
    conquered_ = 0;
    for (uint32_t e = inc_.head[focus]; e != kNone; e = inc_.next[e]) {
      ++conquered_;
      const uint32_t* t = &triangles_[3 * size_t(inc_.tri[e])];
      for (int k = 0; k < 3; ++k) {
        if (t[k] > focus) scratch_.push_back(t[k]);
      }
    }
    std::sort(scratch_.begin(), scratch_.end());
    visited_.clear();
    valence_.clear();
    for (size_t i = 0; i < scratch_.size(); ++i) {
      if (i > 0 && scratch_[i] == scratch_[i - 1]) {
        ++valence_.back();
      } else {
        visited_.push_back(scratch_[i]);
        valence_.push_back(1);
      }
    }
    if (visited_.size() > 2) {
      scratch_.clear();
      for (size_t i = 0; i < visited_.size(); ++i) {
        if (valence_[i] == 1) scratch_.push_back(visited_[i]);
      }
      for (size_t i = 0; i < visited_.size(); ++i) {
        if (valence_[i] != 1) scratch_.push_back(visited_[i]);
      }
      visited_.swap(scratch_);
    }
  }

  bool AddVisited(size_t i) {
    if (i >= visited_.size()) return false;
    fan_.push_back(visited_[i]);
    return true;
  }
  bool AddNew() {
    if (vertex_count_ >= nv_) return false;
    visited_.push_back(vertex_count_);
    fan_.push_back(vertex_count_++);
    return true;
  }
  // A fan vertex chosen by an operation bit: a new vertex, or an existing one by reference
  // (negative: the (-i)th visited vertex; else an offset from the focus vertex).
  bool AddByOperation(uint32_t focus) {
    int64_t op;
    if (!ops_.Take(&op)) return false;
    if (op != 1) return AddNew();
    int64_t index;
    if (!indices_.Take(&index)) return false;
    if (index < 0) return AddVisited(size_t(-(index + 1)));
    const int64_t v = index + int64_t(focus);
    if (v >= int64_t(nv_)) return false;
    fan_.push_back(uint32_t(v));
    return true;
  }

  Status DecodeFans(uint32_t focus) {
    int64_t num_fans;
    if (!fans_.Take(&num_fans)) return Status::kCorrupt;
    for (int64_t f = 0; f < num_fans; ++f) {
      int64_t degree, config;
      if (!degrees_.Take(&degree) || !configs_.Take(&config)) return Status::kCorrupt;
      degree += 2 - int64_t(conquered_);
      fan_.assign(1, focus);
      bool ok = true;
      switch (config) {
        case 0:  // first visited, new vertices, second visited
        case 7:  // second visited, new vertices, first visited
          ok = AddVisited(config == 0 ? 0 : 1);
          for (int64_t u = 1; ok && u < degree - 1; ++u) ok = AddNew();
          ok = ok && AddVisited(config == 0 ? 1 : 0);
          break;
        case 1:  // first visited, coded vertices, second visited
        case 8:  // second visited, coded vertices, first visited
          ok = AddVisited(config == 1 ? 0 : 1);
          for (int64_t u = 1; ok && u < degree - 1; ++u) ok = AddByOperation(focus);
          ok = ok && AddVisited(config == 1 ? 1 : 0);
          break;
        case 2:  // new vertices, then first visited
        case 3:  // new vertices, then second visited
          for (int64_t u = 0; ok && u < degree - 1; ++u) ok = AddNew();
          ok = ok && AddVisited(config == 2 ? 0 : 1);
          break;
        case 4:  // first visited, then new vertices
        case 5:  // second visited, then new vertices
          ok = AddVisited(config == 4 ? 0 : 1);
          for (int64_t u = 1; ok && u < degree; ++u) ok = AddNew();
          break;
        case 6:  // new vertices only
          for (int64_t u = 0; ok && u < degree; ++u) ok = AddNew();
          break;
        case 9:  // every vertex coded
          for (int64_t u = 0; ok && u < degree; ++u) ok = AddByOperation(focus);
          break;
        default:
          ok = false;
      }
      if (!ok) return Status::kCorrupt;
      for (size_t k = 2; k < fan_.size(); ++k) {
        if (triangles_.size() >= 3 * size_t(nt_)) return Status::kCorrupt;
        const uint32_t t = uint32_t(triangles_.size() / 3);
        const uint32_t b = fan_[k - 1], c = fan_[k];
        triangles_.insert(triangles_.end(), {focus, b, c});
        if (!inc_.Add(focus, t) || !inc_.Add(b, t) || !inc_.Add(c, t)) return Status::kCorrupt;
      }
    }
    return Status::kOk;
  }

  uint32_t nv_, nt_;
  uint32_t vertex_count_ = 0;
  uint32_t conquered_ = 0;
  Incidence inc_;
  SymbolArray &fans_, &degrees_, &configs_, &ops_, &indices_;
  std::vector<uint32_t> triangles_, visited_, valence_, scratch_, fan_;
};

}  // namespace

Status DecodeLegacyConnectivity(LegacyReader* r, uint32_t num_vertices, uint32_t num_triangles,
                                LegacyConnectivity* out) {
  const uint8_t mask = r->ReadUChar();
  const uint64_t capacity = r->ReadUInt32();
  if (r->failed()) return Status::kTruncated;
  if (mask & 1) return Status::kUnsupported;  // coded vertex order: never implemented
  const bool has_order = (mask & 2) != 0;
  if (capacity > 0xFFFFFFFFu || num_vertices == 0 || num_triangles == 0) return Status::kCorrupt;
  // No array of a valid stream is longer than this (fans and their vertices are bounded by
  // triangles and vertices); it bounds allocations by the header's (already bounded) counts.
  const size_t limit = 4 * (size_t(num_vertices) + num_triangles) + 64;
  SymbolArray arrays[6];
  const bool ascii = r->encoding() == LegacyEncoding::kAscii;
  // Fans per vertex, degrees, configurations, operation bits, references, triangle order.
  const BinaryKind kinds[6] = {BinaryKind::kIntEG, BinaryKind::kIntEG, BinaryKind::kUInt,
                               BinaryKind::kBit,   BinaryKind::kIntEG, BinaryKind::kIntEG};
  const BinaryKind ascii_kinds[6] = {BinaryKind::kUInt, BinaryKind::kUInt,  BinaryKind::kUInt,
                                     BinaryKind::kBit,  BinaryKind::kIntEG, BinaryKind::kUInt};
  const uint32_t alphabet[6] = {4, 16, 10, 0, 8, 16};
  for (int i = 0; i < (has_order ? 6 : 5); ++i) {
    const Status s = ascii ? LoadAscii(r, ascii_kinds[i], limit, &arrays[i])
                           : LoadBinary(r, kinds[i], alphabet[i], limit, &arrays[i]);
    if (s != Status::kOk) return s;
  }
  TfanDecoder tfan(num_vertices, num_triangles, uint32_t(capacity), arrays);
  const Status s = tfan.Run();
  if (s != Status::kOk) return s;
  out->triangles.swap(tfan.triangles());
  out->placement.clear();
  if (has_order) {
    // Each entry is the zigzag-coded step from the previous triangle's position + 1.
    std::vector<uint8_t> used(num_triangles, 0);
    out->placement.resize(num_triangles);
    int64_t next = 0;
    SymbolArray& order = arrays[5];
    for (uint32_t i = 0; i < num_triangles; ++i) {
      int64_t step;
      if (!order.Take(&step) || step < 0) return Status::kCorrupt;
      const int64_t t = LegacyUnsignedToSigned(uint64_t(step)) + next;
      if (t < 0 || t >= int64_t(num_triangles) || used[size_t(t)]) return Status::kCorrupt;
      used[size_t(t)] = 1;
      out->placement[i] = uint32_t(t);
      next = t + 1;
    }
  }
  return Status::kOk;
}

}  // namespace o3dgc
