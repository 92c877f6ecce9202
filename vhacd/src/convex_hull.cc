#include "convex_hull.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "grid_points.h"

namespace vhacd {
namespace internal {

namespace {

constexpr uint32_t kNone = UINT32_MAX;

struct Face {
  uint32_t v[3];  // points
  uint32_t s[3];  // the same vertices as slots (QuickHull::slot_point_)
  int32_t nb[3];  // nb[i]: face across edge v[i] -> v[(i+1)%3]
  Vec3 n;         // unnormalized outward normal
  Vec3 base;      // the point v[0] (read once: the points may be mapped on every read)
  double nlen;
  // The points outside this face, in the order they were assigned: a list through
  // QuickHull::next_, so that every list together takes one index per point.
  uint32_t first = kNone, last = kNone;
  bool alive = true;
  uint32_t visible_stamp = 0;
  uint32_t hidden_stamp = 0;
};

enum class Attempt { kOk, kRetry };

// The input points, in order.
class PointArray {
 public:
  explicit PointArray(const std::vector<Vec3>& points) : points_(points) {}
  size_t size() const { return points_.size(); }
  const Vec3& operator[](size_t i) const { return points_[i]; }

 private:
  const std::vector<Vec3>& points_;
};

// Points from head or base, by ref (see ComputeConvexHull).
class ReferencedPoints {
 public:
  ReferencedPoints(const std::vector<Vec3>& head, const GridPoints& base,
                   const std::vector<uint32_t>& refs)
      : head_(head), base_(base), refs_(refs) {}
  size_t size() const { return refs_.size(); }
  Vec3 operator[](size_t i) const {
    const uint32_t r = refs_[i];
    return r >= kHeadRef ? head_[r - kHeadRef] : base_[r];
  }

 private:
  const std::vector<Vec3>& head_;
  const GridPoints& base_;
  const std::vector<uint32_t>& refs_;
};

template <typename Points>
class QuickHull {
 public:
  QuickHull(const Points& pts, double eps) : p_(pts), eps_(eps) {}

