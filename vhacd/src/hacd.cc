// vhacd::DecomposeHacd: the HACD pipeline (see include/vhacd/hacd.h).
#include "vhacd/hacd.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <queue>
#include <thread>
#include <unordered_map>

#include "context.h"
#include "convex_hull.h"
#include "error_metrics.h"
#include "hacd_cost.h"
#include "hacd_graph.h"
#include "hacd_hull.h"
#include "hacd_orient.h"
#include "hacd_raycast.h"
#include "input_mesh.h"
#include "simplify_qem.h"
#include "thread_pool.h"
#include "voxelizer.h"
#include "working_frame.h"

namespace vhacd {

HacdParameters HacdParameters::Recommended() {
  HacdParameters p;
  p.min_clusters = 2;
  p.concavity = 100.0;
  p.invert_input_faces = false;
  p.add_extra_dist_points = true;
  p.add_face_points = true;
  p.connect_distance = 30.0;
  p.target_triangles = 2000;
  return p;
}

Status ValidateHacdParameters(const HacdParameters& p, std::string* why) {
  auto bad = [&](const char* msg) {
    if (why != nullptr) *why = msg;
    return Status::kInvalidParameter;
  };
  auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  if (p.target_triangles >= (uint32_t{1} << 31)) return bad("target_triangles must be below 2^31");
  if (p.max_vertices_per_hull < 4 || p.max_vertices_per_hull > 1024)
    return bad("max_vertices_per_hull must be in [4, 1024]");
  if (!in(p.scale_factor, 1.0, 1e6)) return bad("scale_factor must be in [1, 1e6]");
  if (!in(p.small_cluster_threshold, 0.0, 100.0))
    return bad("small_cluster_threshold must be in [0, 100]");
  if (p.min_clusters < 1 || p.min_clusters > 100000)
    return bad("min_clusters must be in [1, 100000]");
  if (!in(p.concavity, 0.0, 1e7)) return bad("concavity must be in [0, 1e7]");
  if (!in(p.connect_distance, -1.0, 1e7)) return bad("connect_distance must be in [-1, 1e7]");
  if (!in(p.volume_weight, 0.0, 1e3)) return bad("volume_weight must be in [0, 1000]");
  if (!in(p.compacity_weight, 0.0, 1e3)) return bad("compacity_weight must be in [0, 1000]");
  if (!in(p.flat_region_threshold, 0.0, 100.0))
    return bad("flat_region_threshold must be in [0, 100]");
  if (!in(p.computation_weight, 0.0, 1e3)) return bad("computation_weight must be in [0, 1000]");
  if (p.max_clusters > 100000) return bad("max_clusters must be in [0, 100000]");
  if (!in(p.max_concavity, 0.0, 1.0)) return bad("max_concavity must be in [0, 1]");
  if (p.hull_count > 100000) return bad("hull_count must be in [0, 100000]");
  if (p.num_threads > 256) return bad("num_threads must be in [0, 256]");
  if (why != nullptr) why->clear();
  return Status::kOk;
}

namespace {

using internal::Vec3;
using Tri = std::array<uint32_t, 3>;

Result Fail(Status s, std::string message) {
  Result r;
  r.status = s;
  r.message = std::move(message);
  return r;
}

// The clustering state: the dual graph whose nodes are clusters.
class Clustering {
 public:
  struct Edge {
    uint32_t a = 0, b = 0;
    double shared = 0.0;
    double cost = 0.0, concavity = 0.0;
    uint32_t version_a = UINT32_MAX, version_b = UINT32_MAX;  // cluster versions of `cost`
    uint32_t generation = 0;                                  // of its newest heap entry
    bool alive = true;
  };
  struct Cluster {
    std::vector<uint32_t> dist;     // sorted distance point ids (ids < vertex count: mesh vertices)
    std::vector<Vec3> hull_points;  // points spanning its hull
    std::vector<uint32_t> edges;
    std::vector<uint32_t> triangles;
    double area = 0.0, perimeter = 0.0;
    uint32_t version = 0;
    bool alive = true;
  };

