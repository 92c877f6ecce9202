// Decoder robustness: truncations, byte flips, lying headers.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "entropy.h"
#include "o3dgc/o3dgc.h"
#include "stream_header.h"
#include "test_meshes.h"

namespace {

using namespace o3dgc;

std::vector<uint8_t> SmallStream(bool keep_order, StreamType type = StreamType::kBinary) {
  o3dgc_test::TestMesh t = o3dgc_test::Awkward();
  t.joints.assign(t.nv() * 4, 3);
  t.joints[5] = -100000;
  t.colors.assign(t.nv() * 4, 0.25f);
  t.colors[7] = 0.75f;
  t.normals.assign(t.nv() * 3, 0.0f);
  for (size_t i = 0; i < t.nv(); ++i) t.normals[3 * i + (i % 3)] = 1.0f;
  EncodeParams p;
  p.keep_order = keep_order;
  p.stream_type = type;
  std::vector<uint8_t> s;
  EXPECT_EQ(Encode(t.View(), p, &s), Status::kOk);
  return s;
}

void ExpectSane(const DecodedMesh& m) {
  for (float f : m.positions) ASSERT_TRUE(std::isfinite(f));
  for (float f : m.normals) ASSERT_TRUE(std::isfinite(f));
  for (const auto& a : m.float_attributes) {
    for (float f : a.values) ASSERT_TRUE(std::isfinite(f));
  }
  for (uint32_t i : m.indices) ASSERT_LT(i, m.num_vertices());
}

TEST(Malformed, EveryTruncationIsRejected) {
  for (bool keep : {false, true}) {
    for (StreamType type : {StreamType::kBinary, StreamType::kAscii}) {
      const auto s = SmallStream(keep, type);
      for (size_t n = 0; n < s.size(); ++n) {
        DecodedMesh m;
        for (bool crc : {true, false}) {
          DecodeOptions o;
          o.verify_checksum = crc;
          EXPECT_NE(Decode(s.data(), n, o, &m), Status::kOk) << n;
        }
      }
    }
  }
}

TEST(Malformed, RandomByteFlipsNeverCrash) {
  std::mt19937 rng(42);
  int accepted = 0;
  for (bool keep : {false, true}) {
    const auto s = SmallStream(keep);
    for (int iter = 0; iter < 3000; ++iter) {
      auto c = s;
      const int flips = 1 + int(rng() % 4);
      for (int f = 0; f < flips; ++f) c[rng() % c.size()] ^= uint8_t(1 + rng() % 255);
      DecodeOptions o;
      o.verify_checksum = false;  // exercise the parser itself
      DecodedMesh m;
      if (Decode(c.data(), c.size(), o, &m) == Status::kOk) {
        ++accepted;
        ExpectSane(m);
      }
      o.verify_checksum = true;
      if (c != s) {
        EXPECT_NE(Decode(c.data(), c.size(), o, &m), Status::kOk);
      }
    }
  }
  SUCCEED() << accepted << " corrupted streams decoded to valid meshes";
}

// `iterations` times: a few bits of the payload flipped (where the parser is exercised), decoded
// without the checksum (a result, if any, must be sane), then the flipped stream cut short (must
// fail).
void ExpectFlipsAndCutsHandled(const std::vector<uint8_t>& s, std::mt19937& rng, int iterations) {
  for (int iter = 0; iter < iterations; ++iter) {
    auto c = s;
    const int flips = 1 + int(rng() % 3);
    for (int f = 0; f < flips; ++f) c[12 + rng() % (c.size() - 12)] ^= uint8_t(1u << (rng() % 8));
    DecodeOptions o;
    o.verify_checksum = false;
    DecodedMesh m;
    if (Decode(c.data(), c.size(), o, &m) == Status::kOk) ExpectSane(m);
    const size_t n = 1 + rng() % c.size();
    EXPECT_NE(Decode(c.data(), n - (n == c.size() ? 1 : 0), o, &m), Status::kOk);
  }
}

TEST(Malformed, RandomByteFlipsOnLargerMeshes) {
  std::mt19937 rng(4242);
  std::vector<std::vector<uint8_t>> streams;
  for (bool keep : {false, true}) {
    o3dgc_test::TestMesh t = o3dgc_test::Torus(12, 8);
    EncodeParams p;
    p.keep_order = keep;
    std::vector<uint8_t> s;
    ASSERT_EQ(Encode(t.View(), p, &s), Status::kOk);
    streams.push_back(s);
    o3dgc_test::TestMesh g = o3dgc_test::Grid(9, 7);
    ASSERT_EQ(Encode(g.View(), p, &s), Status::kOk);
    streams.push_back(s);
  }
  for (const auto& s : streams) ExpectFlipsAndCutsHandled(s, rng, 800);
}

TEST(Malformed, ByteFlipsAndTruncationsPastTheRawBitsThreshold) {
  // Meshes of 4096 vertices or more take residual signs and low bits from the raw bit stream,
  // read backwards from the payload's end: flipped and cut streams of that kind too.
  std::mt19937 rng(77);
  o3dgc_test::TestMesh torus = o3dgc_test::Torus(72, 60);  // colours and joint ids too
  o3dgc_test::TestMesh grid = o3dgc_test::Grid(72, 60);    // uvs
  ASSERT_GE(torus.nv(), 4096u);
  // Positions jittered by about +-2^7 quantization steps: residuals large enough for the encoder
  // to send class shifts (see attribute_coder_test.cc).
  o3dgc_test::TestMesh noisy = grid;
  for (size_t i = 0; i < noisy.positions.size(); ++i) {
    noisy.positions[i] +=
        0.008f * float(std::sin(double(i) * 12.9898) * 0.5 + std::cos(double(i) * 7.233) * 0.5);
  }
  EncodeParams fast;
  fast.fast_decode = true;  // the coding order of fast_decode streams
  for (const auto& [t, p] :
       {std::make_pair(&torus, EncodeParams()), std::make_pair(&grid, EncodeParams()),
        std::make_pair(&noisy, EncodeParams()), std::make_pair(&noisy, fast)}) {
    std::vector<uint8_t> s;
    ASSERT_EQ(Encode(t->View(), p, &s), Status::kOk);
    ExpectFlipsAndCutsHandled(s, rng, 150);
    // The unflipped stream cut anywhere, the raw bits' end included.
    for (int i = 0; i < 60; ++i) {
      const size_t n = 1 + rng() % (s.size() - 1);
      DecodedMesh m;
      DecodeOptions o;
      o.verify_checksum = false;
      EXPECT_NE(Decode(s.data(), n, o, &m), Status::kOk) << n;
    }
  }
}

TEST(Malformed, AsciiStreamByteFlips) {
  std::mt19937 rng(77);
  const auto s = SmallStream(false, StreamType::kAscii);
  for (int iter = 0; iter < 1000; ++iter) {
    auto c = s;
    c[4 + rng() % (c.size() - 4)] ^= uint8_t(1 + rng() % 255);
    DecodedMesh m;
    DecodeOptions o;
    o.verify_checksum = false;
    if (Decode(c.data(), c.size(), o, &m) == Status::kOk) ExpectSane(m);
  }
}

TEST(Malformed, RandomGarbageAfterHeader) {
  std::mt19937 rng(9);
  const auto s = SmallStream(false);
  for (int iter = 0; iter < 2000; ++iter) {
    std::vector<uint8_t> c(s.begin(), s.begin() + 11);
    const size_t n = rng() % 300;
    for (size_t i = 0; i < n; ++i) c.push_back(uint8_t(rng()));
    // Fix the payload length so the header parses.
    std::vector<uint8_t> out;
    WriteHeader(false, false, false, false, n, &out);
    out.insert(out.end(), c.begin() + 11, c.end());
    FinalizeCrc(&out);
    DecodedMesh m;
    if (Decode(out.data(), out.size(), DecodeOptions(), &m) == Status::kOk) ExpectSane(m);
  }
}

TEST(Malformed, HugeVertexCountRejectedQuickly) {
  // A payload whose header claims 2^32 vertices and 2^31 triangles.
  std::vector<uint8_t> payload;
  {
    ArithmeticEncoder enc(&payload);
    EGModel m;
    EncodeEG(enc, m, uint64_t(1) << 32);
    EncodeEG(enc, m, uint64_t(1) << 31);
    enc.EncodeBits(0, 2);
    EncodeEG(enc, m, 0);
    EncodeEG(enc, m, 0);
    // Position descriptor: semantic position, 3 components, parallelogram, 14 bits, uniform range,
    // min = 0 and range = 0 (all zero floats).
    enc.EncodeBits(1, 3);
    enc.EncodeBits(2, 2);
    enc.EncodeBits(2, 2);
    enc.EncodeBits(13, 5);
    enc.EncodeBits(0, 1);
    for (int i = 0; i < 40; ++i) enc.EncodeBits(0, 32);
    enc.Finish();
  }
  std::vector<uint8_t> s;
  WriteHeader(false, false, false, false, payload.size(), &s);
  s.insert(s.end(), payload.begin(), payload.end());
  FinalizeCrc(&s);
  const auto t0 = std::chrono::steady_clock::now();
  DecodedMesh m;
  DecodeOptions o;
  o.max_vertices = size_t(1) << 40;
  o.max_triangles = size_t(1) << 40;
  const Status st = Decode(s.data(), s.size(), o, &m);
  EXPECT_EQ(st, Status::kLimitExceeded) << StatusName(st);
  EXPECT_EQ(Decode(s.data(), s.size(), DecodeOptions(), &m), Status::kLimitExceeded);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 0.5);
}

