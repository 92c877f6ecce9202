// Arithmetic coder and integer binarizations.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "arithmetic_coder.h"
#include "decision_log.h"
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

// Decisions recorded into a DecisionLog and replayed after some other coding give the bytes that
// coding them there directly gives (models warming up and settled, every symbol, skewed and fair
// bits, EG values, equiprobable bits), whatever was coded before them.
TEST(ArithmeticCoder, ReplayedDecisionsCodeTheSameBytes) {
  // Models in an array the log can register (indexed records) and one it cannot.
  auto code = [](auto& coder, std::vector<SymbolModelN<8>>& contexts, std::mt19937& rng) {
    BitModel skewed, fair;
    SymbolModelN<8> gates(5);
    SymbolModelN<16> wide;
    EGModel eg;
    for (int i = 0; i < 5000; ++i) {
      coder.Encode(int(rng() % 100 < 4), skewed);
      coder.Encode(int(rng() & 1), fair);
      coder.Encode(int(rng() % 100 < 70 ? 1 : rng() % 5), gates);
      coder.Encode(int(rng() % 8), contexts[rng() % contexts.size()]);
      coder.Encode(int(rng() % 100 < 50 ? 15 : rng() % 16), wide);
      coder.EncodeBits(uint32_t(rng()), int(rng() % 33));
      EncodeEG(coder, eg, i % 131 == 0 ? (uint64_t(1) << 39) : rng() % 300);
    }
  };
  for (int prefix_bits : {0, 5, 64, 101}) {
    std::vector<uint8_t> direct, replayed;
    std::mt19937 prefix_rng(3);
    {
      ArithmeticEncoder enc(&direct);
      for (int i = 0; i < prefix_bits; ++i) enc.EncodeBits(prefix_rng() & 1, 1);
      std::mt19937 rng(11);
      std::vector<SymbolModelN<8>> contexts(300, SymbolModelN<8>(5));
      code(enc, contexts, rng);
      enc.Finish();
    }
    DecisionLog log;
    std::mt19937 rng(11);
    std::vector<SymbolModelN<8>> contexts(300, SymbolModelN<8>(5));
    log.UseModels(contexts);
    code(log, contexts, rng);
    prefix_rng.seed(3);
    ArithmeticEncoder enc(&replayed);
    for (int i = 0; i < prefix_bits; ++i) enc.EncodeBits(prefix_rng() & 1, 1);
    log.ReplayInto(&enc);
    enc.Finish();
    EXPECT_EQ(replayed, direct) << prefix_bits << " bits before";
  }
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

TEST(ArithmeticCoder, SymbolsRawBitsAndResidualsRoundTrip) {
  std::mt19937 rng(11);
  std::vector<int> symbols, bits;
  std::vector<uint32_t> raw;
  std::vector<int> raw_count;
  std::vector<int64_t> residuals;
  std::vector<uint8_t> buf;
  {
    ArithmeticEncoder enc(&buf);
    SymbolModel skewed, flat;
    SymbolModelN<8> small;
    SymbolModelN<32> large;
    BitModel bit;
    ResidualModel rm, rm_raw, rm_shift, rm_raw_shift;
    ResidualEscape rx;
    for (int i = 0; i < 20000; ++i) {
      symbols.push_back(int(rng() % 100) < 90 ? int(rng() % 3) : int(rng() % 16));
      enc.Encode(symbols.back(), skewed);
      symbols.push_back(int(rng() % 16));
      enc.Encode(symbols.back(), flat);
      symbols.push_back(int(rng() % 8));
      enc.Encode(symbols.back(), small);
      symbols.push_back(int(rng() % 32));
      enc.Encode(symbols.back(), large);
      bits.push_back(int(rng() & 1));
      enc.Encode(bits.back(), bit);
      raw_count.push_back(int(rng() % 33));
      raw.push_back(raw_count.back() ? uint32_t(rng()) >> (32 - raw_count.back()) : 0);
      enc.EncodeRaw(raw.back(), raw_count.back());
      // Mostly small, sometimes huge (escape classes), sometimes zero; with every class shift.
      const int64_t r = i % 101 == 0 ? (int64_t(1) << 38) - 3
                        : i % 5 == 1 ? int64_t(rng() % 15) - 7
                                     : int64_t(rng() % 2001) - 1000;
      residuals.push_back(i % 7 == 0 ? 0 : (i % 3 ? r : -r));
      const int shift = i % (kMaxClassShift + 1);
      EncodeResidual<false>(enc, rm, rx, residuals.back());
      EncodeResidual<true>(enc, rm_raw, rx, residuals.back());
      EncodeResidual<false>(enc, rm_shift, rx, residuals.back(), shift);
      EncodeResidual<true>(enc, rm_raw_shift, rx, residuals.back(), shift);
    }
    enc.Finish();
  }
  ArithmeticDecoder dec(buf.data(), buf.size());
  SymbolModel skewed, flat;
  SymbolModelN<8> small;
  SymbolModelN<32> large;
  BitModel bit;
  ResidualModel rm, rm_raw, rm_shift, rm_raw_shift;
  ResidualEscape rx;
  for (int i = 0; i < 20000; ++i) {
    ASSERT_EQ(dec.Decode(skewed), symbols[4 * i]);
    ASSERT_EQ(dec.Decode(flat), symbols[4 * i + 1]);
    ASSERT_EQ(dec.Decode(small), symbols[4 * i + 2]);
    ASSERT_EQ(dec.Decode(large), symbols[4 * i + 3]);
    ASSERT_EQ(dec.Decode(bit), bits[i]);
    ASSERT_EQ(dec.DecodeRaw(raw_count[i]), raw[i]);
    ASSERT_EQ(DecodeResidual<false>(dec, rm, rx), residuals[i]);
    ASSERT_EQ(DecodeResidual<true>(dec, rm_raw, rx), residuals[i]);
    const int shift = i % (kMaxClassShift + 1);
    ASSERT_EQ(DecodeShiftedResidual<false>(dec, rm_shift, rx, shift), residuals[i])
        << "shift " << shift;
    ASSERT_EQ(DecodeShiftedResidual<true>(dec, rm_raw_shift, rx, shift), residuals[i])
        << "shift " << shift;
  }
  EXPECT_FALSE(dec.failed());
}

// The SIMD and scalar builds must adapt identically (streams cross platforms): compare a model of
// N symbols against the definition, written out here.
template <int N>
void CheckSymbolModelDefinition(unsigned seed) {
  std::mt19937 rng(seed);
  SymbolModelN<N> m;
  int32_t slow[N], fast[N];
  for (int i = 0; i < N; ++i) slow[i] = fast[i] = (i + 1) * (32768 / N);
  int n = 0;
  for (int step = 0; step < 3000; ++step) {
    const int s = int(rng() % 100) < 70 ? int(rng() % 4) : int(rng() % N);
    int rate = 2;
    for (int t : {2, 6, 14, 30, 62, 126}) rate += n > t;
    n = n < 255 ? n + 1 : n;
    const int fast_rate = rate < 3 ? rate : 3;
    for (int i = 0; i < N - 1; ++i) {
      const int32_t target = i < s ? (i + 1) * 4 : 32768 - (N - 1 - i) * 4;
      slow[i] += (target - slow[i]) >> rate;
      fast[i] += (target - fast[i]) >> fast_rate;
      ASSERT_GE(slow[i] - (i ? slow[i - 1] : 0), 4);
      ASSERT_GE(fast[i] - (i ? fast[i - 1] : 0), 4);
    }
    m.Update(s);
    for (int i = 0; i < N; ++i) {
      ASSERT_EQ(m.slow[i], slow[i]) << N << " " << step << " " << i;
      ASSERT_EQ(m.fast[i], fast[i]) << N << " " << step << " " << i;
    }
    const uint32_t r = (uint32_t(rng()) >> 16) | 0x100;
    const uint32_t code = uint32_t(uint64_t(rng()) * (uint64_t(r) << 16) >> 32);
    int expected = 0;
    while (expected < N - 1 && uint64_t(r) * m.cumulative(expected) <= code) ++expected;
    uint32_t lo = 0, hi = 0;
    ASSERT_EQ(m.Find(r, code, &lo, &hi), expected) << N << " " << step;
    ASSERT_EQ(lo, expected ? m.cumulative(expected - 1) : 0u) << N << " " << step;
    ASSERT_EQ(hi, m.cumulative(expected)) << N << " " << step;
  }
}

TEST(ArithmeticCoder, SymbolModelMatchesItsDefinition) {
  CheckSymbolModelDefinition<8>(3);
  CheckSymbolModelDefinition<16>(4);
  CheckSymbolModelDefinition<32>(5);
}

TEST(ArithmeticCoder, SkewedSymbolsCostLittle) {
  std::vector<uint8_t> buf;
  ArithmeticEncoder enc(&buf);
  SymbolModel m;
  for (int i = 0; i < 100000; ++i) enc.Encode(3, m);
  enc.Finish();
  // Every other symbol keeps 2 * kMinFreq / 2^16: ~0.014 bit per decision.
  EXPECT_LT(buf.size(), 250u);
}

TEST(ArithmeticCoder, TerminationIgnoresWhatFollows) {
  // The range code decodes the same whatever bytes follow it (raw bits, padding, another stream).
  std::mt19937 rng(5);
  for (int n = 0; n < 60; ++n) {
    std::vector<uint8_t> buf;
    std::vector<int> bits;
    {
      ArithmeticEncoder enc(&buf);
      BitModel m;
      for (int i = 0; i < n * 7; ++i) {
        bits.push_back(int(rng() % 5 == 0));
        enc.Encode(bits.back(), m);
      }
      enc.Finish(buf.size() + n);  // n bytes of zero padding when needed
    }
    for (int fill : {0x00, 0xFF, 0x5A}) {
      std::vector<uint8_t> padded = buf;
      padded.insert(padded.end(), 8, uint8_t(fill));
      ArithmeticDecoder dec(padded.data(), buf.size() + (fill ? 8 : 0));
      BitModel m;
      for (size_t i = 0; i < bits.size(); ++i)
        ASSERT_EQ(dec.Decode(m), bits[i]) << n << " " << fill;
    }
  }
}

TEST(ArithmeticCoder, RawStreamReadsPastTheStartFail) {
  const uint8_t data[3] = {0x12, 0x34, 0x56};
  ArithmeticDecoder dec(data, 3);
  for (int i = 0; i < 100 && !dec.failed(); ++i) dec.DecodeRaw(32);
  EXPECT_TRUE(dec.failed());
}

}  // namespace