  // When the merges stop.
  struct Limits {
    double concavity = 0.0;    // merges of this concavity or more are refused...
    size_t min_clusters = 1;   // ... and none leaves fewer clusters than this, ...
    size_t max_clusters = 0;   // ... then, when > 0, the cheapest merges go on down to this many
    bool floor_small = false;  // the forced merges of small clusters also stop at min_clusters
  };

  Clustering(const HacdParameters& p, const internal::HacdCostParams& cp,
             const std::vector<internal::DistPoint>& dist, double total_area)
      : p_(p), cp_(cp), dist_(dist) {
    area_threshold_ = total_area * p.small_cluster_threshold / 100.0;
  }

  std::vector<Cluster>& clusters() { return clusters_; }
  const std::vector<Cluster>& clusters() const { return clusters_; }
  const std::vector<internal::DistPoint>& dist() const { return dist_; }
  std::vector<Edge>& edges() { return edges_; }
  size_t alive_count() const { return alive_; }

  bool Run(internal::Context* ctx, const Limits& lim) {
    alive_ = clusters_.size();
    n0_ = alive_;
    if (!Merge(ctx, lim.concavity, lim)) return false;
    if (lim.max_clusters > 0 && alive_ > lim.max_clusters) {
      // The budget: every remaining edge again, without the concavity limit.
      heap_ = decltype(heap_)();
      for (Edge& e : edges_) e.version_a = UINT32_MAX;
      for (uint32_t e = 0; e < edges_.size(); ++e)
        if (edges_[e].alive) Push(e);
      if (!Merge(ctx, HUGE_VAL, lim)) return false;
    }
    return true;
  }

 private:
  struct Entry {
    double cost;
    uint32_t edge, generation;
    bool operator>(const Entry& o) const { return cost != o.cost ? cost > o.cost : edge > o.edge; }
  };

  // Collapses edges cheapest first while their concavity is below `ceiling` (or a cluster is
  // small) and more than the limits' count remain.
  bool Merge(internal::Context* ctx, double ceiling, const Limits& lim) {
    ceiling_ = ceiling;
    const size_t target =
        std::max(lim.min_clusters,
                 lim.max_clusters > 0 && ceiling == HUGE_VAL ? lim.max_clusters : size_t{1});
    if (!started_) {
      started_ = true;
      if (!internal::ParallelFor(ctx, edges_.size(), [&](size_t e) { Evaluate(&edges_[e]); }))
        return false;
      for (uint32_t e = 0; e < edges_.size(); ++e) Push(e);
    }
    size_t pops = 0;
    while (!heap_.empty()) {
      if ((++pops & 63) == 0 && ctx != nullptr) {
        if (ctx->Cancelled()) return false;
        ctx->Progress(100.0 * (n0_ - alive_) / std::max<size_t>(1, n0_), "merging clusters");
      }
      const Entry top = heap_.top();
      heap_.pop();
      Edge& e = edges_[top.edge];
      if (!e.alive || e.generation != top.generation) continue;
      const bool small =
          (clusters_[e.a].area < area_threshold_ || clusters_[e.b].area < area_threshold_) &&
          (!lim.floor_small || alive_ > lim.min_clusters);
      const bool may_merge = alive_ > target;
      if (!small && !may_merge) continue;
      if (e.version_a != clusters_[e.a].version || e.version_b != clusters_[e.b].version) {
        Evaluate(&e);
        Push(top.edge);
        continue;
      }
      if (!small && !(e.concavity < ceiling_)) continue;
      Collapse(top.edge);
    }
    return true;
  }

  bool Small(const Cluster& c) const { return c.area < area_threshold_; }

  void Evaluate(Edge* e) const {
    const Cluster& a = clusters_[e->a];
    const Cluster& b = clusters_[e->b];
    std::vector<Vec3> pts(a.hull_points);
    pts.insert(pts.end(), b.hull_points.begin(), b.hull_points.end());
    const double limit = (Small(a) || Small(b)) ? HUGE_VAL : ceiling_;
    const internal::MergeCost mc =
        internal::EvaluateCluster(pts, dist_, a.dist, b.dist, a.area + b.area,
                                  a.perimeter + b.perimeter - 2.0 * e->shared, limit, cp_, nullptr);
    e->cost = mc.cost;
    e->concavity = mc.concavity;
    e->version_a = a.version;
    e->version_b = b.version;
  }

