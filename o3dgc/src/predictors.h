// Predictors of per-vertex attribute values from already coded vertices, and the order in which
// parallelogram-predicted attributes are coded (DegreeTraversal). A vertex may only use vertices
// coded before it.
#ifndef O3DGC_SRC_PREDICTORS_H_
#define O3DGC_SRC_PREDICTORS_H_

#include <cstddef>
#include <cstdint>
#include <vector>

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
// coder's neighbour table) when that neighbour shares both u and w, else kNoVertex.
struct Wedge {
  uint32_t u, w, x;
};

// Vertex -> wedges (CSR), in increasing triangle order; degenerate triangles are left out.
class WedgeTable {
 public:
  // `opposite`: 3 per triangle, neighbour triangle * 4 + its slot or 0xFFFFFFFF (see
  // Front::TakeOpposite).
  void Build(const std::vector<uint32_t>& triangles, uint32_t num_vertices,
             const std::vector<uint32_t>& opposite);
  const Wedge* begin(uint32_t v) const { return wedges_.data() + start_[v]; }
  const Wedge* end(uint32_t v) const { return wedges_.data() + start_[v + 1]; }
  uint32_t num_vertices() const { return uint32_t(start_.size() - 1); }

 private:
  std::vector<uint32_t> start_;
  std::vector<Wedge> wedges_;
};

// The order in which parallelogram-predicted values are coded: a greedy traversal that always
// continues with a vertex having the most triangles whose other two corners are already coded (so
// that most vertices have several parallelograms; levels 0..3, 3 meaning three or more), ties
// broken last-in first-out; a new component starts at the lowest uncoded id. Deterministic in the
// triangle list. Run incrementally, so the coder predicts each vertex when it is reached:
//   for (uint32_t c; (c = t.Next()) != kNoVertex;) { predict and code c; t.Visit(c); }
class DegreeTraversal {
 public:
  explicit DegreeTraversal(const WedgeTable& wedges);
  uint32_t Next();
  void Visit(uint32_t c);
  const uint8_t* done() const { return done_.data(); }
  uint32_t previous() const { return previous_; }  // the last visited vertex, kNoVertex at first

 private:
  static constexpr int kLevels = 4;
  void Push(int level, uint32_t v) { stacks_[level].push_back(v); }
  const WedgeTable& wedges_;
  std::vector<uint8_t> done_;
  std::vector<uint32_t> degree_;
  std::vector<uint32_t> stacks_[kLevels];
  uint32_t visited_ = 0, next_start_ = 0, previous_ = kNoVertex;
};

enum PredictionKind { kPredPrevious = 0, kPredNeighbours = 1, kPredParallelogram = 2 };

struct PredictionContext {
  int kind = kPredPrevious;
  uint64_t neighbour_magnitude = 0;  // mean residual magnitude of the decoded neighbours
};

// Multi-parallelogram prediction of vertex c (values: dim ints per vertex; done: which vertices are
// coded; previous: the last coded vertex or kNoVertex; magnitudes: per-vertex residual magnitudes of
// coded vertices). Averages u + w - x over the wedges of c with u, w and x coded (component-wise
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
                                         int64_t maxq, int64_t pred[4], int64_t alt[2], bool* ambiguous);

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

}  // namespace o3dgc

#endif  // O3DGC_SRC_PREDICTORS_H_
