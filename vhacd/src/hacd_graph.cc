#include "hacd_graph.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vhacd {
namespace internal {

uint32_t LabelPieces(size_t triangle_count, const std::vector<DualEdge>& edges,
                     std::vector<uint32_t>* label) {
  std::vector<uint32_t> parent(triangle_count);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const DualEdge& e : edges) {
    const uint32_t ra = find(e.a), rb = find(e.b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  label->assign(triangle_count, 0);
  std::vector<uint32_t> id(triangle_count, UINT32_MAX);
  uint32_t count = 0;
  for (size_t t = 0; t < triangle_count; ++t) {
    const uint32_t r = find(static_cast<uint32_t>(t));
    if (id[r] == UINT32_MAX) id[r] = count++;
    (*label)[t] = id[r];
  }
  return count;
}

namespace {

void SortUnique(std::vector<DualEdge>* edges) {
  std::sort(edges->begin(), edges->end(), [](const DualEdge& x, const DualEdge& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  std::vector<DualEdge> out;
  for (const DualEdge& e : *edges) {
    if (!out.empty() && out.back().a == e.a && out.back().b == e.b)
      out.back().shared_length += e.shared_length;
    else
      out.push_back(e);
  }
  edges->swap(out);
}

}  // namespace

bool BuildDualGraph(const std::vector<Vec3>& points,
                    const std::vector<std::array<uint32_t, 3>>& triangles, double connect_distance,
                    Context* ctx, std::vector<DualEdge>* edges) {
  edges->clear();
  std::vector<std::pair<uint64_t, uint32_t>> uses;
  uses.reserve(triangles.size() * 3);
  for (uint32_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      uses.emplace_back((uint64_t{std::min(a, b)} << 32) | std::max(a, b), t);
    }
  std::sort(uses.begin(), uses.end());
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].first == uses[i].first) ++j;
    const double len = (points[uses[i].first >> 32] - points[uint32_t(uses[i].first)]).norm();
    for (size_t x = i; x < j; ++x)
      for (size_t y = x + 1; y < j; ++y)
        if (uses[x].second != uses[y].second)
          edges->push_back({std::min(uses[x].second, uses[y].second),
                            std::max(uses[x].second, uses[y].second), len});
    i = j;
  }
  SortUnique(edges);
  if (ctx != nullptr && ctx->Cancelled()) return false;
  if (connect_distance < 0 || triangles.empty()) return true;
  std::vector<uint32_t> piece;
  if (LabelPieces(triangles.size(), *edges, &piece) < 2) return true;

  // Vertex -> (piece, one triangle); a vertex shared by two pieces counts for the first.
  const uint32_t none = UINT32_MAX;
  std::vector<uint32_t> vpiece(points.size(), none), vtri(points.size(), none);
  for (uint32_t t = 0; t < triangles.size(); ++t)
    for (uint32_t v : triangles[t])
      if (vtri[v] == none) {
        vtri[v] = t;
        vpiece[v] = piece[t];
      }
  std::vector<uint32_t> verts;
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = -lo;
  for (uint32_t v = 0; v < points.size(); ++v)
    if (vtri[v] != none) {
      verts.push_back(v);
      lo = lo.cwiseMin(points[v]);
      hi = hi.cwiseMax(points[v]);
    }
  // Uniform grid of about one vertex per cell, cells no smaller than needed.
  const Vec3 ext = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
  double cell = std::cbrt(ext[0] * ext[1] * ext[2] / std::max<size_t>(1, verts.size()));
  cell = std::max(cell, ext.maxCoeff() / 256.0);
  int dims[3];
  for (int k = 0; k < 3; ++k)
    dims[k] = std::max(1, std::min(256, static_cast<int>(std::ceil(ext[k] / cell))));
  auto cell_of = [&](const Vec3& p, int k) {
    return std::max(0, std::min(dims[k] - 1, static_cast<int>((p[k] - lo[k]) / cell)));
  };
  const size_t ncells = size_t(dims[0]) * dims[1] * dims[2];
  std::vector<uint32_t> start(ncells + 1, 0), ids(verts.size());
  auto index = [&](int x, int y, int z) { return (size_t(z) * dims[1] + y) * dims[0] + x; };
  for (uint32_t v : verts)
    ++start[index(cell_of(points[v], 0), cell_of(points[v], 1), cell_of(points[v], 2)) + 1];
  for (size_t c = 0; c < ncells; ++c) start[c + 1] += start[c];
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (uint32_t v : verts)
      ids[fill[index(cell_of(points[v], 0), cell_of(points[v], 1), cell_of(points[v], 2))]++] = v;
  }
  // Nearest vertex of another piece: rings of cells outward until the ring is farther than the
  // best hit or than connect_distance.
  const int max_ring = static_cast<int>(std::ceil(connect_distance / cell)) + 1;
  std::vector<DualEdge> extra;
  for (size_t n = 0; n < verts.size(); ++n) {
    if ((n & 4095) == 0 && ctx != nullptr && ctx->Cancelled()) return false;
    const uint32_t v = verts[n];
    const Vec3& p = points[v];
    const int c[3] = {cell_of(p, 0), cell_of(p, 1), cell_of(p, 2)};
    double best = connect_distance;
    uint32_t best_v = none;
    const int rings = std::min(max_ring, std::max({dims[0], dims[1], dims[2]}));
    for (int r = 0; r <= rings; ++r) {
      if (best_v != none && (r - 1) * cell > best) break;
      for (int z = c[2] - r; z <= c[2] + r; ++z) {
        if (z < 0 || z >= dims[2]) continue;
        for (int y = c[1] - r; y <= c[1] + r; ++y) {
          if (y < 0 || y >= dims[1]) continue;
          const bool face_zy = std::abs(z - c[2]) == r || std::abs(y - c[1]) == r;
          for (int x = c[0] - r; x <= c[0] + r; x += (face_zy ? 1 : std::max(1, 2 * r))) {
            if (x < 0 || x >= dims[0]) continue;
            const size_t ci = index(x, y, z);
            for (uint32_t k = start[ci]; k < start[ci + 1]; ++k) {
              const uint32_t w = ids[k];
              if (vpiece[w] == vpiece[v]) continue;
              const double d = (points[w] - p).norm();
              if (d <= best && (best_v == none || d < best || w < best_v)) {
                best = d;
                best_v = w;
              }
            }
          }
        }
      }
    }
    if (best_v != none) {
      const uint32_t ta = vtri[v], tb = vtri[best_v];
      extra.push_back({std::min(ta, tb), std::max(ta, tb), 0.0});
    }
  }
  edges->insert(edges->end(), extra.begin(), extra.end());
  SortUnique(edges);
  return true;
}

}  // namespace internal
}  // namespace vhacd
