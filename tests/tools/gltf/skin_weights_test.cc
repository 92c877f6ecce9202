#include "gltf/skin_weights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hullpack {
namespace {

// The validator's check: float32 running sum in component order, 2e-7 allowed per non-zero weight.
bool ValidatorAccepts(const float* w) {
  float sum = 0;
  double allowed = 0;
  for (int k = 0; k < 4; ++k) {
    if (w[k] == 0) continue;
    sum = sum + w[k];
    allowed += 2e-7;
  }
  return std::fabs(double(sum) - 1) <= allowed;
}

TEST(SkinWeights, QuantizedWeightsSumToOneAgain) {
  // Weights on a 10-bit grid, as a stream decodes them: sums off by up to a step.
  std::vector<float> w;
  for (int a = 0; a <= 1023; a += 7) {
    for (int b = 0; a + b <= 1023; b += 61) {
      const int c = (1023 - a - b) / 3;
      w.insert(w.end(), {float(a / 1023.0 + 0.0004), float(b / 1023.0), float(c / 1023.0),
                         float((1023 - a - b - c) / 1023.0 - 0.0003)});
      for (int k = 1; k <= 4; ++k) w[w.size() - k] = std::max(0.0f, w[w.size() - k]);
    }
  }
  const std::vector<float> before = w;
  const size_t n = w.size() / 4;
  size_t rejected = 0;
  for (size_t v = 0; v < n; ++v) rejected += !ValidatorAccepts(&before[v * 4]);
  ASSERT_GT(rejected, n / 2);  // the test data does need it
  EXPECT_EQ(NormalizeSkinWeights(w.data(), n), rejected);
  for (size_t v = 0; v < n; ++v) {
    EXPECT_TRUE(ValidatorAccepts(&w[v * 4])) << v;
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(w[v * 4 + k], 0);
      EXPECT_NEAR(w[v * 4 + k], before[v * 4 + k], 1e-3)
          << v;  // a rescale, not a change of influences
    }
  }
}

TEST(SkinWeights, ExactAndZeroVerticesStayAsTheyAre) {
  std::vector<float> w = {1, 0, 0, 0, 0.5f, 0.25f, 0.25f, 0, 0, 0, 0, 0};
  const std::vector<float> before = w;
  EXPECT_EQ(NormalizeSkinWeights(w.data(), 3), 0u);
  EXPECT_EQ(w, before);
}

TEST(SkinWeights, FarOffSumsAreScaled) {
  std::vector<float> w = {0.1f, 0.05f, 0.05f, 0};
  EXPECT_EQ(NormalizeSkinWeights(w.data(), 1), 1u);
  EXPECT_NEAR(w[0], 0.5, 1e-7);
  EXPECT_NEAR(w[1], 0.25, 1e-7);
  EXPECT_TRUE(ValidatorAccepts(w.data()));
}

}  // namespace
}  // namespace hullpack
