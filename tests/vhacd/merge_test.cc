#include "merge.h"

#include <gtest/gtest.h>

#include "test_hulls.h"

namespace vhacd {
namespace internal {
namespace {

TEST(MergeTest, MergesTouchingBoxesButNotAnLShape) {
  Context ctx(nullptr, 2);
  MergeParams mp;
  mp.volume0 = 8.0;
  std::vector<HullMesh> hulls = {BoxHull(0, 0, 0, 1, 1, 1), BoxHull(1, 0, 0, 2, 1, 1)};
  ASSERT_TRUE(MergeHulls(&hulls, mp, &ctx));
  ASSERT_EQ(hulls.size(), 1u);
  EXPECT_NEAR(hulls[0].Volume(), 2.0, 1e-12);
  // An L: merging adds a unit of empty volume (cost 1/8 > gamma).
  hulls = {BoxHull(0, 0, 0, 2, 1, 1), BoxHull(0, 1, 0, 1, 2, 1)};
  ASSERT_TRUE(MergeHulls(&hulls, mp, &ctx));
  EXPECT_EQ(hulls.size(), 2u);
  // Far apart: never merged under gamma, but merged to meet a budget.
  hulls = {BoxHull(0, 0, 0, 1, 1, 1), BoxHull(5, 0, 0, 6, 1, 1), BoxHull(0, 5, 0, 1, 6, 1)};
  ASSERT_TRUE(MergeHulls(&hulls, mp, &ctx));
  EXPECT_EQ(hulls.size(), 3u);
  mp.max_hulls = 1;
  ASSERT_TRUE(MergeHulls(&hulls, mp, &ctx));
  EXPECT_EQ(hulls.size(), 1u);
  EXPECT_NEAR(hulls[0].Volume(), 23.5, 1e-9);  // hull of the three boxes
}

TEST(MergeTest, HullsOfDifferentGroupsMergeOnlyForTheBudget) {
  Context ctx(nullptr, 2);
  MergeParams mp;
  mp.volume0 = 8.0;
  // Touching boxes (a free merge) of two groups stay apart; of one group they merge.
  const std::vector<uint32_t> two = {0, 1}, one = {3, 3};
  std::vector<HullMesh> hulls = {BoxHull(0, 0, 0, 1, 1, 1), BoxHull(1, 0, 0, 2, 1, 1)};
  mp.groups = &two;
  ASSERT_TRUE(MergeHulls(&hulls, mp, &ctx));
  EXPECT_EQ(hulls.size(), 2u);
  mp.groups = &one;
  ASSERT_TRUE(MergeHulls(&hulls, mp, &ctx));
  EXPECT_EQ(hulls.size(), 1u);
  // A budget merges across groups.
  hulls = {BoxHull(0, 0, 0, 1, 1, 1), BoxHull(1, 0, 0, 2, 1, 1)};
  mp.groups = &two;
  mp.max_hulls = 1;
  ASSERT_TRUE(MergeHulls(&hulls, mp, &ctx));
  ASSERT_EQ(hulls.size(), 1u);
  EXPECT_NEAR(hulls[0].Volume(), 2.0, 1e-12);
}

TEST(MergeTest, MergedHullContainsBoth) {
  const HullMesh a = BoxHull(0, 0, 0, 1, 1, 1), b = BoxHull(2, 2, 2, 3, 3, 3);
  const HullMesh m = MergedHull(a, b);
  HullPlanes hp(m);
  for (const Vec3& p : a.vertices) EXPECT_LE(hp.SignedDistanceBound(p), 1e-9);
  for (const Vec3& p : b.vertices) EXPECT_LE(hp.SignedDistanceBound(p), 1e-9);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
