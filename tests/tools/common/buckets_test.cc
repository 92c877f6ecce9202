#include "common/buckets.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace hullpack {
namespace {

TEST(BucketBy, GroupsIdsByKeyInAscendingOrderAndLeavesOutTheSkipped) {
  const std::vector<uint32_t> keys = {2, 0, kNoBucket, 2, 0, 3, 2};
  const Buckets b = BucketBy(keys.size(), 5, [&](size_t i) { return keys[i]; });
  EXPECT_EQ(b.start, (std::vector<uint32_t>{0, 2, 2, 5, 6, 6}));
  EXPECT_EQ(b.ids, (std::vector<uint32_t>{1, 4, 0, 3, 6, 5}));
}

TEST(BucketBy, NothingToGroup) {
  const Buckets b = BucketBy(0, 3, [](size_t) { return 0u; });
  EXPECT_EQ(b.start, (std::vector<uint32_t>{0, 0, 0, 0}));
  EXPECT_TRUE(b.ids.empty());
}

}  // namespace
}  // namespace hullpack
