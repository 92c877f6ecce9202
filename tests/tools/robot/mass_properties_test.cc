#include "robot/mass_properties.h"

#include <gtest/gtest.h>

#include "common/test_shapes.h"

namespace hullpack {
namespace {

Mesh Box(double x0, double y0, double z0, double x1, double y1, double z1) {
  Mesh m;
  test_shapes::AppendTo(test_shapes::Box(x0, y0, z0, x1, y1, z1), &m);
  return m;
}

TEST(MassProperties, BoxIsExact) {
  Result<MassProperties> r = HullUnionMassProperties({Box(1, 2, 3, 3, 3, 4)}, 10);  // 2 x 1 x 1
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_NEAR(r->volume, 2, 1e-9);
  EXPECT_NEAR(r->mass, 20, 1e-9);
  EXPECT_NEAR(r->center[0], 2, 1e-9);
  EXPECT_NEAR(r->center[1], 2.5, 1e-9);
  EXPECT_NEAR(r->center[2], 3.5, 1e-9);
  // Solid cuboid: I_xx = m (b^2 + c^2) / 12.
  EXPECT_NEAR(r->inertia[0], 20 * (1 + 1) / 12.0, 1e-9);
  EXPECT_NEAR(r->inertia[1], 20 * (4 + 1) / 12.0, 1e-9);
  EXPECT_NEAR(r->inertia[2], 20 * (4 + 1) / 12.0, 1e-9);
  for (int i = 3; i < 6; ++i) EXPECT_NEAR(r->inertia[i], 0, 1e-9);
}

TEST(MassProperties, TouchingHullsAddUp) {
  Result<MassProperties> r =
      HullUnionMassProperties({Box(0, 0, 0, 1, 1, 1), Box(1, 0, 0, 2, 1, 1)}, 1);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r->volume, 2, 1e-9);
  EXPECT_NEAR(r->center[0], 1, 1e-9);
  EXPECT_NEAR(r->inertia[1], (4 + 1) / 12.0 * 2, 1e-9);
}

TEST(MassProperties, OverlapsAreCountedOnce) {
  // Two unit cubes overlapping by half: the union is 1.5 x 1 x 1.
  Result<MassProperties> r =
      HullUnionMassProperties({Box(0, 0, 0, 1, 1, 1), Box(0.5, 0, 0, 1.5, 1, 1)}, 1);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r->volume, 1.5, 0.01);
  EXPECT_NEAR(r->center[0], 0.75, 0.005);
  EXPECT_NEAR(r->inertia[2], 1.5 * (2.25 + 1) / 12.0, 0.01);
  // Plain sums would give volume 2.
  Result<MassProperties> same =
      HullUnionMassProperties({Box(0, 0, 0, 1, 1, 1), Box(0, 0, 0, 1, 1, 1)}, 1);
  ASSERT_TRUE(same.ok());
  EXPECT_NEAR(same->volume, 1, 0.01);
}

TEST(MassProperties, RejectsBadInput) {
  EXPECT_FALSE(HullUnionMassProperties({}, 1).ok());
  EXPECT_FALSE(HullUnionMassProperties({Box(0, 0, 0, 1, 1, 1)}, 0).ok());
  Mesh inside_out = Box(0, 0, 0, 1, 1, 1);
  for (size_t t = 0; t < inside_out.indices.size(); t += 3)
    std::swap(inside_out.indices[t + 1], inside_out.indices[t + 2]);
  Result<MassProperties> r = HullUnionMassProperties({inside_out}, 1);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("no volume"), std::string::npos);
}

}  // namespace
}  // namespace hullpack
