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

// How thin `hull` is: the smallest distance from a face's plane to the farthest vertex behind it
// (the exact width of a convex hull up to edge-edge directions, close enough to pick a step).
double HullThickness(const Mesh& hull) {
  double thinnest = std::numeric_limits<double>::infinity();
  const size_t n = hull.vertex_count();
  auto point = [&](uint32_t v, int k) { return double(hull.positions[size_t(v) * 3 + k]); };
  for (size_t t = 0; t + 2 < hull.indices.size(); t += 3) {
    const uint32_t a = hull.indices[t], b = hull.indices[t + 1], c = hull.indices[t + 2];
    if (a >= n || b >= n || c >= n) continue;
    double u[3], w[3], normal[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = point(b, k) - point(a, k);
      w[k] = point(c, k) - point(a, k);
    }
    normal[0] = u[1] * w[2] - u[2] * w[1];
    normal[1] = u[2] * w[0] - u[0] * w[2];
    normal[2] = u[0] * w[1] - u[1] * w[0];
    const double length =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    if (!(length > 0)) continue;
    double farthest = 0;
    for (size_t v = 0; v < n; ++v) {
      double d = 0;
      for (int k = 0; k < 3; ++k) d += (point(uint32_t(v), k) - point(a, k)) * normal[k];
      farthest = std::max(farthest, std::fabs(d) / length);
    }
    thinnest = std::min(thinnest, farthest);
  }
  return std::isfinite(thinnest) ? thinnest : 0;
}

// The step for one hull: the mesh's step, finer for a hull thinner than four steps so that it
// keeps its volume (physics engines reject flat hulls), but never so fine that the hull spans
// more than 65535 steps.
double HullStep(const Mesh& hull, double mesh_step) {
  const double thickness = HullThickness(hull);
  if (!(thickness > 0) || thickness >= 4 * mesh_step) return mesh_step;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = hull.positions[k];
  for (size_t i = 0; i < hull.positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], double(hull.positions[i]));
    hi[i % 3] = std::max(hi[i % 3], double(hull.positions[i]));
  }
  const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  // ShortStep keeps 3 significant digits, so it loses less than 1 %.
  const double finest = ShortStep(1.01 * (span + 2 * mesh_step) / 65000.0);
  return std::min(mesh_step, std::max(finest, ShortStep(thickness / 4)));
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
    const double hull_step = HullStep(hull, step);
    std::vector<int64_t> q(n * 3);
    int64_t lo[3] = {std::numeric_limits<int64_t>::max(), std::numeric_limits<int64_t>::max(),
                     std::numeric_limits<int64_t>::max()};
    for (size_t i = 0; i < n * 3; ++i) {
      const double cell = std::round(double(hull.positions[i]) / hull_step);
      if (!(std::fabs(cell) < 9e15))
        return Status(StatusCode::kInvalidMesh, "hull coordinate out of range for its budget");
      q[i] = static_cast<int64_t>(cell);
      lo[i % 3] = std::min(lo[i % 3], q[i]);
    }
    HullGrid grid;
    grid.scale = hull_step;
    for (int k = 0; k < 3; ++k) grid.translation[k] = ShortDecimal(double(lo[k]) * hull_step);
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
