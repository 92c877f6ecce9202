#include "simplify_qem.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "thread_pool.h"

namespace vhacd {
namespace internal {
namespace {

using Tri = std::array<uint32_t, 3>;

// Border and seam planes weigh this much more than the surface's own planes (per squared length).
constexpr double kBorderWeight = 8.0;
// A collapse may turn a triangle's normal by at most acos(kMinNormalCos).
constexpr double kMinNormalCos = 0.2;
// Phase one's slabs: one per this many triangles, at most kMaxBlocks (see Collapser::Run).
constexpr size_t kBlockTriangles = 16384;
constexpr size_t kMaxBlocks = 8;
constexpr uint32_t kAnyBlock = UINT32_MAX, kCut = UINT32_MAX - 1;

struct Candidate {
  double cost = 0.0;
  uint32_t from = 0, to = 0;  // `from` is removed, `to` moves to `pos`
  Vec3 pos = Vec3::Zero();
};

// A heap entry (small: the heap is the hot spot); the position is recomputed when it is popped.
struct Entry {
  double cost = 0.0;
  uint32_t from = 0, to = 0;
  uint32_t stamp_from = 0, stamp_to = 0;
  bool operator>(const Entry& o) const {
    return std::tie(cost, from, to) > std::tie(o.cost, o.from, o.to);
  }
};

class Collapser {
 public:
  // The set-up runs on ctx's threads; every sum keeps the order of a sequential pass (triangles in
  // index order), so the result does not depend on the thread count.
  Collapser(const QemMesh& in, const std::vector<uint64_t>& seams, const QemOptions& opt,
            Context* ctx)
      : opt_(opt), pos_(in.points), tris_(in.triangles), ctx_(ctx) {
    const size_t n = pos_.size(), nt = tris_.size();
    quadric_.assign(n, Eigen::Matrix4d::Zero());
    area_.assign(n, 0.0);
    vtris_.resize(n);
    stamp_.assign(n, 0);
    dead_.assign(n, 0);
    border_.assign(n, 0);
    locked_.assign(n, 0);
    seam_nbrs_.resize(n);
    tri_dead_.assign(nt, 0);
    mark_.assign(n, 0);
    orig_normal_.assign(nt, Vec3::Zero());
    std::vector<uint32_t> degree(n, 0);
    for (const Tri& tri : tris_)
      for (uint32_t v : tri) ++degree[v];
    for (size_t v = 0; v < n; ++v) vtris_[v].reserve(degree[v]);
    for (uint32_t t = 0; t < nt; ++t)
      for (uint32_t v : tris_[t]) vtris_[v].push_back(t);
    // Face planes: per triangle, then summed per vertex over its triangles in index order.
    std::vector<double> tri_area(nt, 0.0);
    Chunked(nt, [&](size_t t) {
      const Tri& tri = tris_[t];
      const Vec3 nrm = (pos_[tri[1]] - pos_[tri[0]]).cross(pos_[tri[2]] - pos_[tri[0]]);
      const double len = nrm.norm();
      if (!(len > 0)) return;
      orig_normal_[t] = nrm / len;
      tri_area[t] = 0.5 * len;
    });
    Chunked(n, [&](size_t v) {
      for (uint32_t t : vtris_[v]) {
        if (!(tri_area[t] > 0)) continue;
        AddPlane(static_cast<uint32_t>(v), orig_normal_[t], pos_[tris_[t][0]], tri_area[t]);
        area_[v] += tri_area[t];
      }
    });
    // Edges (a < b) with the triangles using them, in (a, b, triangle) order: bucketed by a, each
    // bucket sorted. Use counts: 1 = border, > 2 = non-manifold (locked).
    std::vector<uint32_t> first(n + 1, 0);
    for (const Tri& tri : tris_)
      for (int k = 0; k < 3; ++k) ++first[std::min(tri[k], tri[(k + 1) % 3]) + 1];
    for (size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    std::vector<std::pair<uint32_t, uint32_t>> uses(first[n]);  // (b, triangle)
    {
      std::vector<uint32_t> fill(first.begin(), first.end() - 1);
      for (uint32_t t = 0; t < nt; ++t)
        for (int k = 0; k < 3; ++k) {
          const uint32_t a = tris_[t][k], b = tris_[t][(k + 1) % 3];
          uses[fill[std::min(a, b)]++] = {std::max(a, b), t};
        }
    }
    Chunked(n, [&](size_t v) { std::sort(uses.begin() + first[v], uses.begin() + first[v + 1]); });
    std::vector<uint64_t> seam_keys(seams);
    std::sort(seam_keys.begin(), seam_keys.end());
    for (uint32_t a = 0; a < n; ++a) {
      for (size_t i = first[a]; i < first[a + 1];) {
        size_t j = i;
        while (j < first[a + 1] && uses[j].first == uses[i].first) ++j;
        const uint32_t b = uses[i].first;
        const uint64_t key = (uint64_t{a} << 32) | b;
        const bool seam = std::binary_search(seam_keys.begin(), seam_keys.end(), key);
        if (j - i > 2) {
          locked_[a] = locked_[b] = 1;
        } else if (j - i == 1 || seam) {
          border_[a] = border_[b] = 1;
          if (seam) {
            seam_nbrs_[a].push_back(b);
            seam_nbrs_[b].push_back(a);
          }
          for (size_t k = i; k < j; ++k) AddBorderPlane(a, b, uses[k].second);
        }
        unique_edges_.push_back(key);
        i = j;
      }
    }
    if (opt_.lock_boundary)
      for (size_t v = 0; v < n; ++v) locked_[v] |= border_[v];
  }

  bool Run(Context* ctx, QemMesh* out) {
    const size_t nt = tris_.size();
    // Phase one, on large meshes: the mesh cut into slabs, each decimated on its own (in
    // parallel) with the vertices of triangles crossing a cut kept in place, down to its share
    // of a count well above the target (only when that is at most half the mesh). The slabs are a
    // function of the mesh alone, and no two touch the same vertex or triangle, so the result does
    // not depend on the thread count.
    const size_t blocks = std::min<size_t>(kMaxBlocks, nt / kBlockTriangles);
    const size_t phase1 = std::max(2 * opt_.target_triangles, nt / 16);
    double done = 0.0;   // the share of the progress bar phase one takes
    uint64_t marks = 0;  // the largest link-condition mark phase one wrote
    if (blocks >= 2 && 2 * phase1 <= nt) {
      done = static_cast<double>(nt - phase1) /
             static_cast<double>(nt - std::min(nt, opt_.target_triangles));
      if (!DecimateSlabs(ctx, blocks, phase1, done, &marks)) return false;
    }
    // Phase two (the only one on smaller meshes): every edge, cheapest first, one at a time.
    Lane lane;
    lane.target = opt_.target_triangles;
    lane.mark_generation = marks;
    for (uint8_t dead : tri_dead_) lane.alive += dead ? 0 : 1;
    {
      std::vector<Entry> first;
      std::vector<uint8_t> ok;
      FirstCandidates(unique_edges_, &first, &ok);
      lane.heap.reserve(unique_edges_.size());
      for (size_t i = 0; i < first.size(); ++i)
        if (ok[i]) lane.heap.push_back(first[i]);
      std::make_heap(lane.heap.begin(), lane.heap.end(), std::greater<Entry>());
    }
    std::vector<uint64_t>().swap(unique_edges_);
    if (cancelled_) return false;
    if (!Loop(&lane, ctx, true, done, 1.0 - done)) return false;
    error_ = std::max(error_, lane.error);
    Output(out);
    return true;
  }

 private:
  // One collapse sequence: its heap, its scratch space and the slab it may touch (phase one),
  // or the whole mesh.
  struct Lane {
    uint32_t block = kAnyBlock;
    size_t alive = 0;   // its triangles still alive
    size_t target = 0;  // it stops at this many
    double error = 0.0;
    std::vector<Entry> heap;  // a binary min-heap (std::push_heap / pop_heap)
    std::vector<uint32_t> nv;
    uint64_t mark_generation = 0;
  };

  // Phase one: each of `blocks` slabs decimated on its own lane down to its share of `count`
  // triangles (`share` of the progress bar); the edges left go to unique_edges_ for phase two.
  // *marks receives the largest link-condition mark written. Returns false when cancelled.
  bool DecimateSlabs(Context* ctx, size_t blocks, size_t count, double share, uint64_t* marks) {
    const size_t nt = tris_.size();
    AssignBlocks(blocks);
    std::vector<Lane> lanes(blocks);
    for (size_t b = 0; b < blocks; ++b) lanes[b].block = static_cast<uint32_t>(b);
    for (const Tri& tri : tris_)
      if (block_[tri[0]] == block_[tri[1]] && block_[tri[1]] == block_[tri[2]] &&
          block_[tri[0]] < blocks)
        ++lanes[block_[tri[0]]].alive;
    // Lanes count the triangles whose corners are all in their slab (a triangle dies only by a
    // collapse of two of its free corners).
    for (Lane& lane : lanes) lane.target = lane.alive * count / nt;
    std::vector<uint64_t> keys;
    for (uint64_t key : unique_edges_)
      if (block_[key >> 32] < blocks && block_[key >> 32] == block_[uint32_t(key)])
        keys.push_back(key);
    std::vector<Entry> first;
    std::vector<uint8_t> ok;
    FirstCandidates(keys, &first, &ok);
    if (cancelled_) return false;
    for (size_t i = 0; i < keys.size(); ++i)
      if (ok[i]) lanes[block_[keys[i] >> 32]].heap.push_back(first[i]);
    std::vector<uint64_t>().swap(unique_edges_);
    std::vector<uint8_t> stopped(blocks, 0);  // per lane: cancelled
    if (!ParallelFor(ctx, blocks, [&](size_t b) {
          Lane& lane = lanes[b];
          std::make_heap(lane.heap.begin(), lane.heap.end(), std::greater<Entry>());
          if (!Loop(&lane, ctx, b == 0, 0.0, share)) stopped[b] = 1;
        }))
      return false;
    if (std::find(stopped.begin(), stopped.end(), 1) != stopped.end()) return false;
    for (const Lane& lane : lanes) {
      error_ = std::max(error_, lane.error);
      *marks = std::max(*marks, lane.mark_generation);
    }
    std::fill(block_.begin(), block_.end(), kAnyBlock);
    for (size_t t = 0; t < nt; ++t)
      if (!tri_dead_[t])
        for (int k = 0; k < 3; ++k) {
          const uint32_t a = tris_[t][k], b = tris_[t][(k + 1) % 3];
          unique_edges_.push_back((uint64_t{std::min(a, b)} << 32) | std::max(a, b));
        }
    std::sort(unique_edges_.begin(), unique_edges_.end());
    unique_edges_.erase(std::unique(unique_edges_.begin(), unique_edges_.end()),
                        unique_edges_.end());
    return true;
  }

  // The candidates of `keys` (a < b edges), computed on ctx's threads.
  void FirstCandidates(const std::vector<uint64_t>& keys, std::vector<Entry>* first,
                       std::vector<uint8_t>* ok) {
    first->assign(keys.size(), Entry());
    ok->assign(keys.size(), 0);
    Chunked(keys.size(), [&](size_t i) {
      Candidate c;
      if (!Best(static_cast<uint32_t>(keys[i] >> 32), uint32_t(keys[i]), &c)) return;
      (*first)[i] = {c.cost, c.from, c.to, stamp_[c.from], stamp_[c.to]};
      (*ok)[i] = 1;
    });
  }

  // block_[v]: the slab of v along the box's longest axis (equal vertex counts), or kCut when v
  // is a corner of a triangle with corners in two slabs.
  void AssignBlocks(size_t blocks) {
    const size_t n = pos_.size();
    Vec3 lo = Vec3::Constant(HUGE_VAL), hi = -lo;
    for (const Vec3& p : pos_) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    std::vector<std::pair<double, uint32_t>> order(n);
    for (uint32_t v = 0; v < n; ++v) order[v] = {pos_[v][axis], v};
    std::sort(order.begin(), order.end());
    block_.assign(n, kAnyBlock);
    for (size_t i = 0; i < n; ++i) block_[order[i].second] = static_cast<uint32_t>(i * blocks / n);
    std::vector<uint8_t> cut(n, 0);
    for (const Tri& tri : tris_)
      if (block_[tri[0]] != block_[tri[1]] || block_[tri[1]] != block_[tri[2]])
        for (uint32_t v : tri) cut[v] = 1;
    for (size_t v = 0; v < n; ++v)
      if (cut[v]) block_[v] = kCut;
  }

  // In phase one a lane collapses only edges whose ends are both free vertices of its slab.
  bool InLane(const Lane& lane, uint32_t a, uint32_t b) const {
    return lane.block == kAnyBlock || (block_[a] == lane.block && block_[b] == lane.block);
  }

  // Collapses the lane's cheapest valid edges until its target (or the error limit) is reached.
  // Returns false when cancelled. With `report`, its progress is shown as `base` + `span` * its
  // own fraction.
  bool Loop(Lane* lane, Context* ctx, bool report, double base, double share) {
    const size_t start = lane->alive;
    size_t pops = 0;
    while (!lane->heap.empty() && lane->alive > lane->target) {
      if ((++pops & 1023) == 0 && ctx != nullptr) {
        if (ctx->Cancelled()) return false;
        const double span = static_cast<double>(start - std::min(start, lane->target));
        if (report && span > 0)
          ctx->Progress(100.0 * (base + share * (start - lane->alive) / span), "collapsing edges");
      }
      std::pop_heap(lane->heap.begin(), lane->heap.end(), std::greater<Entry>());
      const Entry e = lane->heap.back();
      lane->heap.pop_back();
      if (dead_[e.from] || dead_[e.to] || stamp_[e.from] != e.stamp_from ||
          stamp_[e.to] != e.stamp_to)
        continue;
      Candidate c;
      if (!Best(e.from, e.to, &c)) continue;
      const double err = ErrorOf(c);
      if (opt_.max_error > 0 && err > opt_.max_error) break;
      if (!Valid(lane, c)) continue;
      Collapse(lane, c);
      lane->error = std::max(lane->error, err);
    }
    return true;
  }

  // fn(i) for i in [0, n) on ctx's threads, in blocks (the per-item work is small).
  // A cancelled loop leaves work undone: cancelled_ then makes Run fail.
  template <typename F>
  void Chunked(size_t n, const F& fn) {
    constexpr size_t kBlock = 2048;
    if (!ParallelFor(ctx_, (n + kBlock - 1) / kBlock, [&](size_t b) {
          for (size_t i = b * kBlock, end = std::min(n, i + kBlock); i < end; ++i) fn(i);
        }))
      cancelled_ = true;
  }

  void AddPlane(uint32_t v, const Vec3& n, const Vec3& p, double w) {
    const Eigen::Vector4d q(n[0], n[1], n[2], -n.dot(p));
    quadric_[v] += w * q * q.transpose();
  }

  void AddBorderPlane(uint32_t a, uint32_t b, uint32_t t) {
    const Tri& tri = tris_[t];
    const Vec3 fn = (pos_[tri[1]] - pos_[tri[0]]).cross(pos_[tri[2]] - pos_[tri[0]]);
    const Vec3 e = pos_[b] - pos_[a];
    Vec3 m = e.cross(fn);
    const double len = m.norm();
    if (!(len > 0)) return;
    m /= len;
    const double w = kBorderWeight * e.squaredNorm();
    AddPlane(a, m, pos_[a], w);
    AddPlane(b, m, pos_[a], w);
  }

  static double Eval(const Eigen::Matrix4d& q, const Vec3& p) {
    const Eigen::Vector4d h(p[0], p[1], p[2], 1.0);
    return std::max(0.0, h.dot(q * h));
  }

  double ErrorOf(const Candidate& c) const {
    const double w = area_[c.from] + area_[c.to];
    return w > 0 ? std::sqrt(c.cost / w) : 0.0;
  }

  bool IsSeamEdge(uint32_t a, uint32_t b) const {
    const auto& s = seam_nbrs_[a];
    return std::find(s.begin(), s.end(), b) != s.end();
  }

  // Triangles containing both a and b.
  int SharedTriangles(uint32_t a, uint32_t b) const {
    int n = 0;
    for (uint32_t t : vtris_[a])
      if (!tri_dead_[t] && Has(tris_[t], b)) ++n;
    return n;
  }
  static bool Has(const Tri& t, uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

  void Push(Lane* lane, uint32_t a, uint32_t b) {
    if (!InLane(*lane, a, b)) return;
    Candidate best;
    if (!Best(a, b, &best)) return;
    auto& heap = lane->heap;
    heap.push_back({best.cost, best.from, best.to, stamp_[best.from], stamp_[best.to]});
    std::push_heap(heap.begin(), heap.end(), std::greater<Entry>());
    // Superseded entries pile up (each collapse re-pushes the edges around the kept vertex); a
    // heap several times larger than the mesh's edge count is mostly cache misses, so drop them.
    if (heap.size() > 64 && heap.size() > 4 * lane->alive) {
      heap.erase(std::remove_if(heap.begin(), heap.end(),
                                [&](const Entry& x) {
                                  return dead_[x.from] || dead_[x.to] ||
                                         stamp_[x.from] != x.stamp_from ||
                                         stamp_[x.to] != x.stamp_to;
                                }),
                 heap.end());
      std::make_heap(heap.begin(), heap.end(), std::greater<Entry>());
    }
  }

  // The cheapest collapse of edge (a, b) allowed by the border, seam and lock rules.
  bool Best(uint32_t a, uint32_t b, Candidate* out) const {
    if (dead_[a] || dead_[b] || a == b) return false;
    if (locked_[a] && locked_[b]) return false;
    const Eigen::Matrix4d q = quadric_[a] + quadric_[b];
    Candidate best;
    best.cost = -1;
    auto consider = [&](uint32_t from, uint32_t to, const Vec3& p) {
      const double cost = Eval(q, p);
      if (best.cost < 0 || cost < best.cost) {
        best.cost = cost;
        best.from = from;
        best.to = to;
        best.pos = p;
      }
    };
    const bool ba = border_[a] || locked_[a], bb = border_[b] || locked_[b];
    if (locked_[a]) {
      consider(b, a, pos_[a]);
    } else if (locked_[b]) {
      consider(a, b, pos_[b]);
    } else if (ba && bb) {
      if (SharedTriangles(a, b) != 1 && !IsSeamEdge(a, b)) return false;
      consider(b, a, pos_[a]);
      consider(a, b, pos_[b]);
    } else if (ba) {
      consider(b, a, pos_[a]);
    } else if (bb) {
      consider(a, b, pos_[b]);
    } else {
      const Vec3 mid = 0.5 * (pos_[a] + pos_[b]);
      const Eigen::Matrix3d m = q.topLeftCorner<3, 3>();
      const Vec3 rhs = -q.topRightCorner<3, 1>();
      // Cramer's rule, refused when the matrix is near singular (a flat or straight region).
      const Vec3 c0 = m.col(1).cross(m.col(2)), c1 = m.col(2).cross(m.col(0)),
                 c2 = m.col(0).cross(m.col(1));
      const double det = m.col(0).dot(c0);
      if (std::fabs(det) > 1e-9 * m.squaredNorm() * std::sqrt(m.squaredNorm())) {
        const Vec3 x = Vec3(c0.dot(rhs), c1.dot(rhs), c2.dot(rhs)) / det;
        const double reach = 2.0 * (pos_[a] - pos_[b]).norm();
        if (x.allFinite() && (x - mid).norm() <= reach) consider(b, a, x);
      }
      consider(b, a, pos_[a]);
      consider(a, b, pos_[b]);
      consider(b, a, mid);
    }
    if (best.cost < 0) return false;
    *out = best;
    return true;
  }

  void Neighbours(uint32_t v, std::vector<uint32_t>* out) const {
    out->clear();
    for (uint32_t t : vtris_[v])
      if (!tri_dead_[t])
        for (uint32_t w : tris_[t])
          if (w != v) out->push_back(w);
    std::sort(out->begin(), out->end());
    out->erase(std::unique(out->begin(), out->end()), out->end());
  }

  bool Valid(Lane* lane, const Candidate& c) {
    const uint32_t u = c.from, v = c.to;
    // Link condition: the common neighbours are exactly the apexes of the edge's triangles.
    // Neighbours of u get mark `first`; those also around v are moved to `first + 1` and counted.
    // (Lanes mark only the vertices of their own slab; phase two starts above every lane's marks.
    // 64 bits: the marks never wrap.)
    const uint64_t first = lane->mark_generation += 2, common = first + 1;
    for (uint32_t t : vtris_[u])
      if (!tri_dead_[t])
        for (uint32_t w : tris_[t])
          if (w != u) mark_[w] = first;
    size_t common_count = 0;
    for (uint32_t t : vtris_[v])
      if (!tri_dead_[t])
        for (uint32_t w : tris_[t])
          if (w != v && mark_[w] == first) {
            mark_[w] = common;
            ++common_count;
          }
    size_t edge_tris = 0, other_tris = 0;
    for (uint32_t t : vtris_[u]) {
      if (tri_dead_[t]) continue;
      if (Has(tris_[t], v)) {
        ++edge_tris;
        uint32_t apex = 0;
        for (uint32_t w : tris_[t])
          if (w != u && w != v) apex = w;
        if (mark_[apex] != common) return false;
      } else {
        ++other_tris;
      }
    }
    if (edge_tris == 0 || common_count != edge_tris) return false;
    for (uint32_t t : vtris_[v])
      if (!tri_dead_[t] && !Has(tris_[t], u)) ++other_tris;
    if (other_tris == 0) return false;  // the collapse would delete a whole piece
    // No triangle may flip, fold or become degenerate.
    for (uint32_t w : {u, v})
      for (uint32_t t : vtris_[w]) {
        if (tri_dead_[t]) continue;
        const Tri& tri = tris_[t];
        if (Has(tri, u) && Has(tri, v)) continue;
        Vec3 p[3], q[3];
        for (int k = 0; k < 3; ++k) {
          p[k] = pos_[tri[k]];
          q[k] = (tri[k] == u || tri[k] == v) ? c.pos : p[k];
        }
        const Vec3 n0 = (p[1] - p[0]).cross(p[2] - p[0]);
        const Vec3 n1 = (q[1] - q[0]).cross(q[2] - q[0]);
        const double l0 = n0.norm(), l1 = n1.norm();
        if (!(l1 > 1e-12 * (q[1] - q[0]).squaredNorm()) || !(l1 > 0)) return false;
        if (l0 > 0 && n0.dot(n1) < kMinNormalCos * l0 * l1) return false;
        // Nor drift, collapse after collapse, away from the input triangle it comes from.
        if (n1.dot(orig_normal_[t]) < kMinNormalCos * l1) return false;
      }
    return true;
  }

  void Collapse(Lane* lane, const Candidate& c) {
    const uint32_t u = c.from, v = c.to;
    for (uint32_t t : vtris_[u]) {
      if (tri_dead_[t]) continue;
      Tri& tri = tris_[t];
      if (Has(tri, v)) {
        tri_dead_[t] = 1;
        --lane->alive;
        continue;
      }
      for (uint32_t& w : tri)
        if (w == u) w = v;
      vtris_[v].push_back(t);
    }
    std::vector<uint32_t>().swap(vtris_[u]);
    auto& vt = vtris_[v];
    vt.erase(std::remove_if(vt.begin(), vt.end(), [&](uint32_t t) { return tri_dead_[t] != 0; }),
             vt.end());
    // Seam links follow the surviving vertex.
    for (uint32_t w : seam_nbrs_[u]) {
      if (w == v) continue;
      auto& sw = seam_nbrs_[w];
      for (uint32_t& x : sw)
        if (x == u) x = v;
      if (!IsSeamEdge(v, w)) seam_nbrs_[v].push_back(w);
    }
    auto& sv = seam_nbrs_[v];
    sv.erase(std::remove(sv.begin(), sv.end(), u), sv.end());
    std::vector<uint32_t>().swap(seam_nbrs_[u]);

    quadric_[v] += quadric_[u];
    area_[v] += area_[u];
    border_[v] |= border_[u];
    locked_[v] |= locked_[u];
    pos_[v] = c.pos;
    dead_[u] = 1;
    ++stamp_[v];
    ++stamp_[u];
    Neighbours(v, &lane->nv);
    for (uint32_t w : lane->nv) Push(lane, v, w);
  }

  void Output(QemMesh* out) {
    std::vector<uint32_t> remap(pos_.size(), UINT32_MAX);
    out->points.clear();
    out->triangles.clear();
    out->source.clear();
    out->triangle_source.clear();
    for (size_t t = 0; t < tris_.size(); ++t) {
      if (tri_dead_[t]) continue;
      out->triangle_source.push_back(static_cast<uint32_t>(t));
      Tri tri = tris_[t];
      for (uint32_t& w : tri) {
        if (remap[w] == UINT32_MAX) {
          remap[w] = static_cast<uint32_t>(out->points.size());
          out->points.push_back(pos_[w]);
          out->source.push_back(w);
        }
        w = remap[w];
      }
      out->triangles.push_back(tri);
    }
    out->error = error_;
  }

  QemOptions opt_;
  std::vector<Vec3> pos_;
  std::vector<Tri> tris_;
  Context* ctx_ = nullptr;
  bool cancelled_ = false;
  std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>> quadric_;
  std::vector<double> area_;
  std::vector<std::vector<uint32_t>> vtris_, seam_nbrs_;
  std::vector<uint32_t> stamp_;
  std::vector<uint8_t> dead_, border_, locked_, tri_dead_;
  std::vector<uint64_t> unique_edges_;
  std::vector<Vec3> orig_normal_;
  double error_ = 0.0;
  std::vector<uint64_t> mark_;   // link-condition marks, see Valid()
  std::vector<uint32_t> block_;  // phase one's slabs, see AssignBlocks()
};

}  // namespace

bool SimplifyQem(const QemMesh& in, const std::vector<uint64_t>& seam_edges,
                 const QemOptions& options, Context* ctx, QemMesh* out) {
  if (in.points.empty() || in.triangles.empty()) {
    *out = in;
    out->source.resize(in.points.size());
    for (size_t i = 0; i < in.points.size(); ++i) out->source[i] = static_cast<uint32_t>(i);
    return true;
  }
  // Work on a translated, unit-diagonal copy: thresholds are then scale-free.
  Vec3 lo = in.points[0], hi = in.points[0];
  for (const Vec3& p : in.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec3 center = 0.5 * (lo + hi);
  double diag = (hi - lo).norm();
  if (!(diag > 0) || !std::isfinite(diag)) diag = 1.0;
  QemMesh local;
  local.points.reserve(in.points.size());
  for (const Vec3& p : in.points) local.points.push_back((p - center) / diag);
  local.triangles = in.triangles;
  QemOptions opt = options;
  opt.max_error = options.max_error / diag;
  Collapser collapser(local, seam_edges, opt, ctx);
  if (!collapser.Run(ctx, out)) return false;
  for (Vec3& p : out->points) p = center + p * diag;
  out->error *= diag;
  return true;
}

}  // namespace internal
}  // namespace vhacd
