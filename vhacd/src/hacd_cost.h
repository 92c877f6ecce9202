// HACD's edge-collapse cost: the concavity of a candidate cluster (rays from its distance points to
// the boundary of its convex hull, and the flat-region measure), plus the shape, volume and
// computation terms (formula in include/vhacd/hacd.h).
#ifndef VHACD_SRC_HACD_COST_H_
#define VHACD_SRC_HACD_COST_H_

#include <Eigen/Eigenvalues>
#include <cstdint>
#include <vector>

#include "convex_hull.h"

namespace vhacd {
namespace internal {

// A ray origin and its unit direction.
struct DistPoint {
  Vec3 p = Vec3::Zero();
  Vec3 n = Vec3::Zero();
};

struct HacdCostParams {
  double scale = 1000.0;        // ScaleFactor
  double flat_threshold = 1.0;  // FlatRegionThreshold, % of scale
  double compacity_weight = 0.0;
  double volume_weight = 0.0;
  double computation_weight = 0.0;
  double total_dist_points = 1.0;
  double inside_margin = 1e-6;  // a ray origin this far outside the hull still counts
};

struct MergeCost {
  double concavity = 0.0;
  double cost = 0.0;
};

// Cost of a cluster whose hull is spanned by `hull_points` (the kept hull points of its parts),
// with the distance points dist[ids_a[i]] and dist[ids_b[i]], total `area` and `perimeter`.
// The concavity computation stops early once it exceeds `limit` (the result is then >= limit).
// *kept (when non-null) receives the points spanning the cluster's hull (its hull's vertices, or
// the vertices of its 2D hull when flat).
MergeCost EvaluateCluster(const std::vector<Vec3>& hull_points, const std::vector<DistPoint>& dist,
                          const std::vector<uint32_t>& ids_a, const std::vector<uint32_t>& ids_b,
                          double area, double perimeter, double limit, const HacdCostParams& params,
                          std::vector<Vec3>* kept);

// The principal axes of a point set: the eigen decomposition of its covariance about its
// centroid, written to *centroid when non-null (eigenvalues ascending: col(0) spreads least).
Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> PrincipalAxes(const std::vector<Vec3>& points,
                                                             Vec3* centroid = nullptr);

// Vertices of the 2D convex hull of (nearly) coplanar points and its area. Used for flat clusters.
double FlatHull(const std::vector<Vec3>& points, std::vector<Vec3>* kept);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_HACD_COST_H_
