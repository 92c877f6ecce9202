#include "pipeline/hull_quantize.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "pipeline/mesh_codec.h"

namespace hullpack {
namespace {

// `v` rounded down to 3 significant decimal digits (as the JSON holds it, so that writer, reader
// and engines all compute with the same double).
double ShortStep(double v) {
  const double e = std::floor(std::log10(v)) - 2;
  const double mantissa = std::floor(v / std::pow(10.0, e));
  char text[40];
  std::snprintf(text, sizeof(text), "%.0fe%d", mantissa, static_cast<int>(e));
  double s = std::strtod(text, nullptr);
  if (s > v) {  // the decimal rounded up in binary: one digit less
    std::snprintf(text, sizeof(text), "%.0fe%d", mantissa - 1, static_cast<int>(e));
    s = std::strtod(text, nullptr);
  }
  return s;
}

// `v` as the shortest of up to 9 significant digits that reads back exactly.
double ShortDecimal(double v) {
  char text[40];
  std::snprintf(text, sizeof(text), "%.9g", v);
  return std::strtod(text, nullptr);
}

}  // namespace

Result<QuantizedHulls> QuantizeHulls(const std::vector<Mesh>& hulls, double max_error) {
  if (hulls.empty()) return Status(StatusCode::kInvalidArgument, "no hulls to quantize");
  if (!(max_error > 0) || !std::isfinite(max_error))
    return Status(StatusCode::kInvalidArgument, "error budget must be positive");
  // Half a cell diagonal within the budget, with room for the float rounding of the result.
  const double step = ShortStep(0.999 * 2.0 * max_error / std::sqrt(3.0));
  QuantizedHulls out;
  uint32_t widest = 0;
  for (const Mesh& hull : hulls) {
    const size_t n = hull.vertex_count();
    if (n == 0) return Status(StatusCode::kInvalidMesh, "a hull has no vertices");
    std::vector<int64_t> q(n * 3);
    int64_t lo[3] = {std::numeric_limits<int64_t>::max(), std::numeric_limits<int64_t>::max(),
                     std::numeric_limits<int64_t>::max()};
    for (size_t i = 0; i < n * 3; ++i) {
      const double cell = std::round(double(hull.positions[i]) / step);
      if (!(std::fabs(cell) < 9e15))
        return Status(StatusCode::kInvalidMesh, "hull coordinate out of range for its budget");
      q[i] = static_cast<int64_t>(cell);
      lo[i % 3] = std::min(lo[i % 3], q[i]);
    }
    HullGrid grid;
    grid.scale = step;
    for (int k = 0; k < 3; ++k) grid.translation[k] = ShortDecimal(double(lo[k]) * step);
    grid.local.resize(n * 3);
    for (size_t i = 0; i < n * 3; ++i) {
      const int64_t local = q[i] - lo[i % 3];
      if (local > 65535) {
        return Status(StatusCode::kInvalidArgument,
                      "a hull spans more than 65535 steps of its error budget: raise --hull-error");
      }
      grid.local[i] = static_cast<uint16_t>(local);
      widest = std::max(widest, static_cast<uint32_t>(local));
    }
    Mesh decoded;
    decoded.indices = hull.indices;
    decoded.positions = DequantizeHull(grid);
    out.max_error = std::max(out.max_error, MaxVertexDistance(hull, decoded));
    out.grids.push_back(std::move(grid));
    out.decoded.push_back(std::move(decoded));
  }
  if (out.max_error > max_error)
    return Status(StatusCode::kInternal, "hull vertices moved beyond their budget");
  while ((uint32_t(1) << out.position_bits) <= widest) ++out.position_bits;
  return out;
}

}  // namespace hullpack
