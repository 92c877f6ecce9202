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

void WedgeTable::Build(const std::vector<uint32_t>& triangles, uint32_t num_vertices,
                       const std::vector<uint32_t>& opposite) {
  start_.assign(size_t(num_vertices) + 1, 0);
  const size_t nt = triangles.size() / 3;
  const uint32_t* tri = triangles.data();
  auto ok = [&](size_t t) {
    const uint32_t* v = tri + 3 * t;
    return v[0] != v[1] && v[1] != v[2] && v[0] != v[2];
  };
  for (size_t t = 0; t < nt; ++t) {
    if (!ok(t)) continue;
    for (int j = 0; j < 3; ++j) ++start_[tri[3 * t + j] + 1];
  }
  for (uint32_t v = 0; v < num_vertices; ++v) start_[v + 1] += start_[v];
  wedges_.resize(start_[num_vertices]);
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  const bool has_opposite = opposite.size() >= 3 * nt;
  for (size_t t = 0; t < nt; ++t) {
    if (!ok(t)) continue;
    const uint32_t* v = tri + 3 * t;
    for (int j = 0; j < 3; ++j) {
      const uint32_t p = v[j == 2 ? 0 : j + 1], q = v[j == 0 ? 2 : j - 1];
      uint32_t x = kNoVertex;
      const uint32_t e = has_opposite ? opposite[3 * t + j] : 0xFFFFFFFFu;
      if (e != 0xFFFFFFFFu) {
        // The neighbour counts only if its edge has the same two vertices (attribute seams can
        // split a position edge).
        const uint32_t* o = tri + 3 * size_t(e / 4);
        const int s = int(e % 4);
        const uint32_t op = o[s == 2 ? 0 : s + 1], oq = o[s == 0 ? 2 : s - 1];
        if ((op == p && oq == q) || (op == q && oq == p)) x = o[s];
      }
      wedges_[fill[v[j]]++] = Wedge{p, q, x};
    }
  }
}

DegreeTraversal::DegreeTraversal(const WedgeTable& wedges)
    : wedges_(wedges), done_(wedges.num_vertices(), 0), degree_(wedges.num_vertices(), 0) {
  for (auto& s : stacks_) s.reserve(64);
}

uint32_t DegreeTraversal::Next() {
  const uint32_t n = wedges_.num_vertices();
  if (visited_ >= n) return kNoVertex;
  for (;;) {
    int level = kLevels - 1;
    while (level >= 0 && stacks_[level].empty()) --level;
    if (level < 0) {
      while (done_[next_start_]) ++next_start_;
      return next_start_;
    }
    const uint32_t c = stacks_[level].back();
    stacks_[level].pop_back();
    if (done_[c]) continue;
    const int cur = degree_[c] < kLevels ? int(degree_[c]) : kLevels - 1;
    if (cur != level) continue;  // stale entry: a newer one sits at its current level
    return c;
  }
}

void DegreeTraversal::Visit(uint32_t c) {
  done_[c] = 1;
  ++visited_;
  previous_ = c;
  for (const Wedge* it = wedges_.begin(c); it != wedges_.end(c); ++it) {
    const uint32_t u = it->u, w = it->w;
    if (!done_[u] && done_[w]) {
      ++degree_[u];
      Push(degree_[u] < kLevels ? int(degree_[u]) : kLevels - 1, u);
    } else if (done_[u] && !done_[w]) {
      ++degree_[w];
      Push(degree_[w] < kLevels ? int(degree_[w]) : kLevels - 1, w);
    } else if (!done_[u] && !done_[w]) {
      Push(0, w);
      Push(0, u);
    }
  }
}

