// Error report of a decomposition: per-hull concavity, volume IoU, two-sided Hausdorff distances.
// Everything is measured in grid units (a similarity of the input), so fractions of the bounding
// box diagonal are those of the input.
#ifndef VHACD_SRC_ERROR_METRICS_H_
#define VHACD_SRC_ERROR_METRICS_H_

#include <vector>

#include "context.h"
#include "convex_hull.h"
#include "vhacd/vhacd.h"
#include "voxelizer.h"

namespace vhacd {
namespace internal {

// Nearest-triangle queries on a triangle soup, through a uniform grid of buckets.
class TriangleLocator {
 public:
  TriangleLocator(const GridMesh& mesh, double cell_size);
  double Distance(const Vec3& p) const;
  // Also gives the index of a nearest triangle (mesh.triangles.size() when there is none).
  double Distance(const Vec3& p, uint32_t* nearest) const;
  // As Distance, but stops at the first triangle found within `enough` of p, and gives that one
  // and its distance (then <= enough, not always the least). For a largest distance over many
  // points: a point that cannot raise the largest so far needs no exact value.
  double DistanceUnlessWithin(const Vec3& p, double enough, uint32_t* nearest) const;

 private:
  // For a triangle whose box spans more than 2 x 2 x 2 cells (a sliver, most often), whose box is
  // a loose bound: its plane, and its longest edge with the triangle's height over it.
  struct Sliver {
    Vec3 start, edge, normal;  // normal: unit, or zero for a degenerate triangle
    double inv_length2, height, offset;
    static Sliver Of(const Vec3& a, const Vec3& b, const Vec3& c);
    // A lower bound of the distance from q to the triangle, tight for a sliver.
    double Bound(const Vec3& q) const;
  };
  const GridMesh& mesh_;
  double cell_;
  Vec3 origin_;
  int dims_[3];
  std::vector<uint32_t> start_, ids_;
  std::vector<Sliver> slivers_;
  std::vector<uint32_t> sliver_of_;  // per triangle, its index in slivers_ or kNone (empty if none)
  static constexpr uint32_t kNone = 0xFFFFFFFFu;
};

struct MetricsInput {
  const GridMesh* mesh = nullptr;
  const VoxelGrid* grid = nullptr;
  const std::vector<HullMesh>* hulls = nullptr;
  double diagonal = 1.0;  // bounding-box diagonal of the input, grid units
  double volume0 = 1.0;   // concavity normalization, voxel units
  bool closed = false;
  // A locator of `mesh` to measure with (optional): the report builds its own without one.
  const TriangleLocator* locator = nullptr;
};

// Points about `spacing` apart inside the triangle, in rows parallel to its longest edge (linear
// in the area, and empty for a degenerate triangle).
void SampleTriangle(Vec3 a, Vec3 b, Vec3 c, double spacing, std::vector<Vec3>* out);

// The error report's surface samples, and the stride between its vertex samples on a mesh of
// `points` points (half the samples are vertices).
constexpr size_t kSurfaceSamples = 20000;
inline size_t VertexSampleStride(size_t points) {
  return points / (kSurfaceSamples / 2 + 1) > 1 ? points / (kSurfaceSamples / 2 + 1) : 1;
}

// About kSurfaceSamples points spread over the surface, deterministic: vertices first (every
// VertexSampleStride-th in the lexicographic order of positions: mesh.vertex_samples, or with none
// given, the points in their order), then a stratified grid on each triangle.
std::vector<Vec3> SampleSurface(const GridMesh& mesh);

// Fills report->hulls, volume_iou, the Hausdorff distances and concavity. False when cancelled.
bool ComputeErrorReport(const MetricsInput& in, Context* ctx, Report* report);

// Resets the measures ComputeErrorReport fills (per-hull reports, IoU, coverage, Hausdorff
// distances, concavity) and keeps the rest: for a run that needed them only internally.
void ClearMeasures(Report* report);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_ERROR_METRICS_H_