  void Push(uint32_t e) {
    ++edges_[e].generation;
    heap_.push({edges_[e].cost, e, edges_[e].generation});
  }

  void Collapse(uint32_t eid) {
    const uint32_t ia = edges_[eid].a, ib = edges_[eid].b;
    Cluster& a = clusters_[ia];
    Cluster& b = clusters_[ib];
    std::vector<Vec3> pts(a.hull_points);
    pts.insert(pts.end(), b.hull_points.begin(), b.hull_points.end());
    std::vector<Vec3> kept;
    internal::EvaluateCluster(pts, dist_, {}, {}, 0.0, 0.0, 0.0, cp_, &kept);
    a.hull_points = kept.size() >= 3 ? std::move(kept) : std::move(pts);
    a.perimeter = std::max(0.0, a.perimeter + b.perimeter - 2.0 * edges_[eid].shared);
    a.area += b.area;
    std::vector<uint32_t> merged;
    merged.reserve(a.dist.size() + b.dist.size());
    std::set_union(a.dist.begin(), a.dist.end(), b.dist.begin(), b.dist.end(),
                   std::back_inserter(merged));
    a.dist.swap(merged);
    std::vector<uint32_t>().swap(b.dist);
    a.triangles.insert(a.triangles.end(), b.triangles.begin(), b.triangles.end());
    std::vector<uint32_t>().swap(b.triangles);
    std::vector<Vec3>().swap(b.hull_points);
    // Re-attach b's edges to a, merging parallel ones.
    std::unordered_map<uint32_t, uint32_t> to;  // neighbour cluster -> edge of a
    for (uint32_t e : a.edges) {
      Edge& ed = edges_[e];
      if (!ed.alive) continue;
      to[ed.a == ia ? ed.b : ed.a] = e;
    }
    for (uint32_t e : b.edges) {
      Edge& ed = edges_[e];
      if (!ed.alive) continue;
      const uint32_t x = ed.a == ib ? ed.b : ed.a;
      if (x == ia) {
        ed.alive = false;
        continue;
      }
      auto it = to.find(x);
      if (it != to.end()) {
        edges_[it->second].shared += ed.shared;
        ed.alive = false;
        continue;
      }
      if (ed.a == ib)
        ed.a = ia;
      else
        ed.b = ia;
      if (ed.a > ed.b) std::swap(ed.a, ed.b);
      a.edges.push_back(e);
      to[x] = e;
    }
    std::vector<uint32_t>().swap(b.edges);
    b.alive = false;
    --alive_;
    a.edges.erase(std::remove_if(a.edges.begin(), a.edges.end(),
                                 [&](uint32_t e) { return !edges_[e].alive; }),
                  a.edges.end());
    std::sort(a.edges.begin(), a.edges.end());
    ++a.version;
    // Stale costs stay as lower bounds: each is recomputed when it reaches the top of the heap.
    for (uint32_t e : a.edges) Push(e);
  }

