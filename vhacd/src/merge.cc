#include "merge.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>

#include "stick_out.h"
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
  Box b{h.vertices.empty() ? Vec3::Zero() : h.vertices[0],
        h.vertices.empty() ? Vec3::Zero() : h.vertices[0]};
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
  const bool budget = params.max_hulls > 0 && n > params.max_hulls;
  const double stick_cap = params.max_stick > 0 ? 3.0 * params.max_stick : 1e30;
  std::vector<double> vol(n), stick(n, 0.0);
  std::vector<Box> box(n);
  std::vector<char> alive(n, 1);
  std::vector<uint32_t> version(n, 0);
  // A hull merged over the budget keeps the group of the first of the pair.
  auto same_group = [&](uint32_t i, uint32_t j) {
    return params.groups == nullptr || (*params.groups)[i] == (*params.groups)[j];
  };
  for (size_t i = 0; i < n; ++i) {
    vol[i] = hulls[i].Volume();
    box[i] = BoxOf(hulls[i]);
  }
  if (params.meter != nullptr && !ParallelFor(ctx, n, [&](size_t i) {
        stick[i] = params.meter->Measure(hulls[i], stick_cap);
      }))
    return false;
  // Candidate pairs, ordered by (key1, key2, i, j); stale entries (an older version of a hull, or
  // a merged-away hull) are skipped when popped. `under` holds the merges allowed under gamma,
  // `over` every evaluated pair for the hull budget.
  struct Cand {
    double key1, key2;
    uint32_t i, j, vi, vj;
    bool exact;  // key1 is the merged hull's stick-out, not yet only its lower bound
    bool operator>(const Cand& o) const {
      if (key1 != o.key1) return key1 > o.key1;
      if (key2 != o.key2) return key2 > o.key2;
      if (i != o.i) return i > o.i;
      return j > o.j;
    }
  };
  std::priority_queue<Cand, std::vector<Cand>, std::greater<Cand>> under, over;
  auto evaluate = [&](const std::vector<std::pair<uint32_t, uint32_t>>& pairs) {
    std::vector<double> cost(pairs.size()), depth(pairs.size()), lower(pairs.size());
    if (!ParallelFor(ctx, pairs.size(), [&](size_t k) {
          const uint32_t i = pairs[k].first, j = pairs[k].second;
          const HullMesh m = MergedHull(hulls[i], hulls[j]);
          const double c = std::max(0.0, m.Volume() - vol[i] - vol[j]) / params.volume0;
          cost[k] = c;
          // The exact depth only matters for the budget; otherwise whether it exceeds the limit.
          if (params.meter != nullptr) {
            lower[k] = std::min(stick_cap, std::max(stick[i], stick[j]));
            if (params.max_stick <= 0)
              depth[k] = c < params.gamma ? 0.0 : kInf;
            else if (c < params.gamma &&
                     (!use_depth ||
                      params.field->HullDepth(m, params.max_depth) <= params.max_depth))
              depth[k] = params.meter->MeasureMerged(m, hulls[i], stick[i], hulls[j], stick[j],
                                                     params.max_stick);
            else
              depth[k] = kInf;
          } else if (!use_depth)
            depth[k] = 0.0;
          else if (budget)
            depth[k] = std::max(params.field->SurfaceDepth(m), params.field->HullDepth(m));
          else if (c < params.gamma) {
            depth[k] = params.field->SurfaceDepth(m, params.max_depth);
            if (depth[k] <= params.max_depth)
              depth[k] = std::max(depth[k], params.field->HullDepth(m, params.max_depth));
          } else
            depth[k] = kInf;
        }))
      return false;
    for (size_t k = 0; k < pairs.size(); ++k) {
      const uint32_t i = pairs[k].first, j = pairs[k].second;
      const double limit =
          params.meter != nullptr ? std::max(0.0, params.max_stick) : params.max_depth;
      if (cost[k] < params.gamma && (!(use_depth || params.meter) || depth[k] <= limit) &&
          same_group(i, j))
        under.push({cost[k], 0.0, i, j, version[i], version[j], true});
      if (budget)
        over.push({params.meter ? lower[k]
                   : use_depth  ? depth[k]
                                : cost[k],
                   cost[k], i, j, version[i], version[j], params.meter == nullptr});
    }
    return true;
  };
  auto pairs_with = [&](uint32_t h, bool everything) {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t k = 0; k < n; ++k)
      if (k != h && alive[k] && (budget || same_group(h, k)) &&
          (everything || BoxGap(box[h], box[k]) <= params.adjacency))
        pairs.emplace_back(std::min(h, k), std::max(h, k));
    return pairs;
  };
  {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t i = 0; i < n; ++i)
      for (uint32_t j = i + 1; j < n; ++j)
        if ((budget || same_group(i, j)) && BoxGap(box[i], box[j]) <= params.adjacency)
          pairs.emplace_back(i, j);
    if (!evaluate(pairs)) return false;
  }
  auto valid = [&](const Cand& c) {
    return alive[c.i] && alive[c.j] && version[c.i] == c.vi && version[c.j] == c.vj;
  };
  size_t count = n;
  bool all_pairs = false;
  for (;;) {
    while (!under.empty() && !valid(under.top())) under.pop();
    const bool over_budget = budget && count > params.max_hulls;
    Cand pick{};
    bool have = false;
    if (!under.empty() && count > params.min_hulls) {
      pick = under.top();
      under.pop();
      have = true;
    } else if (over_budget) {
      while (!over.empty() && !valid(over.top())) over.pop();
      if (over.empty() && !all_pairs) {
        // Only far-apart hulls remain: evaluate every pair once, then keep going.
        all_pairs = true;
        std::vector<std::pair<uint32_t, uint32_t>> pairs;
        for (uint32_t i = 0; i < n; ++i)
          for (uint32_t j = i + 1; j < n; ++j)
            if (alive[i] && alive[j] && BoxGap(box[i], box[j]) > params.adjacency)
              pairs.emplace_back(i, j);
        if (!evaluate(pairs)) return false;
        continue;
      }
      if (!over.empty()) {
        pick = over.top();
        over.pop();
        if (!pick.exact) {
          // Lazy: the exact stick-out (merges beyond the cap are ranked by volume alone).
          const HullMesh m = MergedHull(hulls[pick.i], hulls[pick.j]);
          pick.key1 = std::min(
              stick_cap, params.meter->MeasureMerged(m, hulls[pick.i], stick[pick.i], hulls[pick.j],
                                                     stick[pick.j], stick_cap));
          pick.exact = true;
          over.push(pick);
          continue;
        }
        have = true;
      }
    }
    if (!have) break;
    const uint32_t bi = pick.i, bj = pick.j;
    HullMesh merged = MergedHull(hulls[bi], hulls[bj]);
    if (params.meter != nullptr)
      stick[bi] = params.meter->MeasureMerged(merged, hulls[bi], stick[bi], hulls[bj], stick[bj],
                                              stick_cap);
    hulls[bi] = std::move(merged);
    vol[bi] = hulls[bi].Volume();
    box[bi] = BoxOf(hulls[bi]);
    ++version[bi];
    alive[bj] = 0;
    hulls[bj] = HullMesh();
    --count;
    if (!evaluate(pairs_with(bi, all_pairs))) return false;
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
