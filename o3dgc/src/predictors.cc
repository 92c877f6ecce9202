// Predictors (see predictors.h).
#include "predictors.h"

#include <algorithm>
#include <cmath>

namespace o3dgc {

void MeshAdjacency::Build(const std::vector<uint32_t>& triangles, uint32_t num_vertices) {
  tris_ = &triangles;
  start_.assign(size_t(num_vertices) + 1, 0);
  const size_t nt = triangles.size() / 3;
  auto ok = [&](size_t t) {
    const uint32_t* v = &triangles[3 * t];
    return v[0] != v[1] && v[1] != v[2] && v[0] != v[2];
  };
  for (size_t t = 0; t < nt; ++t) {
    if (!ok(t)) continue;
    for (int j = 0; j < 3; ++j) ++start_[triangles[3 * t + j] + 1];
  }
  for (uint32_t v = 0; v < num_vertices; ++v) start_[v + 1] += start_[v];
  tri_.resize(start_[num_vertices]);
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  for (size_t t = 0; t < nt; ++t) {
    if (!ok(t)) continue;
    for (int j = 0; j < 3; ++j) tri_[fill[triangles[3 * t + j]]++] = uint32_t(t);
  }
}

void WedgeTable::Count(const uint32_t* tri, size_t nt, uint32_t num_vertices,
                       const std::vector<uint32_t>* counts) {
  start_.assign(size_t(num_vertices) + 2, 0);
  uint32_t* start = start_.data() + 1;  // counts at start[v + 1], then fill positions at start[v]
  if (counts) {
    const size_t n = counts->size() < num_vertices ? counts->size() : num_vertices;
    for (size_t v = 0; v < n; ++v) start[v + 1] = (*counts)[v];
  }
  for (size_t t = 0; t < (counts ? 0 : nt); ++t) {
    const uint32_t a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
    const uint32_t ok = (a != b) & (b != c) & (a != c);
    start[a + 1] += ok;
    start[b + 1] += ok;
    start[c + 1] += ok;
  }
  max_wedges_ = 0;
  for (uint32_t v = 0; v < num_vertices; ++v) {
    max_wedges_ = start[v + 1] > max_wedges_ ? start[v + 1] : max_wedges_;
    start[v + 1] += start[v];
  }
  wedges_.reset(new Wedge[start[num_vertices]]);
}

void WedgeTable::Build(const std::vector<uint32_t>& triangles, uint32_t num_vertices,
                       const std::vector<uint32_t>& opposite, bool verify) {
  component_ends_ = nullptr;
  const size_t nt = triangles.size() / 3;
  const uint32_t* tri = triangles.data();
  const uint32_t* opp = opposite.size() >= 3 * nt ? opposite.data() : nullptr;
  Count(tri, nt, num_vertices);
  uint32_t* start = start_.data() + 1;
  Wedge* out = wedges_.get();
  static constexpr uint8_t kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};
  for (size_t t = 0; t < nt; ++t) {
    const uint32_t* v = tri + 3 * t;
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
    for (int j = 0; j < 3; ++j) {
      const uint32_t p = v[kNext[j]], q = v[kPrev[j]];
      uint32_t x = v[j];  // no neighbour: the vertex itself, never coded before itself
      const uint32_t e = opp ? opp[3 * t + j] : 0xFFFFFFFFu;
      if (e != 0xFFFFFFFFu) {
        const uint32_t s = e % 3;
        const uint32_t* o = tri + (size_t(e) - s);
        x = o[s];
        // With attribute seams a neighbour across the position edge may not share the attribute
        // edge; then it does not count.
        if (verify) {
          const uint32_t op = o[kNext[s]], oq = o[kPrev[s]];
          if (!((op == p && oq == q) || (op == q && oq == p))) x = v[j];
        }
      }
      out[start[v[j]]++] = Wedge{p, q, x};
    }
  }
  start_.pop_back();  // start[v] advanced to the end of v's wedges: start_[v + 1] now
}