  // Returns kRetry on a topological inconsistency (tolerant mode only).
  Attempt Run(const uint32_t init[4], HullMesh* out) {
    faces_.clear();
    faces_.reserve(64);
    dead_ = 0;
    slot_point_.clear();
    start_at_.clear();
    stamp_at_.clear();
    next_.assign(p_.size(), kNone);
    const uint32_t a = init[0], b = init[1], c = init[2], d = init[3];
    const uint32_t sa = AddSlot(a), sb = AddSlot(b), sc = AddSlot(c), sd = AddSlot(d);
    AddFace(sa, sb, sc);
    AddFace(sa, sd, sb);
    AddFace(sb, sd, sc);
    AddFace(sc, sd, sa);
    LinkInitial();
    // Assign every other point to the face it is farthest above.
    for (uint32_t i = 0; i < p_.size(); ++i) {
      if (i == a || i == b || i == c || i == d) continue;
      Assign(i, 0, 4);
    }
    std::vector<int32_t> visible;
    std::vector<std::pair<int32_t, int>> horizon;
    uint32_t stamp = 0;
    for (size_t fi = 0; fi < faces_.size(); ++fi) {
      if (!faces_[fi].alive || faces_[fi].first == kNone) continue;
      if (dead_ > faces_.size() / 2 && faces_.size() >= kDropDeadAt) {
        fi = DropDeadFaces(fi);
        dead_ = 0;
      }
      // Farthest outside point of this face.
      const Face& f0 = faces_[fi];
      uint32_t eye = f0.first;
      double best = -1.0;
      for (uint32_t q = f0.first; q != kNone; q = next_[q]) {
        const double dd = Dot(f0, p_[q]);
        if (dd > best) {
          best = dd;
          eye = q;
        }
      }
      const Vec3 eye_point = p_[eye];
      ++stamp;
      visible.clear();
      horizon.clear();
      visible.push_back(static_cast<int32_t>(fi));
      faces_[fi].visible_stamp = stamp;
      for (size_t k = 0; k < visible.size(); ++k) {
        const int32_t f = visible[k];
        for (int e = 0; e < 3; ++e) {
          const int32_t g = faces_[f].nb[e];
          Face& fg = faces_[g];
          if (fg.visible_stamp == stamp) continue;
          if (fg.hidden_stamp != stamp) {
            if (Above(fg, eye_point)) {
              fg.visible_stamp = stamp;
              visible.push_back(g);
              continue;
            }
            fg.hidden_stamp = stamp;
          }
          horizon.emplace_back(f, e);
        }
      }
      // New faces over the horizon.
      const uint32_t seye = AddSlot(eye);
      const size_t first_new = faces_.size();
      for (const auto& he : horizon) {
        const Face& f = faces_[he.first];
        const uint32_t va = f.s[he.second], vb = f.s[(he.second + 1) % 3];
        const int32_t g = f.nb[he.second];
        const int32_t nf = AddFace(va, vb, seye);
        faces_[nf].nb[0] = g;
        Face& fg = faces_[g];
        int k = 0;
        while (k < 3 && !(fg.s[k] == vb && fg.s[(k + 1) % 3] == va)) ++k;
        if (k == 3) return Attempt::kRetry;
        fg.nb[k] = nf;
        if (stamp_at_[va] == stamp) return Attempt::kRetry;  // the horizon is not a simple loop
        stamp_at_[va] = stamp;
        start_at_[va] = nf;
      }
      for (size_t nf = first_new; nf < faces_.size(); ++nf) {
        const uint32_t vb = faces_[nf].s[1];
        if (stamp_at_[vb] != stamp) return Attempt::kRetry;
        faces_[nf].nb[1] = start_at_[vb];
        faces_[start_at_[vb]].nb[2] = static_cast<int32_t>(nf);
      }
      // Redistribute the outside points of the visible faces, face by face in list order. Assign
      // only looks at the new faces, so the lists can be walked while it appends to theirs.
      for (int32_t f : visible) faces_[f].alive = false;
      dead_ += visible.size();
      for (int32_t f : visible) {
        uint32_t q = faces_[f].first;
        faces_[f].first = faces_[f].last = kNone;
        while (q != kNone) {
          const uint32_t after = next_[q];
          if (q != eye) Assign(q, first_new, faces_.size());
          q = after;
        }
      }
    }
    std::vector<uint32_t>().swap(next_);
    // Compact.
    out->vertices.clear();
    out->triangles.clear();
    std::vector<uint32_t> remap(slot_point_.size(), UINT32_MAX);
    for (const Face& f : faces_) {
      if (!f.alive) continue;
      std::array<uint32_t, 3> t;
      for (int i = 0; i < 3; ++i) {
        if (remap[f.s[i]] == UINT32_MAX) {
          remap[f.s[i]] = static_cast<uint32_t>(out->vertices.size());
          out->vertices.push_back(p_[f.v[i]]);
        }
        t[i] = remap[f.s[i]];
      }
      out->triangles.push_back(t);
    }
    // Every face must have live neighbours (closed surface).
    for (const Face& f : faces_)
      if (f.alive)
        for (int e = 0; e < 3; ++e)
          if (f.nb[e] < 0 || !faces_[f.nb[e]].alive) return Attempt::kRetry;
    return Attempt::kOk;
  }

 private:
  // Dead faces are never visited again, but each step leaves its visible faces dead: on a large
  // input they outnumber the live ones many times over.
  static constexpr size_t kDropDeadAt = 4096;

