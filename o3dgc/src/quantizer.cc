// Uniform scalar quantization (see quantizer.h).
#include "quantizer.h"

#include <cmath>

namespace o3dgc {

void Quantizer::Fit(const float* data, size_t stride, size_t count) {
  double lo[4], hi[4];
  for (uint32_t c = 0; c < dimension; ++c) {
    lo[c] = 0;
    hi[c] = 0;
  }
  for (size_t i = 0; i < count; ++i) {
    const float* v =
        reinterpret_cast<const float*>(reinterpret_cast<const char*>(data) + i * stride);
    for (uint32_t c = 0; c < dimension; ++c) {
      if (i == 0 || v[c] < lo[c]) lo[c] = v[c];
      if (i == 0 || v[c] > hi[c]) hi[c] = v[c];
    }
  }
  double extent = 0, diagonal2 = 0;
  for (uint32_t c = 0; c < dimension; ++c) {
    min[c] = float(lo[c]);  // exact: lo is a float value
    if (hi[c] - lo[c] > extent) extent = hi[c] - lo[c];
    diagonal2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
  }
  const double shared = mode == RangeMode::kDiagonal ? std::sqrt(diagonal2) : extent;
  float shared_range = float(shared);
  for (uint32_t c = 0; c < dimension; ++c) {
    while (double(min[c]) + double(shared_range) < hi[c]) {
      shared_range = std::nextafter(shared_range, INFINITY);
    }
  }
  for (uint32_t c = 0; c < dimension; ++c) {
    if (mode != RangeMode::kPerAxis) {
      range[c] = shared_range;
      continue;
    }
    double e = hi[c] - lo[c];
    float r = float(e);
    // Round up so that every value lies within [min, min + range].
    while (double(min[c]) + double(r) < hi[c]) r = std::nextafter(r, INFINITY);
    range[c] = r;
  }
}

namespace {

// One pass over the vectors, all components at once (a pass per component read and wrote every
// cache line of both arrays `dim` times). A component of zero range has step 0: base + q * 0 is
// its min exactly, as Dequantize returns.
template <uint32_t kDim>
void DequantizeRows(const int32_t* q, const uint32_t* index, size_t count, const double* base,
                    const double* step, float* out) {
  for (size_t i = 0; i < count; ++i) {
    const int32_t* p = q + (index ? size_t(index[i]) : i) * kDim;
    for (uint32_t c = 0; c < kDim; ++c) out[i * kDim + c] = float(base[c] + double(p[c]) * step[c]);
  }
}

}  // namespace

void Quantizer::DequantizeAll(const int32_t* q, const uint32_t* index, size_t count,
                              float* out) const {
  if (count == 0) return;  // an empty mesh's arrays may be null: no pointer arithmetic on them
  double base[4] = {0, 0, 0, 0}, step[4] = {0, 0, 0, 0};
  for (uint32_t c = 0; c < dimension && c < 4; ++c) {
    base[c] = double(min[c]);
    step[c] = range[c] > 0 ? double(range[c]) / double(max_q()) : 0.0;
  }
  switch (dimension) {
    case 1:
      return DequantizeRows<1>(q, index, count, base, step, out);
    case 2:
      return DequantizeRows<2>(q, index, count, base, step, out);
    case 3:
      return DequantizeRows<3>(q, index, count, base, step, out);
    case 4:
      return DequantizeRows<4>(q, index, count, base, step, out);
    default:
      return;  // dimensions are 1..4 (checked when the header is read)
  }
}

bool Quantizer::Valid() const {
  for (uint32_t c = 0; c < dimension; ++c) {
    if (!std::isfinite(min[c]) || !std::isfinite(range[c]) || range[c] < 0) return false;
    if (!std::isfinite(float(double(min[c]) + double(range[c])))) return false;
  }
  return true;
}

}  // namespace o3dgc
