// 7-bit packing.
#include <gtest/gtest.h>

#include <random>

#include "ascii_stream.h"

namespace {

using namespace o3dgc;

TEST(AsciiStream, PackUnpackAllLengths) {
  std::mt19937 rng(3);
  for (size_t n = 0; n < 64; ++n) {
    std::vector<uint8_t> bin(n);
    for (auto& b : bin) b = uint8_t(rng());
    const auto asc = PackAscii(bin);
    EXPECT_TRUE(IsAsciiStream(asc.data(), asc.size()));
    for (uint8_t c : asc) ASSERT_LT(c, 128);
    EXPECT_EQ(asc.size(), 4 + (n * 8 + 6) / 7);
    std::vector<uint8_t> back;
    ASSERT_EQ(UnpackAscii(asc.data(), asc.size(), &back), Status::kOk);
    EXPECT_EQ(back, bin);
  }
}

TEST(AsciiStream, RejectsHighBytes) {
  auto asc = PackAscii(std::vector<uint8_t>(10, 0xAB));
  asc[6] |= 0x80;
  std::vector<uint8_t> back;
  EXPECT_EQ(UnpackAscii(asc.data(), asc.size(), &back), Status::kCorrupt);
}

}  // namespace
