// KeyTable: the weld table of the encoder.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <vector>

#include "key_table.h"

namespace {

using o3dgc::KeyTable;

// Against a map: every entry finds the first entry with its key, whatever the mix of repeats.
TEST(KeyTable, FindsTheFirstEntryWithTheKey) {
  std::mt19937 rng(7);
  for (const uint32_t distinct : {1u, 3u, 50u, 5000u}) {
    const size_t n = 20000;
    std::vector<uint32_t> keys(3 * n);
    for (size_t i = 0; i < n; ++i) {
      const uint32_t k = rng() % distinct;
      // Keys that differ in one word only, so that a table comparing part of a key would merge
      // them.
      keys[3 * i] = k % 7;
      keys[3 * i + 1] = 0x3F800000u;
      keys[3 * i + 2] = k / 7;
    }
    KeyTable table(keys.data(), n);
    std::map<std::array<uint32_t, 3>, uint32_t> first;
    for (uint32_t i = 0; i < n; ++i) {
      const std::array<uint32_t, 3> k = {keys[3 * i], keys[3 * i + 1], keys[3 * i + 2]};
      const uint32_t expected = first.emplace(k, i).first->second;
      ASSERT_EQ(table.FindOrInsert(i), expected) << "entry " << i << ", " << distinct << " keys";
    }
  }
}

// Entries that are never inserted (unreferenced vertices) are never found; keys compare bitwise.
TEST(KeyTable, SkipsUninsertedEntriesAndComparesBitwise) {
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, -0.0f, 0, 0};
  KeyTable table(positions.data(), 5);
  EXPECT_EQ(table.FindOrInsert(1), 1u);
  EXPECT_EQ(table.FindOrInsert(2), 2u);  // entry 0 was skipped: 2 is the first with (0, 0, 0)
  EXPECT_EQ(table.FindOrInsert(3), 1u);
  EXPECT_EQ(table.FindOrInsert(4), 4u);  // -0 and +0 differ bitwise: not welded
  EXPECT_EQ(table.FindOrInsert(0), 2u);
}

}  // namespace