// Format 1.2's modelled low bits (a grid-built model takes them): flips and cuts of the payload.
TEST(Malformed, ModelledLowBitsFlipsAndCuts) {
  const o3dgc_test::TestMesh t = o3dgc_test::GridBlocks(6, 5);
  std::vector<uint8_t> s;
  StreamInfo info;
  ASSERT_EQ(Encode(t.View(), EncodeParams(), &s, &info), Status::kOk);
  ASSERT_TRUE(info.low_bits);
  std::mt19937 rng(12);
  ExpectFlipsAndCutsHandled(s, rng, 3000);
  for (size_t n = 0; n < s.size(); ++n) {
    DecodedMesh m;
    DecodeOptions o;
    o.verify_checksum = false;
    EXPECT_NE(Decode(s.data(), n, o, &m), Status::kOk) << n;
  }
}

TEST(Malformed, HeaderChecks) {
  auto s = SmallStream(false);
  DecodedMesh m;
  auto c = s;
  c[0] = 'X';
  EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kBadMagic);
  c = s;
  c[4] = 99;
  EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kBadVersion);
  c = s;
  c[4] = 7;  // the pre-1.0 development format
  EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kBadVersion);
  c = s;
  c[5] = kFormatMinor + 1;  // a later minor version
  EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kBadVersion);
  for (const uint8_t flag : {4, 8, 128}) {  // bits 0 (keep_order) and 1 (fast_decode) are defined
    c = s;
    c[5] = 1;
    c[6] |= flag;
    EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kCorrupt) << int(flag);
  }
  for (const uint8_t flag : {8, 16, 128}) {  // 1.2 adds bit 2 (modelled low bits)
    c = s;
    c[5] = uint8_t(kLowBitsMinor);
    c[6] |= flag;
    EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kCorrupt) << int(flag);
  }
  for (const uint8_t flag : {16, 32, 128}) {  // 1.3 adds bit 3 (adaptive low bits everywhere)
    c = s;
    c[5] = uint8_t(kAllAdaptiveMinor);
    c[6] |= flag;
    EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kCorrupt) << int(flag);
  }
  c = s;
  c.push_back(0);
  EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kCorrupt);
  c = s;
  c.back() ^= 1;
  EXPECT_EQ(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kChecksumMismatch);
  EXPECT_EQ(Decode(nullptr, 0, DecodeOptions(), &m), Status::kBadMagic);
  DecodeOptions small;
  small.max_vertices = 3;
  EXPECT_EQ(Decode(s.data(), s.size(), small, &m), Status::kLimitExceeded);
  EXPECT_STREQ(StatusName(Status::kCorrupt), "corrupt");
}

}  // namespace
