// Quadric-error edge-collapse simplification on a welded indexed mesh (the engine behind
// vhacd::Simplify and HACD's decimation step; rules in include/vhacd/simplify.h).
#ifndef VHACD_SRC_SIMPLIFY_QEM_H_
#define VHACD_SRC_SIMPLIFY_QEM_H_

#include <array>
#include <cstdint>
#include <vector>

#include "context.h"
#include "convex_hull.h"

namespace vhacd {
namespace internal {

struct QemOptions {
  size_t target_triangles = 0;  // 0: no count target
  double max_error = 0.0;       // absolute distance; 0: no error limit
  bool lock_boundary = false;
};

struct QemMesh {
  std::vector<Vec3> points;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> source;  // output only: the input point each output point comes from
  std::vector<uint32_t> triangle_source;  // output only: the input triangle of each triangle
  double error = 0.0;                     // output only: largest collapse error (absolute distance)
};

// `seam_edges` holds (min << 32 | max) keys of edges to keep like boundaries (any order).
// Returns false when cancelled.
bool SimplifyQem(const QemMesh& in, const std::vector<uint64_t>& seam_edges,
                 const QemOptions& options, Context* ctx, QemMesh* out);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_SIMPLIFY_QEM_H_