PredictionContext PredictParallelogram(const WedgeTable& wedges, const uint8_t* done, uint32_t c,
                                       uint32_t previous, const int32_t* values, int dim,
                                       const uint32_t* magnitudes, int64_t* pred) {
  int64_t par[4] = {0, 0, 0, 0};
  constexpr int kMaxKept = 16;
  int64_t kept[kMaxKept][4];
  int n_par = 0;
  const Wedge* const first = wedges.begin(c);
  const Wedge* const last = wedges.end(c);
  for (const Wedge* it = first; it != last; ++it) {
    const uint32_t u = it->u, w2 = it->w, x = it->x;
    if (!done[u] || !done[w2] || x == kNoVertex || !done[x]) continue;
    for (int k = 0; k < dim; ++k) {
      const int64_t pk = int64_t(values[size_t(u) * dim + k]) + values[size_t(w2) * dim + k] -
                         values[size_t(x) * dim + k];
      par[k] += pk;
      if (n_par < kMaxKept) kept[n_par][k] = pk;
    }
    ++n_par;
  }
  PredictionContext ctx;
  if (n_par >= 2) {
    for (int k = 0; k < dim; ++k) pred[k] = DivRound(par[k], n_par);
    ctx.kind = kPredParallelogram;
    // Three or more parallelograms: the component-wise median is more robust than the mean.
    if (n_par >= 3 && n_par <= kMaxKept) {
      for (int k = 0; k < dim; ++k) {
        int64_t col[kMaxKept];
        for (int i = 0; i < n_par; ++i) {  // insertion sort: n_par is small
          int64_t xv = kept[i][k];
          int q = i;
          for (; q > 0 && col[q - 1] > xv; --q) col[q] = col[q - 1];
          col[q] = xv;
        }
        pred[k] = (n_par & 1) ? col[n_par / 2] : DivRound(col[n_par / 2 - 1] + col[n_par / 2], 2);
      }
    }
    // The context is the disagreement between the parallelograms: twice the mean absolute
    // deviation, summed over the components.
    const int m = n_par < kMaxKept ? n_par : kMaxKept;
    uint64_t dev = 0;
    for (int i = 0; i < m; ++i) {
      for (int k = 0; k < dim; ++k) {
        const int64_t d = kept[i][k] - pred[k];
        dev += uint64_t(d < 0 ? -d : d);
      }
    }
    ctx.neighbour_magnitude = dev * 2 / uint64_t(m);
    return ctx;
  }
  // One parallelogram or none: the context (and the fallback) come from the coded neighbours.
  int64_t nb[4] = {0, 0, 0, 0};
  int n_nb = 0;
  uint64_t mag = 0;
  for (const Wedge* it = first; it != last; ++it) {
    for (const uint32_t u : {it->u, it->w}) {
      if (!done[u]) continue;
      for (int k = 0; k < dim; ++k) nb[k] += values[size_t(u) * dim + k];
      if (magnitudes) mag += magnitudes[u];
      ++n_nb;
    }
  }
  ctx.neighbour_magnitude = n_nb ? mag / uint64_t(n_nb) : 0;
  if (n_par == 1) {
    for (int k = 0; k < dim; ++k) pred[k] = par[k];
    ctx.kind = kPredParallelogram;
  } else if (n_nb > 0) {
    for (int k = 0; k < dim; ++k) pred[k] = DivRound(nb[k], n_nb);
    ctx.kind = kPredNeighbours;
  } else {
    for (int k = 0; k < dim; ++k) {
      pred[k] = previous != kNoVertex ? values[size_t(previous) * dim + k] : 0;
    }
    ctx.kind = kPredPrevious;
    if (magnitudes && previous != kNoVertex) ctx.neighbour_magnitude = magnitudes[previous];
  }
  return ctx;
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
    if (x != kNoVertex && done[x]) {
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
  ctx.neighbour_magnitude = n_mag ? mag / uint64_t(n_mag)
                                  : (previous != kNoVertex ? magnitudes[previous] : 0);
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
                                         int64_t maxq, int64_t pred[4], int64_t alt[2], bool* ambiguous) {
  PredictionContext pc;
  *ambiguous = false;
  alt[0] = alt[1] = 0;
  if (geometry) {
    pc = PredictTexCoord(wedges, done, c, previous, values, geometry, magnitudes, pred, alt, ambiguous);
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