  const HacdParameters& p_;
  internal::HacdCostParams cp_;
  const std::vector<internal::DistPoint>& dist_;
  double area_threshold_ = 0.0;
  double ceiling_ = 0.0;
  size_t n0_ = 0;
  bool started_ = false;
  std::vector<Cluster> clusters_;
  std::vector<Edge> edges_;
  size_t alive_ = 0;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap_;
};

Result DecomposeHacdImpl(const MeshView& view, const HacdParameters& params, Observer* observer) {
  std::string why;
  Status st = ValidateHacdParameters(params, &why);
  if (st != Status::kOk) return Fail(st, why);
  internal::Context ctx(observer, internal::ThreadCount(params.num_threads));
  internal::InputMesh input;
  st = internal::ReadMesh(view, &ctx, &input, &why);
  if (st != Status::kOk) return Fail(st, why);
  Result result;
  Report& rep = result.report;
  rep.closed_input = input.closed;
  internal::Clock clock, total;

  // Normalization: centre of the box, then the diagonal scaled to 2 * scale_factor.
  Vec3 center;
  double extent = 0.0;
  std::vector<Vec3> pq = std::move(input.points);
  if (!internal::NormalizeToUnitBox(&pq, &center, &extent))
    return Fail(Status::kInvalidMesh, "the mesh has a degenerate or overflowing bounding box");
  Vec3 qlo = Vec3::Constant(HUGE_VAL), qhi = -qlo;
  for (const Vec3& p : pq) {
    qlo = qlo.cwiseMin(p);
    qhi = qhi.cwiseMax(p);
  }
  const double qdiag = (qhi - qlo).norm();
  const double to_norm = 2.0 * params.scale_factor / qdiag;
  for (Vec3& p : pq) p *= to_norm;
  auto to_world = [&](const Vec3& n) -> Vec3 { return center + (n / to_norm) * extent; };
  const double diag = 2.0 * params.scale_factor;

  std::vector<Tri> tris = input.triangles.ToArrays();

  // Decimation (the simplifier does not need consistent windings: the triangles are oriented
  // after it, on the smaller mesh).
  ctx.BeginStage("Simplification", 0, 15);
  std::vector<Vec3> pts = pq;
  if (params.target_triangles > 0 && tris.size() > params.target_triangles) {
    internal::QemMesh in, out;
    in.points = pq;
    in.triangles = tris;
    internal::QemOptions qo;
    qo.target_triangles = params.target_triangles;
    if (!internal::SimplifyQem(in, {}, qo, &ctx, &out))
      return Fail(Status::kCancelled, "cancelled");
    pts = std::move(out.points);
    tris = std::move(out.triangles);
    ctx.Log("decimated to " + std::to_string(tris.size()) + " triangles");
  }
  if (tris.empty()) return Fail(Status::kInternalError, "decimation left no triangle");
  internal::OrientConsistently(pts, &tris);
  if (params.invert_input_faces)
    for (Tri& t : tris) std::swap(t[1], t[2]);
  rep.seconds_simplify = clock.Lap();

  // Dual graph and distance points.
  ctx.BeginStage("Dual graph", 15, 25);
  std::vector<internal::DualEdge> dual;
  if (!internal::BuildDualGraph(pts, tris, params.connect_distance, &ctx, &dual))
    return Fail(Status::kCancelled, "cancelled");
  const size_t nv = pts.size(), nt = tris.size();
  std::vector<Vec3> vnormal(nv, Vec3::Zero()), fnormal(nt), centroid(nt);
  std::vector<double> farea(nt);
  double total_area = 0.0;
  for (size_t t = 0; t < nt; ++t) {
    const Vec3 n = (pts[tris[t][1]] - pts[tris[t][0]]).cross(pts[tris[t][2]] - pts[tris[t][0]]);
    for (uint32_t v : tris[t]) vnormal[v] += n;
    farea[t] = 0.5 * n.norm();
    total_area += farea[t];
    fnormal[t] = farea[t] > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    centroid[t] = (pts[tris[t][0]] + pts[tris[t][1]] + pts[tris[t][2]]) / 3.0;
  }
  std::vector<internal::DistPoint> dist(nv);
  for (size_t v = 0; v < nv; ++v) {
    const double len = vnormal[v].norm();
    dist[v] = {pts[v], len > 0 ? Vec3(vnormal[v] / len) : Vec3::Zero()};
  }
  std::vector<uint32_t> face_id(nt, UINT32_MAX), extra_id(nt, UINT32_MAX);
  if (params.add_face_points)
    for (size_t t = 0; t < nt; ++t)
      if (farea[t] > 0) {
        face_id[t] = static_cast<uint32_t>(dist.size());
        dist.push_back({centroid[t], fnormal[t]});
      }
  // Rays from each triangle's centre along its inverted normal: the first surface hit gives the
  // solid's depth behind the triangle (for the hulls) and, when that surface faces the same way,
  // the extra distance point.
  std::vector<double> depth(nt, 0.0);
  const internal::RayCaster caster(pts, tris);
  {
    std::vector<internal::DistPoint> extra(nt);
    std::vector<uint8_t> found(nt, 0);
    const double min_t = 1e-9 * diag;
    if (!internal::ParallelFor(&ctx, nt, [&](size_t t) {
          if (!(farea[t] > 0)) return;
          const Vec3 dir = -fnormal[t];
          uint32_t hit = 0;
          double d = 0;
          if (!caster.Cast(centroid[t], dir, min_t, static_cast<uint32_t>(t), &hit, &d)) return;
          depth[t] = d;
          if (!(fnormal[hit].dot(dir) > 0)) return;
          extra[t] = {centroid[t] + d * dir, fnormal[hit]};
          found[t] = 1;
        }))
      return Fail(Status::kCancelled, "cancelled");
    if (params.add_extra_dist_points)
      for (size_t t = 0; t < nt; ++t)
        if (found[t]) {
          extra_id[t] = static_cast<uint32_t>(dist.size());
          dist.push_back(extra[t]);
        }
  }

  internal::HacdCostParams cp;
  cp.scale = params.scale_factor;
  cp.flat_threshold = params.flat_region_threshold;
  cp.compacity_weight = params.compacity_weight;
  cp.volume_weight = params.volume_weight;
  cp.computation_weight = params.computation_weight;
  cp.total_dist_points = static_cast<double>(dist.size());
  cp.inside_margin = 1e-6 * diag;
  rep.parts_before_merge = static_cast<uint32_t>(nt);
  ctx.Log("dual graph: " + std::to_string(nt) + " nodes, " + std::to_string(dual.size()) +
          " edges");

  // Clusters and their hulls, for given limits (max_concavity may tighten them and run again).
  auto decompose = [&](const Clustering::Limits& lim, std::vector<internal::HullMesh>* hulls,
                       size_t* clusters_left) {
    Clustering clustering(params, cp, dist, total_area);
    auto& clusters = clustering.clusters();
    clusters.resize(nt);
    for (size_t t = 0; t < nt; ++t) {
      auto& c = clusters[t];
      c.dist.assign(tris[t].begin(), tris[t].end());
      if (face_id[t] != UINT32_MAX) c.dist.push_back(face_id[t]);
      if (extra_id[t] != UINT32_MAX) c.dist.push_back(extra_id[t]);
      std::sort(c.dist.begin(), c.dist.end());
      for (uint32_t v : tris[t]) c.hull_points.push_back(pts[v]);
      c.area = farea[t];
      c.triangles.assign(1, static_cast<uint32_t>(t));
      for (int k = 0; k < 3; ++k)
        c.perimeter += (pts[tris[t][k]] - pts[tris[t][(k + 1) % 3]]).norm();
    }
    auto& edges = clustering.edges();
    edges.reserve(dual.size());
    for (const auto& d : dual) {
      Clustering::Edge e;
      e.a = d.a;
      e.b = d.b;
      e.shared = d.shared_length;
      clusters[d.a].edges.push_back(static_cast<uint32_t>(edges.size()));
      clusters[d.b].edges.push_back(static_cast<uint32_t>(edges.size()));
      edges.push_back(e);
    }
    ctx.BeginStage("Clustering", 25, 85);
    if (!clustering.Run(&ctx, lim)) return false;
    rep.seconds_clip += clock.Lap();
    *clusters_left = clustering.alive_count();

    // One hull per cluster.
    ctx.BeginStage("Hull generation", 85, 90);
    std::vector<const Clustering::Cluster*> alive;
    for (const auto& c : clusters)
      if (c.alive) alive.push_back(&c);
    hulls->assign(alive.size(), internal::HullMesh());
    if (!internal::ParallelFor(&ctx, alive.size(), [&](size_t i) {
          internal::FillInput fi;
          for (uint32_t id : alive[i]->dist)
            if (id < nv) fi.surface.push_back(pts[id]);
          for (uint32_t t : alive[i]->triangles) {
            fi.behind.push_back(centroid[t]);
            fi.inward.push_back(-fnormal[t]);
            fi.depth.push_back(depth[t]);
          }
          fi.dist = &dist;
          fi.dist_ids = &alive[i]->dist;
          fi.area = alive[i]->area;
          fi.cost = &cp;
          fi.caster = &caster;
          fi.thickness = 1e-4 * diag;
          fi.tolerance = cp.inside_margin;
          fi.max_vertices = params.max_vertices_per_hull;
          (*hulls)[i] = internal::FilledClusterHull(fi);
        }))
      return false;
    hulls->erase(std::remove_if(hulls->begin(), hulls->end(),
                                [](const internal::HullMesh& h) { return h.empty(); }),
                 hulls->end());
    rep.seconds_hulls += clock.Lap();
    return true;
  };

  // Error report, measured like Decompose's on a voxel grid of the input (not the decimated mesh).
  std::unique_ptr<internal::VoxelGrid> grid;
  internal::GridMesh gmesh;
  internal::GridPlacement place;
  double volume0 = 0.0;
  auto measure = [&](const std::vector<internal::HullMesh>& hulls, Report* r) {
    ctx.BeginStage("Error report", 90, 100);
    if (!grid) {
      place = internal::ChooseGrid(qlo * to_norm, qhi * to_norm, 100000);
      gmesh.triangles = input.triangles;
      std::vector<Vec3> gpoints(pq.size());
      for (size_t i = 0; i < pq.size(); ++i) gpoints[i] = (pq[i] - place.origin) / place.h;
      internal::HullMesh whole;
      if (internal::ComputeConvexHull(gpoints, -1.0, &whole) == internal::HullStatus::kOk)
        volume0 = whole.Volume();
      gmesh.points = internal::GridPoints(gpoints);
      grid = std::make_unique<internal::VoxelGrid>();
      if (!internal::Voxelize(gmesh, place.dims, &ctx, grid.get())) return false;
    }
    std::vector<internal::HullMesh> ghulls = hulls;
    for (auto& h : ghulls)
      for (Vec3& p : h.vertices) p = (p - place.origin) / place.h;
    internal::MetricsInput mi;
    mi.mesh = &gmesh;
    mi.grid = grid.get();
    mi.hulls = &ghulls;
    mi.diagonal = diag / place.h;
    mi.volume0 = std::max(volume0, 1.0);
    mi.closed = input.closed;
    const bool ok = internal::ComputeErrorReport(mi, &ctx, r);
    r->seconds_report += clock.Lap();
    return ok;
  };

  // The limits: HACD's own (Concavity, NClusters), or a hull count, a budget or a target error.
  Clustering::Limits lim;
  lim.concavity = params.concavity;
  lim.min_clusters = params.min_clusters;
  lim.max_clusters = params.max_clusters;
  if (lim.max_clusters > 0) lim.min_clusters = std::min(lim.min_clusters, lim.max_clusters);
  const bool exact = params.hull_count > 0;
  const bool target = !exact && params.max_concavity > 0;
  if (exact) {
    lim.min_clusters = lim.max_clusters = params.hull_count;
    lim.floor_small = true;
  } else if (target) {
    lim.concavity = params.max_concavity * diag;
  }
  std::vector<internal::HullMesh> hulls;
  size_t left = 0;
  if (!target) {
    if (!decompose(lim, &hulls, &left)) return Fail(Status::kCancelled, "cancelled");
    if (hulls.empty()) return Fail(Status::kInternalError, "no cluster gave a hull");
    if (params.compute_report && !measure(hulls, &rep))
      return Fail(Status::kCancelled, "cancelled");
    rep.attempts = 1;
    if (exact && hulls.size() != params.hull_count) {
      rep.target_reached = false;
      rep.target_note =
          "the surface could be clustered into only " + std::to_string(hulls.size()) +
          (left > params.hull_count
               ? " clusters (pieces farther apart than connect_distance cannot merge)"
               : " clusters (it has " + std::to_string(nt) + " triangles after decimation)");
    }
  } else {
    // Each attempt clusters with a tighter ceiling until the measured concavity reaches the
    // target; the first that does is kept, else the closest.
    const double d = params.max_concavity;
    constexpr int kAttempts = 3;
    constexpr double kTighten = 0.6;
    Report best;
    bool have = false;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
      std::vector<internal::HullMesh> h;
      Report r = rep;
      if (!decompose(lim, &h, &left) || (!h.empty() && !measure(h, &r)))
        return Fail(Status::kCancelled, "cancelled");
      if (h.empty()) continue;
      ctx.Log("max_concavity attempt " + std::to_string(attempt + 1) + ": ceiling " +
              std::to_string(lim.concavity / diag) + " of the diagonal, " +
              std::to_string(h.size()) + " hulls, concavity " + std::to_string(r.concavity));
      r.attempts = static_cast<uint32_t>(attempt + 1);
      if (!have || r.concavity < best.concavity) {
        best = r;
        hulls = std::move(h);
        have = true;
      }
      if (r.concavity <= d) break;
      lim.concavity *= kTighten;
    }
    if (!have) return Fail(Status::kInternalError, "no cluster gave a hull");
    const Report stages = rep;
    rep = best;
    rep.seconds_simplify = stages.seconds_simplify;
    rep.seconds_clip = stages.seconds_clip;
    rep.seconds_hulls = stages.seconds_hulls;
    rep.target_reached = rep.concavity <= d;
    if (!rep.target_reached) {
      std::string over;
      size_t n_over = 0;
      for (size_t i = 0; i < rep.hulls.size(); ++i)
        if (rep.hulls[i].distance > d && n_over++ < 8)
          over += (over.empty() ? "" : ", ") + std::to_string(i);
      std::string cause;
      if (rep.hausdorff_mesh_to_hulls > d)
        cause = "parts of the surface lie outside every hull by " +
                std::to_string(rep.hausdorff_mesh_to_hulls) +
                " (detail lost to the decimation to target_triangles or to "
                "max_vertices_per_hull)";
      if (n_over > 0) {
        if (!cause.empty()) cause += "; ";
        cause += std::to_string(n_over) + " hull(s) farther than max_concavity from the surface (" +
                 over + (n_over > 8 ? ", ..." : "") + "): " +
                 (params.max_clusters > 0 && left >= params.max_clusters
                      ? "the max_clusters budget forced merges past it"
                      : "clusters forced to merge (small_cluster_threshold, min_clusters), or "
                        "concave parts the rays along the surface normals do not see");
      }
      rep.target_note = "max_concavity " + std::to_string(d) + " not reached (" +
                        std::to_string(rep.concavity) + "): " + cause;
    }
  }
  // The caller did not ask for the measures (a target may have needed them).
  if (!params.compute_report) internal::ClearMeasures(&rep);

