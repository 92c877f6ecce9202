#include "merge.h"

#include <algorithm>
#include <limits>

#include "thread_pool.h"

namespace vhacd {
namespace internal {

HullMesh MergedHull(const HullMesh& a, const HullMesh& b) {
  std::vector<Vec3> pts(a.vertices);
  pts.insert(pts.end(), b.vertices.begin(), b.vertices.end());
  HullMesh h;
  if (ComputeConvexHull(pts, -1.0, &h) != HullStatus::kOk) h = a.Volume() >= b.Volume() ? a : b;
  return h;
}

namespace {
struct Box {
  Vec3 lo, hi;
};
Box BoxOf(const HullMesh& h) {
  Box b{h.vertices.empty() ? Vec3::Zero() : h.vertices[0], h.vertices.empty() ? Vec3::Zero() : h.vertices[0]};
  for (const Vec3& p : h.vertices) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}
double BoxGap(const Box& a, const Box& b) {
  double gap = 0.0;
  for (int k = 0; k < 3; ++k) gap = std::max({gap, a.lo[k] - b.hi[k], b.lo[k] - a.hi[k]});
  return gap;
}
}  // namespace

bool MergeHulls(std::vector<HullMesh>* hulls_io, const MergeParams& params, Context* ctx) {
  std::vector<HullMesh>& hulls = *hulls_io;
  const size_t n = hulls.size();
  if (n < 2) return true;
  const double kInf = std::numeric_limits<double>::infinity();
  const bool use_depth = params.field != nullptr && params.max_depth > 0;
  std::vector<double> vol(n);
  std::vector<Box> box(n);
  std::vector<char> alive(n, 1);
  for (size_t i = 0; i < n; ++i) {
    vol[i] = hulls[i].Volume();
    box[i] = BoxOf(hulls[i]);
  }
  // cost/depth[i * n + j] for i < j; kInf when not computed (far apart).
  std::vector<double> cost(n * n, kInf), depth(n * n, kInf);
  bool all_pairs = false;
  auto compute_pairs = [&](const std::vector<std::pair<uint32_t, uint32_t>>& pairs) {
    return ParallelFor(ctx, pairs.size(), [&](size_t k) {
      const uint32_t i = pairs[k].first, j = pairs[k].second;
      const HullMesh m = MergedHull(hulls[i], hulls[j]);
      const double c = std::max(0.0, m.Volume() - vol[i] - vol[j]) / params.volume0;
      cost[i * n + j] = c;
      // The exact depth only matters for the budget; otherwise whether it exceeds the limit.
      if (!use_depth) depth[i * n + j] = 0.0;
      else if (params.max_hulls > 0) depth[i * n + j] = params.field->HullDepth(m);
      else if (c < params.gamma) depth[i * n + j] = params.field->HullDepth(m, params.max_depth + 0.5);
      else depth[i * n + j] = kInf;
    });
  };
  auto pairs_for = [&](bool everything) {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t i = 0; i < n; ++i)
      for (uint32_t j = i + 1; j < n; ++j)
        if (alive[i] && alive[j] && cost[i * n + j] == kInf &&
            (everything || BoxGap(box[i], box[j]) <= params.adjacency))
          pairs.emplace_back(i, j);
    return pairs;
  };
  if (!compute_pairs(pairs_for(false))) return false;
  size_t count = n;
  for (;;) {
    const bool over_budget = params.max_hulls > 0 && count > params.max_hulls;
    double best = kInf;
    uint32_t bi = 0, bj = 0;
    // Merges under gamma (and the depth limit), cheapest first.
    for (uint32_t i = 0; i < n; ++i) {
      if (!alive[i]) continue;
      for (uint32_t j = i + 1; j < n; ++j) {
        const size_t k = static_cast<size_t>(i) * n + j;
        if (alive[j] && cost[k] < params.gamma && depth[k] <= params.max_depth + 0.5 && cost[k] < best) {
          best = cost[k];
          bi = i;
          bj = j;
        }
      }
    }
    if (best == kInf && over_budget) {
      // Over the budget: the pair whose merged hull sticks out least (then the cheapest).
      double best_depth = kInf;
      for (uint32_t i = 0; i < n; ++i) {
        if (!alive[i]) continue;
        for (uint32_t j = i + 1; j < n; ++j) {
          const size_t k = static_cast<size_t>(i) * n + j;
          if (!alive[j] || cost[k] == kInf) continue;
          const double d = use_depth ? depth[k] : cost[k];
          if (d < best_depth || (d == best_depth && cost[k] < best)) {
            best_depth = d;
            best = cost[k];
            bi = i;
            bj = j;
          }
        }
      }
      if (best == kInf && !all_pairs) {
        all_pairs = true;
        if (!compute_pairs(pairs_for(true))) return false;
        continue;
      }
    }
    if (best == kInf) break;
    hulls[bi] = MergedHull(hulls[bi], hulls[bj]);
    vol[bi] = hulls[bi].Volume();
    box[bi] = BoxOf(hulls[bi]);
    alive[bj] = 0;
    hulls[bj] = HullMesh();
    --count;
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t k = 0; k < n; ++k) {
      if (!alive[k] || k == bi) continue;
      const uint32_t i = std::min(k, bi), j = std::max(k, bi);
      cost[i * n + j] = kInf;
      depth[i * n + j] = kInf;
      if (all_pairs || BoxGap(box[i], box[j]) <= params.adjacency) pairs.emplace_back(i, j);
    }
    if (!compute_pairs(pairs)) return false;
    ctx->Progress(100.0 * (n - count) / n, "merging");
  }
  std::vector<HullMesh> out;
  for (size_t i = 0; i < n; ++i)
    if (alive[i]) out.push_back(std::move(hulls[i]));
  hulls = std::move(out);
  return true;
}

}  // namespace internal
}  // namespace vhacd
