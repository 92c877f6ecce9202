// The FastAC-compatible decoder of original Open3DGC streams: model arithmetic checked against
// hand-computed values, and round trips through a test-side encoder (the encoding half of the
// same range coder) over long, skewed and mixed symbol sequences.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "legacy_arithmetic_decoder.h"
#include "legacy_test_encoder.h"

namespace {

using namespace o3dgc;
using legacy_test::TestEncoder;

TEST(LegacyArithmeticDecoder, BitModelUpdateFollowsTheCounts) {
  // Four zeros, then the first re-estimate: p0 = 5/6 in 1/8192, computed as the original does
  // (0x80000000 / 6 * 5 >> 18 = 6826); the next period is 4 * 5 / 4 = 5 bits.
  const std::vector<uint8_t> zeros(16, 0);
  LegacyArithmeticDecoder dec(zeros.data(), 0, zeros.size(), zeros.size());
  LegacyAdaptiveBitModel m;
  for (int i = 0; i < 4; ++i) EXPECT_EQ(dec.Decode(m), 0u);
  EXPECT_EQ(m.bit_0_prob, 6826u);
  EXPECT_EQ(m.update_cycle, 5u);
  EXPECT_EQ(m.bits_until_update, 5u);
}

TEST(LegacyArithmeticDecoder, DataModelStartsUniform) {
  LegacyAdaptiveDataModel m;
  ASSERT_TRUE(m.Init(4));
  for (uint32_t s = 0; s < 4; ++s) EXPECT_EQ(m.Low(s), s * 8192u);
  EXPECT_FALSE(m.Init(1));
  EXPECT_FALSE(m.Init(2049));
  EXPECT_TRUE(m.Init(2048));
}

TEST(LegacyArithmeticDecoder, RoundTripsMixedModels) {
  std::mt19937 rng(7);
  for (uint32_t symbols : {2u, 3u, 12u, 17u, 300u, 2048u}) {
    // Skewed data (long runs of one symbol drive the models to their extreme probabilities and
    // past the count rescaling), then uniform data.
    std::vector<uint32_t> data, bits, eg;
    for (int i = 0; i < 40000; ++i) {
      data.push_back(i < 20000 ? (rng() % 50 == 0 ? rng() % symbols : 0) : rng() % symbols);
      bits.push_back(i < 30000 ? (rng() % 100 == 0) : rng() & 1);
      eg.push_back(i % 3 == 0 ? rng() % 100000 : rng() % 4);
    }
    TestEncoder enc;
    LegacyAdaptiveDataModel em;
    ASSERT_TRUE(em.Init(symbols));
    LegacyAdaptiveBitModel eb, eprefix;
    LegacyStaticBitModel estatic;
    for (size_t i = 0; i < data.size(); ++i) {
      enc.Encode(data[i], em);
      enc.Encode(bits[i], eb);
      enc.EncodeExpGolomb(eg[i], 0, estatic, eprefix);
    }
    const std::vector<uint8_t> bytes = enc.Finish();
    // The decoder reads past its section into whatever follows: garbage must not matter.
    std::vector<uint8_t> stream = bytes;
    stream.insert(stream.end(), {0xAB, 0xCD, 0xEF, 0x12});
    LegacyArithmeticDecoder dec(stream.data(), 0, bytes.size(), stream.size());
    LegacyAdaptiveDataModel dm;
    ASSERT_TRUE(dm.Init(symbols));
    LegacyAdaptiveBitModel db, dprefix;
    LegacyStaticBitModel dstatic;
    for (size_t i = 0; i < data.size(); ++i) {
      ASSERT_EQ(dec.Decode(dm), data[i]) << symbols << " at " << i;
      ASSERT_EQ(dec.Decode(db), bits[i]) << i;
      uint32_t v = 0;
      ASSERT_TRUE(dec.DecodeExpGolomb(0, dstatic, dprefix, &v));
      ASSERT_EQ(v, eg[i]) << i;
    }
    EXPECT_FALSE(dec.failed());
  }
}

TEST(LegacyArithmeticDecoder, ExpGolombOrderIsBounded) {
  // All-ones bytes make every prefix bit a 1: the order would pass 31 (the original shifts an
  // int by it); the decoder refuses instead.
  const std::vector<uint8_t> ones(64, 0xFF);
  LegacyArithmeticDecoder dec(ones.data(), 0, ones.size(), ones.size());
  LegacyStaticBitModel bits;
  LegacyAdaptiveBitModel prefix;
  uint32_t v = 12345;
  EXPECT_FALSE(dec.DecodeExpGolomb(0, bits, prefix, &v));
  EXPECT_EQ(v, 12345u);
}

TEST(LegacyArithmeticDecoder, ReadingFarPastTheSectionFails) {
  std::vector<uint8_t> bytes(6, 0x5A);
  LegacyArithmeticDecoder dec(bytes.data(), 0, 2, bytes.size());
  LegacyStaticBitModel m;
  EXPECT_FALSE(dec.failed());  // 4 bytes read: 2 past the section, within the allowance
  for (int i = 0; i < 200 && !dec.failed(); ++i) dec.Decode(m);
  EXPECT_TRUE(dec.failed());
}

}  // namespace
