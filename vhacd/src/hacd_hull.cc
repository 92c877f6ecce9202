#include "hacd_hull.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "hull_simplify.h"

namespace vhacd {
namespace internal {

namespace {

// The hull without faces whose corners are (nearly) collinear: a point left on a hull edge makes a
// zero-area face whose normal is noise, which physics engines and convexity checks trip over. The
// middle point of such a face is dropped (the hull loses nothing) and the hull rebuilt.
HullMesh WithoutSlivers(HullMesh hull) {
  constexpr int kRounds = 16;
  constexpr double kMinSine = 1e-8;
  for (int round = 0; round < kRounds; ++round) {
    uint32_t middle = UINT32_MAX;
    for (const auto& t : hull.triangles) {
      const Vec3 &a = hull.vertices[t[0]], &b = hull.vertices[t[1]], &c = hull.vertices[t[2]];
      const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(),
                   ca = (a - c).squaredNorm();
      const double longest = std::max({ab, bc, ca});
      if ((b - a).cross(c - a).norm() > kMinSine * longest) continue;
      middle = longest == ab ? t[2] : longest == bc ? t[0] : t[1];
      break;
    }
    if (middle == UINT32_MAX) return hull;
    std::vector<Vec3> pts;
    for (uint32_t v = 0; v < hull.vertices.size(); ++v)
      if (v != middle) pts.push_back(hull.vertices[v]);
    HullMesh rebuilt;
    if (ComputeConvexHull(pts, -1.0, &rebuilt) != HullStatus::kOk) return hull;
    hull = std::move(rebuilt);
  }
  return hull;
}

}  // namespace

HullMesh ClusterHull(const std::vector<Vec3>& pts, double thickness, uint32_t max_vertices) {
  HullMesh hull;
  HullStatus st = ComputeConvexHull(pts, -1.0, &hull);
  bool thin = st != HullStatus::kOk;
  if (!thin) {
    // Thinner than `thickness` everywhere: give it that thickness.
    double area = 0.0;
    for (const auto& t : hull.triangles)
      area += 0.5 * (hull.vertices[t[1]] - hull.vertices[t[0]])
                        .cross(hull.vertices[t[2]] - hull.vertices[t[0]])
                        .norm();
    thin = hull.Volume() < 0.25 * area * thickness;
  }
  if (thin) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es = PrincipalAxes(pts);
    std::vector<Vec3> thick;
    const Vec3 n = es.eigenvectors().col(0), m = es.eigenvectors().col(1);
    const bool line = es.eigenvalues()[1] <= 1e-18 * std::max(1e-300, es.eigenvalues()[2]);
    for (const Vec3& p : pts) {
      thick.push_back(p + 0.5 * thickness * n);
      thick.push_back(p - 0.5 * thickness * n);
      if (line) {
        thick.push_back(p + 0.5 * thickness * m);
        thick.push_back(p - 0.5 * thickness * m);
      }
    }
    HullMesh h2;
    if (ComputeConvexHull(thick, -1.0, &h2) == HullStatus::kOk) hull = h2;
  }
  if (hull.empty()) return hull;
  return WithoutSlivers(SimplifyHull(hull, max_vertices, 0.0));
}

namespace {

// The ray part of the cluster's concavity on `hull` (see EvaluateCluster), where a ray counts only
// as far as its farthest sampled point outside the solid: a stretch of hull in front of the surface
// that is still inside the solid (another piece of the surface closes it, e.g. a lid over a pot)
// does not reach out of the solid. Rays no longer than `limit` are not sampled. The hull faces
// where the rays reaching farther than `limit` out of the solid end go to *faces.
double OutsideConcavity(const FillInput& in, const HullMesh& hull, double limit,
                        std::vector<uint32_t>* faces) {
  constexpr int kSamples = 16;
  std::vector<Vec3> normals;
  std::vector<double> offsets;
  std::vector<uint32_t> face_of;
  for (uint32_t f = 0; f < hull.triangles.size(); ++f) {
    const auto& t = hull.triangles[f];
    const Vec3 n = (hull.vertices[t[1]] - hull.vertices[t[0]])
                       .cross(hull.vertices[t[2]] - hull.vertices[t[0]]);
    const double len = n.norm();
    if (!(len > 0)) continue;
    normals.push_back(n / len);
    offsets.push_back(normals.back().dot(hull.vertices[t[0]]));
    face_of.push_back(f);
  }
  double worst = 0.0;
  for (uint32_t id : *in.dist_ids) {
    const DistPoint& d = (*in.dist)[id];
    bool contained = true;
    for (size_t f = 0; f < normals.size() && contained; ++f)
      contained = normals[f].dot(d.p) - offsets[f] < in.cost->inside_margin;
    if (!contained) continue;
    double t = HUGE_VAL;
    size_t hit = 0;
    for (size_t f = 0; f < normals.size(); ++f) {
      const double nd = normals[f].dot(d.n);
      if (nd <= 1e-12) continue;
      const double tf = (offsets[f] - normals[f].dot(d.p)) / nd;
      if (tf < t) {
        t = tf;
        hit = f;
      }
    }
    if (t == HUGE_VAL) continue;
    if (t <= limit) {
      worst = std::max(worst, t);
      continue;
    }
    double reach = 0.0;
    for (int k = kSamples; k >= 1; --k) {
      const double s = t * k / kSamples;
      if (!in.caster->Inside(d.p + s * d.n)) {
        reach = s;
        break;
      }
    }
    worst = std::max(worst, std::min(reach, t));
    if (reach > limit) faces->push_back(face_of[hit]);
  }
  return worst;
}

}  // namespace

HullMesh FilledClusterHull(const FillInput& in) {
  HullMesh hull = ClusterHull(in.surface, in.thickness, in.max_vertices);
  if (hull.empty()) return hull;
  const double limit = EvaluateCluster(hull.vertices, *in.dist, *in.dist_ids, {}, in.area, 0.0,
                                       HUGE_VAL, *in.cost, nullptr)
                           .concavity +
                       in.tolerance;
  const HullPlanes before(hull);
  // Every triangle's point behind it starts halfway through the solid; a point that is a corner of
  // a hull face where a ray ends too far out of the solid goes back by an eighth of the depth, and
  // the hull is made again; when the hull's middle leaves the solid, every point goes back.
  constexpr int kRounds = 12;
  constexpr double kStep = 0.125;
  std::vector<double> fraction(in.behind.size(), 0.5);
  std::vector<std::pair<std::array<double, 3>, uint32_t>> owner;  // behind point -> triangle
  std::vector<uint32_t> faces;
  for (int round = 0; round < kRounds; ++round) {
    std::vector<Vec3> pts = in.surface;
    owner.clear();
    for (size_t t = 0; t < in.behind.size(); ++t) {
      if (!(in.depth[t] > 0) || !(fraction[t] > 0)) continue;
      pts.push_back(in.behind[t] + (fraction[t] * in.depth[t]) * in.inward[t]);
      owner.push_back({{pts.back()[0], pts.back()[1], pts.back()[2]}, static_cast<uint32_t>(t)});
    }
    if (pts.size() == in.surface.size()) break;
    HullMesh filled = ClusterHull(pts, in.thickness, in.max_vertices);
    if (filled.empty()) break;
    const Vec3 c = filled.Centroid();
    bool inside = true;
    for (size_t k = 0; k <= filled.vertices.size() && inside; ++k) {
      const Vec3 q = k == 0 ? c : Vec3(0.5 * (filled.vertices[k - 1] + c));
      inside = before.Contains(q, in.thickness) || in.caster->Inside(q);
    }
    faces.clear();
    if (inside && !(OutsideConcavity(in, filled, limit, &faces) > limit)) return filled;
    // The behind points to move back: the corners of the faces the far rays end on, else all.
    std::sort(owner.begin(), owner.end());
    bool moved = false;
    for (uint32_t f : faces)
      for (uint32_t v : filled.triangles[f]) {
        const Vec3& p = filled.vertices[v];
        const std::array<double, 3> key{p[0], p[1], p[2]};
        auto it = std::lower_bound(owner.begin(), owner.end(), std::make_pair(key, uint32_t{0}));
        for (; it != owner.end() && it->first == key; ++it) {
          double& fr = fraction[it->second];
          if (fr > 0) {
            fr = std::max(0.0, fr - kStep);
            moved = true;
          }
        }
      }
    if (!moved)
      for (double& fr : fraction) fr = std::max(0.0, fr - kStep);
  }
  return hull;
}

}  // namespace internal
}  // namespace vhacd
