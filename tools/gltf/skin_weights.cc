#include "gltf/skin_weights.h"

#include <cmath>

namespace hullpack {

size_t NormalizeSkinWeights(float* weights, size_t vertex_count) {
  size_t off = 0;
  for (size_t v = 0; v < vertex_count; ++v) {
    float* w = weights + v * 4;
    double sum = 0;
    int largest = 0;
    for (int k = 0; k < 4; ++k) {
      sum += w[k];
      if (w[k] > w[largest]) largest = k;
    }
    if (!(sum > 0) || !std::isfinite(sum)) continue;
    if (std::fabs(sum - 1) > 1e-6) ++off;
    double others = 0;
    for (int k = 0; k < 4; ++k) {
      if (k == largest) continue;
      w[k] = static_cast<float>(w[k] / sum);
      others += w[k];
    }
    w[largest] = static_cast<float>(1.0 - others);
  }
  return off;
}

}  // namespace hullpack
