// Connectivity encoder (see connectivity_encoder.h).
#include "connectivity_encoder.h"

#include <algorithm>
#include <memory>
#include <type_traits>

#include "connectivity_front.h"
#include "entropy.h"

namespace o3dgc {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;
constexpr uint32_t kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};

// `Coder`: an ArithmeticEncoder, or a DecisionLog to replay into one.
template <typename Coder>
class Encoder {
 public:
  Encoder(const uint32_t* tris, size_t num_triangles, uint32_t num_vertices, Coder* enc,
          ConnectivityEncoding* out, bool keep_edges, uint32_t minor)
      : tris_(tris),
        nt_(num_triangles),
        nv_in_(num_vertices),
        enc_(*enc),
        out_(*out),
        m_(new ConnectivityModels(minor)),
        keep_edges_(keep_edges) {}

  void Run() {
    // Recorded, the gate outcomes take their model's index instead of its probabilities.
    if constexpr (std::is_same<Coder, DecisionLog>::value) enc_.UseModels(m_->gate);
    Classify();
    BuildVertexTriangles();
    // Two flags spare the per-triangle flip and copy decisions when they cannot occur: a triangle
    // found across a gate a->b can only need a flip if some directed edge is used by two primary
    // triangles (two incident triangles of a vertex with the same successor).
    has_copies_ = false;
    for (size_t t = 0; t < nt_ && !has_copies_; ++t) has_copies_ = kind_[t] == kCopy;
    // A successor seen twice around a vertex is found with a stamp per vertex (the vertex whose
    // triangles were last looked at).
    has_flips_ = false;
    {
      std::vector<uint32_t> stamp(nv_in_, kNone);
      for (uint32_t a = 0; a < nv_in_ && !has_flips_; ++a) {
        uint32_t repeated = 0;
        for (uint32_t k = vt_start_[a]; k < vt_start_[a + 1]; ++k) {
          const uint32_t corner = vt_[k];
          const uint32_t b = tris_[corner - corner % 3 + kNext[corner % 3]];
          repeated |= stamp[b] == a;
          stamp[b] = a;
        }
        has_flips_ = repeated != 0;
      }
    }
    enc_.EncodeBits(has_flips_ ? 1 : 0, 1);
    enc_.EncodeBits(has_copies_ ? 1 : 0, 1);
    new_of_old_.assign(nv_in_, kNone);
    visited_.assign(nt_, 0);
    // Every input triangle is emitted once (primary, copy or degenerate).
    out_.triangles.resize(nt_ * 3);
    out_.source.resize(nt_);
    out_.old_of_new.reserve(nv_in_);  // every vertex is referenced: each gets a new id
    front_.Reserve(nv_in_, nt_, keep_edges_, /*compact=*/true);

    size_t scan = 0;
    for (;;) {
      front_.MakeRoom();
      if (front_.empty()) {
        while (scan < nt_ && (kind_[scan] != kPrimary || visited_[scan])) ++scan;
        if (scan == nt_) {
          enc_.Encode(0, m_->more_components);
          break;
        }
        enc_.Encode(1, m_->more_components);
        components_.StartPart(front_.num_vertices());
        const size_t t = scan;
        visited_[t] = 1;
        const uint32_t x = CodeVertexRef(tris_[3 * t]);
        const uint32_t y = CodeVertexRef(tris_[3 * t + 1]);
        const uint32_t z = CodeVertexRef(tris_[3 * t + 2]);
        front_.StartTriangle(uint32_t(emitted_), x, y, z);
        Emit(t, x, y, z);
        continue;
      }
      const int32_t g = front_.Pop();
      if (g < 0) continue;
      const uint32_t a = front_.gate(g).a, b = front_.gate(g).b;
      const uint32_t oa = out_.old_of_new[a], ob = out_.old_of_new[b];
      // Find an unvisited primary triangle across a-b, preferring the consistent orientation.
      size_t found = kNone;
      int flip = 0;
      uint32_t oc = kNone;
      // Search the shorter of the two vertices' triangle lists (a fan apex can have many). Each
      // entry is the list vertex's corner, so its two neighbours in the triangle are known.
      const bool from_a = vt_start_[oa + 1] - vt_start_[oa] <= vt_start_[ob + 1] - vt_start_[ob];
      const uint32_t os = from_a ? oa : ob, other = from_a ? ob : oa;
      for (uint32_t k = vt_start_[os]; k < vt_start_[os + 1]; ++k) {
        const uint32_t corner = vt_[k];
        const uint32_t t = corner / 3, j = corner % 3;
        if (visited_[t]) continue;
        const uint32_t* v = &tris_[3 * size_t(t)];
        const uint32_t next = v[kNext[j]], prev = v[kPrev[j]];
        if (next != other && prev != other) continue;
        // The triangle holds b->a when a follows b: from a, b is the previous corner; from b, a is
        // the next one.
        const bool consistent = from_a ? prev == other : next == other;
        const uint32_t third = next == other ? prev : next;
        if (consistent) {
          found = t;
          flip = 0;
          oc = third;
          break;
        }
        if (found == kNone) {
          found = t;
          flip = 1;
          oc = third;
        }
      }
      const Front::Candidates cand = front_.Look(a, b, m_->rich ? prev_ : -1);
      GateModel& model = m_->gate[size_t(cand.context)];
      if (found == kNone) {
        enc_.Encode(kGateClose, model);
        prev_ = kGateClose;
        front_.Close(g);
        continue;
      }
      uint32_t c = new_of_old_[oc];
      int32_t gate_bc = Front::kSearch;
      if (c == kNone) {
        prev_ = kGateNew;
        c = NewVertex(oc);
        gate_bc = Front::kNoGate;
      } else if (cand.right >= 0 && c == cand.right) {
        prev_ = kGateRight;
        gate_bc = cand.right_gate;
      } else if (cand.left >= 0 && c == cand.left) {
        prev_ = kGateLeft;
      } else {
        prev_ = kGateOther;
      }
      enc_.Encode(prev_, model);
      if (prev_ == kGateOther) CodeOther(a, b, c);
      if (has_flips_) enc_.Encode(flip, m_->flip);
      visited_[found] = 1;
      front_.Attach(g, uint32_t(emitted_), a, b, c, flip != 0, gate_bc);
      if (flip) {
        Emit(found, a, b, c);
      } else {
        Emit(found, b, a, c);
      }
    }
    // Degenerate triangles, with explicit references.
    EncodeEG(enc_, m_->extra_count, degenerate_.size());
    if (!degenerate_.empty()) components_.Share();
    for (uint32_t t : degenerate_) {
      const uint32_t x = CodeVertexRef(tris_[3 * t]);
      const uint32_t y = CodeVertexRef(tris_[3 * t + 1]);
      const uint32_t z = CodeVertexRef(tris_[3 * t + 2]);
      Push(t, x, y, z);
    }
    out_.opposite = front_.TakeOpposite(nt_);
    out_.opposite_vertices = front_.TakeOppositeVertices(nt_);
    out_.component_ends = components_.Finish(front_.num_vertices());
    if (!has_copies_ && degenerate_.empty()) {
      out_.vertex_triangles.resize(front_.num_vertices());
      for (uint32_t v = 0; v < front_.num_vertices(); ++v)
        out_.vertex_triangles[v] = front_.degree(v);
    }
  }