  // Drops the dead faces, keeping the live ones in their order (the order the main loop visits
  // them in, so the hull does not change); returns the new index of live face `keep`.
  size_t DropDeadFaces(size_t keep) {
    std::vector<int32_t> index(faces_.size(), -1);
    int32_t m = 0;
    for (size_t f = 0; f < faces_.size(); ++f)
      if (faces_[f].alive) index[f] = m++;
    size_t k = 0;
    for (size_t f = 0; f < faces_.size(); ++f) {
      if (!faces_[f].alive) continue;
      if (k != f) faces_[k] = faces_[f];
      for (int32_t& g : faces_[k].nb)
        if (g >= 0) g = index[g];
      ++k;
    }
    faces_.resize(k);
    return static_cast<size_t>(index[keep]);
  }

  // A point becomes a face vertex at most once (an eye leaves every outside list): its slot
  // indexes the per-vertex arrays, which stay as small as the hull instead of the input.
  uint32_t AddSlot(uint32_t point) {
    slot_point_.push_back(point);
    start_at_.push_back(-1);
    stamp_at_.push_back(0);
    return static_cast<uint32_t>(slot_point_.size() - 1);
  }

  int32_t AddFace(uint32_t sa, uint32_t sb, uint32_t sc) {
    Face f;
    f.s[0] = sa;
    f.s[1] = sb;
    f.s[2] = sc;
    const uint32_t a = slot_point_[sa], b = slot_point_[sb], c = slot_point_[sc];
    f.v[0] = a;
    f.v[1] = b;
    f.v[2] = c;
    f.nb[0] = f.nb[1] = f.nb[2] = -1;
    f.base = p_[a];
    f.n = (p_[b] - f.base).cross(p_[c] - f.base);
    f.nlen = f.n.norm();
    faces_.push_back(std::move(f));
    return static_cast<int32_t>(faces_.size() - 1);
  }

  void LinkInitial() {
    for (int f = 0; f < 4; ++f)
      for (int e = 0; e < 3; ++e) {
        const uint32_t a = faces_[f].v[e], b = faces_[f].v[(e + 1) % 3];
        for (int g = 0; g < 4; ++g) {
          if (g == f) continue;
          for (int k = 0; k < 3; ++k)
            if (faces_[g].v[k] == b && faces_[g].v[(k + 1) % 3] == a) faces_[f].nb[e] = g;
        }
      }
  }

  // Points are passed by value, read once per use: a mesh read in place is mapped on every read.
  static double Dot(const Face& f, const Vec3& p) { return f.n.dot(p - f.base); }
  bool Above(const Face& f, const Vec3& p) const { return Dot(f, p) > eps_ * f.nlen; }

  void Assign(uint32_t q, size_t begin, size_t end) {
    const Vec3 p = p_[q];
    double best = 0.0;
    size_t best_f = end;
    for (size_t f = begin; f < end; ++f) {
      const Face& fa = faces_[f];
      if (!fa.alive) continue;
      const double dd = Dot(fa, p);
      if (dd > eps_ * fa.nlen) {
        const double dist = dd / fa.nlen;
        if (best_f == end || dist > best) {
          best = dist;
          best_f = f;
        }
      }
    }
    if (best_f == end) return;
    Face& f = faces_[best_f];
    next_[q] = kNone;
    if (f.last == kNone)
      f.first = q;
    else
      next_[f.last] = q;
    f.last = q;
  }

  const Points& p_;
  double eps_;
  std::vector<Face> faces_;
  size_t dead_ = 0;                   // dead faces in faces_
  std::vector<uint32_t> slot_point_;  // the point of each slot
  // start_at_[s]: the new face whose horizon edge starts at slot s (valid when stamp_at_[s] ==
  // the current stamp).
  std::vector<int32_t> start_at_;
  std::vector<uint32_t> stamp_at_;
  std::vector<uint32_t> next_;  // next_[q]: the point after q in its face's outside list
};

}  // namespace

const char* HullStatusName(HullStatus status) {
  switch (status) {
    case HullStatus::kOk:
      return "ok";
    case HullStatus::kTooFewPoints:
      return "too few points";
    case HullStatus::kNonFinite:
      return "non-finite coordinate";
    case HullStatus::kCollinear:
      return "collinear points";
    case HullStatus::kCoplanar:
      return "coplanar points";
    case HullStatus::kFailed:
      return "numerical failure";
  }
  return "unknown";
}

namespace {

template <typename Points>
HullStatus Hull(const Points& points, double tolerance, HullMesh* out) {
  out->vertices.clear();
  out->triangles.clear();
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i)
    if (!points[i].allFinite()) return HullStatus::kNonFinite;
  if (n < 4) return HullStatus::kTooFewPoints;
  if (n >= std::numeric_limits<uint32_t>::max()) return HullStatus::kFailed;

