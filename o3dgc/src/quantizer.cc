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
    const float* v = reinterpret_cast<const float*>(reinterpret_cast<const char*>(data) + i * stride);
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


void Quantizer::DequantizeAll(const int32_t* q, const uint32_t* index, size_t count,
                              float* out) const {
  if (count == 0) return;  // an empty mesh's arrays may be null: no pointer arithmetic on them
  const uint32_t dim = dimension;
  for (uint32_t c = 0; c < dim; ++c) {
    // Locals: the float stores below could alias the members.
    const double base = double(min[c]), step = double(range[c]) / double(max_q());
    float* o = out + c;
    if (!(range[c] > 0)) {
      const float m = min[c];
      for (size_t i = 0; i < count; ++i) o[i * dim] = m;
    } else if (index) {
      for (size_t i = 0; i < count; ++i) {
        o[i * dim] = float(base + double(q[size_t(index[i]) * dim + c]) * step);
      }
    } else {
      const int32_t* p = q + c;
      for (size_t i = 0; i < count; ++i) o[i * dim] = float(base + double(p[i * dim]) * step);
    }
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
