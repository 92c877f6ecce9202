// Per-vertex arrays of original Open3DGC streams on a tetrahedron, sections built in code in both
// encodings: predictor candidates and their order, the coded choice, residuals, dequantization.
#include <gtest/gtest.h>

#include <vector>

#include "legacy_attribute_decoder.h"
#include "legacy_test_encoder.h"

namespace {

using namespace o3dgc;
using legacy_test::TestEncoder;
using legacy_test::Writer;

// Triangles as TFAN decodes the tetrahedron.
const std::vector<uint32_t> kTetra = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 2, 3};

// One residual per vertex (dimension 1): `choice` < 0 when the vertex has fewer than two
// candidates (no choice coded).
struct Coded {
  uint64_t residual;  // unsigned for vertex 0, zigzag otherwise
  int choice;
};

std::vector<uint8_t> Section(LegacyEncoding enc, uint8_t mode, const std::vector<Coded>& values) {
  Writer w{enc, {}};
  w.U32(0);
  const bool ascii = enc == LegacyEncoding::kAscii;
  w.U8(uint8_t(((ascii ? 5 : 4) << 4) | mode));
  if (ascii) {
    for (const Coded& c : values) w.AsciiUInt(c.residual);
    w.PatchU32(0, uint32_t(w.out.size()));
    const size_t choices = w.out.size();
    w.U32(0);
    for (const Coded& c : values) {
      if (c.choice >= 0) w.U8(uint8_t(c.choice));
    }
    w.PatchU32(choices, uint32_t(w.out.size() - choices));
  } else {
    constexpr uint32_t kM = 32;
    TestEncoder e;
    LegacyStaticBitModel bits;
    LegacyAdaptiveBitModel prefix;
    e.EncodeExpGolomb(0, 0, bits, prefix);   // Exp-Golomb order
    e.EncodeExpGolomb(kM, 0, bits, prefix);  // escape symbol M
    LegacyAdaptiveDataModel values_model, choice_model;
    values_model.Init(kM + 2);
    choice_model.Init(3);
    for (const Coded& c : values) {
      if (c.choice >= 0) e.Encode(uint32_t(c.choice), choice_model);
      if (c.residual < kM) {
        e.Encode(uint32_t(c.residual), values_model);
      } else {
        e.Encode(kM, values_model);
        e.EncodeExpGolomb(uint32_t(c.residual - kM), 0, bits, prefix);
      }
    }
    const std::vector<uint8_t> coded = e.Finish();
    w.out.insert(w.out.end(), coded.begin(), coded.end());
    w.PatchU32(0, uint32_t(w.out.size()));
  }
  w.U8(0x5A);  // the next section
  return w.out;
}

uint64_t Zig(int64_t v) { return v < 0 ? uint64_t(-1 - 2 * v) : uint64_t(2 * v); }

LegacyArrayDesc Desc(float min, float max, int bits) {
  LegacyArrayDesc d;
  d.count = 4;
  d.dimension = 1;
  d.bits = bits;
  d.min[0] = min;
  d.max[0] = max;
  return d;
}

TEST(LegacyAttribute, ParallelogramCandidatesAndChoice) {
  // Quantized values 10, 12, 7, 20. Vertex 1 has one candidate (vertex 0): predicted by vertex
  // 0 as "the previous vertex". Vertex 2: neighbours 0 and 1, choice 1 -> 12. Vertex 3: the
  // parallelograms (0,1 | 2) -> 10+12-7 and (0,2 | 1) -> 10+7-12 come before any neighbour
  // (ordered by the opposite vertex, largest first); choice 1 -> 5.
  const std::vector<Coded> coded = {{10, -1}, {Zig(2), -1}, {Zig(7 - 12), 1}, {Zig(20 - 5), 1}};
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    const std::vector<uint8_t> bytes = Section(enc, 5, coded);
    LegacyReader r(bytes.data(), bytes.size(), enc);
    LegacyAttributeDecoder dec(&r, kTetra, 4);
    std::vector<float> out;
    // 8 bits over [0, 255]: a cell size of exactly 1.
    ASSERT_EQ(dec.DecodeFloats(Desc(0.0f, 255.0f, 8), &out), Status::kOk);
    EXPECT_EQ(out, (std::vector<float>{10, 12, 7, 20}));
    EXPECT_EQ(r.pos(), bytes.size() - 1);
  }
}

TEST(LegacyAttribute, DifferentialAndDequantization) {
  // Mode 1: vertex 3's candidates are its neighbours 0 and 1 (the two smallest ids); choice 0.
  const std::vector<Coded> coded = {{10, -1}, {Zig(2), -1}, {Zig(-5), 1}, {Zig(10), 0}};
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    const std::vector<uint8_t> bytes = Section(enc, 1, coded);
    LegacyReader r(bytes.data(), bytes.size(), enc);
    LegacyAttributeDecoder dec(&r, kTetra, 4);
    std::vector<float> out;
    ASSERT_EQ(dec.DecodeFloats(Desc(-1.0f, 1.0f, 4), &out), Status::kOk);
    // q * (2 / 15) - 1 in float.
    const float step = 2.0f / 15.0f;
    EXPECT_EQ(out, (std::vector<float>{10 * step - 1, 12 * step - 1, 7 * step - 1, 20 * step - 1}));
    // The same section as int values.
    LegacyReader ri(bytes.data(), bytes.size(), enc);
    LegacyAttributeDecoder deci(&ri, kTetra, 4);
    std::vector<int32_t> ints;
    ASSERT_EQ(deci.DecodeInts(Desc(0, 0, 0), &ints), Status::kOk);
    EXPECT_EQ(ints, (std::vector<int32_t>{10, 12, 7, 20}));
  }
}

TEST(LegacyAttribute, RejectsBadSections) {
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    std::vector<float> out;
    // A choice naming a third candidate (only two are kept).
    const std::vector<uint8_t> pick = Section(enc, 1, {{10, -1}, {2, -1}, {1, 2}, {1, 0}});
    LegacyReader r(pick.data(), pick.size(), enc);
    LegacyAttributeDecoder dec(&r, kTetra, 4);
    EXPECT_EQ(dec.DecodeFloats(Desc(0, 1, 8), &out), Status::kCorrupt);
    // Surface-normal prediction outside the normals.
    const std::vector<uint8_t> surf = Section(enc, 6, {{10, -1}, {2, -1}, {1, 0}, {1, 0}});
    LegacyReader rs(surf.data(), surf.size(), enc);
    LegacyAttributeDecoder decs(&rs, kTetra, 4);
    EXPECT_EQ(decs.DecodeFloats(Desc(0, 1, 8), &out), Status::kUnsupported);
    // Zero quantization bits (the original divides by 2^0 - 1).
    const std::vector<uint8_t> ok = Section(enc, 1, {{10, -1}, {2, -1}, {1, 0}, {1, 0}});
    LegacyReader rz(ok.data(), ok.size(), enc);
    LegacyAttributeDecoder decz(&rz, kTetra, 4);
    EXPECT_EQ(decz.DecodeFloats(Desc(0, 1, 0), &out), Status::kCorrupt);
    for (size_t n = 0; n + 1 < ok.size(); ++n) {
      LegacyReader rt(ok.data(), n, enc);
      LegacyAttributeDecoder dect(&rt, kTetra, 4);
      EXPECT_NE(dect.DecodeFloats(Desc(0, 1, 8), &out), Status::kOk) << n;
    }
  }
}

}  // namespace
