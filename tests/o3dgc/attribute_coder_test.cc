// Attribute coding: the class shifts of large meshes, chosen from the residuals and sent with them.
#include <gtest/gtest.h>

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

}  // namespace
