// Connectivity decoder (see connectivity_decoder.h and connectivity_encoder.cc, its mirror).
#include "connectivity_decoder.h"

#include <memory>

#include "connectivity_front.h"
#include "entropy.h"

namespace o3dgc {
namespace {

class Decoder {
 public:
  Decoder(ArithmeticDecoder* dec, size_t num_triangles, size_t max_vertices,
          std::vector<uint32_t>* out, bool keep_edges, uint32_t minor, bool compact)
      : dec_(*dec),
        nt_(num_triangles),
        max_vertices_(max_vertices),
        out_(*out),
        m_(new ConnectivityModels(minor)),
        keep_edges_(keep_edges),
        compact_(compact) {}

  Status Run() {
    ScopedDecoder scoped(&dec_);  // the state in registers for the loop
    ArithmeticDecoder& dec = *scoped;
    // The caller checked the counts against what the payload can hold, so sizing the output and
    // the front for them is bounded by the stream's size.
    out_.resize(nt_ * 3);
    tri_ = out_.data();
    front_.Reserve(max_vertices_ < nt_ + 3 ? max_vertices_ : nt_ + 3, nt_, keep_edges_, compact_);
    has_flips_ = dec.DecodeBits(1) != 0;
    has_copies_ = dec.DecodeBits(1) != 0;
    const bool rich = m_->rich;
    int prev = 0;  // the previous gate outcome (format 1.1 contexts)
    // Bounded work whatever the stream: every pass pops a gate (at most 3 per triangle) or starts
    // a triangle (at most nt_), so a truncated stream (read as zeros) is found after the loop.
    for (;;) {
      if (compact_) front_.MakeRoom();
      if (front_.empty()) {
        if (!dec.Decode(m_->more_components)) break;
        if (Full()) return Status::kCorrupt;
        components_.StartPart(front_.num_vertices());
        uint32_t x, y, z;
        Status s;
        if ((s = VertexRef(dec, &x)) != Status::kOk) return s;
        if ((s = VertexRef(dec, &y)) != Status::kOk) return s;
        if ((s = VertexRef(dec, &z)) != Status::kOk) return s;
        if (x == y || y == z || x == z) return Status::kCorrupt;
        front_.StartTriangle(uint32_t(count_), x, y, z);
        if ((s = Emit(dec, x, y, z)) != Status::kOk) return s;
        continue;
      }
      uint32_t a, b;
      const int32_t g = front_.PopWithEnds(&a, &b);
      if (g < 0) continue;
      const Front::Candidates cand = front_.Look(a, b, rich ? prev : -1);
      const int outcome = dec.Decode(m_->gate[size_t(cand.context)]);
      prev = outcome;
      if (outcome == kGateClose) {
        front_.Close(g);
        continue;
      }
      if (Full()) return Status::kCorrupt;
      uint32_t c;
      int32_t gate_bc = Front::kSearch;
      if (outcome == kGateNew) {
        if (front_.num_vertices() >= max_vertices_) return Status::kCorrupt;
        c = front_.AddVertex();
        gate_bc = Front::kNoGate;
      } else if (outcome == kGateRight && cand.right >= 0) {
        c = uint32_t(cand.right);
        gate_bc = cand.right_gate;
      } else if (outcome == kGateLeft && cand.left >= 0) {
        c = uint32_t(cand.left);
      } else if (outcome == kGateOther) {
        const Status s = Other(dec, a, b, &c);
        if (s != Status::kOk) return s;
      } else {
        return Status::kCorrupt;  // a candidate that does not exist, or an unused symbol
      }
      if (c == a || c == b) return Status::kCorrupt;
      const int flip = has_flips_ ? dec.Decode(m_->flip) : 0;
      front_.Attach(g, uint32_t(count_), a, b, c, flip != 0, gate_bc);
      const Status s = flip ? Emit(dec, a, b, c) : Emit(dec, b, a, c);
      if (s != Status::kOk) return s;
    }
    const uint64_t extras = DecodeEG(dec, m_->extra_count);
    if (extras > nt_ - count_) return Status::kCorrupt;
    extras_ = extras;
    if (extras != 0) components_.Share();
    for (uint64_t i = 0; i < extras; ++i) {
      if (dec.failed()) return Status::kTruncated;
      uint32_t v[3];
      for (int j = 0; j < 3; ++j) {
        const Status s = VertexRef(dec, &v[j]);
        if (s != Status::kOk) return s;
      }
      Push(v[0], v[1], v[2]);
    }
    if (count_ != nt_) return Status::kCorrupt;
    if (dec.failed()) return Status::kTruncated;
    return Status::kOk;
  }