 private:
  enum : uint8_t { kPrimary = 0, kCopy = 1, kDegenerate = 2 };

  // Marks degenerate triangles and copies (triangles whose vertex set an earlier triangle, the
  // primary, already has) and chains each primary's copies in triangle order. Triangles with the
  // same vertex set share their smallest vertex, so they are bucketed by it (a counting sort that
  // keeps triangle order) and compared within buckets: small arrays read in order instead of a
  // hash table of all triangles, whose random accesses dominated encoding large meshes.
  void Classify() {
    kind_.assign(nt_, kPrimary);
    std::vector<uint32_t> start(size_t(nv_in_) + 1, 0);
    for (size_t t = 0; t < nt_; ++t) {
      const uint32_t a = tris_[3 * t], b = tris_[3 * t + 1], c = tris_[3 * t + 2];
      if (a == b || b == c || a == c) {
        kind_[t] = kDegenerate;
        degenerate_.push_back(uint32_t(t));
        continue;
      }
      ++start[size_t(std::min(a, std::min(b, c))) + 1];
    }
    for (uint32_t v = 0; v < nv_in_; ++v) start[v + 1] += start[v];
    std::vector<uint32_t> bucket(start[nv_in_]);
    {
      std::vector<uint32_t> fill(start.begin(), start.end() - 1);
      for (size_t t = 0; t < nt_; ++t) {
        if (kind_[t] == kDegenerate) continue;
        const uint32_t a = tris_[3 * t], b = tris_[3 * t + 1], c = tris_[3 * t + 2];
        bucket[fill[std::min(a, std::min(b, c))]++] = uint32_t(t);
      }
    }
    // The copy chains are allocated at the first copy: most meshes have none.
    std::vector<uint32_t> last_copy;
    auto add_copy = [&](uint32_t p, uint32_t t) {
      if (last_copy.empty()) {
        last_copy.assign(nt_, kNone);
        first_copy_.assign(nt_, kNone);
        next_copy_.assign(nt_, kNone);
      }
      kind_[t] = kCopy;
      if (first_copy_[p] == kNone) {
        first_copy_[p] = t;
      } else {
        next_copy_[last_copy[p]] = t;
      }
      last_copy[p] = t;
    };
    std::vector<SortedPair> large;
    for (uint32_t v = 0; v < nv_in_; ++v) {
      const uint32_t* items = bucket.data() + start[v];
      const uint32_t n = start[v + 1] - start[v];
      if (n < 2) continue;
      if (n <= kSmallBucket) {
        // The first earlier triangle with the same other two vertices is the primary.
        uint64_t keys[kSmallBucket];
        for (uint32_t i = 0; i < n; ++i) {
          keys[i] = OtherTwo(items[i], v);
          for (uint32_t j = 0; j < i; ++j) {
            if (keys[j] == keys[i]) {
              add_copy(items[j], items[i]);
              break;
            }
          }
        }
        continue;
      }
      // A fan apex: sort by (other two vertices, triangle) so that equal sets are adjacent and
      // each group starts with its primary; copies are then added in triangle order.
      large.clear();
      for (uint32_t i = 0; i < n; ++i) large.push_back(SortedPair{OtherTwo(items[i], v), items[i]});
      std::sort(large.begin(), large.end(), [](const SortedPair& x, const SortedPair& y) {
        return x.key != y.key ? x.key < y.key : x.tri < y.tri;
      });
      for (uint32_t i = 1, first = 0; i < n; ++i) {
        if (large[i].key != large[first].key) {
          first = i;
        } else {
          add_copy(large[first].tri, large[i].tri);
        }
      }
    }
  }
  static constexpr uint32_t kSmallBucket = 16;
  struct SortedPair {
    uint64_t key;
    uint32_t tri;
  };
  // The two vertices of triangle t other than its smallest one, v, as one ordered key.
  uint64_t OtherTwo(uint32_t t, uint32_t v) const {
    const uint32_t* x = &tris_[3 * size_t(t)];
    const uint32_t p = x[0] == v ? x[1] : x[0];
    const uint32_t q = x[2] == v ? x[1] : x[2];
    return p < q ? (uint64_t(p) << 32) | q : (uint64_t(q) << 32) | p;
  }

