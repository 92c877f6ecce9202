#include "hull_metrics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <thread>
#include <utility>

namespace hullpack {
namespace bench {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

// splitmix64: a fixed generator, so samples are the same on every platform.
struct Rng {
  uint64_t state;
  uint64_t Next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double Uniform() { return static_cast<double>(Next() >> 11) * (1.0 / 9007199254740992.0); }
};

// Calls fn(i) for i in [0, n) on `threads` threads (dynamic chunks).
template <typename Fn>
void ParallelFor(size_t n, int threads, Fn fn) {
  if (threads <= 0) threads = std::max(1u, std::thread::hardware_concurrency());
  const size_t chunk = std::max<size_t>(1, n / (static_cast<size_t>(threads) * 16));
  std::atomic<size_t> next{0};
  auto work = [&]() {
    for (;;) {
      const size_t b = next.fetch_add(chunk);
      if (b >= n) return;
      for (size_t i = b; i < std::min(n, b + chunk); ++i) fn(i);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

// Largest fn(i) over i in [0, n), in parallel; *arg (when non-null) receives the smallest i
// reaching it.
template <typename Fn>
double ParallelMax(size_t n, int threads, Fn fn, size_t* arg = nullptr) {
  const size_t blocks = std::min<size_t>(n, 1024);
  std::vector<double> best(blocks, 0.0);
  std::vector<size_t> where(blocks, 0);
  ParallelFor(blocks, threads, [&](size_t b) {
    double m = 0.0;
    size_t w = b * n / blocks;
    for (size_t i = b * n / blocks; i < (b + 1) * n / blocks; ++i) {
      const double v = fn(i);
      if (v > m) {
        m = v;
        w = i;
      }
    }
    best[b] = m;
    where[b] = w;
  });
  double m = 0.0;
  if (arg != nullptr) *arg = 0;
  for (size_t b = 0; b < blocks; ++b)
    if (best[b] > m) {
      m = best[b];
      if (arg != nullptr) *arg = where[b];
    }
  return m;
}

double SegmentDistance(const V3& p, const V3& a, const V3& b) {
  const V3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

double BoxDistance2(const V3& p, const V3& lo, const V3& hi) {
  return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).squaredNorm();
}

double TriangleSolidAngle(const V3& q, const V3& A, const V3& B, const V3& C) {
  const V3 a = A - q, b = B - q, c = C - q;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double num = a.dot(b.cross(c));
  const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(num, den);
}

// A hull as half-spaces n.x <= d (unit normals, faces of non-zero area) plus its bounds.
struct HullShape {
  const Soup* soup = nullptr;
  std::vector<V3> normals;
  std::vector<double> offsets;
  V3 lo = V3::Zero(), hi = V3::Zero();

  explicit HullShape(const Soup& s) : soup(&s) {
    if (!s.points.empty()) lo = hi = s.points[0];
    for (const V3& p : s.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    for (const auto& t : s.triangles) {
      const V3 n = (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]);
      const double len = n.norm();
      if (!(len > 0) || !std::isfinite(len)) continue;
      normals.push_back(n / len);
      offsets.push_back(normals.back().dot(s.points[t[0]]));
    }
  }
  // Max over faces of n.p - d: <= 0 inside, otherwise a lower bound of the distance. A hull
  // without a proper face has no inside (+inf).
  double Signed(const V3& p) const {
    if (normals.empty()) return kInf;
    double s = -kInf;
    for (size_t f = 0; f < normals.size(); ++f) s = std::max(s, normals[f].dot(p) - offsets[f]);
    return s;
  }
  double SurfaceDistance(const V3& p) const {
    double best = kInf;
    for (const auto& t : soup->triangles)
      best = std::min(best, PointTriangleDistance(p, soup->points[t[0]], soup->points[t[1]],
                                                  soup->points[t[2]]));
    return best;
  }
};

// Distance from p to the union of the hulls; 0 when p is inside one (within `inside_tol`).
double DistanceToHulls(const V3& p, const std::vector<HullShape>& hulls, double inside_tol) {
  double best = kInf;
  for (const HullShape& h : hulls) {
    if (BoxDistance2(p, h.lo, h.hi) >= best * best) continue;
    const double s = h.Signed(p);
    if (s <= inside_tol) return 0.0;
    if (s >= best) continue;
    best = std::min(best, h.SurfaceDistance(p));
  }
  return best;
}

double Area2(const Soup& s, const std::array<uint32_t, 3>& t) {
  return (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).norm();
}

V3 RandomPointOn(const Soup& s, const std::array<uint32_t, 3>& t, Rng* rng) {
  const double r1 = std::sqrt(rng->Uniform()), r2 = rng->Uniform();
  return (1 - r1) * s.points[t[0]] + r1 * (1 - r2) * s.points[t[1]] + r1 * r2 * s.points[t[2]];
}

}  // namespace

double PointTriangleDistance(const V3& p, const V3& a, const V3& b, const V3& c) {
  // Closest point by Voronoi regions of the triangle (vertices, edges, face).
  const V3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const V3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return SegmentDistance(p, a, b);
  const V3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return SegmentDistance(p, a, c);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return SegmentDistance(p, b, c);
  const double sum = va + vb + vc;
  if (!(sum > 0))  // degenerate triangle: its edges
    return std::min({SegmentDistance(p, a, b), SegmentDistance(p, b, c), SegmentDistance(p, a, c)});
  return (p - (a + ab * (vb / sum) + ac * (vc / sum))).norm();
}

double WindingNumberExact(const Soup& soup, const V3& p) {
  double w = 0.0;
  for (const auto& t : soup.triangles)
    w += TriangleSolidAngle(p, soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
  return w / (4 * kPi);
}

double SignedVolume(const Soup& soup) {
  double v = 0.0;
  for (const auto& t : soup.triangles)
    v += soup.points[t[0]].dot(soup.points[t[1]].cross(soup.points[t[2]]));
  return v / 6.0;
}

std::string CheckHull(const Soup& hull, double tol) {
  const size_t nv = hull.points.size();
  if (nv < 4 || hull.triangles.size() < 4) return "fewer than 4 vertices or triangles";
  for (const V3& p : hull.points)
    if (!p.allFinite()) return "non-finite coordinate";
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (const auto& t : hull.triangles)
    for (int k = 0; k < 3; ++k) {
      if (t[k] >= nv) return "index out of range";
      ++edges[{t[k], t[(k + 1) % 3]}];
    }
  for (const auto& e : edges) {
    auto r = edges.find({e.first.second, e.first.first});
    if (e.second != 1 || r == edges.end() || r->second != 1) return "not closed";
  }
  if (!(SignedVolume(hull) > 0)) return "not outward-facing (volume <= 0)";
  double worst = 0.0;
  for (const auto& t : hull.triangles) {
    const V3 n =
        (hull.points[t[1]] - hull.points[t[0]]).cross(hull.points[t[2]] - hull.points[t[0]]);
    const double len = n.norm();
    if (!(len > 0)) continue;
    for (const V3& q : hull.points) worst = std::max(worst, n.dot(q - hull.points[t[0]]) / len);
  }
  if (worst > tol) return "not convex (a vertex " + std::to_string(worst) + " above a face)";
  return "";
}

// ---------------------------------------------------------------------------------------------
// TriangleBvh

TriangleBvh::TriangleBvh(const Soup& soup) : soup_(soup) {
  const size_t n = soup.triangles.size();
  order_.resize(n);
  std::vector<V3> centroids(n);
  for (size_t t = 0; t < n; ++t) {
    order_[t] = static_cast<uint32_t>(t);
    const auto& tr = soup.triangles[t];
    centroids[t] = (soup.points[tr[0]] + soup.points[tr[1]] + soup.points[tr[2]]) / 3.0;
  }
  nodes_.reserve(2 * n / 3 + 2);
  if (n > 0) Build(0, static_cast<uint32_t>(n), &centroids);
}

uint32_t TriangleBvh::Build(uint32_t first, uint32_t count, std::vector<V3>* centroids) {
  const uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.lo = V3::Constant(kInf);
  node.hi = V3::Constant(-kInf);
  V3 clo = node.lo, chi = node.hi;
  double area = 0.0;
  V3 weighted = V3::Zero();
  node.area_vector = V3::Zero();
  for (uint32_t k = first; k < first + count; ++k) {
    const auto& t = soup_.triangles[order_[k]];
    const V3 cr =
        (soup_.points[t[1]] - soup_.points[t[0]]).cross(soup_.points[t[2]] - soup_.points[t[0]]);
    const double a = 0.5 * cr.norm();
    node.area_vector += 0.5 * cr;
    area += a;
    weighted += a * (*centroids)[order_[k]];
    for (uint32_t v : t) {
      node.lo = node.lo.cwiseMin(soup_.points[v]);
      node.hi = node.hi.cwiseMax(soup_.points[v]);
    }
    clo = clo.cwiseMin((*centroids)[order_[k]]);
    chi = chi.cwiseMax((*centroids)[order_[k]]);
  }
  node.center = area > 0 ? V3(weighted / area) : V3(0.5 * (node.lo + node.hi));
  for (uint32_t k = first; k < first + count; ++k)
    for (uint32_t v : soup_.triangles[order_[k]])
      node.radius = std::max(node.radius, (soup_.points[v] - node.center).norm());
  if (count <= 4) {
    node.first = first;
    node.count = count;
    nodes_[index] = node;
    return index;
  }
  int axis = 0;
  const V3 ext = chi - clo;
  if (ext[1] > ext[axis]) axis = 1;
  if (ext[2] > ext[axis]) axis = 2;
  const uint32_t half = count / 2;
  std::nth_element(
      order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
      [&](uint32_t a, uint32_t b) { return (*centroids)[a][axis] < (*centroids)[b][axis]; });
  node.left = Build(first, half, centroids);
  node.right = Build(first + half, count - half, centroids);
  nodes_[index] = node;
  return index;
}

double TriangleBvh::Distance(const V3& p) const {
  if (nodes_.empty()) return kInf;
  double best2 = kInf;
  uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (BoxDistance2(p, n.lo, n.hi) >= best2) continue;
    if (n.count > 0) {
      for (uint32_t k = n.first; k < n.first + n.count; ++k) {
        const auto& t = soup_.triangles[order_[k]];
        const double d =
            PointTriangleDistance(p, soup_.points[t[0]], soup_.points[t[1]], soup_.points[t[2]]);
        best2 = std::min(best2, d * d);
      }
      continue;
    }
    // Nearer child last, so it is visited first.
    const double dl = BoxDistance2(p, nodes_[n.left].lo, nodes_[n.left].hi);
    const double dr = BoxDistance2(p, nodes_[n.right].lo, nodes_[n.right].hi);
    if (top + 2 > 128) continue;  // unreachable for a median-split tree of < 2^60 triangles
    if (dl < dr) {
      stack[top++] = n.right;
      stack[top++] = n.left;
    } else {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
  return std::sqrt(best2);
}

double TriangleBvh::Winding(const V3& p) const {
  if (nodes_.empty()) return 0.0;
  constexpr double kBeta = 2.0;  // a cluster counts as far beyond kBeta times its radius
  double omega = 0.0;
  uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    const V3 d = n.center - p;
    const double dist = d.norm();
    if (dist > kBeta * n.radius) {
      omega += n.area_vector.dot(d) / (dist * dist * dist);
      continue;
    }
    if (n.count > 0) {
      for (uint32_t k = n.first; k < n.first + n.count; ++k) {
        const auto& t = soup_.triangles[order_[k]];
        omega += TriangleSolidAngle(p, soup_.points[t[0]], soup_.points[t[1]], soup_.points[t[2]]);
      }
      continue;
    }
    if (top + 2 > 128) continue;
    stack[top++] = n.left;
    stack[top++] = n.right;
  }
  return omega / (4 * kPi);
}

// ---------------------------------------------------------------------------------------------
// MeshMeasure

MeshMeasure::MeshMeasure(Soup mesh, const MetricsOptions& options)
    : mesh_(std::move(mesh)), options_(options) {
  // Bounds and diagonal of the referenced points; drop triangles with repeated indices.
  std::vector<char> used(mesh_.points.size(), 0);
  std::vector<std::array<uint32_t, 3>> tris;
  for (const auto& t : mesh_.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    tris.push_back(t);
    for (uint32_t v : t) used[v] = 1;
  }
  mesh_.triangles.swap(tris);
  lo_ = V3::Constant(kInf);
  hi_ = V3::Constant(-kInf);
  for (size_t i = 0; i < mesh_.points.size(); ++i)
    if (used[i]) {
      lo_ = lo_.cwiseMin(mesh_.points[i]);
      hi_ = hi_.cwiseMax(mesh_.points[i]);
    }
  if (mesh_.triangles.empty()) lo_ = hi_ = V3::Zero();
  diagonal_ = (hi_ - lo_).norm();

  // Closed: weld identical positions, then every undirected edge used exactly twice.
  {
    std::vector<uint32_t> idx(mesh_.points.size());
    for (size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<uint32_t>(i);
    auto less = [&](uint32_t a, uint32_t b) {
      const V3 &p = mesh_.points[a], &q = mesh_.points[b];
      if (p[0] != q[0]) return p[0] < q[0];
      if (p[1] != q[1]) return p[1] < q[1];
      return p[2] < q[2];
    };
    std::sort(idx.begin(), idx.end(), less);
    std::vector<uint32_t> weld(mesh_.points.size());
    for (size_t k = 0; k < idx.size(); ++k)
      weld[idx[k]] =
          (k > 0 && mesh_.points[idx[k]] == mesh_.points[idx[k - 1]]) ? weld[idx[k - 1]] : idx[k];
    std::vector<uint64_t> edges;
    for (const auto& t : mesh_.triangles) {
      const uint32_t w[3] = {weld[t[0]], weld[t[1]], weld[t[2]]};
      if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;
      for (int k = 0; k < 3; ++k) {
        const uint64_t a = std::min(w[k], w[(k + 1) % 3]), b = std::max(w[k], w[(k + 1) % 3]);
        edges.push_back(a << 32 | b);
      }
    }
    std::sort(edges.begin(), edges.end());
    closed_ = !edges.empty();
    for (size_t i = 0; i < edges.size();) {
      size_t j = i;
      while (j < edges.size() && edges[j] == edges[i]) ++j;
      if (j - i != 2) closed_ = false;
      i = j;
    }
  }

  bvh_ = std::make_unique<TriangleBvh>(mesh_);

  // Surface samples: the vertices, then area-weighted random points.
  for (size_t i = 0; i < mesh_.points.size(); ++i)
    if (used[i]) samples_.push_back(mesh_.points[i]);
  std::vector<double> cdf(mesh_.triangles.size());
  double total = 0.0;
  for (size_t t = 0; t < mesh_.triangles.size(); ++t)
    cdf[t] = total += Area2(mesh_, mesh_.triangles[t]);
  Rng rng{options_.seed};
  if (total > 0)
    for (size_t s = 0; s < options_.mesh_samples; ++s) {
      const size_t t = std::min<size_t>(
          std::upper_bound(cdf.begin(), cdf.end(), rng.Uniform() * total) - cdf.begin(),
          cdf.size() - 1);
      samples_.push_back(RandomPointOn(mesh_, mesh_.triangles[t], &rng));
    }

  // Inside lattice (flat boxes get a minimum thickness so the lattice stays finite).
  V3 ext = (hi_ - lo_).cwiseMax(std::max(diagonal_, 1e-300) * 1e-3);
  // Cells tile the box exactly (a lattice point per cell centre), so counts are volumes.
  const double cube = std::cbrt(ext[0] * ext[1] * ext[2] /
                                static_cast<double>(std::max<size_t>(1, options_.solid_points)));
  for (int a = 0; a < 3; ++a) {
    dims_[a] = std::max(1, static_cast<int>(std::lround(ext[a] / cube)));
    step_[a] = ext[a] / dims_[a];
  }
  origin_ = 0.5 * (lo_ + hi_) - 0.5 * step_.cwiseProduct(V3(dims_[0], dims_[1], dims_[2]));
  const size_t nl = static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2];
  solid_.assign(nl, 0);
  ParallelFor(static_cast<size_t>(dims_[2]) * dims_[1], options_.threads, [&](size_t row) {
    const int k = static_cast<int>(row / dims_[1]), j = static_cast<int>(row % dims_[1]);
    for (int i = 0; i < dims_[0]; ++i) {
      const V3 p = CellPoint(i, j, k);
      solid_[row * dims_[0] + i] = std::fabs(bvh_->Winding(p)) >= 0.5;
    }
  });
  for (uint8_t s : solid_) solid_count_ += s;
}

MeshMeasure::~MeshMeasure() = default;

V3 MeshMeasure::CellPoint(int i, int j, int k) const {
  // A random point of the cell, the same for every query (the hash of the cell and the seed): an
  // unbiased volume estimate whatever the shapes' alignment with the lattice.
  Rng rng{options_.seed ^
          (static_cast<uint64_t>(static_cast<uint32_t>(i)) * 0x9e3779b97f4a7c15ull) ^
          (static_cast<uint64_t>(static_cast<uint32_t>(j)) * 0xc2b2ae3d27d4eb4full) ^
          (static_cast<uint64_t>(static_cast<uint32_t>(k)) * 0x165667b19e3779f9ull)};
  const double u = rng.Uniform(), v = rng.Uniform(), w = rng.Uniform();
  return origin_ + step_.cwiseProduct(V3(i + u, j + v, k + w));
}

HullMetrics MeshMeasure::Measure(const std::vector<Soup>& hulls) const {
  HullMetrics m;
  m.hulls = hulls.size();
  const double diag = diagonal_ > 0 ? diagonal_ : 1.0;
  std::vector<HullShape> shapes;
  shapes.reserve(hulls.size());
  for (const Soup& h : hulls) {
    m.max_hull_vertices = std::max(m.max_hull_vertices, h.points.size());
    const std::string problem = CheckHull(h, options_.convexity_tol * diag);
    if (!problem.empty()) {
      if (m.invalid_hulls == 0)
        m.first_problem = "hull " + std::to_string(&h - hulls.data()) + ": " + problem;
      ++m.invalid_hulls;
    }
    shapes.emplace_back(h);
  }
  if (hulls.empty()) return m;

  // mesh -> hulls.
  const double inside_tol = 1e-9 * diag;
  size_t arg = 0;
  const double d_mh = ParallelMax(
      samples_.size(), options_.threads,
      [&](size_t i) { return DistanceToHulls(samples_[i], shapes, inside_tol); }, &arg);
  if (!samples_.empty()) m.worst_mesh_point = samples_[arg];

  // hulls -> mesh, on the exposed part of the hulls' surfaces.
  struct HullSample {
    uint32_t hull;
    V3 p, n;
  };
  std::vector<HullSample> hs;
  double total = 0.0;
  std::vector<double> cdf;
  std::vector<std::pair<uint32_t, uint32_t>> faces;  // (hull, triangle)
  for (uint32_t h = 0; h < hulls.size(); ++h) {
    const Soup& s = hulls[h];
    std::vector<V3> vn(s.points.size(), V3::Zero());
    for (uint32_t t = 0; t < s.triangles.size(); ++t) {
      const auto& tr = s.triangles[t];
      const V3 cr = (s.points[tr[1]] - s.points[tr[0]]).cross(s.points[tr[2]] - s.points[tr[0]]);
      const double len = cr.norm();
      if (!(len > 0) || !std::isfinite(len)) continue;
      for (uint32_t v : tr) vn[v] += cr / len;
      faces.emplace_back(h, t);
      cdf.push_back(total += len);
    }
    for (size_t v = 0; v < s.points.size(); ++v)
      if (vn[v].norm() > 0) hs.push_back({h, s.points[v], vn[v].normalized()});
  }
  Rng rng{options_.seed ^ 0x5bd1e995ull};
  if (total > 0)
    for (size_t k = 0; k < options_.hull_samples; ++k) {
      const size_t f = std::min<size_t>(
          std::upper_bound(cdf.begin(), cdf.end(), rng.Uniform() * total) - cdf.begin(),
          cdf.size() - 1);
      const Soup& s = hulls[faces[f].first];
      const auto& tr = s.triangles[faces[f].second];
      const V3 n =
          (s.points[tr[1]] - s.points[tr[0]]).cross(s.points[tr[2]] - s.points[tr[0]]).normalized();
      hs.push_back({faces[f].first, RandomPointOn(s, tr, &rng), n});
    }
  const double gap = options_.gap * diag;
  const double d_hm = ParallelMax(
      hs.size(), options_.threads,
      [&](size_t k) {
        const V3& p = hs[k].p;
        for (uint32_t h = 0; h < shapes.size(); ++h) {
          if (h == hs[k].hull || BoxDistance2(p, shapes[h].lo, shapes[h].hi) >= gap * gap) continue;
          const double s = shapes[h].Signed(p);
          if (s <= 0) return 0.0;  // inside a neighbour: not on the union's boundary
          if (s < gap && shapes[h].SurfaceDistance(p) < gap)
            return 0.0;  // across a gap narrower than `gap`
        }
        return bvh_->Distance(p);
      },
      &arg);
  if (!hs.empty()) {
    m.worst_hull_point = hs[arg].p;
    m.worst_hull = hs[arg].hull;
    m.worst_hull_point_in_solid = std::fabs(bvh_->Winding(hs[arg].p)) >= 0.5;
    std::vector<HullShape> others;
    for (size_t h = 0; h < shapes.size(); ++h)
      if (h != hs[arg].hull) others.push_back(shapes[h]);
    m.worst_hull_point_gap =
        others.empty() ? -1.0 : DistanceToHulls(hs[arg].p, others, inside_tol) / diag;
  }
  m.mesh_to_hulls = d_mh / diag;
  m.hulls_to_mesh = d_hm / diag;
  m.concavity = std::max(m.mesh_to_hulls, m.hulls_to_mesh);

  // Volumes on the lattice, extended to the hulls' bounds (at most one lattice size beyond each
  // side).
  int elo[3], ehi[3];
  for (int a = 0; a < 3; ++a) {
    elo[a] = 0;
    ehi[a] = dims_[a] - 1;
  }
  std::vector<std::array<int, 6>> range(shapes.size());
  for (size_t h = 0; h < shapes.size(); ++h)
    for (int a = 0; a < 3; ++a) {
      const double l = std::floor((shapes[h].lo[a] - origin_[a]) / step_[a]);
      const double u = std::floor((shapes[h].hi[a] - origin_[a]) / step_[a]);
      range[h][a] = static_cast<int>(std::clamp(l, -1.0 * dims_[a], 2.0 * dims_[a] - 1));
      range[h][a + 3] = static_cast<int>(std::clamp(u, -1.0 * dims_[a] - 1, 2.0 * dims_[a] - 1));
      elo[a] = std::min(elo[a], range[h][a]);
      ehi[a] = std::max(ehi[a], range[h][a + 3]);
    }
  const int ed[3] = {ehi[0] - elo[0] + 1, ehi[1] - elo[1] + 1, ehi[2] - elo[2] + 1};
  std::vector<uint64_t> slice_hull(ed[2], 0), slice_inter(ed[2], 0);
  ParallelFor(static_cast<size_t>(ed[2]), options_.threads, [&](size_t kk) {
    const int k = static_cast<int>(kk) + elo[2];
    std::vector<uint8_t> mark(static_cast<size_t>(ed[0]) * ed[1], 0);
    for (size_t h = 0; h < shapes.size(); ++h) {
      if (k < range[h][2] || k > range[h][5]) continue;
      for (int j = range[h][1]; j <= range[h][4]; ++j)
        for (int i = range[h][0]; i <= range[h][3]; ++i) {
          uint8_t& mk = mark[static_cast<size_t>(j - elo[1]) * ed[0] + (i - elo[0])];
          if (!mk && shapes[h].Signed(CellPoint(i, j, k)) <= 0) mk = 1;
        }
    }
    uint64_t nh = 0, ni = 0;
    for (int j = elo[1]; j <= ehi[1]; ++j)
      for (int i = elo[0]; i <= ehi[0]; ++i) {
        if (!mark[static_cast<size_t>(j - elo[1]) * ed[0] + (i - elo[0])]) continue;
        ++nh;
        if (i >= 0 && j >= 0 && k >= 0 && i < dims_[0] && j < dims_[1] && k < dims_[2] &&
            solid_[(static_cast<size_t>(k) * dims_[1] + j) * dims_[0] + i])
          ++ni;
      }
    slice_hull[kk] = nh;
    slice_inter[kk] = ni;
  });
  uint64_t nh = 0, ni = 0;
  for (int k = 0; k < ed[2]; ++k) {
    nh += slice_hull[k];
    ni += slice_inter[k];
  }
  const uint64_t uni = solid_count_ + nh - ni;
  m.coverage = solid_count_ > 0 ? static_cast<double>(ni) / solid_count_ : -1.0;
  m.solid_iou = uni > 0 ? static_cast<double>(ni) / uni : 1.0;
  if (closed_) m.iou = m.solid_iou;
  return m;
}

}  // namespace bench
}  // namespace hullpack