void WedgeTable::BuildFromOppositeVertices(const std::vector<uint32_t>& triangles,
                                           uint32_t num_vertices,
                                           const std::vector<uint32_t>& opposite_vertices,
                                           const std::vector<uint32_t>* vertex_triangles,
                                           const std::vector<uint32_t>* component_ends) {
  component_ends_ = component_ends;
  const size_t nt = triangles.size() / 3;
  const uint32_t* tri = triangles.data();
  const uint32_t* oppv = opposite_vertices.size() >= 3 * nt ? opposite_vertices.data() : nullptr;
  Count(tri, nt, num_vertices,
        vertex_triangles && !vertex_triangles->empty() ? vertex_triangles : nullptr);
  uint32_t* start = start_.data() + 1;
  Wedge* out = wedges_.get();
  // Counts from the connectivity front: every triangle went through it, and it never makes a
  // degenerate one, so no checks.
  const bool checks = !(vertex_triangles && !vertex_triangles->empty());
  for (size_t t = 0; t < nt; ++t) {
    // Locals: the stores below may alias the triangle array for all the compiler knows.
    const uint32_t a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
    if (checks && (a == b || b == c || a == c)) continue;
    uint32_t xa = a, xb = b, xc = c;  // no neighbour: the vertex itself
    if (oppv) {
      const uint32_t oa = oppv[3 * t], ob = oppv[3 * t + 1], oc = oppv[3 * t + 2];
      xa = oa != 0xFFFFFFFFu ? oa : a;
      xb = ob != 0xFFFFFFFFu ? ob : b;
      xc = oc != 0xFFFFFFFFu ? oc : c;
    }
    out[start[a]++] = Wedge{b, c, xa};
    out[start[b]++] = Wedge{c, a, xb};
    out[start[c]++] = Wedge{a, b, xc};
  }
  start_.pop_back();
}

CodingOrder::CodingOrder(const WedgeTable& wedges, Kind kind)
    : wedges_(wedges), kind_(kind), done_(wedges.num_vertices(), 0) {
  par_.resize(size_t(wedges.max_wedges()) + 1);
  if (kind == kVertexId) return;
  moved_.resize(size_t(wedges.max_wedges()) + 1);
  degree_.assign(wedges.num_vertices(), 0);
  log_.reset(new Visited[wedges.num_vertices()]);
  // The stacks' usual size: a front of candidates, far below one entry per wedge.
  const size_t start = std::min<size_t>(wedges.num_wedges(), 1024 + wedges.num_vertices() / 16) + 1;
  for (int l = 1; l < kLevels; ++l) {
    stacks_[l].reset(new uint32_t[start]);
    top_[l] = stacks_[l].get();
    end_[l] = top_[l] + start;
  }
}

void CodingOrder::Grow(int level, size_t pushes) {
  const size_t used = size_t(top_[level] - stacks_[level].get());
  const size_t capacity = std::max(2 * size_t(end_[level] - stacks_[level].get()), used + pushes);
  std::unique_ptr<uint32_t[]> grown(new uint32_t[capacity]);
  std::copy(stacks_[level].get(), top_[level], grown.get());
  stacks_[level] = std::move(grown);
  top_[level] = stacks_[level].get() + used;
  end_[level] = stacks_[level].get() + capacity;
}

uint32_t CodingOrder::NextWithoutParallelogram() {
  // When exactly the vertices below a component end B are coded, the logged visits have no
  // uncoded neighbour left (no triangle reaches from below B to B and above), so the search
  // below would find none: it is skipped. (Exactly those: the order enters a component only at
  // its lowest uncoded id, and none from B on before every vertex below B is coded, so
  // visited_ == B says it.) On meshes of many parts the search at each part's end walked every
  // visit of the part.
  if (const std::vector<uint32_t>* ends = wedges_.component_ends()) {
    while (component_ < ends->size() && (*ends)[component_] < visited_) ++component_;
    if (component_ < ends->size() && (*ends)[component_] == visited_) log_size_ = 0;
  }
  // The level-0 stack would hold, for every visit in order, w then u of each wedge whose u and w
  // were both uncoded then; it is taken from the top, stale entries skipped. A vertex uncoded and
  // without parallelogram now had both uncoded at every visit next to it (else it would have
  // gained a parallelogram), so walking the logged visits newest first, their wedges last first,
  // u before w, and taking the first such vertex gives the same sequence.
  while (log_size_ > 0) {
    Visited& v = log_[log_size_ - 1];
    const Wedge* const first = wedges_.begin(v.vertex);
    const uint32_t entries = 2 * uint32_t(wedges_.end(v.vertex) - first);
    while (v.searched < entries) {
      const Wedge& w = first[(entries - 1 - v.searched) / 2];
      const uint32_t candidate = (v.searched & 1) ? w.w : w.u;
      ++v.searched;
      if (!done_[candidate] && degree_[candidate] == 0) return candidate;
    }
    --log_size_;
  }
  while (done_[next_start_]) ++next_start_;
  return next_start_;
}