  Vec3 maxabs = Vec3::Zero();
  Vec3 lo = points[0], hi = points[0];
  for (size_t i = 0; i < n; ++i) {
    const Vec3& p = points[i];
    maxabs = maxabs.cwiseMax(p.cwiseAbs());
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  double eps = tolerance;
  if (tolerance < 0) eps = 1e-13 * (maxabs.sum() + (hi - lo).norm());

  for (int attempt = 0; attempt < 4; ++attempt) {
    // Initial simplex from the extreme points.
    // Each point read once per pass: a mesh read in place is mapped on every read.
    uint32_t ext[6] = {0, 0, 0, 0, 0, 0};
    Vec3 ext_lo = points[0], ext_hi = ext_lo;
    for (uint32_t i = 0; i < n; ++i) {
      const Vec3 p = points[i];
      for (int a = 0; a < 3; ++a) {
        if (p[a] < ext_lo[a]) {
          ext_lo[a] = p[a];
          ext[2 * a] = i;
        }
        if (p[a] > ext_hi[a]) {
          ext_hi[a] = p[a];
          ext[2 * a + 1] = i;
        }
      }
    }
    uint32_t i0 = ext[0], i1 = ext[1];
    double best = -1.0;
    for (int s = 0; s < 6; ++s)
      for (int t = s + 1; t < 6; ++t) {
        const double d = (points[ext[s]] - points[ext[t]]).squaredNorm();
        if (d > best) {
          best = d;
          i0 = ext[s];
          i1 = ext[t];
        }
      }
    if (std::sqrt(best) <= eps) return HullStatus::kCollinear;
    const Vec3 p0 = points[i0];
    const Vec3 dir = points[i1] - p0;
    uint32_t i2 = i0;
    best = -1.0;
    for (uint32_t i = 0; i < n; ++i) {
      const double d = (points[i] - p0).cross(dir).squaredNorm();
      if (d > best) {
        best = d;
        i2 = i;
      }
    }
    if (std::sqrt(best) / dir.norm() <= eps) return HullStatus::kCollinear;
    const Vec3 nrm = dir.cross(points[i2] - p0);
    uint32_t i3 = i0;
    best = -1.0;
    double signed_best = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
      const double d = nrm.dot(points[i] - p0);
      if (std::fabs(d) > best) {
        best = std::fabs(d);
        signed_best = d;
        i3 = i;
      }
    }
    if (best <= eps * nrm.norm()) return HullStatus::kCoplanar;
    uint32_t init[4] = {i0, i1, i2, i3};
    if (signed_best > 0) std::swap(init[1], init[2]);  // make (i0,i1,i2) face away from i3

    QuickHull<Points> qh(points, eps);
    if (qh.Run(init, out) == Attempt::kOk) return HullStatus::kOk;
    if (tolerance == 0.0)
      eps = 1e-12 * (maxabs.sum() + (hi - lo).norm());
    else
      eps *= 100.0;
  }
  out->vertices.clear();
  out->triangles.clear();
  return HullStatus::kFailed;
}

}  // namespace

HullStatus ComputeConvexHull(const std::vector<Vec3>& points, double tolerance, HullMesh* out) {
  return Hull(PointArray(points), tolerance, out);
}

HullStatus ComputeConvexHull(const std::vector<Vec3>& head, const GridPoints& base,
                             const std::vector<uint32_t>& refs, double tolerance, HullMesh* out) {
  return Hull(ReferencedPoints(head, base, refs), tolerance, out);
}

double HullMesh::Volume() const {
  if (triangles.empty()) return 0.0;
  const Vec3 c = vertices[0];
  double v = 0.0;
  for (const auto& t : triangles)
    v += (vertices[t[0]] - c).dot((vertices[t[1]] - c).cross(vertices[t[2]] - c));
  return v / 6.0;
}

Vec3 HullMesh::Centroid() const {
  if (vertices.empty()) return Vec3::Zero();
  const Vec3 c = vertices[0];
  Vec3 acc = Vec3::Zero();
  double vol = 0.0;
  for (const auto& t : triangles) {
    const Vec3 a = vertices[t[0]] - c, b = vertices[t[1]] - c, d = vertices[t[2]] - c;
    const double v = a.dot(b.cross(d));
    vol += v;
    acc += v * (a + b + d) / 4.0;
  }
  if (!(std::fabs(vol) > 0)) {
    Vec3 m = Vec3::Zero();
    for (const Vec3& p : vertices) m += p;
    return m / static_cast<double>(vertices.size());
  }
  return c + acc / vol;
}

double HullMesh::MaxConvexityViolation() const {
  double worst = -std::numeric_limits<double>::infinity();
  for (const auto& t : triangles) {
    Vec3 nrm = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    const double len = nrm.norm();
    if (!(len > 0)) continue;
    nrm /= len;
    for (const Vec3& p : vertices) worst = std::max(worst, nrm.dot(p - vertices[t[0]]));
  }
  return worst;
}

HullPlanes::HullPlanes(const HullMesh& hull) {
  if (!hull.vertices.empty()) {
    bmin = hull.vertices[0];
    bmax = hull.vertices[0];
  }
  for (const Vec3& p : hull.vertices) {
    bmin = bmin.cwiseMin(p);
    bmax = bmax.cwiseMax(p);
  }
  for (const auto& t : hull.triangles) {
    Vec3 nrm = (hull.vertices[t[1]] - hull.vertices[t[0]])
                   .cross(hull.vertices[t[2]] - hull.vertices[t[0]]);
    const double len = nrm.norm();
    if (!(len > 0)) continue;
    nrm /= len;
    normals.push_back(nrm);
    offsets.push_back(nrm.dot(hull.vertices[t[0]]));
  }
}

double HullPlanes::SignedDistanceBound(const Vec3& p) const {
  double worst = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < normals.size(); ++i)
    worst = std::max(worst, normals[i].dot(p) - offsets[i]);
  return worst;
}

namespace {
double PointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}
}  // namespace

bool HullPlanes::Contains(const Vec3& p, double margin) const {
  for (size_t i = 0; i < normals.size(); ++i)
    if (!(normals[i].dot(p) - offsets[i] < margin)) return false;
  return true;
}

double PointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  // Degenerate (collinear) triangles: distance to the three segments.
  if (!(ab.cross(ac).squaredNorm() > 1e-24 * ab.squaredNorm() * ac.squaredNorm()))
    return std::min({PointSegmentDistance(p, a, b), PointSegmentDistance(p, b, c),
                     PointSegmentDistance(p, c, a)});
  // Closest point by Voronoi regions (Ericson, Real-Time Collision Detection, 5.1.5).
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return (p - (a + v * ab)).norm();
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return (p - (a + w * ac)).norm();
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return (p - (b + w * (c - b))).norm();
  }
  const double denom = va + vb + vc;
  if (!(std::fabs(denom) > 0)) return std::min({ap.norm(), bp.norm(), cp.norm()});
  const double v = vb / denom, w = vc / denom;
  return (p - (a + ab * v + ac * w)).norm();
}

}  // namespace internal
}  // namespace vhacd
