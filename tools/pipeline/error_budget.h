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
// distances below it. EncodeWithinError encodes the fewest-bit grid each mode guarantees, and one
// bit fewer when the measured error leaves room for it, decodes each, measures the error reached
// (MaxVertexDistance) and keeps the smallest stream within the budget.
#ifndef HULLPACK_TOOLS_PIPELINE_ERROR_BUDGET_H_
#define HULLPACK_TOOLS_PIPELINE_ERROR_BUDGET_H_

#include <array>
#include <vector>

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
  EncodedMesh encoded;
  Mesh decoded;                  // the chosen stream, decoded (name and material ids left empty)
  std::vector<uint32_t> groups;  // its decoded triangle groups
  int position_bits = 0;
  o3dgc::RangeMode position_range = o3dgc::RangeMode::kUniform;
  double max_error = 0;  // reached, model units
  int streams_tried = 0;
  double seconds_encode = 0;  // all candidates
  double seconds_decode = 0;  // the chosen stream
};

// `settings` gives everything but the position grid. `max_error` > 0, model units (or 0 for a
// mesh of zero size, which every grid keeps exactly).
Result<BudgetedEncoding> EncodeWithinError(const Mesh& mesh, const std::vector<uint32_t>& groups,
                                           const MeshCodecSettings& settings, double max_error);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_ERROR_BUDGET_H_
