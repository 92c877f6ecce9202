// Robust 3D convex hull (quickhull) in double precision.
//
// Two modes:
//  * exact (tolerance == 0): the coordinates must be integers (or multiples of 1/2) of magnitude
//    < 65536; every orientation test is then computed exactly, so coplanar, collinear and
//    duplicate points are handled without any tolerance. Used on voxel coordinates.
//  * tolerant (tolerance < 0: automatic, > 0: absolute distance): a point closer than the
//    tolerance to a face is considered on it. Used on arbitrary floating-point input.
// The output is a closed, outward-facing (counter-clockwise seen from outside) triangle mesh whose
// vertices are a subset of the input points.
#ifndef VHACD_SRC_CONVEX_HULL_H_
#define VHACD_SRC_CONVEX_HULL_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

namespace vhacd {
namespace internal {

using Vec3 = Eigen::Vector3d;
class GridPoints;

struct HullMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;

  bool empty() const { return triangles.empty(); }
  double Volume() const;
  Vec3 Centroid() const;  // of the solid
  // Largest signed distance of a vertex above a face plane (<= 0 up to rounding when convex).
  double MaxConvexityViolation() const;
};

enum class HullStatus {
  kOk = 0,
  kTooFewPoints,  // fewer than 4 points
  kNonFinite,     // a NaN or Inf coordinate
  kCollinear,     // all points on a line (or coincident)
  kCoplanar,      // all points on a plane
  kFailed,        // numerical failure even after retries (tolerant mode only)
};

const char* HullStatusName(HullStatus status);

HullStatus ComputeConvexHull(const std::vector<Vec3>& points, double tolerance, HullMesh* out);
// The same for the points named by `refs`, in that order: a ref with kHeadRef set is
// head[ref - kHeadRef], any other base[ref]. The hull of a subset of a large array (a mesh's
// points) mixed with a few points of its own, without a copy of the array; the same result as on
// the points copied in that order.
constexpr uint32_t kHeadRef = 0x80000000u;
HullStatus ComputeConvexHull(const std::vector<Vec3>& head, const GridPoints& base,
                             const std::vector<uint32_t>& refs, double tolerance, HullMesh* out);

// Half-space form of a hull: n.x <= d for every face (n unit length).
struct HullPlanes {
  std::vector<Vec3> normals;
  std::vector<double> offsets;
  Vec3 bmin = Vec3::Zero(), bmax = Vec3::Zero();

  explicit HullPlanes(const HullMesh& hull);
  // Max over faces of n.p - d: <= 0 inside, > 0 outside (a lower bound of the distance).
  double SignedDistanceBound(const Vec3& p) const;
  // True when n.p - d < margin for every face (early exit).
  bool Contains(const Vec3& p, double margin = 0.0) const;
};

// Exact Euclidean distance from p to triangle (a, b, c).
double PointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_CONVEX_HULL_H_
