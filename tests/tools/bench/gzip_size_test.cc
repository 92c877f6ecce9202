#include "bench/gzip_size.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace hullpack {
namespace {

TEST(GzipSize, EmptyInputIsHeaderEmptyBlockAndTrailer) {
  // 10-byte header without a name, a 2-byte final empty block, 8-byte CRC and length.
  EXPECT_EQ(GzipSize(nullptr, 0), 20u);
}

TEST(GzipSize, RepetitiveInputShrinksAndRandomInputDoesNot) {
  const std::vector<uint8_t> zeros(10000, 0);
  EXPECT_LT(GzipSize(zeros.data(), zeros.size()), 100u);
  std::mt19937 rng(7);
  std::vector<uint8_t> noise(10000);
  for (uint8_t& b : noise) b = static_cast<uint8_t>(rng());
  const size_t gz = GzipSize(noise.data(), noise.size());
  EXPECT_GE(gz, noise.size());
  EXPECT_LT(gz, noise.size() + 64);
}

TEST(GzipSize, SevenBitTextCostsAboutSevenBitsPerByte) {
  // Uniform 7-bit bytes: a dynamic Huffman code gives back the unused eighth bit.
  std::mt19937 rng(11);
  std::vector<uint8_t> ascii(20000);
  for (uint8_t& b : ascii) b = static_cast<uint8_t>(rng() & 0x7F);
  const size_t gz = GzipSize(ascii.data(), ascii.size());
  EXPECT_LT(gz, ascii.size() * 7 / 8 + 200);
  EXPECT_GT(gz, ascii.size() * 7 / 8 - 200);
}

}  // namespace
}  // namespace hullpack
