// Position quantization chosen from an error budget: the smallest stream whose decoded positions
// all lie within `max_error` of the original.
//
// The codec offers three ways to size its quantization grid (o3dgc::RangeMode). With b bits,
// extents e = (ex, ey, ez), largest extent R and bounding-box diagonal D, rounding to the nearest
// grid point moves a position by at most
//   kUniform   (cubic cells of side R / (2^b - 1)):        sqrt(3) / 2 * R / (2^b - 1)
//   kPerAxis   (cells ex, ey, ez / (2^b - 1)):               D / 2 / (2^b - 1)
//   kDiagonal  (cubic cells of side D / (2^b - 1)):        sqrt(3) / 2 * D / (2^b - 1)
// A budget usually falls between two bit counts of one mode, so the three modes land at different
// distances below it. The error of a grid is known without coding (o3dgc::PositionQuantizationError
// applies the encoder's quantizer and the decoder's reconstruction to every vertex), so
// EncodeWithinError finds, for each mode, the fewest bits whose error is within the budget, encodes
// only those candidates and keeps the smallest stream. The candidates share one o3dgc::GridEncoder:
// what does not depend on the grid (connectivity, seams) is coded once, then the candidates' grids
// (at most three) run in parallel.
#ifndef HULLPACK_TOOLS_PIPELINE_ERROR_BUDGET_H_
#define HULLPACK_TOOLS_PIPELINE_ERROR_BUDGET_H_

#include <array>
#include <vector>

#include "common/parallel.h"
#include "common/status.h"
#include "pipeline/mesh_codec.h"
#include "scene/scene.h"

namespace hullpack {

// Fewest bits (1..30) for which `mode` guarantees the bound above for a mesh of per-axis `extent`.
int GuaranteedPositionBits(o3dgc::RangeMode mode, const std::array<double, 3>& extent,
                           double max_error);

// "uniform", "per-axis", "diagonal".
const char* RangeModeName(o3dgc::RangeMode mode);

struct BudgetedEncoding {
  // One stream, or one per part of a mesh split for its size (all on the same grid). Not decoded
  // here: a caller that keeps many streams decodes them once the sources are gone (DecodeMesh).
  std::vector<EncodedMesh> streams;
  int position_bits = 0;
  o3dgc::RangeMode position_range = o3dgc::RangeMode::kUniform;
  // Reached, model units: the largest distance between a vertex and its decoded position.
  double max_error = 0;
  int streams_tried = 0;
  double seconds_encode = 0;  // all candidates (wall time, they run in parallel)
};

// The bytes of all streams of `e`.
size_t StreamBytes(const BudgetedEncoding& e);

// The position error of `mesh` coded with `bits` on the `mode` grid, model units; -1 when the
// encoder would reject the positions.
double PositionGridError(const Mesh& mesh, o3dgc::RangeMode mode, int bits);

// `settings` gives everything but the position grid. `max_error` > 0, model units (or 0 for a
// mesh of zero size, which every grid keeps exactly). Candidates are encoded on `threads` (and
// on the cores its lender frees as they free up); the result does not depend on it.
// settings.progress, when set, sees the fraction of all candidates encoded (from any of those
// threads, one call at a time). With `max_part_triangles` > 0, a larger mesh that SplitTriangles
// can split is coded in parts of at most that many triangles, one after the other, all on the grid
// of the whole mesh: the candidates are compared by the bytes of the first part (a large sample of
// the mesh), the other parts are coded on the chosen grid only, and the encoder's memory follows a
// part instead of the mesh.
Result<BudgetedEncoding> EncodeWithinError(const Mesh& mesh, const std::vector<uint32_t>& groups,
                                           const MeshCodecSettings& settings, double max_error,
                                           const ThreadBudget& threads = 1,
                                           size_t max_part_triangles = 0);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_ERROR_BUDGET_H_