PredictionContext PredictParallelogram(const WedgeTable& wedges, const uint8_t* done, uint32_t c,
                                       uint32_t previous, const int32_t* values, int dim,
                                       const uint32_t* magnitudes, int64_t* pred) {
  switch (dim) {
    case 1:
      return PredictParallelogramT<1>(wedges, done, c, previous, values, magnitudes, pred);
    case 2:
      return PredictParallelogramT<2>(wedges, done, c, previous, values, magnitudes, pred);
    case 3:
      return PredictParallelogramT<3>(wedges, done, c, previous, values, magnitudes, pred);
    default:
      return PredictParallelogramT<4>(wedges, done, c, previous, values, magnitudes, pred);
  }
}

PredictionContext PredictTexCoord(const WedgeTable& wedges, const uint8_t* done, uint32_t c,
                                  uint32_t previous, const int32_t* uv, const double* geometry,
                                  const uint32_t* magnitudes, int64_t pred[2], int64_t alt[2],
                                  bool* ambiguous) {
  *ambiguous = false;
  double sum[2] = {0, 0}, und_a[2] = {0, 0}, und_b[2] = {0, 0};
  int n_dec = 0, n_und = 0;
  const double* pc = geometry + 3 * size_t(c);
  for (const Wedge* it = wedges.begin(c); it != wedges.end(c); ++it) {
    const uint32_t a = it->u, b = it->w;
    if (!done[a] || !done[b]) continue;
    const double* pa = geometry + 3 * size_t(a);
    const double* pb = geometry + 3 * size_t(b);
    double e[3], d[3];
    for (int k = 0; k < 3; ++k) {
      e[k] = pb[k] - pa[k];
      d[k] = pc[k] - pa[k];
    }
    const double ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    if (!(ee > 0)) continue;
    const double tt = (d[0] * e[0] + d[1] * e[1] + d[2] * e[2]) / ee;
    double h2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double hk = d[k] - tt * e[k];
      h2 += hk * hk;
    }
    const double ratio = std::sqrt(h2 / ee);
    const double ua[2] = {double(uv[2 * size_t(a)]), double(uv[2 * size_t(a) + 1])};
    const double ub[2] = {double(uv[2 * size_t(b)]), double(uv[2 * size_t(b) + 1])};
    const double eu[2] = {ub[0] - ua[0], ub[1] - ua[1]};
    const double foot[2] = {ua[0] + tt * eu[0], ua[1] + tt * eu[1]};
    const double perp[2] = {-eu[1] * ratio, eu[0] * ratio};
    const double cand_a[2] = {foot[0] + perp[0], foot[1] + perp[1]};
    const double cand_b[2] = {foot[0] - perp[0], foot[1] - perp[1]};
    // The neighbour across a-b with a decoded third vertex decides the side.
    int side = 0;
    const uint32_t x = it->x;
    if (done[x]) {
      const double cx = eu[0] * (double(uv[2 * size_t(x) + 1]) - ua[1]) -
                        eu[1] * (double(uv[2 * size_t(x)]) - ua[0]);
      // perp points to the positive side (cross(eu, perp) > 0); go away from x.
      side = cx > 0 ? -1 : 1;
    }
    if (side == 0) {
      und_a[0] += cand_a[0];
      und_a[1] += cand_a[1];
      und_b[0] += cand_b[0];
      und_b[1] += cand_b[1];
      ++n_und;
    } else {
      const double* cnd = side > 0 ? cand_a : cand_b;
      sum[0] += cnd[0];
      sum[1] += cnd[1];
      ++n_dec;
    }
  }
  if (n_dec == 0 && n_und == 0) {
    return PredictParallelogram(wedges, done, c, previous, uv, 2, magnitudes, pred);
  }
  PredictionContext ctx;
  ctx.kind = kPredParallelogram;
  uint64_t mag = 0;
  int n_mag = 0;
  for (const Wedge* it = wedges.begin(c); it != wedges.end(c); ++it) {
    for (const uint32_t u : {it->u, it->w}) {
      if (!done[u]) continue;
      mag += magnitudes[u];
      ++n_mag;
    }
  }
  ctx.neighbour_magnitude =
      n_mag ? mag / uint64_t(n_mag) : (previous != kNoVertex ? magnitudes[previous] : 0);
  auto round_to = [](double x) {
    if (!(x > -1e12)) x = -1e12;
    if (!(x < 1e12)) x = 1e12;
    return int64_t(std::floor(x + 0.5));
  };
  if (n_dec > 0) {
    pred[0] = round_to(sum[0] / n_dec);
    pred[1] = round_to(sum[1] / n_dec);
  } else {
    *ambiguous = true;
    pred[0] = round_to(und_a[0] / n_und);
    pred[1] = round_to(und_a[1] / n_und);
    alt[0] = round_to(und_b[0] / n_und);
    alt[1] = round_to(und_b[1] / n_und);
  }
  return ctx;
}

