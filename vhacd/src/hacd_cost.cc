#include "hacd_cost.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace vhacd {
namespace internal {

Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> PrincipalAxes(const std::vector<Vec3>& points,
                                                             Vec3* centroid) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : points) c += p;
  c /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) cov += (p - c) * (p - c).transpose();
  if (centroid != nullptr) *centroid = c;
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov);
}

double FlatHull(const std::vector<Vec3>& points, std::vector<Vec3>* kept) {
  if (points.size() < 3) {
    if (kept != nullptr) *kept = points;
    return 0.0;
  }
  Vec3 c;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es = PrincipalAxes(points, &c);
  const Vec3 u = es.eigenvectors().col(2), v = es.eigenvectors().col(1);
  struct P2 {
    double x, y;
    uint32_t i;
  };
  std::vector<P2> q(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    q[i] = {(points[i] - c).dot(u), (points[i] - c).dot(v), static_cast<uint32_t>(i)};
  std::sort(q.begin(), q.end(), [](const P2& a, const P2& b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.i < b.i);
  });
  auto cross = [](const P2& o, const P2& a, const P2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<P2> h(2 * q.size());
  size_t k = 0;
  for (size_t i = 0; i < q.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], q[i]) <= 0) --k;
    h[k++] = q[i];
  }
  for (size_t i = q.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], q[i]) <= 0) --k;
    h[k++] = q[i];
  }
  h.resize(k > 1 ? k - 1 : k);
  double area = 0.0;
  for (size_t i = 0; i < h.size(); ++i) {
    const P2& a = h[i];
    const P2& b = h[(i + 1) % h.size()];
    area += a.x * b.y - a.y * b.x;
  }
  if (kept != nullptr) {
    kept->clear();
    for (const P2& p : h) kept->push_back(points[p.i]);
  }
  return 0.5 * std::fabs(area);
}

MergeCost EvaluateCluster(const std::vector<Vec3>& hull_points, const std::vector<DistPoint>& dist,
                          const std::vector<uint32_t>& ids_a, const std::vector<uint32_t>& ids_b,
                          double area, double perimeter, double limit, const HacdCostParams& params,
                          std::vector<Vec3>* kept) {
  MergeCost out;
  HullMesh hull;
  const HullStatus st = ComputeConvexHull(hull_points, -1.0, &hull);
  double hull_area = 0.0, volume = 0.0;
  if (st == HullStatus::kOk) {
    for (const auto& t : hull.triangles)
      hull_area += 0.5 * (hull.vertices[t[1]] - hull.vertices[t[0]])
                             .cross(hull.vertices[t[2]] - hull.vertices[t[0]])
                             .norm();
    hull_area *= 0.5;  // both sides of a flat region
    volume = std::max(0.0, hull.Volume());
    if (kept != nullptr) *kept = hull.vertices;
  } else {
    hull_area = FlatHull(hull_points, kept);
  }
  // Flat measure, weighted by how flat the hull is.
  const double vol2surf = hull_area > 0 ? volume / hull_area : 0.0;
  const double x = vol2surf * 100.0 / (params.scale * std::max(1e-12, params.flat_threshold));
  const double weight_flat = std::max(0.0, 1.0 - x * x);
  double concavity = weight_flat * std::sqrt(std::fabs(hull_area - area));
  if (st == HullStatus::kOk && concavity < limit) {
    const HullPlanes planes(hull);
    double ray = 0.0;
    for (const std::vector<uint32_t>* ids : {&ids_a, &ids_b}) {
      for (uint32_t id : *ids) {
        const DistPoint& d = dist[id];
        if (!planes.Contains(d.p, params.inside_margin)) continue;
        double t = HUGE_VAL;
        for (size_t f = 0; f < planes.normals.size(); ++f) {
          const double nd = planes.normals[f].dot(d.n);
          if (nd <= 1e-12) continue;
          t = std::min(t, (planes.offsets[f] - planes.normals[f].dot(d.p)) / nd);
        }
        if (t == HUGE_VAL) continue;
        ray = std::max(ray, t);
        if (ray + concavity >= limit) break;
      }
      if (ray + concavity >= limit) break;
    }
    concavity += ray;
  }
  out.concavity = concavity;
  const double shape = area > 0 ? perimeter * perimeter / (4.0 * M_PI * area) : 0.0;
  out.cost = concavity + params.compacity_weight * shape + params.volume_weight * volume +
             params.computation_weight * static_cast<double>(ids_a.size() + ids_b.size()) /
                 std::max(1.0, params.total_dist_points);
  return out;
}

}  // namespace internal
}  // namespace vhacd
