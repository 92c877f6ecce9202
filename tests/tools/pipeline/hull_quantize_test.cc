#include "pipeline/hull_quantize.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/test_shapes.h"
#include "pipeline/mesh_codec.h"

namespace hullpack {
namespace {

// The closed box [x0, x1] x [0, 1] x [0, h], outward triangles.
Mesh Box(float x0, float x1, float h) {
  Mesh m;
  test_shapes::AppendTo(test_shapes::Box(x0, 0, 0, x1, 1, h), &m);
  return m;
}

TEST(HullQuantize, EveryVertexWithinTheBudgetOnSmallLocalIntegers) {
  const std::vector<Mesh> hulls = {Box(0.1f, 1.37f, 0.9f), Box(1.37f, 2.2f, 1.7f)};
  for (double budget : {0.01, 0.001, 0.0001}) {
    Result<QuantizedHulls> q = QuantizeHulls(hulls, budget);
    ASSERT_TRUE(q.ok()) << q.status().ToString();
    ASSERT_EQ(q->grids.size(), 2u);
    EXPECT_LE(q->max_error, budget);
    EXPECT_GT(q->max_error, budget / 20);  // the grid is as coarse as the budget allows
    for (size_t h = 0; h < 2; ++h) {
      const HullGrid& g = q->grids[h];
      EXPECT_EQ(g.local.size(), hulls[h].positions.size());
      EXPECT_LE(MaxVertexDistance(hulls[h], q->decoded[h]), budget);
      EXPECT_EQ(q->decoded[h].positions, DequantizeHull(g));  // what an engine computes
      EXPECT_EQ(q->decoded[h].indices, hulls[h].indices);
      // Each hull relative to its own lowest corner: some coordinate of each axis is 0.
      for (int k = 0; k < 3; ++k) {
        uint16_t lo = 65535;
        for (size_t i = k; i < g.local.size(); i += 3) lo = std::min(lo, g.local[i]);
        EXPECT_EQ(lo, 0);
      }
      // The step is a short decimal, the same double in JSON and here.
      char text[32];
      std::snprintf(text, sizeof(text), "%.3g", g.scale);
      EXPECT_EQ(std::strtod(text, nullptr), g.scale);
    }
    // Both hulls share one grid: their common face x = 1.37 dequantizes to one value.
    EXPECT_EQ(q->decoded[0].positions[3], q->decoded[1].positions[0]);
  }
  // 8-bit coordinates at a coarse budget, more bits at a fine one.
  EXPECT_LE(QuantizeHulls(hulls, 0.01)->position_bits, 8);
  EXPECT_GT(QuantizeHulls(hulls, 0.0001)->position_bits, 8);
}

// The z extent of a decoded hull.
double Thickness(const Mesh& hull) {
  float lo = hull.positions[2], hi = hull.positions[2];
  for (size_t i = 2; i < hull.positions.size(); i += 3) {
    lo = std::min(lo, hull.positions[i]);
    hi = std::max(hi, hull.positions[i]);
  }
  return double(hi) - double(lo);
}

TEST(HullQuantize, AThinHullKeepsItsThicknessOnAFinerStep) {
  // A sheet far thinner than the budget's step, beside a thick block: the sheet would round to a
  // flat hull, which physics engines reject.
  const std::vector<Mesh> hulls = {Box(0, 1, 0.001f), Box(1, 2, 1)};
  const double budget = 0.004;
  Result<QuantizedHulls> q = QuantizeHulls(hulls, budget);
  ASSERT_TRUE(q.ok()) << q.status().ToString();
  EXPECT_LE(q->max_error, budget);
  EXPECT_NEAR(Thickness(q->decoded[0]), 0.001, 0.0003);
  EXPECT_LT(q->grids[0].scale, 0.001 / 3);
  // The block keeps the coarse step the budget allows.
  EXPECT_GT(q->grids[1].scale, 0.001);
  EXPECT_NEAR(Thickness(q->decoded[1]), 1.0, budget);
}

TEST(HullQuantize, AVeryLongThinHullStaysWithinSixteenBits) {
  // 1000 long and 0.01 thick: a quarter of its thickness would need more than 16 bits, so the
  // step is the finest that fits, and the sheet still keeps some thickness.
  Mesh sheet;
  test_shapes::AppendTo(test_shapes::Box(0, 0, 0, 1000, 1, 0.01f), &sheet);
  Result<QuantizedHulls> q = QuantizeHulls({sheet}, 1.0);
  ASSERT_TRUE(q.ok()) << q.status().ToString();
  EXPECT_LE(q->position_bits, 16);
  EXPECT_GT(Thickness(q->decoded[0]), 0.0);
}

TEST(HullQuantize, BadInputIsAnError) {
  EXPECT_FALSE(QuantizeHulls({}, 0.01).ok());
  EXPECT_FALSE(QuantizeHulls({Box(0, 1, 1)}, 0).ok());
  EXPECT_FALSE(QuantizeHulls({Box(0, 1, 1)}, 1e-7).ok());  // more than 16 bits per coordinate
}

}  // namespace
}  // namespace hullpack
