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
          std::vector<uint32_t>* out)
      : dec_(*dec), nt_(num_triangles), max_vertices_(max_vertices), out_(*out),
        m_(new ConnectivityModels) {}

  Status Run() {
    out_.clear();
    // Reserve for what real streams need (well over one bit per triangle); a stream that codes
    // more grows the vectors as it actually decodes, so a lying header allocates nothing.
    size_t expect = dec_.size() * 8 + 1024;
    if (expect > nt_) expect = nt_;
    out_.reserve(expect * 3);
    front_.Reserve(max_vertices_ < expect + 3 ? max_vertices_ : expect + 3, expect * 2);
    has_flips_ = dec_.DecodeBits(1) != 0;
    has_copies_ = dec_.DecodeBits(1) != 0;
    for (;;) {
      if (dec_.failed()) return Status::kTruncated;
      if (front_.empty()) {
        if (!dec_.Decode(m_->more_components)) break;
        if (Full()) return Status::kCorrupt;
        uint32_t x, y, z;
        Status s;
        if ((s = VertexRef(&x)) != Status::kOk) return s;
        if ((s = VertexRef(&y)) != Status::kOk) return s;
        if ((s = VertexRef(&z)) != Status::kOk) return s;
        if (x == y || y == z || x == z) return Status::kCorrupt;
        front_.StartTriangle(uint32_t(out_.size() / 3), x, y, z);
        if ((s = Emit(x, y, z)) != Status::kOk) return s;
        continue;
      }
      const int32_t g = front_.Pop();
      if (g < 0) continue;
      const uint32_t a = front_.gate(g).a, b = front_.gate(g).b;
      const int ctx = front_.Context(a, b);
      if (!dec_.Decode(m_->attach[ctx])) {
        front_.Close(g);
        continue;
      }
      if (Full()) return Status::kCorrupt;
      uint32_t c;
      if (dec_.Decode(m_->is_new[ctx])) {
        if (front_.num_vertices() >= max_vertices_) return Status::kCorrupt;
        c = front_.AddVertex();
      } else {
        const int64_t r = front_.RightCandidate(b);
        const int64_t l = front_.LeftCandidate(a);
        int64_t chosen = -1;
        if (r >= 0 && dec_.Decode(m_->is_right[ctx])) chosen = r;
        if (chosen < 0 && l >= 0 && l != r && dec_.Decode(m_->is_left[ctx])) chosen = l;
        if (chosen < 0) {
          const uint64_t d = DecodeEG(dec_, m_->other_ref);
          if (d >= front_.num_vertices()) return Status::kCorrupt;
          chosen = int64_t(front_.num_vertices() - 1 - d);
        }
        c = uint32_t(chosen);
      }
      if (c == a || c == b) return Status::kCorrupt;
      const int flip = has_flips_ ? dec_.Decode(m_->flip) : 0;
      front_.Attach(g, uint32_t(out_.size() / 3), a, b, c, flip != 0);
      const Status s = flip ? Emit(a, b, c) : Emit(b, a, c);
      if (s != Status::kOk) return s;
    }
    const uint64_t extras = DecodeEG(dec_, m_->extra_count);
    if (extras > nt_ - out_.size() / 3) return Status::kCorrupt;
    for (uint64_t i = 0; i < extras; ++i) {
      if (dec_.failed()) return Status::kTruncated;
      uint32_t v[3];
      for (int j = 0; j < 3; ++j) {
        const Status s = VertexRef(&v[j]);
        if (s != Status::kOk) return s;
      }
      Push(v[0], v[1], v[2]);
    }
    if (out_.size() != nt_ * 3) return Status::kCorrupt;
    if (dec_.failed()) return Status::kTruncated;
    return Status::kOk;
  }

  uint32_t num_vertices() const { return front_.num_vertices(); }
  std::vector<uint32_t> TakeOpposite() { return front_.TakeOpposite(nt_); }

 private:
  bool Full() const { return out_.size() >= nt_ * 3; }
  void Push(uint32_t x, uint32_t y, uint32_t z) {
    out_.push_back(x);
    out_.push_back(y);
    out_.push_back(z);
  }

  Status VertexRef(uint32_t* v) {
    if (dec_.Decode(m_->start_new)) {
      if (front_.num_vertices() >= max_vertices_) return Status::kCorrupt;
      *v = front_.AddVertex();
      return Status::kOk;
    }
    const uint64_t d = DecodeEG(dec_, m_->start_ref);
    if (d >= front_.num_vertices()) return Status::kCorrupt;
    *v = uint32_t(front_.num_vertices() - 1 - d);
    return Status::kOk;
  }

  Status Emit(uint32_t x, uint32_t y, uint32_t z) {
    Push(x, y, z);
    if (!has_copies_) return Status::kOk;
    const uint64_t count = DecodeEG(dec_, m_->copies);
    if (count > nt_ - out_.size() / 3) return Status::kCorrupt;
    for (uint64_t i = 0; i < count; ++i) {
      if (dec_.Decode(m_->copy_flip)) {
        Push(x, z, y);
      } else {
        Push(x, y, z);
      }
    }
    return Status::kOk;
  }

  ArithmeticDecoder& dec_;
  const size_t nt_;
  const size_t max_vertices_;
  std::vector<uint32_t>& out_;
  std::unique_ptr<ConnectivityModels> m_;
  Front front_;
  bool has_flips_ = false, has_copies_ = false;
};

}  // namespace

Status DecodeConnectivity(ArithmeticDecoder* dec, size_t num_triangles, size_t max_vertices,
                          std::vector<uint32_t>* triangles, uint32_t* num_vertices,
                          std::vector<uint32_t>* opposite) {
  Decoder d(dec, num_triangles, max_vertices, triangles);
  const Status s = d.Run();
  *num_vertices = d.num_vertices();
  if (s == Status::kOk && opposite) *opposite = d.TakeOpposite();
  return s;
}

}  // namespace o3dgc