  uint32_t num_vertices() const { return front_.num_vertices(); }
  // Triangles per vertex, when every triangle went through the front (see DecodeConnectivity).
  std::vector<uint32_t> VertexTriangles() const {
    std::vector<uint32_t> counts;
    if (has_copies_ || extras_ != 0) return counts;
    counts.resize(front_.num_vertices());
    for (uint32_t v = 0; v < front_.num_vertices(); ++v) counts[v] = front_.degree(v);
    return counts;
  }
  // See DecodeConnectivity.
  std::vector<uint32_t> TakeComponentEnds() { return components_.Finish(front_.num_vertices()); }
  std::vector<uint32_t> TakeOpposite() { return front_.TakeOpposite(nt_); }
  std::vector<uint32_t> TakeOppositeVertices() { return front_.TakeOppositeVertices(nt_); }
  const ArithmeticDecoder& decoder() const { return dec_; }

 private:
  bool Full() const { return count_ >= nt_; }
  // Callers check Full() (or the copy count) first.
  void Push(uint32_t x, uint32_t y, uint32_t z) {
    uint32_t* t = tri_ + 3 * count_++;
    t[0] = x;
    t[1] = y;
    t[2] = z;
  }

  // The third vertex of a kGateOther triangle at gate a->b (see the encoder's CodeOther).
  O3DGC_NOINLINE Status Other(ArithmeticDecoder& dec, uint32_t a, uint32_t b, uint32_t* c) {
    if (m_->rich && dec.Decode(m_->walk)) {
      const bool left = dec.Decode(m_->walk_side) != 0;
      const uint64_t steps = DecodeEG(dec, m_->walk_steps) + 2;
      if (steps > kMaxWalkSteps) return Status::kCorrupt;
      const int64_t v = front_.Walk(left ? a : b, left, uint32_t(steps));
      if (v < 0) return Status::kCorrupt;
      *c = uint32_t(v);
      return Status::kOk;
    }
    const uint64_t d = DecodeEG(dec, m_->other_ref);
    if (d >= front_.num_vertices()) return Status::kCorrupt;
    *c = uint32_t(front_.num_vertices() - 1 - d);
    components_.UseEarlier(*c);
    return Status::kOk;
  }

  O3DGC_INLINE Status VertexRef(ArithmeticDecoder& dec, uint32_t* v) {
    if (dec.Decode(m_->start_new)) {
      if (front_.num_vertices() >= max_vertices_) return Status::kCorrupt;
      *v = front_.AddVertex();
      return Status::kOk;
    }
    const uint64_t d = DecodeEG(dec, m_->start_ref);
    if (d >= front_.num_vertices()) return Status::kCorrupt;
    *v = uint32_t(front_.num_vertices() - 1 - d);
    components_.UseEarlier(*v);
    return Status::kOk;
  }

  O3DGC_INLINE Status Emit(ArithmeticDecoder& dec, uint32_t x, uint32_t y, uint32_t z) {
    Push(x, y, z);
    if (!has_copies_) return Status::kOk;
    const uint64_t count = DecodeEG(dec, m_->copies);
    if (count > nt_ - count_) return Status::kCorrupt;
    for (uint64_t i = 0; i < count; ++i) {
      if (dec.Decode(m_->copy_flip)) {
        Push(x, z, y);
      } else {
        Push(x, y, z);
      }
    }
    return Status::kOk;
  }

  ArithmeticDecoder dec_;
  const size_t nt_;
  const size_t max_vertices_;
  std::vector<uint32_t>& out_;
  uint32_t* tri_ = nullptr;
  size_t count_ = 0;  // triangles decoded so far
  std::unique_ptr<ConnectivityModels> m_;
  Front front_;
  bool has_flips_ = false, has_copies_ = false;
  uint64_t extras_ = 0;
  ComponentEnds components_;
  const bool keep_edges_;
  const bool compact_;  // Front::MakeRoom between steps
};

}  // namespace

Status DecodeConnectivity(ArithmeticDecoder* dec, size_t num_triangles, size_t max_vertices,
                          std::vector<uint32_t>* triangles, uint32_t* num_vertices,
                          std::vector<uint32_t>* opposite, std::vector<uint32_t>* opposite_vertices,
                          std::vector<uint32_t>* vertex_triangles, uint32_t minor,
                          bool compact_front, std::vector<uint32_t>* component_ends) {
  Decoder d(dec, num_triangles, max_vertices, triangles, opposite != nullptr, minor, compact_front);
  const Status s = d.Run();
  *dec = d.decoder();
  *num_vertices = d.num_vertices();
  if (s == Status::kOk && opposite) *opposite = d.TakeOpposite();
  if (s == Status::kOk && opposite_vertices) *opposite_vertices = d.TakeOppositeVertices();
  if (s == Status::kOk && vertex_triangles) *vertex_triangles = d.VertexTriangles();
  if (s == Status::kOk && component_ends) *component_ends = d.TakeComponentEnds();
  return s;
}

}  // namespace o3dgc
