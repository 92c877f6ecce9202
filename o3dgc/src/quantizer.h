// Uniform scalar quantization of float attributes.
//
// A component x in [min, min + range] maps to q = round((x - min) / range * (2^bits - 1)); the
// reconstruction min + q * range / (2^bits - 1) is within half a step of x. `range` is one value
// for all components (RangeMode::kUniform: the largest extent, cubic cells; kDiagonal: the
// bounding-box diagonal) or one per component (kPerAxis).
#ifndef O3DGC_SRC_QUANTIZER_H_
#define O3DGC_SRC_QUANTIZER_H_

#include <cstddef>
#include <cstdint>

#include "o3dgc/o3dgc.h"

namespace o3dgc {

struct Quantizer {
  uint32_t dimension = 0;
  int bits = 0;
  RangeMode mode = RangeMode::kUniform;
  float min[4] = {0, 0, 0, 0};
  float range[4] = {0, 0, 0, 0};

  uint32_t max_q() const { return uint32_t((uint64_t(1) << bits) - 1); }
  // Sets min/range from `count` vectors of `dimension` floats at data + i * stride bytes.
  void Fit(const float* data, size_t stride, size_t count);
  int32_t Quantize(float x, uint32_t component) const {
    if (!(range[component] > 0)) return 0;
    const double t = (double(x) - double(min[component])) / double(range[component]);
    // floor(y) clamped to [0, max_q]: truncation gives the same for y in (0, max_q) (no libm
    // call: SSE2 has no rounding instruction).
    const double y = t * double(max_q()) + 0.5;
    if (!(y > 0)) return 0;
    if (y >= double(max_q())) return int32_t(max_q());
    return int32_t(y);
  }
  float Dequantize(int32_t q, uint32_t component) const {
    if (!(range[component] > 0)) return min[component];
    return float(double(min[component]) + double(q) * (double(range[component]) / double(max_q())));
  }
  // Dequantize of `count` vectors of `dimension` values; vector i is read at q + dimension *
  // index[i] (index null: i). The same values as Dequantize, with the steps computed once.
  void DequantizeAll(const int32_t* q, const uint32_t* index, size_t count, float* out) const;
  // True if min/range are finite, range >= 0 and min + range is finite (decoder-side check).
  bool Valid() const;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_QUANTIZER_H_
