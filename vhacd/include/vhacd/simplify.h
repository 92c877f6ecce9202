// vhacd/simplify.h: quadric-error mesh simplification (Garland–Heckbert edge collapses).
//
// Usable alone (an engine may link the library for this function only); HACD calls it first when
// HacdParameters::target_triangles > 0. Depends on Eigen and the standard library only, never
// throws, never returns NaN or Inf.
//
// Algorithm: every vertex carries the sum of the area-weighted plane quadrics of its triangles,
// plus constraint planes (perpendicular to the surface, heavily weighted) along boundary edges and
// attribute seams, so that open borders and seams keep their shape. Edges are collapsed cheapest
// first; an interior collapse moves the surviving vertex to the point minimizing the summed quadric
// (or the best endpoint or midpoint when that point is ill-defined or far away). A collapse is
// refused when it would
//   - flip or nearly fold a triangle (normal turned by more than ~78 degrees),
//   - make the surface non-manifold (link condition) or close a hole,
//   - move a boundary or seam vertex off its endpoint position, or join two boundary or seam
//     vertices through an edge that is not a boundary (seam) edge itself.
// Edges shared by more than two triangles are never collapsed.
//
// A mesh of 32768 triangles or more is first cut into slabs along its longest axis (one per 16384
// triangles, at most 8). When max(2 x target, 1/16 of the mesh) is at most half the mesh, each slab
// is decimated on its own down to its share of that count, the vertices of triangles crossing a cut
// kept in place; then the whole mesh goes on as one. The slabs depend on the mesh only, so the
// result does not depend on the thread count (HACD runs the slabs side by side).
#ifndef VHACD_SIMPLIFY_H_
#define VHACD_SIMPLIFY_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "vhacd/vhacd.h"

namespace vhacd {

struct SimplifyParameters {
  // Stop once the mesh has at most this many triangles; 0 = no count target. [0, 2^31)
  uint32_t target_triangles = 0;
  // Stop before a collapse whose error (root mean square distance to the planes of the collapsed
  // region, fraction of the bounding-box diagonal) would exceed this; 0 = no error limit. [0, 1]
  double target_error = 0.0;
  // Never move a boundary vertex (open borders stay exactly as they are).
  bool lock_boundary = false;
};

// Returns kOk, or kInvalidParameter with the offending field named in *why (when non-null). At
// least one of target_triangles and target_error must be non-zero.
Status ValidateSimplifyParameters(const SimplifyParameters& params, std::string* why);

struct SimplifyResult {
  Status status = Status::kOk;
  std::string message;  // human-readable detail for a non-ok status
  // The simplified mesh. Identical positions of the input are welded first; point i of the output
  // was derived from input point point_source[i] (copy its attributes). Triangles keep the winding
  // of the input triangles they come from.
  std::vector<double> points;     // 3 per point
  std::vector<uint32_t> indices;  // 3 per triangle
  std::vector<uint32_t> point_source;
  // Input triangle each output triangle descends from (its material, its normal: an output
  // triangle never turns more than ~78 degrees away from it).
  std::vector<uint32_t> triangle_source;
  double error = 0.0;  // largest collapse error made, fraction of the bounding-box diagonal

  bool ok() const { return status == Status::kOk; }
  size_t triangle_count() const { return indices.size() / 3; }
};

// Simplifies `mesh` (any soup: open, non-manifold, several components; degenerate and duplicate
// triangles are dropped). An attribute seam is an edge whose two triangles refer to different input
// points at one of its ends (split vertices with identical positions). Deterministic. `observer`
// (may be null) gets progress and can cancel (status kCancelled).
SimplifyResult Simplify(const MeshView& mesh, const SimplifyParameters& params,
                        Observer* observer = nullptr);

}  // namespace vhacd

#endif  // VHACD_SIMPLIFY_H_