  // Corners (triangle * 3 + slot) of the primary triangles around every vertex, by triangle.
  void BuildVertexTriangles() {
    vt_start_.assign(nv_in_ + 1, 0);
    for (size_t t = 0; t < nt_; ++t) {
      if (kind_[t] != kPrimary) continue;
      for (int j = 0; j < 3; ++j) ++vt_start_[tris_[3 * t + j] + 1];
    }
    for (uint32_t v = 0; v < nv_in_; ++v) vt_start_[v + 1] += vt_start_[v];
    vt_.resize(vt_start_[nv_in_]);
    std::vector<uint32_t> fill(vt_start_.begin(), vt_start_.end() - 1);
    for (size_t t = 0; t < nt_; ++t) {
      if (kind_[t] != kPrimary) continue;
      for (int j = 0; j < 3; ++j) vt_[fill[tris_[3 * t + j]]++] = uint32_t(3 * t + j);
    }
  }

  void Push(size_t source, uint32_t x, uint32_t y, uint32_t z) {
    uint32_t* v = out_.triangles.data() + 3 * emitted_;
    v[0] = x;
    v[1] = y;
    v[2] = z;
    out_.source[emitted_++] = uint32_t(source);
  }

  uint32_t NewVertex(uint32_t old) {
    const uint32_t id = front_.AddVertex();
    new_of_old_[old] = id;
    out_.old_of_new.push_back(old);
    return id;
  }

