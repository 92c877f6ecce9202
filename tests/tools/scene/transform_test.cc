#include "scene/transform.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hullpack {
namespace {

Trs Rotated(double angle, double ax, double ay, double az) {
  const double n = std::sqrt(ax * ax + ay * ay + az * az);
  Trs trs;
  trs.rotation = {std::sin(angle / 2) * ax / n, std::sin(angle / 2) * ay / n,
                  std::sin(angle / 2) * az / n, std::cos(angle / 2)};
  return trs;
}

TEST(Transform, TrsMatrixComposesTranslationRotationScale) {
  Trs trs = Rotated(M_PI / 2, 0, 0, 1);  // a quarter turn about z
  trs.translation = {1, 2, 3};
  trs.scale = {2, 1, 1};
  const Matrix4 m = TrsMatrix(trs);
  // The scaled x axis (2, 0, 0) turns into (0, 2, 0), then moves by the translation.
  EXPECT_NEAR(m[0], 0, 1e-12);
  EXPECT_NEAR(m[1], 2, 1e-12);
  EXPECT_NEAR(m[4], -1, 1e-12);
  EXPECT_NEAR(m[10], 1, 1e-12);
  EXPECT_EQ(m[12], 1);
  EXPECT_EQ(m[13], 2);
  EXPECT_EQ(m[14], 3);
}

TEST(Transform, DecomposeMatrixInvertsTrsMatrix) {
  for (const Trs& start : {Rotated(0.3, 1, 2, 3), Rotated(3.0, -1, 0.5, 0.2),
                           Rotated(M_PI, 0, 1, 0), Rotated(M_PI - 1e-9, 1, 0, 0)}) {
    Trs trs = start;
    trs.translation = {-4, 0.5, 7};
    trs.scale = {0.5, 3, 1.25};
    Trs back;
    ASSERT_TRUE(DecomposeMatrix(TrsMatrix(trs), &back));
    const Matrix4 a = TrsMatrix(trs), b = TrsMatrix(back);
    for (size_t k = 0; k < 16; ++k) EXPECT_NEAR(a[k], b[k], 1e-9) << k;
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(back.scale[k], trs.scale[k], 1e-9);
  }
}

TEST(Transform, AMirrorBecomesANegativeScale) {
  Matrix4 m = kIdentity;
  m[10] = -1;  // z mirrored
  Trs trs;
  ASSERT_TRUE(DecomposeMatrix(m, &trs));
  const Matrix4 back = TrsMatrix(trs);
  for (size_t k = 0; k < 16; ++k) EXPECT_NEAR(back[k], m[k], 1e-12) << k;
  EXPECT_LT(trs.scale[0], 0);
}

TEST(Transform, ShearZeroScaleAndProjectionAreRefused) {
  Matrix4 shear = kIdentity;
  shear[4] = 0.5;  // y axis leans towards x
  Matrix4 flat = kIdentity;
  flat[5] = 0;
  Matrix4 projective = kIdentity;
  projective[3] = 0.1;
  Trs trs;
  EXPECT_FALSE(DecomposeMatrix(shear, &trs));
  EXPECT_FALSE(DecomposeMatrix(flat, &trs));
  EXPECT_FALSE(DecomposeMatrix(projective, &trs));
}

}  // namespace
}  // namespace hullpack
