// TFAN connectivity of original Open3DGC streams, on small connectivity parts built in code in
// both encodings: fan configurations, visited-vertex references, triangle order, and rejection of
// inconsistent parts.
#include <gtest/gtest.h>

#include <vector>

#include "legacy_connectivity_decoder.h"
#include "legacy_test_encoder.h"

namespace {

using namespace o3dgc;
using legacy_test::ArrayKind;
using legacy_test::WriteArray;
using legacy_test::Writer;

struct Tfan {
  uint8_t mask = 0;
  uint32_t capacity = 3;
  std::vector<int64_t> fans, degrees, configs, ops, indices, order;
};

std::vector<uint8_t> Part(LegacyEncoding enc, const Tfan& t) {
  Writer w{enc, {}};
  w.U8(t.mask);
  w.U32(t.capacity);
  const bool ascii = enc == LegacyEncoding::kAscii;
  // The encoder's alphabets (M) per array; ASCII writes counts and degrees unsigned.
  WriteArray(&w, ascii ? ArrayKind::kUnsigned : ArrayKind::kSigned, 4, t.fans);
  WriteArray(&w, ascii ? ArrayKind::kUnsigned : ArrayKind::kSigned, 16, t.degrees);
  WriteArray(&w, ArrayKind::kUnsigned, 10, t.configs);
  WriteArray(&w, ArrayKind::kBits, 0, t.ops);
  WriteArray(&w, ArrayKind::kSigned, 8, t.indices);
  if (t.mask & 2) WriteArray(&w, ascii ? ArrayKind::kUnsigned : ArrayKind::kSigned, 16, t.order);
  w.U8(0x5A);  // what follows the part (the position section) must be left unread
  return w.out;
}

Status Decode(LegacyEncoding enc, const Tfan& t, uint32_t nv, uint32_t nt, LegacyConnectivity* c,
              size_t* end = nullptr) {
  const std::vector<uint8_t> bytes = Part(enc, t);
  LegacyReader r(bytes.data(), bytes.size(), enc);
  const Status s = DecodeLegacyConnectivity(&r, nv, nt, c);
  if (end) *end = bytes.size() - r.pos();
  return s;
}

// A tetrahedron: vertex 0 gets one fan over all four vertices (config 9: three new vertices,
// then the first visited one, vertex 1, by reference -1); vertex 1 closes the last face with
// config 0 (its two visited vertices 2 and 3, no new ones). Degrees are stored as
// degree - 2 + triangles already around the focus vertex.
Tfan Tetrahedron() {
  Tfan t;
  t.fans = {1, 1, 0, 0};
  t.degrees = {2, 2};
  t.configs = {9, 0};
  t.ops = {0, 0, 0, 1};
  t.indices = {-1};
  return t;
}

TEST(LegacyConnectivity, DecodesFansInBothEncodings) {
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    LegacyConnectivity c;
    size_t left = 0;
    ASSERT_EQ(Decode(enc, Tetrahedron(), 4, 4, &c, &left), Status::kOk);
    EXPECT_EQ(c.triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 2, 3}));
    EXPECT_TRUE(c.placement.empty());
    EXPECT_EQ(left, 1u);
  }
}

TEST(LegacyConnectivity, SimpleConfigurations) {
  // Two separate triangles: each component starts at a new focus vertex with config 6 (all new).
  Tfan t;
  t.fans = {1, 0, 0, 1, 0, 0};
  t.degrees = {0, 0};
  t.configs = {6, 6};
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    LegacyConnectivity c;
    ASSERT_EQ(Decode(enc, t, 6, 2, &c), Status::kOk);
    EXPECT_EQ(c.triangles, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  }
  // A quad fan (config 6, degree 3), then vertex 1 adds a triangle on edge 1-2 with a new vertex:
  // config 2 = new vertices, then the first visited vertex.
  Tfan q;
  q.fans = {1, 1, 0, 0, 0};
  q.degrees = {1, 1};
  q.configs = {6, 2};
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    LegacyConnectivity c;
    ASSERT_EQ(Decode(enc, q, 5, 3, &c), Status::kOk);
    EXPECT_EQ(c.triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
  }
}

TEST(LegacyConnectivity, TriangleOrder) {
  Tfan t = Tetrahedron();
  t.mask = 2;
  // Decoded triangle i goes to position prev + 1 + step (zigzag coded): 3, 0, 2, 1.
  // Steps from the previous position + 1: 3, -4, 1, -2 -> zigzag 6, 7, 2, 3.
  t.order = {6, 7, 2, 3};
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    LegacyConnectivity c;
    ASSERT_EQ(Decode(enc, t, 4, 4, &c), Status::kOk);
    EXPECT_EQ(c.placement, (std::vector<uint32_t>{3, 0, 2, 1}));
  }
  t.order = {6, 7, 2, 1};  // position 1 twice
  LegacyConnectivity c;
  EXPECT_EQ(Decode(LegacyEncoding::kBinary, t, 4, 4, &c), Status::kCorrupt);
}

TEST(LegacyConnectivity, RejectsInconsistentParts) {
  for (LegacyEncoding enc : {LegacyEncoding::kBinary, LegacyEncoding::kAscii}) {
    LegacyConnectivity c;
    EXPECT_EQ(Decode(enc, Tetrahedron(), 4, 5, &c), Status::kCorrupt);  // too few triangles
    EXPECT_EQ(Decode(enc, Tetrahedron(), 4, 3, &c), Status::kCorrupt);  // too many
    EXPECT_EQ(Decode(enc, Tetrahedron(), 3, 4, &c), Status::kCorrupt);  // too many vertices
    Tfan t = Tetrahedron();
    t.capacity = 2;  // vertex 0 is in three triangles
    EXPECT_EQ(Decode(enc, t, 4, 4, &c), Status::kCorrupt);
    t = Tetrahedron();
    t.indices = {-4};  // three visited vertices exist at that point
    EXPECT_EQ(Decode(enc, t, 4, 4, &c), Status::kCorrupt);
    t = Tetrahedron();
    t.indices = {7};  // focus + 7 is past the last vertex
    EXPECT_EQ(Decode(enc, t, 4, 4, &c), Status::kCorrupt);
    t = Tetrahedron();
    t.configs = {9, 10};  // no such configuration
    EXPECT_EQ(Decode(enc, t, 4, 4, &c), Status::kCorrupt);
    t = Tetrahedron();
    t.fans = {1, 1};  // runs out of fan counts
    EXPECT_EQ(Decode(enc, t, 4, 4, &c), Status::kCorrupt);
    t = Tetrahedron();
    t.mask = 1;  // coded vertex order: the original never implemented it
    EXPECT_EQ(Decode(enc, t, 4, 4, &c), Status::kUnsupported);
    const std::vector<uint8_t> bytes = Part(enc, Tetrahedron());
    for (size_t n = 0; n + 1 < bytes.size(); ++n) {
      LegacyReader r(bytes.data(), n, enc);
      EXPECT_NE(DecodeLegacyConnectivity(&r, 4, 4, &c), Status::kOk) << n;
    }
  }
}

}  // namespace
