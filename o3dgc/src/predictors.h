// Predictors of per-vertex attribute values from already coded vertices, and the order in which
// parallelogram-predicted attributes are coded (CodingOrder). A vertex may only use vertices
// coded before it.
#ifndef O3DGC_SRC_PREDICTORS_H_
#define O3DGC_SRC_PREDICTORS_H_

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "arithmetic_coder.h"  // O3DGC_INLINE

namespace o3dgc {

constexpr uint32_t kNoVertex = 0xFFFFFFFFu;

// Vertex -> incident triangles (CSR) of a triangle list; degenerate triangles are left out. Used by
// the coders that visit vertices in id order (surface normals).
class MeshAdjacency {
 public:
  void Build(const std::vector<uint32_t>& triangles, uint32_t num_vertices);
  const uint32_t* begin(uint32_t v) const { return tri_.data() + start_[v]; }
  const uint32_t* end(uint32_t v) const { return tri_.data() + start_[v + 1]; }
  const uint32_t* corners(uint32_t t) const { return tris_->data() + 3 * size_t(t); }
  uint32_t num_vertices() const { return uint32_t(start_.size() - 1); }

 private:
  const std::vector<uint32_t>* tris_ = nullptr;
  std::vector<uint32_t> start_, tri_;
};

// One incident triangle of a vertex c, as the predictors need it: the triangle is (c, u, w) in
// cyclic order, and x is the third vertex of its neighbour across u-w (from the connectivity
// coder's neighbour table) when that neighbour shares both u and w, else c itself (a vertex is
// never coded before itself, so "x coded" is the whole test).
struct Wedge {
  uint32_t u, w, x;
};

// Vertex -> wedges (CSR), in increasing triangle order; degenerate triangles are left out.
class WedgeTable {
 public:
  // `opposite`: 3 per triangle, the neighbour's opposite corner (triangle * 3 + slot) or
  // 0xFFFFFFFF (see Front::TakeOpposite). `verify`: check that a neighbour shares the edge's two
  // vertices (needed when attribute seams split edges; the connectivity coder's neighbours always
  // share them).
  void Build(const std::vector<uint32_t>& triangles, uint32_t num_vertices,
             const std::vector<uint32_t>& opposite, bool verify);
  // For the mesh the connectivity coder numbered: `opposite_vertices` (3 per triangle, see
  // Front::TakeOppositeVertices) gives x directly. `vertex_triangles` (optional, as
  // DecodeConnectivity gives it: the non-degenerate triangles at each vertex, zero past its end)
  // spares counting them; non-empty, it promises that no triangle is degenerate (every triangle
  // went through the connectivity front), so the per-triangle checks are skipped too.
  // `component_ends` (optional, as DecodeConnectivity gives it): ascending vertex ids B such that
  // no triangle has corners both below B and from B on, for CodingOrder; not copied: it must
  // outlive the table.
  void BuildFromOppositeVertices(const std::vector<uint32_t>& triangles, uint32_t num_vertices,
                                 const std::vector<uint32_t>& opposite_vertices,
                                 const std::vector<uint32_t>* vertex_triangles = nullptr,
                                 const std::vector<uint32_t>* component_ends = nullptr);
  const Wedge* begin(uint32_t v) const { return wedges_.get() + start_[v]; }
  const Wedge* end(uint32_t v) const { return wedges_.get() + start_[v + 1]; }
  uint32_t num_vertices() const { return uint32_t(start_.size() - 1); }
  size_t num_wedges() const { return start_.empty() ? 0 : start_.back(); }
  uint32_t max_wedges() const { return max_wedges_; }  // the most wedges of one vertex
  // See BuildFromOppositeVertices; null when not known.
  const std::vector<uint32_t>* component_ends() const { return component_ends_; }