uint64_t NeighbourMagnitude(const MeshAdjacency& adj, uint32_t c, const uint32_t* magnitudes) {
  uint64_t mag = 0;
  int n = 0;
  for (const uint32_t* it = adj.begin(c); it != adj.end(c); ++it) {
    const uint32_t* v = adj.corners(*it);
    for (int j = 0; j < 3; ++j) {
      if (v[j] < c) {
        mag += magnitudes[v[j]];
        ++n;
      }
    }
  }
  if (n == 0) return c > 0 ? magnitudes[c - 1] : 0;
  return mag / uint64_t(n);
}

void OctEncode(const double n[3], double* u, double* v) {
  const double s = std::fabs(n[0]) + std::fabs(n[1]) + std::fabs(n[2]);
  double x = n[0] / s, y = n[1] / s;
  if (n[2] < 0) {
    const double ox = x, oy = y;
    x = (1 - std::fabs(oy)) * (ox >= 0 ? 1 : -1);
    y = (1 - std::fabs(ox)) * (oy >= 0 ? 1 : -1);
  }
  *u = x;
  *v = y;
}

void OctDecode(double u, double v, double n[3]) {
  double z = 1 - std::fabs(u) - std::fabs(v);
  double x = u, y = v;
  if (z < 0) {
    x = (1 - std::fabs(v)) * (u >= 0 ? 1 : -1);
    y = (1 - std::fabs(u)) * (v >= 0 ? 1 : -1);
  }
  const double len = std::sqrt(x * x + y * y + z * z);
  n[0] = x / len;
  n[1] = y / len;
  n[2] = z / len;
}

PredictionContext PredictAttributeVertex(const WedgeTable& wedges, const uint8_t* done, uint32_t c,
                                         uint32_t previous, const int32_t* values, int dim,
                                         const double* geometry, const uint32_t* magnitudes,
                                         int64_t maxq, int64_t pred[4], int64_t alt[2],
                                         bool* ambiguous) {
  PredictionContext pc;
  *ambiguous = false;
  alt[0] = alt[1] = 0;
  if (geometry) {
    pc = PredictTexCoord(wedges, done, c, previous, values, geometry, magnitudes, pred, alt,
                         ambiguous);
  } else {
    pc = PredictParallelogram(wedges, done, c, previous, values, dim, magnitudes, pred);
  }
  for (int k = 0; k < dim; ++k) pred[k] = pred[k] < 0 ? 0 : (pred[k] > maxq ? maxq : pred[k]);
  if (*ambiguous) {
    for (int k = 0; k < 2; ++k) alt[k] = alt[k] < 0 ? 0 : (alt[k] > maxq ? maxq : alt[k]);
  }
  return pc;
}

}  // namespace o3dgc
