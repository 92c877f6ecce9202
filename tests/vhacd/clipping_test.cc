#include "clipping.h"

#include <gtest/gtest.h>

namespace vhacd {
namespace internal {
namespace {

TEST(ClippingTest, LSplitsIntoTwoConvexParts) {
  Part p;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x)
        if (x < 8 || y < 8) {
          Voxel v;
          v.c[0] = static_cast<uint16_t>(x + 1);
          v.c[1] = static_cast<uint16_t>(y + 1);
          v.c[2] = static_cast<uint16_t>(z + 1);
          v.surface = 0;
          p.voxels.push_back(v);
        }
  const size_t total = p.voxels.size();
  Context ctx(nullptr, 2);
  ClipParams cp;
  ClipOutput out;
  ASSERT_TRUE(ClipRecursively(p, cp, &ctx, &out));
  ASSERT_EQ(out.parts.size(), 2u);
  size_t sum = 0;
  for (size_t i = 0; i < out.parts.size(); ++i) {
    sum += out.parts[i].voxels.size();
    EXPECT_LE(out.concavity[i], cp.concavity);
  }
  EXPECT_EQ(sum, total);
  EXPECT_NEAR(out.volume0, 4.0 * (256 - 32), 1e-9);
  // depth 1 stops after one cut even when more would help; a convex block is never cut.
  Part block;
  for (int x = 0; x < 10; ++x) {
    Voxel v;
    v.c[0] = static_cast<uint16_t>(x + 1);
    v.c[1] = v.c[2] = 1;
    v.surface = 1;
    block.voxels.push_back(v);
  }
  ASSERT_TRUE(ClipRecursively(block, cp, &ctx, &out));
  EXPECT_EQ(out.parts.size(), 1u);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