 private:
  // Counts wedges per vertex into start_ (start_[v + 2]) and sizes wedges_; `counts` (optional)
  // gives them.
  void Count(const uint32_t* tri, size_t nt, uint32_t num_vertices,
             const std::vector<uint32_t>* counts = nullptr);
  std::vector<uint32_t> start_;
  std::unique_ptr<Wedge[]> wedges_;  // every entry is written by Build (no zero fill first)
  uint32_t max_wedges_ = 0;
  const std::vector<uint32_t>* component_ends_ = nullptr;
};

// The order in which parallelogram-predicted values are coded, one of two:
//  - kGreedy: always continue with a vertex having the most triangles whose other two corners are
//    already coded (so that most vertices have several parallelograms; levels 0..3, 3 meaning three
//    or more), ties broken last-in first-out; a new component starts at the lowest uncoded id.
//  - kVertexId: the vertex ids in increasing order, which is the order the connectivity decoder
//    creates them in (along its front, unless the stream keeps the input order); c's
//    parallelograms are its wedges with u, w and x below c. Fewer parallelograms than kGreedy
//    finds (2-5 % more bytes on the corpus), but no candidate stacks, and the per-vertex tables are
//    read in memory order instead of jumping: faster decoding (EncodeParams::fast_decode).
// Both are deterministic in the triangle list. Run incrementally, so the coder predicts each vertex
// when it is reached:
//   for (uint32_t c; (c = t.Next()) != kNoVertex;) {
//     const uint32_t previous = t.previous();
//     const int n = t.Visit(c);  // t.parallelograms() lists c's n parallelograms
//     predict and code c;
//   }
// (A coder may also predict first and Visit after: Visit only changes what Next returns.)
class CodingOrder {
 public:
  enum Kind : uint8_t { kGreedy = 0, kVertexId = 1 };
  // The kind a stream uses (the fast_decode flag of its header).
  static Kind ForStream(bool fast_decode) { return fast_decode ? kVertexId : kGreedy; }
  CodingOrder(const WedgeTable& wedges, Kind kind);
  uint32_t Next();
  // Marks c coded and makes its uncoded neighbours candidates. Returns the number of c's
  // parallelograms: its wedges whose u, w and x were coded before c, listed in wedge order by
  // parallelograms().
  int Visit(uint32_t c);
  const Wedge* const* parallelograms() const { return par_.data(); }
  const uint8_t* done() const { return done_.data(); }
  uint32_t previous() const { return previous_; }  // the last visited vertex, kNoVertex at first

