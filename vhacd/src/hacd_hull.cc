#include "hacd_hull.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
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
    Vec3 c = Vec3::Zero();
    for (const Vec3& p : pts) c += p;
    c /= static_cast<double>(pts.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Vec3& p : pts) cov += (p - c) * (p - c).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
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

HullMesh FilledClusterHull(const FillInput& in) {
  HullMesh hull = ClusterHull(in.surface, in.thickness, in.max_vertices);
  if (hull.empty()) return hull;
  auto concavity = [&](const HullMesh& h, double limit) {
    return EvaluateCluster(h.vertices, *in.dist, *in.dist_ids, {}, in.area, 0.0, limit, *in.cost,
                           nullptr)
        .concavity;
  };
  const double limit = concavity(hull, HUGE_VAL) + in.tolerance;
  const HullPlanes before(hull);
  for (double fraction : {0.5, 0.375, 0.25, 0.125}) {
    std::vector<Vec3> pts = in.surface;
    for (size_t t = 0; t < in.behind.size(); ++t)
      if (in.depth[t] > 0) pts.push_back(in.behind[t] + (fraction * in.depth[t]) * in.inward[t]);
    if (pts.size() == in.surface.size()) break;
    HullMesh filled = ClusterHull(pts, in.thickness, in.max_vertices);
    if (filled.empty()) break;
    const Vec3 c = filled.Centroid();
    bool inside = true;
    for (size_t k = 0; k <= filled.vertices.size() && inside; ++k) {
      const Vec3 q = k == 0 ? c : Vec3(0.5 * (filled.vertices[k - 1] + c));
      inside = before.Contains(q, in.thickness) || in.caster->Inside(q);
    }
    if (inside && !(concavity(filled, limit) > limit)) return filled;
  }
  return hull;
}

}  // namespace internal
}  // namespace vhacd
