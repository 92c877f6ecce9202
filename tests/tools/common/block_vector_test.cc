#include "common/block_vector.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace hullpack {
namespace {

TEST(BlockVector, HoldsWhatIsAppendedAcrossBlocks) {
  BlockVector<uint32_t> v;
  EXPECT_TRUE(v.empty());
  const size_t n = 2 * BlockVector<uint32_t>::kBlock + 17;
  for (size_t i = 0; i < n; ++i) v.push_back(static_cast<uint32_t>(i * 7));
  ASSERT_EQ(v.size(), n);
  for (size_t i :
       {size_t{0}, BlockVector<uint32_t>::kBlock - 1, BlockVector<uint32_t>::kBlock, n - 1})
    EXPECT_EQ(v[i], static_cast<uint32_t>(i * 7));
  v[5] = 1;
  EXPECT_EQ(v[5], 1u);
}

TEST(BlockVector, ForEachVisitsInOrderAndTakeAllGivesOneArray) {
  for (size_t n : {size_t{0}, size_t{3}, BlockVector<int>::kBlock, BlockVector<int>::kBlock + 1}) {
    BlockVector<int> v;
    for (size_t i = 0; i < n; ++i) v.push_back(static_cast<int>(i));
    size_t next = 0;
    bool in_order = true;
    v.ForEach([&](int& x) {
      in_order &= x == static_cast<int>(next++);
      x += 1;
    });
    EXPECT_TRUE(in_order);
    EXPECT_EQ(next, n);
    const std::vector<int> all = v.TakeAll();
    ASSERT_EQ(all.size(), n);
    EXPECT_EQ(all.capacity(), n);
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(all[i], static_cast<int>(i) + 1);
    EXPECT_TRUE(v.empty());
  }
}

}  // namespace
}  // namespace hullpack
