// Fields and header of original Open3DGC streams, on hand-built bytes in both encodings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "legacy_stream_reader.h"
#include "legacy_test_encoder.h"

namespace {

using namespace o3dgc;
using legacy_test::Writer;

// A header: 3 coords, 1 triangle, one 2D texcoord attribute, one 4D int attribute.
std::vector<uint8_t> Header(LegacyEncoding enc, float nan_at_max = 0) {
  Writer w{enc, {}};
  w.U32(kLegacyStartCode);
  w.U32(0);  // stream size, patched below
  w.U8(2);   // TFAN
  w.F32(0.5f);
  w.U8(1);
  w.U32(3);  // coords
  w.U32(0);  // normals
  w.U32(1);  // float attributes
  w.U32(1);  // int attributes
  w.U32(1);  // triangles
  for (int j = 0; j < 3; ++j) {
    w.F32(-1.0f - j);
    w.F32(j == 2 && nan_at_max != 0 ? nan_at_max : 2.0f + j);
  }
  w.U8(14);
  w.U32(3);  // texcoords
  w.U32(0);
  w.U8(2);
  w.F32(0.0f);
  w.F32(1.0f);
  w.F32(0.25f);
  w.F32(0.75f);
  w.U8(1);
  w.U8(4);  // texcoord
  w.U8(12);
  w.U32(3);  // joint ids
  w.U32(0);
  w.U8(4);
  w.U8(1);
  w.U8(2);
  w.PatchU32(enc == LegacyEncoding::kBinary ? 4 : 5, uint32_t(w.out.size()));
  return w.out;
}

TEST(LegacyStreamReader, RecognisesBothStartCodes) {
  LegacyEncoding e;
  const std::vector<uint8_t> bin = Header(LegacyEncoding::kBinary);
  const std::vector<uint8_t> ascii = Header(LegacyEncoding::kAscii);
  EXPECT_TRUE(IsLegacyStream(bin.data(), bin.size(), &e));
  EXPECT_EQ(e, LegacyEncoding::kBinary);
  EXPECT_TRUE(IsLegacyStream(ascii.data(), ascii.size(), &e));
  EXPECT_EQ(e, LegacyEncoding::kAscii);
  for (uint8_t c : ascii) EXPECT_LT(c, 128);
  const uint8_t native[] = {'O', '3', 'D', 'G', 1, 0};
  EXPECT_FALSE(IsLegacyStream(native, sizeof native));
  EXPECT_FALSE(IsLegacyStream(bin.data(), 3));
  EXPECT_FALSE(IsLegacyStream(nullptr, 0));
}

TEST(LegacyStreamReader, AsciiNumbers) {
  // 5; 127 + 3; 127 + 1 + 2 * 64; then 32-bit 0x12345678 as five 7-bit groups.
  const std::vector<uint8_t> bytes = {5,    127,  3 << 1, 127,  (1 << 1) | 1, 2 << 1,
                                      0x78, 0x2C, 0x51,   0x11, 0x01};
  LegacyReader r(bytes.data(), bytes.size(), LegacyEncoding::kAscii);
  EXPECT_EQ(r.ReadAsciiUInt(), 5u);
  EXPECT_EQ(r.ReadAsciiUInt(), 130u);
  EXPECT_EQ(r.ReadAsciiUInt(), 256u);
  EXPECT_EQ(r.ReadUInt32(), 0x12345678u);
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.ReadByte(), 0);
  EXPECT_TRUE(r.failed());
  EXPECT_EQ(LegacyUnsignedToSigned(0), 0);
  EXPECT_EQ(LegacyUnsignedToSigned(1), -1);
  EXPECT_EQ(LegacyUnsignedToSigned(2), 1);
  EXPECT_EQ(LegacyUnsignedToSigned(3), -2);
}

TEST(LegacyStreamReader, EndlessAsciiNumberFails) {
  const std::vector<uint8_t> bytes(20, 127);  // every continuation flag set
  LegacyReader r(bytes.data(), bytes.size(), LegacyEncoding::kAscii);
  r.ReadAsciiUInt();
  EXPECT_TRUE(r.failed());
}

TEST(LegacyStreamReader, ParsesHeaderInBothEncodings) {
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    const std::vector<uint8_t> bytes = Header(enc);
    LegacyHeader h;
    ASSERT_EQ(ParseLegacyHeader(bytes.data(), bytes.size(), &h), Status::kOk);
    EXPECT_EQ(h.encoding, enc);
    EXPECT_EQ(h.stream_size, bytes.size());
    EXPECT_EQ(h.header_bytes, bytes.size());
    EXPECT_EQ(h.coord.count, 3u);
    EXPECT_EQ(h.num_triangles, 1u);
    EXPECT_EQ(h.coord.bits, 14);
    EXPECT_EQ(h.coord.min[2], -3.0f);
    EXPECT_EQ(h.coord.max[2], 4.0f);
    EXPECT_EQ(h.normal.count, 0u);
    ASSERT_EQ(h.floats.size(), 1u);
    EXPECT_EQ(h.floats[0].dimension, 2u);
    EXPECT_EQ(h.floats[0].type, uint8_t(LegacyFloatType::kTexCoord));
    EXPECT_EQ(h.floats[0].bits, 12);
    EXPECT_EQ(h.floats[0].max[1], 0.75f);
    ASSERT_EQ(h.ints.size(), 1u);
    EXPECT_EQ(h.ints[0].dimension, 4u);
    EXPECT_EQ(h.ints[0].type, uint8_t(LegacyIntType::kJointId));
  }
}

TEST(LegacyStreamReader, RejectsBadHeaders) {
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    const std::vector<uint8_t> good = Header(enc);
    LegacyHeader h;
    for (size_t n = 0; n < good.size(); ++n) {
      const Status s = ParseLegacyHeader(good.data(), n, &h);
      EXPECT_TRUE(s == Status::kTruncated || s == Status::kBadMagic) << n;
    }
    const std::vector<uint8_t> nan = Header(enc, std::numeric_limits<float>::quiet_NaN());
    EXPECT_EQ(ParseLegacyHeader(nan.data(), nan.size(), &h), Status::kCorrupt);
    const std::vector<uint8_t> inf = Header(enc, std::numeric_limits<float>::infinity());
    EXPECT_EQ(ParseLegacyHeader(inf.data(), inf.size(), &h), Status::kCorrupt);
    std::vector<uint8_t> mode = good;
    mode[enc == LegacyEncoding::kBinary ? 8 : 10] = 1;  // QBCR: never implemented
    EXPECT_EQ(ParseLegacyHeader(mode.data(), mode.size(), &h), Status::kUnsupported);
  }
}

}  // namespace