  // Output in input coordinates.
  const double vol_scale = std::pow(extent / to_norm, 3);
  if (rep.hulls.size() != hulls.size()) rep.hulls.assign(hulls.size(), HullReport());
  for (size_t i = 0; i < hulls.size(); ++i) {
    ConvexHull out;
    if (!internal::ToOutputHull(hulls[i], to_world, vol_scale, &out))
      return Fail(Status::kInternalError, "a hull has a non-finite coordinate");
    rep.hulls[i].vertex_count = static_cast<uint32_t>(hulls[i].vertices.size());
    rep.hulls[i].volume = out.volume;
    result.hulls.push_back(std::move(out));
  }
  rep.seconds_total = total.Lap();
  ctx.Progress(100, "done");
  ctx.Log("done: " + std::to_string(result.hulls.size()) + " hulls from " + std::to_string(nt) +
          " triangles");
  return result;
}

}  // namespace

Result DecomposeHacd(const MeshView& mesh, const HacdParameters& params, Observer* observer) {
  try {
    return DecomposeHacdImpl(mesh, params, observer);
  } catch (const std::bad_alloc&) {
    return Fail(Status::kOutOfMemory, "out of memory");
  } catch (...) {
    return Fail(Status::kInternalError, "unexpected exception");
  }
}

}  // namespace vhacd
