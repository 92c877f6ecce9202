// Arithmetic coder and integer binarizations.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "arithmetic_coder.h"
#include "entropy.h"

namespace {

using namespace o3dgc;

TEST(ArithmeticCoder, RoundTripsMixedSymbols) {
  std::mt19937 rng(7);
  std::vector<int> bits;
  std::vector<uint32_t> raw;
  std::vector<uint64_t> egs;
  std::vector<int64_t> signeds;
  std::vector<uint8_t> buf;
  {
    ArithmeticEncoder enc(&buf);
    BitModel skewed, fair;
    EGModel eg;
    SignedModel sm;
    for (int i = 0; i < 20000; ++i) {
      const int b = (rng() % 100) < 3;
      bits.push_back(b);
      enc.Encode(b, skewed);
      const int f = int(rng() & 1);
      bits.push_back(f);
      enc.Encode(f, fair);
      raw.push_back(rng() & 0x1FFFFF);
      enc.EncodeBits(raw.back(), 21);
      egs.push_back(i % 97 == 0 ? (uint64_t(1) << 39) + 5 : rng() % 1000);
      EncodeEG(enc, eg, egs.back());
      signeds.push_back(int64_t(rng() % 200001) - 100000);
      EncodeSigned(enc, sm, signeds.back());
    }
    enc.Finish();
  }
  ArithmeticDecoder dec(buf.data(), buf.size());
  BitModel skewed, fair;
  EGModel eg;
  SignedModel sm;
  for (int i = 0; i < 20000; ++i) {
    ASSERT_EQ(dec.Decode(skewed), bits[2 * i]);
    ASSERT_EQ(dec.Decode(fair), bits[2 * i + 1]);
    ASSERT_EQ(dec.DecodeBits(21), raw[i]);
    ASSERT_EQ(DecodeEG(dec, eg), egs[i]);
    ASSERT_EQ(DecodeSigned(dec, sm), signeds[i]);
  }
  EXPECT_FALSE(dec.failed());
}

TEST(ArithmeticCoder, SkewedBitsCostLittle) {
  std::vector<uint8_t> buf;
  ArithmeticEncoder enc(&buf);
  BitModel m;
  for (int i = 0; i < 100000; ++i) enc.Encode(0, m);
  enc.Finish();
  // Probability floor 48/65536: ~0.001 bit per decision.
  EXPECT_LT(buf.size(), 20u);
}

TEST(ArithmeticCoder, EmptyAndTinyStreams) {
  for (int n = 0; n < 40; ++n) {
    std::vector<uint8_t> buf;
    {
      ArithmeticEncoder enc(&buf);
      BitModel m;
      for (int i = 0; i < n; ++i) enc.Encode(i % 3 == 0, m);
      enc.Finish();
    }
    ArithmeticDecoder dec(buf.data(), buf.size());
    BitModel m;
    for (int i = 0; i < n; ++i) ASSERT_EQ(dec.Decode(m), i % 3 == 0) << n;
    EXPECT_FALSE(dec.failed());
  }
}

TEST(ArithmeticCoder, DecoderFailsAfterReadingFarPastTheEnd) {
  const uint8_t data[2] = {0x12, 0x34};
  ArithmeticDecoder dec(data, 2);
  for (int i = 0; i < 2000 && !dec.failed(); ++i) dec.DecodeBits(8);
  EXPECT_TRUE(dec.failed());
}

}  // namespace