 private:
  static constexpr int kLevels = 4;
  uint32_t NextWithoutParallelogram();
  int VisitGreedy(uint32_t c);
  int VisitInIdOrder(uint32_t c);
  const WedgeTable& wedges_;
  const Kind kind_;
  std::vector<uint8_t> done_;
  // kGreedy only (left empty for kVertexId):
  std::vector<uint8_t> degree_;  // saturating at kLevels - 1: only the level is needed
  // Candidates at levels 1..3 (stack 0 is not used), top_[l] one past the newest entry. A visit
  // pushes at most one entry per wedge of c: room for that is made once per visit (Reserve). The
  // stacks start small and double: sized for the worst case (every wedge) they took 12 bytes per
  // wedge, more than the wedge table itself.
  std::unique_ptr<uint32_t[]> stacks_[kLevels];
  uint32_t* top_[kLevels] = {nullptr, nullptr, nullptr, nullptr};
  uint32_t* end_[kLevels] = {nullptr, nullptr, nullptr, nullptr};
  void Reserve(int pushes) {
    for (int l = 1; l < kLevels; ++l) {
      if (end_[l] - top_[l] < pushes) Grow(l, size_t(pushes));
    }
  }
  void Grow(int level, size_t pushes);
  // Level 0 holds the neighbours of visited vertices that have no parallelogram yet, newest
  // first; it is only needed when levels 1..3 are empty, so instead of pushing them at every
  // visit, the visits are logged and their wedges searched on demand (see
  // NextWithoutParallelogram).
  struct Visited {
    uint32_t vertex;
    uint32_t searched;  // entries (wedges * 2, from the last one) already taken
  };
  std::unique_ptr<Visited[]> log_;  // one entry per visit at most
  size_t log_size_ = 0;
  size_t component_ = 0;  // the first of the wedge table's component ends not below visited_
  // Visit's outputs and scratch, sized by the constructor for the vertex with the most wedges.
  std::vector<const Wedge*> par_;
  std::vector<uint64_t> moved_;  // vertex << 2 | new level, per vertex moved up (kGreedy)
  uint32_t visited_ = 0, next_start_ = 0, previous_ = kNoVertex;
};

enum PredictionKind { kPredPrevious = 0, kPredNeighbours = 1, kPredParallelogram = 2 };

struct PredictionContext {
  int kind = kPredPrevious;
  uint64_t neighbour_magnitude = 0;  // mean residual magnitude of the decoded neighbours
};

// Multi-parallelogram prediction of vertex c (values: dim ints per vertex; done: which vertices are
// coded; previous: the last coded vertex or kNoVertex; magnitudes: per-vertex residual magnitudes
// of coded vertices). Averages u + w - x over the wedges of c with u, w and x coded (component-wise
// median with three or more; with two or more the context is their spread); without such a wedge
// it averages the coded neighbours, then falls back to the previous vertex. pred receives dim
// values.
PredictionContext PredictParallelogram(const WedgeTable& wedges, const uint8_t* done, uint32_t c,
                                       uint32_t previous, const int32_t* values, int dim,
                                       const uint32_t* magnitudes, int64_t* pred);

// Texture coordinate prediction from the 3D shape (positions known for every vertex, 3 doubles
// per vertex in `geometry`): for every wedge (c, u, w) with u, w coded, the position of c relative
// to the edge u-w (foot of the perpendicular and distance) is transferred to uv space, on the side
// of u-w opposite to the coded third vertex x of the neighbouring triangle. Results of all such
// wedges are averaged. If no wedge had a neighbour to decide the side, `alt` receives the mirrored
// prediction and *ambiguous is set (the caller codes the side).
PredictionContext PredictTexCoord(const WedgeTable& wedges, const uint8_t* done, uint32_t c,
                                  uint32_t previous, const int32_t* uv, const double* geometry,
                                  const uint32_t* magnitudes, int64_t pred[2], int64_t alt[2],
                                  bool* ambiguous);

// One traversal vertex's prediction, identical in the encoder and the decoder: texture
// coordinates from the 3D shape when `geometry` is given, else multi-parallelogram; pred (and alt,
// when *ambiguous) clamped to [0, maxq].
PredictionContext PredictAttributeVertex(const WedgeTable& wedges, const uint8_t* done, uint32_t c,
                                         uint32_t previous, const int32_t* values, int dim,
                                         const double* geometry, const uint32_t* magnitudes,
                                         int64_t maxq, int64_t pred[4], int64_t alt[2],
                                         bool* ambiguous);

// Neighbour residual magnitude for coders that visit vertices in id order (surface normals):
// the mean over the incident triangles' corners with smaller ids, else that of vertex c - 1.
uint64_t NeighbourMagnitude(const MeshAdjacency& adj, uint32_t c, const uint32_t* magnitudes);

// Rounded division for possibly negative numerators, n > 0.
inline int64_t DivRound(int64_t s, int64_t n) {
  return s >= 0 ? (2 * s + n) / (2 * n) : -((-2 * s + n) / (2 * n));
}

// Octahedral mapping of unit vectors to [-1,1]^2 and back.
void OctEncode(const double n[3], double* u, double* v);
void OctDecode(double u, double v, double n[3]);

inline uint32_t CodingOrder::Next() {
  if (visited_ >= wedges_.num_vertices()) return kNoVertex;
  if (kind_ == kVertexId) return visited_;  // 0..visited_-1 are coded
  for (int level = kLevels - 1; level > 0; --level) {
    uint32_t* const stack = stacks_[level].get();
    while (top_[level] != stack) {
      const uint32_t c = *--top_[level];
      // Stale entries: coded meanwhile, or a newer entry sits at the vertex's current level.
      if (done_[c] || int(degree_[c]) != level) continue;
      return c;
    }
  }
  return NextWithoutParallelogram();
}

// The id-order visit is small enough to inline into the coding loops, the greedy one is not (in
// WebAssembly, inlining it spills more registers in the loop than the call costs).
O3DGC_INLINE int CodingOrder::Visit(uint32_t c) {
  return kind_ == kVertexId ? VisitInIdOrder(c) : VisitGreedy(c);
}

inline int CodingOrder::VisitGreedy(uint32_t c) {
  const Wedge* const first = wedges_.begin(c);
  const Wedge* const last = wedges_.end(c);
  // par_ and moved_ hold the most wedges any vertex has (sized by the constructor): no check here.
  const Wedge** par = par_.data();
  uint64_t* moved = moved_.data();
  int n_par = 0, n_moved = 0;
  const uint8_t* const done = done_.data();
  uint8_t* const degree = degree_.data();
  // Before c is marked: x == c stands for "no neighbour".
  for (const Wedge* it = first; it != last; ++it) {
    const uint32_t u = it->u, w = it->w;
    const uint32_t du = done[u], dw = done[w];
    par[n_par] = it;
    n_par += int(du & dw & done[it->x]);
    // Exactly one of u, w coded: the other gains a parallelogram and moves up a level. Written
    // without branches: an entry is always written, and kept only when it is real. The entries
    // (vertex and new level) go to a local list first, not to the level stacks: a stack top in
    // memory, loaded and stored at every wedge, chained the iterations through store forwarding.
    const uint32_t one = du ^ dw;
    const uint32_t a = du ? w : u;
    uint32_t d = degree[a] + one;
    d = d < kLevels ? d : kLevels - 1;
    degree[a] = uint8_t(d);
    moved[n_moved] = uint64_t(a) << 2 | d;
    n_moved += int(one);
  }
  // The same pushes, in wedge order per level, as pushing in the loop would make.
  Reserve(n_moved);
  for (int i = 0; i < n_moved; ++i) *top_[moved[i] & 3]++ = uint32_t(moved[i] >> 2);
  log_[log_size_++] = Visited{c, 0};
  done_[c] = 1;
  ++visited_;
  previous_ = c;
  // The wedges of the vertex Next will most likely return (the newest candidate at the highest
  // level), fetched while the caller codes c: in traversal order they are scattered over a table
  // larger than the caches, and waiting for them took about 6 % of the decoding time (igea).
  int l = kLevels - 1;
  while (l > 0 && top_[l] == stacks_[l].get()) --l;
  if (l > 0) O3DGC_PREFETCH(wedges_.begin(top_[l][-1]));
  return n_par;
}

O3DGC_INLINE int CodingOrder::VisitInIdOrder(uint32_t c) {
  // The coded vertices are those below c: no flags to load. x == c stands for "no neighbour".
  const Wedge** par = par_.data();
  int n_par = 0;
  for (const Wedge *it = wedges_.begin(c), *last = wedges_.end(c); it != last; ++it) {
    par[n_par] = it;
    n_par += int((it->u < c) & (it->w < c) & (it->x < c));
  }
  done_[c] = 1;  // for the predictors' neighbour fallback
  ++visited_;
  previous_ = c;
  return n_par;
}

constexpr int kMaxKept = 16;

// Rounded mean of two values (DivRound(a + b, 2) without a division).
inline int64_t Mean2(int64_t s) { return s >= 0 ? (s + 1) >> 1 : -((1 - s) >> 1); }

// Multi-parallelogram prediction with kDim components (see PredictParallelogram) from c's
// n_par parallelograms `par` (wedges with u, w and x coded, in wedge order).
template <int kDim>
O3DGC_INLINE PredictionContext PredictFromParallelograms(
    const Wedge* const* par, int n_par, const WedgeTable& wedges, const uint8_t* done, uint32_t c,
    uint32_t previous, const int32_t* values, const uint32_t* magnitudes, int64_t* pred) {
  PredictionContext ctx;
  if (n_par >= 2) {
    int64_t kept[kMaxKept][kDim];
    const int m = n_par < kMaxKept ? n_par : kMaxKept;
    for (int i = 0; i < m; ++i) {
      const int32_t* vu = values + size_t(par[i]->u) * kDim;
      const int32_t* vw = values + size_t(par[i]->w) * kDim;
      const int32_t* vx = values + size_t(par[i]->x) * kDim;
      for (int k = 0; k < kDim; ++k) kept[i][k] = int64_t(vu[k]) + vw[k] - vx[k];
    }
    ctx.kind = kPredParallelogram;
    // The context is the disagreement between the parallelograms: twice the mean absolute
    // deviation from the prediction, summed over the components. With two parallelograms that is
    // the distance between them (the prediction lies between them), with three the spread (the
    // prediction is their median).
    if (n_par == 2) {
      uint64_t spread = 0;
      for (int k = 0; k < kDim; ++k) {
        pred[k] = Mean2(kept[0][k] + kept[1][k]);
        const int64_t d = kept[0][k] - kept[1][k];
        spread += uint64_t(d < 0 ? -d : d);
      }
      ctx.neighbour_magnitude = spread;
      return ctx;
    }
    if (n_par == 3) {
      // Three or more parallelograms: the component-wise median is more robust than the mean.
      uint64_t spread = 0;
      for (int k = 0; k < kDim; ++k) {
        const int64_t a = kept[0][k], b = kept[1][k], d = kept[2][k];
        const int64_t lo = a < b ? a : b, hi = a < b ? b : a;
        pred[k] = d < lo ? lo : (d > hi ? hi : d);
        spread += uint64_t((hi > d ? hi : d) - (lo < d ? lo : d));
      }
      ctx.neighbour_magnitude = spread * 2 / 3;
      return ctx;
    }
    if (n_par <= kMaxKept) {
      for (int k = 0; k < kDim; ++k) {
        int64_t col[kMaxKept];
        for (int i = 0; i < n_par; ++i) {  // insertion sort: n_par is small
          const int64_t xv = kept[i][k];
          int q = i;
          for (; q > 0 && col[q - 1] > xv; --q) col[q] = col[q - 1];
          col[q] = xv;
        }
        pred[k] = (n_par & 1) ? col[n_par / 2] : Mean2(col[n_par / 2 - 1] + col[n_par / 2]);
      }
    } else {
      // Many parallelograms (fan apices): the mean of all of them.
      int64_t sum[kDim] = {};
      for (int i = 0; i < n_par; ++i) {
        for (int k = 0; k < kDim; ++k) {
          sum[k] += int64_t(values[size_t(par[i]->u) * kDim + k]) +
                    values[size_t(par[i]->w) * kDim + k] - values[size_t(par[i]->x) * kDim + k];
        }
      }
      for (int k = 0; k < kDim; ++k) pred[k] = DivRound(sum[k], n_par);
    }
    uint64_t dev = 0;
    for (int i = 0; i < m; ++i) {
      for (int k = 0; k < kDim; ++k) {
        const int64_t d = kept[i][k] - pred[k];
        dev += uint64_t(d < 0 ? -d : d);
      }
    }
    ctx.neighbour_magnitude = dev * 2 / uint64_t(m);
    return ctx;
  }
  // One parallelogram or none: the context (and the fallback) come from the coded neighbours.
  int64_t nb[kDim] = {};
  int n_nb = 0;
  uint64_t mag = 0;
  for (const Wedge* it = wedges.begin(c); it != wedges.end(c); ++it) {
    for (const uint32_t u : {it->u, it->w}) {
      if (!done[u]) continue;
      for (int k = 0; k < kDim; ++k) nb[k] += values[size_t(u) * kDim + k];
      if (magnitudes) mag += magnitudes[u];
      ++n_nb;
    }
  }
  ctx.neighbour_magnitude = n_nb ? mag / uint64_t(n_nb) : 0;
  if (n_par == 1) {
    const int32_t* vu = values + size_t(par[0]->u) * kDim;
    const int32_t* vw = values + size_t(par[0]->w) * kDim;
    const int32_t* vx = values + size_t(par[0]->x) * kDim;
    for (int k = 0; k < kDim; ++k) pred[k] = int64_t(vu[k]) + vw[k] - vx[k];
    ctx.kind = kPredParallelogram;
  } else if (n_nb > 0) {
    for (int k = 0; k < kDim; ++k) pred[k] = DivRound(nb[k], n_nb);
    ctx.kind = kPredNeighbours;
  } else {
    for (int k = 0; k < kDim; ++k) {
      pred[k] = previous != kNoVertex ? values[size_t(previous) * kDim + k] : 0;
    }
    ctx.kind = kPredPrevious;
    if (magnitudes && previous != kNoVertex) ctx.neighbour_magnitude = magnitudes[previous];
  }
  return ctx;
}

// The same for a vertex c not visited yet (its parallelograms found here).
template <int kDim>
inline PredictionContext PredictParallelogramT(const WedgeTable& wedges, const uint8_t* done,
                                               uint32_t c, uint32_t previous, const int32_t* values,
                                               const uint32_t* magnitudes, int64_t* pred) {
  std::vector<const Wedge*> par;
  for (const Wedge* it = wedges.begin(c); it != wedges.end(c); ++it) {
    if (done[it->u] && done[it->w] && done[it->x]) par.push_back(it);
  }
  return PredictFromParallelograms<kDim>(par.data(), int(par.size()), wedges, done, c, previous,
                                         values, magnitudes, pred);
}

}  // namespace o3dgc

#endif  // O3DGC_SRC_PREDICTORS_H_
