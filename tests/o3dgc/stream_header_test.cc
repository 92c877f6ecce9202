// Stream header and CRC32.
#include "stream_header.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace o3dgc {
namespace {

uint32_t BytewiseCrc32(const uint8_t* data, size_t size) {
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc & 1) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
  }
  return ~crc;
}

TEST(StreamHeader, Crc32CheckValue) {
  const uint8_t text[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(Crc32(text, sizeof(text)), 0xCBF43926u);  // the CRC-32 check value
  EXPECT_EQ(Crc32(text, 0), 0u);
}

TEST(StreamHeader, Crc32MatchesBitwiseDefinition) {
  std::mt19937 rng(7);
  std::vector<uint8_t> data(300);
  for (uint8_t& b : data) b = uint8_t(rng());
  for (size_t size = 0; size <= data.size(); ++size) {
    ASSERT_EQ(Crc32(data.data(), size), BytewiseCrc32(data.data(), size)) << size;
  }
  // Continued over two calls: the same as one.
  EXPECT_EQ(Crc32(data.data() + 13, 200, Crc32(data.data(), 13)), Crc32(data.data(), 213));
}

}  // namespace
}  // namespace o3dgc
