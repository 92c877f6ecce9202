// Independent error measures of a convex decomposition, for the benchmarks.
//
// Written apart from vhacd/ (its own random surface sampling, its own triangle BVH, the generalized
// winding number as the inside test) so that the library's own report can be checked against it and
// any decomposition program (for instance V-HACD 4.1) can be measured the same way from its hulls.
//
// Definitions (distances as fractions of the mesh's bounding-box diagonal):
//   mesh -> hulls   max over points of the mesh surface of the distance to the union of hulls
//                   (0 for a point inside a hull);
//   hulls -> mesh   max over points of the boundary of the union of hulls of the distance to the
//                   mesh surface; a hull surface point counts as boundary when it is farther than
//                   `gap` from every other hull (so faces shared or overlapped by a neighbour, and
//                   cracks narrower than `gap` between hulls, are interior; this changes the
//                   distance on the outer boundary by at most `gap`);
//   concavity       the larger of the two;
//   solid           lattice points (one random point per cell of a grid over the bounding box)
//                   whose generalized winding number has magnitude >= 1/2 (exact inside for
//                   closed meshes, the usual robust extension for open ones);
//   IoU             |solid ∩ hulls| / |solid ∪ hulls| on the lattice, closed meshes only;
//   coverage        |solid ∩ hulls| / |solid| on the lattice, every mesh.
#ifndef HULLPACK_TOOLS_BENCH_HULL_METRICS_H_
#define HULLPACK_TOOLS_BENCH_HULL_METRICS_H_

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace hullpack {
namespace bench {

using V3 = Eigen::Vector3d;

struct Soup {
  std::vector<V3> points;
  std::vector<std::array<uint32_t, 3>> triangles;
};

// "" when the hull is finite, closed (every directed edge exactly once, and its reverse too),
// outward-facing (positive volume) and convex: no vertex farther than `tol` above a face plane.
std::string CheckHull(const Soup& hull, double tol);

// Signed volume of a closed triangle mesh (positive when outward-facing).
double SignedVolume(const Soup& soup);

struct MetricsOptions {
  size_t mesh_samples = 100000;  // random points on the mesh surface (its vertices are added)
  size_t hull_samples = 100000;  // random points on the hulls' surfaces (their vertices are added)
  size_t solid_points = 262144;  // lattice points over the mesh's bounding box
  double gap = 0.002;            // see "hulls -> mesh" above, fraction of the diagonal
  double convexity_tol = 1e-6;   // CheckHull tolerance, fraction of the diagonal
  uint64_t seed = 1;
  int threads = 0;  // 0: every core
};

struct HullMetrics {
  size_t hulls = 0;
  size_t max_hull_vertices = 0;
  double mesh_to_hulls = -1.0, hulls_to_mesh = -1.0, concavity = -1.0;
  // Where the two maxima were found (a mesh surface point; a hull surface point and its hull).
  V3 worst_mesh_point = V3::Zero(), worst_hull_point = V3::Zero();
  size_t worst_hull = 0;
  bool worst_hull_point_in_solid = false;  // the hulls -> mesh maximum lies inside the mesh solid
  double worst_hull_point_gap = -1.0;      // its distance to the nearest other hull (fraction)
  double iou = -1.0;                       // -1 for open meshes
  // The same ratio for any mesh, against the winding-number solid (an open mesh closed over its
  // holes, e.g. a scan open at its base).
  double solid_iou = -1.0;
  double coverage = -1.0;
  size_t invalid_hulls = 0;
  std::string first_problem;  // of the first invalid hull
};

// Bounding-volume hierarchy over a triangle soup: nearest distance and winding number queries.
class TriangleBvh {
 public:
  explicit TriangleBvh(const Soup& soup);  // `soup` must outlive the BVH
  // Euclidean distance from p to the nearest triangle (+inf for an empty soup).
  double Distance(const V3& p) const;
  // Generalized winding number at p: far clusters as dipoles (first order), near triangles exact.
  double Winding(const V3& p) const;

 private:
  struct Node {
    V3 lo, hi;                      // bounds of the node's triangles
    V3 center;                      // area-weighted centroid
    V3 area_vector;                 // sum of the triangles' area vectors (half the cross products)
    double radius = 0;              // of the ball around `center` holding every triangle
    uint32_t first = 0, count = 0;  // leaf: order_[first .. first + count)
    uint32_t left = 0, right = 0;   // inner node (count == 0)
  };
  uint32_t Build(uint32_t first, uint32_t count, std::vector<V3>* centroids);
  const Soup& soup_;
  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;
};

// Generalized winding number at p by the exact solid-angle sum over every triangle.
double WindingNumberExact(const Soup& soup, const V3& p);

// Exact Euclidean distance from p to the triangle (a, b, c).
double PointTriangleDistance(const V3& p, const V3& a, const V3& b, const V3& c);

// The input mesh, prepared once (samples, BVH, inside lattice) and measured against hull sets.
class MeshMeasure {
 public:
  MeshMeasure(Soup mesh, const MetricsOptions& options);
  ~MeshMeasure();
  MeshMeasure(const MeshMeasure&) = delete;  // the BVH refers to mesh_
  MeshMeasure& operator=(const MeshMeasure&) = delete;

  // Every edge (after welding identical positions) shared by exactly two triangles.
  bool closed() const { return closed_; }
  double diagonal() const { return diagonal_; }
  size_t solid_point_count() const { return solid_count_; }

  HullMetrics Measure(const std::vector<Soup>& hulls) const;

 private:
  Soup mesh_;
  MetricsOptions options_;
  bool closed_ = false;
  double diagonal_ = 0.0;
  V3 lo_, hi_;
  std::unique_ptr<TriangleBvh> bvh_;
  std::vector<V3> samples_;
  // Lattice of cells tiling the mesh's bounding box: cell (i, j, k) is origin_ + [i, i+1] x ...
  // times step_ (per axis), 0 <= i < dims_[0], ...; each holds one fixed random point.
  V3 CellPoint(int i, int j, int k) const;
  V3 origin_;
  V3 step_ = V3::Ones();
  int dims_[3] = {1, 1, 1};
  std::vector<uint8_t> solid_;
  size_t solid_count_ = 0;
};

}  // namespace bench
}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_HULL_METRICS_H_
