// Attribute coding: the class shifts of large meshes, chosen from the residuals and sent with them;
// format 1.2's modelled low bits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "attribute_coder.h"
#include "test_meshes.h"

namespace {

using namespace o3dgc;

// Residuals of one context whose classes (0: zero, 1 + k) follow `weights` (class -> count).
void AddClasses(ClassHistograms* h, int kind, int mctx, const std::map<int, int>& weights) {
  for (const auto& [cls, count] : weights) {
    const int64_t r = cls == 0 ? 0 : int64_t(1) << (cls - 1);
    for (int i = 0; i < count; ++i) h->Add(kind, mctx, i % 2 ? r : -r);
  }
}

TEST(ClassShifts, NoneForSmallResidualsOrAnEmptyTable) {
  EXPECT_FALSE(ChooseClassShifts(ClassHistograms()).any());
  ClassHistograms h;
  // A scan's residuals (igea, 14 bits): classes up to 6 nearly always, one decision each.
  AddClasses(&h, kPredParallelogram, 7,
             {{0, 800}, {1, 900}, {2, 700}, {3, 1000}, {5, 2800}, {7, 2}});
  EXPECT_FALSE(ChooseClassShifts(h).any());
}

TEST(ClassShifts, ShiftWhereLargeClassesAreCommon) {
  ClassHistograms h;
  // rocker_arm at 14 bits, magnitude context 9: classes 5-8 most often, 27 % of them past the
  // direct classes without a shift.
  AddClasses(&h, kPredParallelogram, 9,
             {{0, 108},
              {1, 150},
              {2, 326},
              {3, 668},
              {4, 1124},
              {5, 1798},
              {6, 2284},
              {7, 2262},
              {8, 898},
              {9, 112},
              {10, 5}});
  // Mostly zeros: a shift would give them a second decision.
  AddClasses(&h, kPredParallelogram, 2, {{0, 3000}, {1, 500}, {7, 10}});
  const ClassShifts s = ChooseClassShifts(h);
  EXPECT_TRUE(s.any());
  // Second decisions: shift 0: 3277, 1: 258 + 1015, 2: 584 + 117, 3: 1252 + 5.
  EXPECT_EQ(s.shift[kPredParallelogram][9], 2);
  EXPECT_EQ(s.shift[kPredParallelogram][2], 0);
}

TEST(ClassShifts, NotWorthTheirCostWhenTheyRarelySpareADecision) {
  ClassHistograms h;
  AddClasses(&h, kPredParallelogram, 9, {{5, 100}, {7, 100}, {8, 40}});  // shift 2 spares 140
  EXPECT_TRUE(ChooseClassShifts(h).any());
  // The same among 140 * kMinShiftGain residuals that a shift cannot help.
  AddClasses(&h, kPredParallelogram, 4, {{2, int(140 * kMinShiftGain)}});
  EXPECT_FALSE(ChooseClassShifts(h).any());
}

TEST(ClassShifts, TableRoundTrips) {
  ClassShifts s;
  for (int kind = 0; kind < kPredictionKinds; ++kind) {
    for (int m = 0; m < kMagContexts; ++m)
      s.shift[kind][m] = uint8_t((kind * 5 + m) % (kMaxClassShift + 1));
  }
  std::vector<uint8_t> buf;
  ArithmeticEncoder enc(&buf);
  EncodeClassShifts(&enc, s);
  enc.Finish();
  ArithmeticDecoder dec(buf.data(), buf.size());
  ClassShifts d;
  DecodeClassShifts(&dec, &d);
  for (int kind = 0; kind < kPredictionKinds; ++kind) {
    for (int m = 0; m < kMagContexts; ++m) EXPECT_EQ(d.shift[kind][m], s.shift[kind][m]);
  }
}

TEST(ClassShifts, LargeMeshWithLargeResidualsRoundTripsThroughShifts) {
  // A 4453-vertex grid (past kRawLowBitsMesh) at 16 bits: smooth, then with noise of up to
  // +-2^7 steps, which makes residuals of classes 7-10 common: the encoder sends shifts then.
  const o3dgc_test::TestMesh grid = o3dgc_test::Grid(72, 60);
  const uint32_t n = uint32_t(grid.nv());
  ASSERT_GE(n, kRawLowBitsMesh);
  WedgeTable wedges;
  wedges.Build(grid.indices, n, o3dgc_test::OppositeCorners(grid.indices), true);
  std::mt19937 rng(5);
  for (const int noise : {0, 128}) {
    std::vector<int32_t> q(size_t(n) * 3);
    for (size_t i = 0; i < q.size(); ++i) {
      const int32_t base = int32_t(grid.positions[i] * 50000.0f) + 8000;  // within [0, 2^16)
      q[i] = base + (noise ? int32_t(rng() % uint32_t(2 * noise + 1)) - noise : 0);
    }
    std::vector<uint8_t> buf;
    {
      ArithmeticEncoder enc(&buf);
      EncodeQuantized(&enc, &wedges, q, 3, 16, Prediction::kParallelogram, CodingOrder::kGreedy);
      enc.Finish();
    }
    ArithmeticDecoder table(buf.data(), buf.size());
    ClassShifts sent;
    DecodeClassShifts(&table, &sent);
    EXPECT_EQ(sent.any(), noise != 0) << "noise " << noise;
    ArithmeticDecoder dec(buf.data(), buf.size());
    std::vector<int32_t> decoded;
    ASSERT_EQ(DecodeQuantized(&dec, &wedges, n, 3, 16, Prediction::kParallelogram,
                              CodingOrder::kGreedy, &decoded),
              Status::kOk);
    EXPECT_EQ(decoded, q) << "noise " << noise;
  }
}

// The encoder's first pass over the residuals assumes the parallelogram selection is used or not
// (EncodeQuantized's expect_selection); the bytes are the same either way, on a smooth noisy grid
// (no selection) and on a CAD-like plate (selection), each guessed right and wrong.
TEST(ParallelogramSelection, TheExpectationChangesNoByte) {
  const o3dgc_test::TestMesh grid = o3dgc_test::Grid(72, 60);
  const o3dgc_test::TestMesh plate = o3dgc_test::PocketPlate(12, 10);
  std::mt19937 rng(9);
  for (const o3dgc_test::TestMesh* t : {&grid, &plate}) {
    const uint32_t n = uint32_t(t->nv());
    WedgeTable wedges;
    wedges.Build(t->indices, n, o3dgc_test::OppositeCorners(t->indices), true);
    std::vector<int32_t> q(size_t(n) * 3);
    for (size_t i = 0; i < q.size(); ++i) {
      q[i] = int32_t(std::lround(t->positions[i] * 1000.0f)) + 20000;
      if (t == &grid) q[i] += int32_t(rng() % 9) - 4;
    }
    bool selects = false;
    EstimatePositionBits(wedges, q, 16, CodingOrder::kGreedy, &selects);
    EXPECT_EQ(selects, t == &plate);
    std::vector<uint8_t> bytes[2];
    for (const bool expect : {false, true}) {
      ArithmeticEncoder enc(&bytes[expect]);
      EncodeQuantized(&enc, &wedges, q, 3, 16, Prediction::kParallelogram, CodingOrder::kGreedy,
                      nullptr, LowBits::kNoFlag, expect);
      enc.Finish();
    }
    EXPECT_EQ(bytes[0], bytes[1]) << (t == &grid ? "grid" : "plate");
  }
}

// Positions of a grid-built model (GridBlocks) quantized so that the grid step is 937 steps: the
// residuals are a few multiples of it, whose low bits recur.
std::vector<int32_t> GridQuantized(const o3dgc_test::TestMesh& t) {
  std::vector<int32_t> q(t.positions.size());
  for (size_t i = 0; i < q.size(); ++i) q[i] = int32_t(std::lround(t.positions[i] / 0.7 * 937)) + 5;
  return q;
}

size_t CodedBytes(const WedgeTable& wedges, const std::vector<int32_t>& q, LowBits low_bits) {
  std::vector<uint8_t> buf;
  ArithmeticEncoder enc(&buf);
  EncodeQuantized(&enc, &wedges, q, 3, 16, Prediction::kParallelogram, CodingOrder::kGreedy,
                  nullptr, low_bits);
  enc.Finish();
  return buf.size();
}

TEST(ModelledLowBits, RoundTripEachChoiceAndSmallerOnAGrid) {
  const o3dgc_test::TestMesh t = o3dgc_test::GridBlocks(6, 5);
  const uint32_t n = uint32_t(t.nv());
  WedgeTable wedges;
  wedges.Build(t.indices, n, o3dgc_test::OppositeCorners(t.indices), true);
  const std::vector<int32_t> q = GridQuantized(t);
  for (const LowBits low : {LowBits::kNoFlag, LowBits::kPlain, LowBits::kModelled}) {
    std::vector<uint8_t> buf;
    ArithmeticEncoder enc(&buf);
    EncodeQuantized(&enc, &wedges, q, 3, 16, Prediction::kParallelogram, CodingOrder::kGreedy,
                    nullptr, low);
    enc.Finish();
    ArithmeticDecoder dec(buf.data(), buf.size());
    std::vector<int32_t> decoded;
    ASSERT_EQ(DecodeQuantized(&dec, &wedges, n, 3, 16, Prediction::kParallelogram,
                              CodingOrder::kGreedy, &decoded, nullptr, low != LowBits::kNoFlag),
              Status::kOk);
    EXPECT_EQ(decoded, q) << int(low);
  }
  EXPECT_LT(CodedBytes(wedges, q, LowBits::kModelled), CodedBytes(wedges, q, LowBits::kPlain));
}

TEST(ModelledLowBits, DifferentialValuesRoundTrip) {
  // Residuals of every class, the large ones past kTreeMaxK (coded as without trees).
  std::mt19937 rng(3);
  const uint32_t n = 700;
  std::vector<int32_t> q(size_t(n) * 2);
  for (size_t i = 0; i < q.size(); ++i) q[i] = int32_t(rng() >> (rng() % 32 + 2)) & 0x3FFFFFF;
  std::vector<uint8_t> buf;
  ArithmeticEncoder enc(&buf);
  EncodeQuantized(&enc, nullptr, q, 2, 26, Prediction::kDifferential, CodingOrder::kGreedy, nullptr,
                  LowBits::kModelled);
  enc.Finish();
  ArithmeticDecoder dec(buf.data(), buf.size());
  std::vector<int32_t> decoded;
  ASSERT_EQ(DecodeQuantized(&dec, nullptr, n, 2, 26, Prediction::kDifferential,
                            CodingOrder::kGreedy, &decoded, nullptr, true),
            Status::kOk);
  EXPECT_EQ(decoded, q);
}

TEST(ModelledLowBits, OnlyWhereTheFormatOffersIt) {
  EXPECT_TRUE(HasLowBitsChoice(Prediction::kParallelogram, 100, 3, false));
  EXPECT_TRUE(HasLowBitsChoice(Prediction::kParallelogram, 100, 2, true));
  EXPECT_TRUE(HasLowBitsChoice(Prediction::kDifferential, 100, 4, false));
  EXPECT_FALSE(HasLowBitsChoice(Prediction::kParallelogram, 100, 2, false));
  EXPECT_FALSE(HasLowBitsChoice(Prediction::kNone, 100, 3, false));
  EXPECT_FALSE(HasLowBitsChoice(Prediction::kParallelogram, kRawLowBitsMesh, 3, false));
}

}  // namespace
