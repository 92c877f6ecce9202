// Reading a MeshView into a clean indexed mesh: validation, welding of bit-identical positions,
// degenerate and duplicate triangles dropped. Shared by every decomposer and the simplifier.
#ifndef VHACD_SRC_INPUT_MESH_H_
#define VHACD_SRC_INPUT_MESH_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "context.h"
#include "convex_hull.h"
#include "grid_points.h"
#include "triangle_list.h"
#include "vhacd/vhacd.h"

namespace vhacd {
namespace internal {

struct InputMesh {
  // The welded points, each referenced. Empty when the view's points are kept in place
  // (view_points; see ReadOptions::may_borrow).
  std::vector<Vec3> points;
  PointSource view_points;
  TriangleList triangles;                 // no degenerate, no duplicate
  std::vector<uint32_t> point_source;     // an input point index of each welded point
  std::vector<uint32_t> triangle_source;  // the input triangle index of each triangle
  // The points at ranks 0, s, 2s, ... of the lexicographic order of positions, s as SampleSurface
  // spaces them: the same samples whatever the point order (with ReadOptions::may_borrow).
  std::vector<uint32_t> vertex_samples;
  bool closed = false;

  size_t point_count() const { return view_points.empty() ? points.size() : view_points.size(); }
};

struct ReadOptions {
  // Fill point_source and triangle_source (for callers that map back to the input).
  bool keep_sources = true;
  // The points of an input with no equal positions and no unused point, whose consecutive
  // triangles use points near each other in its order (not a scrambled order), keep their order,
  // and when no triangle is dropped either (and the indices are contiguous) `triangles` borrows
  // the view's indices: a large clean mesh is not copied. Otherwise, and without it, the welded
  // points are in lexicographic order. Only for callers whose results do not depend on the
  // point order; the view must outlive the InputMesh.
  bool may_borrow = false;
  // With may_borrow and the order kept, the points are read in place (view_points) instead of
  // copied into `points`.
  bool points_in_place = false;
};

// Validates `m` and fills *out; on failure returns the status and names the problem in *why.
Status ReadMesh(const MeshView& m, Context* ctx, InputMesh* out, std::string* why,
                const ReadOptions& options = ReadOptions());

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_INPUT_MESH_H_
