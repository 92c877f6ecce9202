#include "clipping.h"

#include <algorithm>
#include <limits>
#include <string>

#include "oriented_cuts.h"
#include "part_hull.h"
#include "stick_out.h"
#include "thread_pool.h"
#include "voxel_islands.h"

namespace vhacd {
namespace internal {

namespace {
// An oriented plane whose voxel cost is at most this multiple of the best axis-aligned one is
// compared with it on the exact surface: the voxel cost charges an oriented cut for its staircase,
// which the part hulls (clipped to the plane) do not have.
constexpr double kOrientedContest = 1.5;
// ... and taken when its halves stick out less than this share of the axis-aligned halves: a plane
// that only shaves a sliver off a part (a ring, whose halves stick out as far as the whole) wins
// by a hair at every level, and the part was never divided.
constexpr double kOrientedGain = 0.75;

// A plane to try: slice c on `axis`, or (dir >= 0) the oriented plane of the part's direction
// dir at offset d (its lines are those of the direction's axis).
struct Task {
  uint32_t part;
  int axis;
  int c;
  int dir = -1;
  double d = 0.0;
};

// Concavity and depth (when a distance field is set and measure_depth) of every part.
bool MeasureParts(const std::vector<Part>& current, const ClipParams& params, bool measure_depth,
                  double volume0, Context* ctx, std::vector<double>* conc_out,
                  std::vector<double>* depth_out) {
  const size_t n = current.size();
  std::vector<double>& conc = *conc_out;
  std::vector<double>& depth = *depth_out;
  conc.assign(n, 0.0);
  depth.assign(n, 0.0);
  if (!ParallelFor(ctx, n, [&](size_t i) {
        std::vector<Vec3> pts;
        PrimitiveHullPoints(current[i], &pts);
        HullMesh h;
        double volume = current[i].volume();
        if (!PrimitiveHull(current[i], pts, &h)) {
          // Mode 1: the trimmed cells of a flat part (a thin sheet) can be coplanar; measure
          // it on its voxels then, or a large flat L-shaped part would never be split.
          if (!current[i].tetra) return;
          PartHullPoints(current[i], false, &pts);
          if (ComputeConvexHull(pts, 0.0, &h) != HullStatus::kOk) return;
          volume = static_cast<double>(current[i].voxels.size());
        }
        conc[i] = std::max(0.0, h.Volume() - volume) / volume0;
        if (params.field != nullptr && params.max_depth > 0 && measure_depth) {
          depth[i] = params.field->HullDepth(h);
          // Mode 1 hulls follow the surface within a voxel and can be thinner than a voxel
          // (a bar bridging a gap holds no voxel centre): also sample the hull's surface.
          if (current[i].tetra && depth[i] <= params.max_depth)
            depth[i] = std::max(depth[i], params.field->SurfaceDepth(h, params.max_depth));
        }
      }))
    return false;
  return true;
}

HullMesh HullOf(const Part& part, const ClipParams& params) {
  return params.part_hulls != nullptr ? params.part_hulls->Of(part)
                                      : BuildPartHull(part, *params.index, params.corners);
}

// stick[i] for every i in `which`: how far part i's hull sticks out of the exact surface (any
// value above `limit` once known to exceed it).
bool MeasureStick(const std::vector<Part>& parts, const std::vector<uint32_t>& which,
                  const ClipParams& params, double limit, Context* ctx,
                  std::vector<double>* stick) {
  stick->resize(parts.size(), 0.0);
  if (params.meter == nullptr || params.index == nullptr) return true;
  return ParallelFor(ctx, which.size(), [&](size_t k) {
    const HullMesh h = HullOf(parts[which[k]], params);
    (*stick)[which[k]] = h.empty() ? 0.0 : params.meter->Measure(h, limit);
  });
}

// The halves of `p` on either side of the plane of `t` (`dir`: its direction when oriented).
void SplitPart(const Part& p, const Task& t, const CutDirection* dir, Part* left, Part* right) {
  const int a = t.axis, c = t.c;
  auto is_left = [&](const uint16_t xyz[3]) {
    return dir != nullptr ? OrientedLeft(*dir, t.d, xyz) : xyz[a] < c;
  };
  Part* half[2] = {left, right};
  for (const Voxel& v : p.voxels) half[is_left(v.c) ? 0 : 1]->voxels.push_back(v);
  for (int side = 0; side < 2; ++side) {
    half[side]->ComputeBounds();
    half[side]->tetra = p.tetra;
    half[side]->cuts = p.cuts;
    // The left half lies where n.x <= d, the right one where n.x >= d.
    if (dir != nullptr)
      half[side]->cuts.push_back(side == 0 ? CutPlane{dir->n, t.d} : CutPlane{-dir->n, -t.d});
  }
  if (p.tetra) {
    for (const SurfaceCell& cell : p.cells) half[is_left(cell.c) ? 0 : 1]->cells.push_back(cell);
    left->ComputeCellVolume();
    right->ComputeCellVolume();
  }
}

// Cuts every part current[split[k]] by its best plane into next[2k] and next[2k + 1] (a part
// without a usable plane moves whole into next[2k]). Moves the parts' primitives out of current.
bool CutParts(std::vector<Part>* current_io, const std::vector<uint32_t>& split,
              const std::vector<double>& conc, const ClipParams& params, const CutWeights& weights,
              Context* ctx, std::vector<Part>* next_out) {
  std::vector<Part>& cur = *current_io;
  std::vector<Part>& next = *next_out;
  const size_t m = split.size();
  std::vector<AxisLines> lines(m * 3);
  std::vector<TetraAxis> tetra(m * 3);  // mode 1 only
  std::vector<RevolutionHint> hints(m);
  std::vector<std::vector<CutDirection>> dirs(m);
  if (!ParallelFor(ctx, m * 5, [&](size_t i) {
        if (i < m * 3) {
          const Part& p = cur[split[i / 3]];
          lines[i] = BuildAxisLines(p, static_cast<int>(i % 3));
          if (p.tetra) tetra[i] = BuildTetraAxis(p, static_cast<int>(i % 3));
        } else if (i < m * 4) {
          hints[i - m * 3] = ComputeRevolutionHint(cur[split[i - m * 3]]);
        } else if (params.oriented_cuts && params.meter != nullptr && params.index != nullptr) {
          dirs[i - m * 4] = OrientedCutDirections(cur[split[i - m * 4]]);
        }
      }))
    return false;

  // Coarse search.
  std::vector<Task> tasks;
  for (size_t k = 0; k < m; ++k)
    for (int axis = 0; axis < 3; ++axis)
      for (int c : CandidatePlanes(cur[split[k]], axis, params.plane_downsampling))
        tasks.push_back({static_cast<uint32_t>(k), axis, c});
  for (size_t k = 0; k < m; ++k)
    for (size_t di = 0; di < dirs[k].size(); ++di)
      for (double d : OrientedCandidateOffsets(dirs[k][di], params.plane_downsampling))
        tasks.push_back({static_cast<uint32_t>(k), dirs[k][di].axis, 0, static_cast<int>(di), d});
  std::vector<double> cost(tasks.size());
  auto run = [&](int hull_ds) {
    return ParallelFor(ctx, tasks.size(), [&](size_t t) {
      const Task& tk = tasks[t];
      const uint32_t pi = split[tk.part];
      const size_t li = tk.part * 3 + tk.axis;
      const TetraAxis* ta = cur[pi].tetra ? &tetra[li] : nullptr;
      cost[t] = tk.dir < 0 ? CutCost(cur[pi], lines[li], tk.c, hull_ds, weights, hints[tk.part],
                                     conc[pi], ta)
                           : OrientedCutCost(cur[pi], lines[li], dirs[tk.part][tk.dir], tk.d,
                                             hull_ds, weights, hints[tk.part], conc[pi], ta);
    });
  };
  if (!run(params.convexhull_downsampling)) return false;
  // The best axis-aligned (kind 0) and oriented (kind 1) plane of part k: best[2k + kind].
  std::vector<Task> best(2 * m, Task{0, -1, 0});
  std::vector<double> best_cost(2 * m, std::numeric_limits<double>::infinity());
  auto keep_best = [&]() {  // ties keep the earlier task: deterministic
    for (size_t t = 0; t < tasks.size(); ++t) {
      const size_t b = 2 * tasks[t].part + (tasks[t].dir >= 0);
      if (cost[t] < best_cost[b]) {
        best_cost[b] = cost[t];
        best[b] = tasks[t];
      }
    }
  };
  keep_best();
  const std::vector<double> coarse_cost = best_cost;  // the downsampled estimates
  // Exact search around the best plane of each kind in `kinds` (bit 1: axis-aligned, bit 2:
  // oriented) of each part in `parts`.
  auto refine = [&](const std::vector<uint32_t>& parts, int kinds) {
    tasks.clear();
    for (uint32_t k : parts) {
      const Part& p = cur[split[k]];
      for (int kind = 0; kind < 2; ++kind) {
        const Task& bt = best[2 * k + kind];
        if (!(kinds & (1 << kind)) || bt.axis < 0) continue;
        const int a = bt.axis;
        if (bt.dir >= 0) {
          // Every unit step around the coarse offset, inside the part.
          const CutDirection& dir = dirs[k][bt.dir];
          for (int j = 1 - params.plane_downsampling; j < params.plane_downsampling; ++j) {
            const double d = bt.d + j;
            if (d > dir.lo && d <= dir.hi) tasks.push_back({k, a, 0, bt.dir, d});
          }
          continue;
        }
        const int lo = std::max(p.bmin[a] + 1, bt.c - params.plane_downsampling + 1);
        const int hi = std::min(p.bmax[a], bt.c + params.plane_downsampling - 1);
        for (int c = lo; c <= hi; ++c) tasks.push_back({k, a, c});
      }
    }
    cost.assign(tasks.size(), 0.0);
    if (!run(1)) return false;
    keep_best();
    return true;
  };
  if (params.plane_downsampling > 1 || params.convexhull_downsampling > 1) {
    std::vector<uint32_t> all(m);
    for (size_t k = 0; k < m; ++k) all[k] = static_cast<uint32_t>(k);
    std::fill(best_cost.begin(), best_cost.end(), std::numeric_limits<double>::infinity());
    if (!refine(all, 3)) return false;
  }
  // The downsampled hulls skip all but every convexhull_downsampling-th row of voxel lines, so a
  // feature thinner than that (a one-voxel sheet floating over a slab) can be invisible to the
  // coarse costs of two axes: their planes look free, the cut removes no concavity, and the part
  // was cut again and again into single voxel columns (thousands of parts, a merge of tens of
  // seconds) before the one plane through the gap was tried. When the exact cost of the chosen
  // cut shows no gain over the part's concavity although the estimate promised one (less than
  // half the exact cost), the estimate was blind: search every plane again with exact hulls.
  if (params.convexhull_downsampling > 1) {
    std::vector<uint32_t> blind;
    for (size_t k = 0; k < m; ++k)
      if (best[2 * k].axis >= 0 && best_cost[2 * k] >= conc[split[k]] &&
          coarse_cost[2 * k] < 0.5 * best_cost[2 * k])
        blind.push_back(static_cast<uint32_t>(k));
    if (!blind.empty()) {
      tasks.clear();
      for (uint32_t k : blind)
        for (int axis = 0; axis < 3; ++axis)
          for (int c : CandidatePlanes(cur[split[k]], axis, params.plane_downsampling))
            tasks.push_back({k, axis, c});
      cost.assign(tasks.size(), 0.0);
      if (!run(1)) return false;
      keep_best();
      if (params.plane_downsampling > 1 && !refine(blind, 1)) return false;
    }
  }
  // The axis-aligned plane, unless the oriented one gives clearly closer hulls: both are tried on
  // the exact surface (how far the halves' hulls stick out of it, the larger of the two), when
  // the oriented plane's voxel cost is close enough to be worth it.
  std::vector<Task> chosen(m);
  std::vector<uint32_t> contest;
  for (size_t k = 0; k < m; ++k) {
    const bool axis = best[2 * k].axis >= 0, oriented = best[2 * k + 1].axis >= 0;
    chosen[k] = best[2 * k + (axis || !oriented ? 0 : 1)];
    if (axis && oriented && best_cost[2 * k + 1] < kOrientedContest * best_cost[2 * k])
      contest.push_back(static_cast<uint32_t>(k));
  }
  // trial[4i + 2 kind + side]: the halves of part contest[i].
  std::vector<Part> trial(contest.size() * 4);
  std::vector<double> trial_stick(trial.size(), 0.0);
  if (!contest.empty()) {
    if (!ParallelFor(ctx, contest.size() * 2, [&](size_t j) {
          const uint32_t k = contest[j / 2];
          const Task& t = best[2 * k + j % 2];
          SplitPart(cur[split[k]], t, t.dir >= 0 ? &dirs[k][t.dir] : nullptr, &trial[2 * j],
                    &trial[2 * j + 1]);
        }))
      return false;
    // The axis-aligned halves exactly, then the oriented ones only as far as needed to know
    // whether they stick out less.
    for (int kind = 0; kind < 2; ++kind)
      if (!ParallelFor(ctx, contest.size() * 2, [&](size_t j) {
            const size_t i = j / 2, t = 4 * i + 2 * kind + j % 2;
            const double limit =
                kind == 0 ? 1e30
                          : kOrientedGain * std::max(trial_stick[4 * i], trial_stick[4 * i + 1]);
            const HullMesh h = HullOf(trial[t], params);
            trial_stick[t] = h.empty() ? 0.0 : params.meter->Measure(h, limit);
          }))
        return false;
    for (size_t i = 0; i < contest.size(); ++i) {
      const double axis_stick = std::max(trial_stick[4 * i], trial_stick[4 * i + 1]);
      const double oriented_stick = std::max(trial_stick[4 * i + 2], trial_stick[4 * i + 3]);
      if (oriented_stick < kOrientedGain * axis_stick)
        chosen[contest[i]] = best[2 * contest[i] + 1];
    }
  }
  // Split.
  std::vector<int> contested(m, -1);
  for (size_t i = 0; i < contest.size(); ++i) contested[contest[i]] = static_cast<int>(i);
  next.assign(m * 2, Part());
  if (!ParallelFor(ctx, m, [&](size_t k) {
        Part& p = cur[split[k]];
        const Task& t = chosen[k];
        if (t.axis < 0) {
          next[2 * k] = std::move(p);
          return;
        }
        if (contested[k] >= 0) {
          const size_t j = 4 * static_cast<size_t>(contested[k]) + 2 * (t.dir >= 0);
          next[2 * k] = std::move(trial[j]);
          next[2 * k + 1] = std::move(trial[j + 1]);
        } else {
          SplitPart(p, t, t.dir >= 0 ? &dirs[k][t.dir] : nullptr, &next[2 * k], &next[2 * k + 1]);
        }
        std::vector<Voxel>().swap(p.voxels);
        std::vector<SurfaceCell>().swap(p.cells);
      }))
    return false;
  return true;
}

}  // namespace

bool ClipRecursively(Part root, const ClipParams& params, Context* ctx, ClipOutput* out) {
  out->parts.clear();
  out->concavity.clear();
  out->depth.clear();
  out->stick.clear();
  root.ComputeBounds();
  if (root.tetra) root.ComputeCellVolume();
  {
    std::vector<Vec3> pts;
    PrimitiveHullPoints(root, &pts);
    HullMesh h;
    out->volume0 = std::max(PrimitiveHull(root, pts, &h) ? h.Volume() : 0.0, root.volume());
  }
  CutWeights weights;
  weights.alpha = params.alpha;
  weights.beta = params.beta;
  weights.volume0 = out->volume0;

  std::vector<Part> current;
  if (params.islands != nullptr && params.islands->count() > 1)
    current = params.islands->Split(std::move(root));
  else
    current.push_back(std::move(root));
  for (int level = 0;; ++level) {
    out->levels = level;
    const size_t n = current.size();
    std::vector<double> conc, depth;
    if (!MeasureParts(current, params, level < params.depth, out->volume0, ctx, &conc, &depth))
      return false;
    std::vector<uint32_t> split, rest;
    std::vector<char> cut(n, 0);
    auto thick = [&](const Part& p) {
      return p.bmax[0] > p.bmin[0] || p.bmax[1] > p.bmin[1] || p.bmax[2] > p.bmin[2];
    };
    for (size_t i = 0; i < n; ++i) {
      const bool too_deep = params.max_depth > 0 && depth[i] > params.max_depth;
      cut[i] =
          level < params.depth && (conc[i] > params.concavity || too_deep) && thick(current[i]);
      if (!cut[i]) rest.push_back(static_cast<uint32_t>(i));
    }
    // The exact measure, on the parts the voxel criteria keep.
    std::vector<double> stick;
    const double limit = params.max_stick > 0 ? params.max_stick : 1e30;
    if (!MeasureStick(current, rest, params, limit, ctx, &stick)) return false;
    for (size_t i = 0; i < n; ++i) {
      if (!cut[i] && params.meter != nullptr && params.max_stick > 0 && level < params.depth &&
          thick(current[i]) && stick[i] > params.max_stick)
        cut[i] = 1;
      if (cut[i]) {
        split.push_back(static_cast<uint32_t>(i));
      } else {
        out->parts.push_back(std::move(current[i]));
        out->concavity.push_back(conc[i]);
        out->depth.push_back(depth[i]);
        out->stick.push_back(stick[i]);
      }
    }
    ctx->Log("clipping level " + std::to_string(level) + ": " + std::to_string(n) + " parts, " +
             std::to_string(split.size()) + " to split");
    if (split.empty()) break;
    std::vector<Part> next;
    if (!CutParts(&current, split, conc, params, weights, ctx, &next)) return false;
    current.clear();
    for (Part& p : next)
      if (!p.voxels.empty()) current.push_back(std::move(p));
    ctx->Progress(100.0 * (level + 1) / std::max(1, params.depth), "clipping");
  }
  return true;
}

bool SplitToCount(size_t count, const ClipParams& params, Context* ctx, ClipOutput* out,
                  size_t per_round) {
  CutWeights weights;
  weights.alpha = params.alpha;
  weights.beta = params.beta;
  weights.volume0 = out->volume0;
  std::vector<char> stuck(out->parts.size(), 0);  // no plane divides it
  while (out->parts.size() < count) {
    // The parts sticking out farthest first, then the most concave; ties keep the lower index.
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < out->parts.size(); ++i) {
      const Part& p = out->parts[i];
      const bool thick = p.bmax[0] > p.bmin[0] || p.bmax[1] > p.bmin[1] || p.bmax[2] > p.bmin[2];
      if (thick && !stuck[i]) order.push_back(i);
    }
    if (order.empty()) break;
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
      if (params.meter != nullptr && out->stick[a] != out->stick[b])
        return out->stick[a] > out->stick[b];
      if (out->depth[a] != out->depth[b]) return out->depth[a] > out->depth[b];
      return out->concavity[a] > out->concavity[b];
    });
    size_t cuts = count - out->parts.size();
    if (per_round > 0) cuts = std::min(cuts, per_round);
    order.resize(std::min(order.size(), cuts));
    std::sort(order.begin(), order.end());
    std::vector<double> conc(out->parts.size(), 0.0);
    for (uint32_t i : order) conc[i] = out->concavity[i];
    std::vector<Part> next;
    if (!CutParts(&out->parts, order, conc, params, weights, ctx, &next)) return false;
    // Rebuild the leaf list: untouched parts keep their place, cut ones are replaced by their
    // halves (measured again).
    std::vector<Part> halves;
    std::vector<char> was_stuck;
    for (size_t k = 0; k < order.size(); ++k) {
      const bool cut = !next[2 * k + 1].voxels.empty();
      for (int side = 0; side < 2; ++side)
        if (!next[2 * k + side].voxels.empty()) {
          halves.push_back(std::move(next[2 * k + side]));
          was_stuck.push_back(!cut);
        }
    }
    std::vector<double> hc, hd, hs;
    if (!MeasureParts(halves, params, true, out->volume0, ctx, &hc, &hd)) return false;
    std::vector<uint32_t> all(halves.size());
    for (size_t k = 0; k < halves.size(); ++k) all[k] = static_cast<uint32_t>(k);
    if (!MeasureStick(halves, all, params, 1e30, ctx, &hs)) return false;
    std::vector<Part> parts;
    std::vector<double> pc, pd, pst;
    std::vector<char> ps;
    std::vector<char> cut_mask(out->parts.size(), 0);
    for (uint32_t i : order) cut_mask[i] = 1;
    for (size_t i = 0; i < out->parts.size(); ++i)
      if (!cut_mask[i]) {
        parts.push_back(std::move(out->parts[i]));
        pc.push_back(out->concavity[i]);
        pd.push_back(out->depth[i]);
        pst.push_back(out->stick[i]);
        ps.push_back(stuck[i]);
      }
    for (size_t k = 0; k < halves.size(); ++k) {
      parts.push_back(std::move(halves[k]));
      pc.push_back(hc[k]);
      pd.push_back(hd[k]);
      pst.push_back(hs[k]);
      ps.push_back(was_stuck[k]);
    }
    out->parts = std::move(parts);
    out->concavity = std::move(pc);
    out->depth = std::move(pd);
    out->stick = std::move(pst);
    stuck = std::move(ps);
  }
  return true;
}

}  // namespace internal
}  // namespace vhacd