  // The third vertex c of a kGateOther triangle at gate a->b: format 1.0 codes how far back it
  // was created; format 1.1 first tries the shorter walk along the front from b or from a (near
  // the gate on CAD meshes: around a hole, the far side of a fan's apex), falling back on that.
  void CodeOther(uint32_t a, uint32_t b, uint32_t c) {
    if (m_->rich) {
      const uint32_t right = front_.WalkSteps(b, false, c), left = front_.WalkSteps(a, true, c);
      enc_.Encode(right != 0 || left != 0, m_->walk);
      if (right != 0 || left != 0) {
        const bool use_left = right == 0 || (left != 0 && left < right);
        enc_.Encode(use_left, m_->walk_side);
        EncodeEG(enc_, m_->walk_steps, (use_left ? left : right) - 2);  // 1 step: a candidate
        return;
      }
    }
    EncodeEG(enc_, m_->other_ref, front_.num_vertices() - 1 - c);
    components_.UseEarlier(c);
  }

  uint32_t CodeVertexRef(uint32_t old) {
    const uint32_t v = new_of_old_[old];
    if (v == kNone) {
      enc_.Encode(1, m_->start_new);
      return NewVertex(old);
    }
    enc_.Encode(0, m_->start_new);
    EncodeEG(enc_, m_->start_ref, front_.num_vertices() - 1 - v);
    components_.UseEarlier(v);
    return v;
  }

  // Records a primary triangle and codes its copies.
  void Emit(size_t t, uint32_t x, uint32_t y, uint32_t z) {
    Push(t, x, y, z);
    if (!has_copies_) return;
    uint32_t count = 0;
    for (uint32_t q = first_copy_[t]; q != kNone; q = next_copy_[q]) ++count;
    EncodeEG(enc_, m_->copies, count);
    for (uint32_t q = first_copy_[t]; q != kNone; q = next_copy_[q]) {
      const uint32_t* v = &tris_[3 * q];
      const uint32_t nx = new_of_old_[v[0]], ny = new_of_old_[v[1]];
      // Same cyclic order as (x, y, z)?
      const bool same = (nx == x && ny == y) || (nx == y && ny == z) || (nx == z && ny == x);
      enc_.Encode(same ? 0 : 1, m_->copy_flip);
      if (same) {
        Push(q, x, y, z);
      } else {
        Push(q, x, z, y);
      }
    }
  }

  const uint32_t* tris_;
  const size_t nt_;
  const uint32_t nv_in_;
  Coder& enc_;
  ConnectivityEncoding& out_;
  std::unique_ptr<ConnectivityModels> m_;
  Front front_;
  std::vector<uint8_t> kind_, visited_;
  std::vector<uint32_t> first_copy_, next_copy_, degenerate_;
  ComponentEnds components_;
  std::vector<uint32_t> vt_start_, vt_;
  std::vector<uint32_t> new_of_old_;
  bool has_flips_ = false, has_copies_ = false;
  size_t emitted_ = 0;  // triangles in out_ so far
  int prev_ = 0;        // the previous gate outcome (format 1.1 contexts)
  const bool keep_edges_;
};

template <typename Coder>
void Run(const uint32_t* triangles, size_t num_triangles, uint32_t num_vertices, Coder* enc,
         ConnectivityEncoding* out, bool keep_edges, uint32_t minor) {
  out->triangles.clear();
  out->source.clear();
  out->old_of_new.clear();
  out->vertex_triangles.clear();
  Encoder<Coder>(triangles, num_triangles, num_vertices, enc, out, keep_edges, minor).Run();
}

}  // namespace

void EncodeConnectivity(const std::vector<uint32_t>& triangles, uint32_t num_vertices,
                        ArithmeticEncoder* enc, ConnectivityEncoding* out, bool keep_edges,
                        uint32_t minor) {
  Run(triangles.data(), triangles.size() / 3, num_vertices, enc, out, keep_edges, minor);
}

void EncodeConnectivity(const uint32_t* triangles, size_t num_triangles, uint32_t num_vertices,
                        DecisionLog* log, ConnectivityEncoding* out, bool keep_edges,
                        uint32_t minor) {
  Run(triangles, num_triangles, num_vertices, log, out, keep_edges, minor);
}

}  // namespace o3dgc
