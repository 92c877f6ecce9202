// PositionQuantizationError: the encoder's position quantizer applied without coding.
#include <cmath>

#include "o3dgc/o3dgc.h"
#include "quantizer.h"

namespace o3dgc {

double PositionQuantizationError(const float* positions, size_t stride, size_t num_vertices,
                                 int bits, RangeMode range) {
  if (bits < 1 || bits > 30 || (num_vertices > 0 && !positions)) return -1;
  if (num_vertices == 0) return 0;
  const auto at = [&](size_t i) {
    return reinterpret_cast<const float*>(reinterpret_cast<const char*>(positions) + i * stride);
  };
  for (size_t i = 0; i < num_vertices; ++i) {
    const float* p = at(i);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return -1;
  }
  // Fitted exactly as Encode fits it, and dequantized as Decode does (Quantizer::DequantizeAll).
  Quantizer q;
  q.dimension = 3;
  q.bits = bits;
  q.mode = range;
  q.Fit(positions, stride, num_vertices);
  if (!q.Valid()) return -1;
  double step[3];
  for (uint32_t c = 0; c < 3; ++c)
    step[c] = q.range[c] > 0 ? double(q.range[c]) / double(q.max_q()) : 0.0;
  double worst2 = 0;
  for (size_t i = 0; i < num_vertices; ++i) {
    const float* p = at(i);
    double d2 = 0;
    for (uint32_t c = 0; c < 3; ++c) {
      const float decoded = float(double(q.min[c]) + double(q.Quantize(p[c], c)) * step[c]);
      const double d = double(decoded) - double(p[c]);
      d2 += d * d;
    }
    if (d2 > worst2) worst2 = d2;
  }
  return std::sqrt(worst2);
}

}  // namespace o3dgc
