// Predictors of per-vertex attribute values from already decoded vertices.
//
// Vertices are predicted in increasing id order (the coding order), so a vertex may only use
// vertices with smaller ids. Multi-parallelogram prediction averages u + v - w over every triangle
// (c, u, v) with u, v decoded whose neighbour across u-v has a decoded third vertex w (component-
// wise median with three or more; with two or more the residual context is their spread); without
// such a pair it averages the decoded neighbours, then falls back to the previous vertex.
#ifndef O3DGC_SRC_PREDICTORS_H_
#define O3DGC_SRC_PREDICTORS_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace o3dgc {

// Vertex -> incident triangles (CSR) of a triangle list; degenerate triangles are left out.
class MeshAdjacency {
 public:
  void Build(const std::vector<uint32_t>& triangles, uint32_t num_vertices);
  // The adjacency of `renamed` = RenameByOrder(source, order), built by permuting source's lists
  // (same result as Build(renamed, n), without a pass over the triangles).
  void BuildPermuted(const MeshAdjacency& source, const std::vector<uint32_t>& order,
                     const std::vector<uint32_t>& renamed);
  const uint32_t* begin(uint32_t v) const { return tri_.data() + start_[v]; }
  const uint32_t* end(uint32_t v) const { return tri_.data() + start_[v + 1]; }
  const uint32_t* corners(uint32_t t) const { return tris_->data() + 3 * size_t(t); }
  uint32_t num_vertices() const { return uint32_t(start_.size() - 1); }
  const std::vector<uint32_t>& triangles() const { return *tris_; }
  // Optional neighbour table (3 per triangle: neighbour triangle * 4 + its slot, or 0xFFFFFFFF),
  // as found by the connectivity coder. With it, predictors look neighbours up instead of
  // searching; neighbours whose shared edge does not have the same two vertices are ignored.
  void SetOpposite(const std::vector<uint32_t>* opposite) { opp_ = opposite; }
  // The third vertex of the neighbour across the edge opposite corner `slot` of triangle t, if
  // that neighbour shares the edge's two vertices; else 0xFFFFFFFF.
  uint32_t OppositeVertex(uint32_t t, int slot) const {
    const uint32_t e = (*opp_)[3 * size_t(t) + slot];
    if (e == 0xFFFFFFFFu) return e;
    const uint32_t* v = corners(t);
    const uint32_t* o = corners(e / 4);
    const int s = int(e % 4);
    const uint32_t p = v[(slot + 1) % 3], q = v[(slot + 2) % 3];
    const uint32_t op = o[(s + 1) % 3], oq = o[(s + 2) % 3];
    if (!((op == p && oq == q) || (op == q && oq == p))) return 0xFFFFFFFFu;
    return o[s];
  }
  bool has_opposite() const { return opp_ != nullptr; }
  const std::vector<uint32_t>* opposite() const { return opp_; }

 private:
  const std::vector<uint32_t>* tris_ = nullptr;
  const std::vector<uint32_t>* opp_ = nullptr;
  std::vector<uint32_t> start_, tri_;
};

enum PredictionKind { kPredPrevious = 0, kPredNeighbours = 1, kPredParallelogram = 2 };

struct PredictionContext {
  int kind = kPredPrevious;
  uint64_t neighbour_magnitude = 0;  // mean residual magnitude of the decoded neighbours
};

// Predicts vertex c (values: dim ints per vertex; magnitudes: per-vertex residual magnitudes of
// decoded vertices, may be null). pred receives dim values.
PredictionContext PredictParallelogram(const MeshAdjacency& adj, uint32_t c, const int32_t* values,
                                       int dim, const uint32_t* magnitudes, int64_t* pred);

// Texture coordinate prediction from the 3D shape (positions known for every vertex, 3 doubles
// per vertex in `geometry`): for every triangle (c, u, v) with u, v decoded, the position of c
// relative to the edge u-v (foot of the perpendicular and distance) is transferred to uv space,
// on the side of u-v opposite to the decoded third vertex of the neighbouring triangle. Results of
// all such triangles are averaged. If no triangle had a neighbour to decide the side, `alt`
// receives the mirrored prediction and *ambiguous is set (the caller codes the side).
PredictionContext PredictTexCoord(const MeshAdjacency& adj, uint32_t c, const int32_t* uv,
                                  const double* geometry, const uint32_t* magnitudes,
                                  int64_t pred[2], int64_t alt[2], bool* ambiguous);

// One attribute vertex's prediction, identical in the encoder and the decoder: texture
// coordinates from the 3D shape when `geometry` is given, else parallelogram or the previous
// vertex by `parallelogram`; pred (and alt, when *ambiguous) clamped to [0, maxq].
PredictionContext PredictAttributeVertex(const MeshAdjacency& adj, uint32_t c, const int32_t* values, int dim,
                                         const double* geometry, bool parallelogram, const uint32_t* magnitudes,
                                         int64_t maxq, int64_t pred[4], int64_t alt[2], bool* ambiguous);

// Neighbour residual magnitude only (for the differential and surface-normal modes).
uint64_t NeighbourMagnitude(const MeshAdjacency& adj, uint32_t c, const uint32_t* magnitudes);

// The order in which attribute values are coded: a greedy traversal that always continues with a
// vertex having the most triangles whose other two corners are already coded (so that most
// vertices have several parallelograms), ties broken last-in first-out; a new component starts at
// the lowest uncoded id. Deterministic in the triangle list. order[i] = vertex coded i-th.
std::vector<uint32_t> MaxDegreeOrder(const MeshAdjacency& adj);

// The triangles of `adj` with every vertex v renamed rank[v], where rank is the inverse of `order`.
std::vector<uint32_t> RenameByOrder(const MeshAdjacency& adj, const std::vector<uint32_t>& order);

// Rounded division for possibly negative numerators, n > 0.
inline int64_t DivRound(int64_t s, int64_t n) {
  return s >= 0 ? (2 * s + n) / (2 * n) : -((-2 * s + n) / (2 * n));
}

// Octahedral mapping of unit vectors to [-1,1]^2 and back.
void OctEncode(const double n[3], double* u, double* v);
void OctDecode(double u, double v, double n[3]);

}  // namespace o3dgc

#endif  // O3DGC_SRC_PREDICTORS_H_
