#include "bench/codec_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace hullpack {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(CodecError, ExactOnHandMadeDifferences) {
  // Unit cube corners (diagonal sqrt(3)); offsets are powers of two, exact in float.
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1};
  const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 2, 0, 0, 0};  // lengths 1, 1, 2, 0
  const std::vector<float> uvs = {0, 0, 0.5f, 0.5f, 1, 1, 0.25f, 0.75f};
  o3dgc::DecodedMesh d;
  d.positions = positions;
  d.positions[0] += 0x1p-10f;  // vertex 0: 2^-10 along x
  d.positions[4] -= 0x1p-9f;   // vertex 1: 2^-9 along y
  // Normals rotated about x by 1 and 3 degrees, one unchanged, and one without an original
  // direction.
  const double a1 = 1 * kPi / 180, a3 = 3 * kPi / 180;
  d.normals = {0,
               -float(std::sin(a1)),
               float(std::cos(a1)),
               0,
               -float(std::sin(a3)),
               float(std::cos(a3)),
               0,
               0,
               1,
               1,
               0,
               0};
  o3dgc::DecodedFloatAttribute uv;
  uv.semantic = o3dgc::Semantic::kTexCoord;
  uv.dimension = 2;
  uv.values = uvs;
  uv.values[2] += 0.1875f;  // 3/16 and 4/16 away: 5/16 in all
  uv.values[3] += 0.25f;
  d.float_attributes.push_back(uv);

  VertexArrays original;
  original.positions = &positions;
  original.normals = &normals;
  original.uvs = &uvs;
  CodecError e;
  std::string why;
  ASSERT_TRUE(MeasureCodecError(original, d, &e, &why)) << why;
  EXPECT_EQ(e.vertices, 4u);
  EXPECT_DOUBLE_EQ(e.diagonal, std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(e.position_max, 0x1p-9 / std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(e.position_rms, std::sqrt((0x1p-20 + 0x1p-18) / 4) / std::sqrt(3.0));
  // The decoded normals are float: the angles are exact to float precision (about 1e-5 degrees).
  EXPECT_EQ(e.normals_counted, 3u);
  EXPECT_NEAR(e.normal_max_deg, 3.0, 2e-5);
  EXPECT_NEAR(e.normal_mean_deg, (1.0 + 3.0 + 0.0) / 3, 2e-5);
  EXPECT_DOUBLE_EQ(e.uv_max, 0.3125);
}

TEST(CodecError, NoNormalsOrUvsAreReportedAsNotMeasured) {
  const std::vector<float> positions = {0, 0, 0, 2, 0, 0};
  o3dgc::DecodedMesh d;
  d.positions = positions;
  VertexArrays original;
  original.positions = &positions;
  CodecError e;
  ASSERT_TRUE(MeasureCodecError(original, d, &e, nullptr));
  EXPECT_EQ(e.position_max, 0);
  EXPECT_EQ(e.normal_max_deg, -1);
  EXPECT_EQ(e.uv_max, -1);
}

TEST(CodecError, MismatchedCountsAreRefused) {
  const std::vector<float> positions = {0, 0, 0, 2, 0, 0};
  o3dgc::DecodedMesh d;
  d.positions = {0, 0, 0};
  VertexArrays original;
  original.positions = &positions;
  CodecError e;
  std::string why;
  EXPECT_FALSE(MeasureCodecError(original, d, &e, &why));
  EXPECT_NE(why, "");
  const std::vector<float> normals = {0, 0, 1, 0, 0, 1};
  original.normals = &normals;
  d.positions = positions;  // right count, but the stream lost the normals
  EXPECT_FALSE(MeasureCodecError(original, d, &e, &why));
}

TEST(CodecError, AngleIsAccurateForTinyAngles) {
  const double a[3] = {1, 0, 0};
  const double tiny = 1e-7;  // radians: acos(dot) would lose it entirely
  const double b[3] = {std::cos(tiny), std::sin(tiny), 0};
  EXPECT_NEAR(AngleDegrees(a, b), tiny * 180 / kPi, 1e-15);
  const double zero[3] = {0, 0, 0};
  EXPECT_EQ(AngleDegrees(a, zero), -1);
  const double opposite[3] = {-3, 0, 0};
  EXPECT_DOUBLE_EQ(AngleDegrees(a, opposite), 180);
}

// A mesh whose positions lie on the 4-bit quantization grid of a 15-unit cube (steps of exactly 1,
// since the codec maps [min, min + range] onto 0..2^bits - 1) except two vertices, 0.25 and 0.125
// off the grid: the codec's error is known exactly.
struct GridMesh {
  std::vector<float> positions = {0,  0,     0, 15, 0, 0,      0, 15, 0,  0, 0,
                                  15, 3.25f, 7, 2,  6, 2.125f, 9, 15, 15, 15};
  std::vector<uint32_t> indices = {0, 1, 2, 0, 1, 3, 0, 2, 3, 1, 2, 6, 4, 1, 2, 5, 1, 3, 6, 3, 2};
  // UVs on a 15-unit square at 4 bits (steps of 1), one 0.25 off.
  std::vector<float> uvs = {0, 0, 15, 0, 0, 15, 15, 15, 2.25f, 3, 7, 8, 1, 1};
};

o3dgc::MeshView View(const GridMesh& m, int uv_bits) {
  o3dgc::MeshView v;
  v.positions = m.positions.data();
  v.num_vertices = m.positions.size() / 3;
  v.indices = m.indices.data();
  v.num_triangles = m.indices.size() / 3;
  o3dgc::FloatAttributeView uv;
  uv.data = m.uvs.data();
  uv.dimension = 2;
  uv.semantic = o3dgc::Semantic::kTexCoord;
  uv.bits = uv_bits;
  v.float_attributes.push_back(uv);
  return v;
}

o3dgc::DecodedMesh RoundTrip(const GridMesh& m, int bits, bool keep_order) {
  o3dgc::EncodeParams p;
  p.position_bits = bits;
  p.keep_order = keep_order;
  std::vector<uint8_t> stream;
  EXPECT_EQ(o3dgc::Encode(View(m, bits), p, &stream), o3dgc::Status::kOk);
  o3dgc::DecodedMesh d;
  EXPECT_EQ(o3dgc::Decode(stream.data(), stream.size(), o3dgc::DecodeOptions(), &d),
            o3dgc::Status::kOk);
  return d;
}

TEST(CodecError, KnownQuantizationErrorThroughTheCodec) {
  const GridMesh m;
  const o3dgc::DecodedMesh d = RoundTrip(m, 4, true);
  VertexArrays original;
  original.positions = &m.positions;
  original.uvs = &m.uvs;
  CodecError e;
  std::string why;
  ASSERT_TRUE(MeasureCodecError(original, d, &e, &why)) << why;
  const double diagonal = 15 * std::sqrt(3.0);
  EXPECT_DOUBLE_EQ(e.diagonal, diagonal);
  EXPECT_DOUBLE_EQ(e.position_max, 0.25 / diagonal);
  EXPECT_DOUBLE_EQ(e.position_rms, std::sqrt((0.25 * 0.25 + 0.125 * 0.125) / 7) / diagonal);
  EXPECT_DOUBLE_EQ(e.uv_max, 0.25);
}

TEST(CodecError, WithinTheQuantizationBoundAtEveryBitCount) {
  const GridMesh m;
  VertexArrays original;
  original.positions = &m.positions;
  for (int bits = 6; bits <= 20; ++bits) {
    const o3dgc::DecodedMesh d = RoundTrip(m, bits, true);
    CodecError e;
    ASSERT_TRUE(MeasureCodecError(original, d, &e, nullptr));
    // Half a cell per axis: sqrt(3)/2 * 15 / (2^bits - 1), relative to the diagonal 15 sqrt(3),
    // plus float rounding of the decoded coordinates (at most 2^-20 of 15 here).
    const double bound = 0.5 / (std::ldexp(1.0, bits) - 1) + 1e-6;
    EXPECT_LE(e.position_max, bound) << bits << " bits";
    EXPECT_GT(e.position_max, 0) << bits << " bits";  // the grid points of 4 bits are off this grid
  }
}

TEST(CodecError, ReorderedStreamDecodesToTheSameVertexRecords) {
  const GridMesh m;
  for (int bits : {4, 11}) {
    const o3dgc::DecodedMesh reordered = RoundTrip(m, bits, false),
                             ordered = RoundTrip(m, bits, true);
    EXPECT_TRUE(SameVertexRecords(reordered, ordered)) << bits;
  }
}

TEST(CodecError, SameVertexRecordsIgnoresOrderButNotValues) {
  o3dgc::DecodedMesh a;
  a.positions = {0, 0, 0, 1, 2, 3, 4, 5, 6};
  a.normals = {0, 0, 1, 0, 1, 0, 1, 0, 0};
  o3dgc::DecodedMesh b = a;
  // The same records, in another order.
  b.positions = {4, 5, 6, 0, 0, 0, 1, 2, 3};
  b.normals = {1, 0, 0, 0, 0, 1, 0, 1, 0};
  EXPECT_TRUE(SameVertexRecords(a, b));
  // Same positions and same normals as sets, but paired differently.
  b.normals = {0, 0, 1, 1, 0, 0, 0, 1, 0};
  EXPECT_FALSE(SameVertexRecords(a, b));
  o3dgc::DecodedMesh c = a;
  c.positions[4] = std::nextafter(2.0f, 3.0f);
  EXPECT_FALSE(SameVertexRecords(a, c));
  c = a;
  c.normals.clear();
  EXPECT_FALSE(SameVertexRecords(a, c));
}

}  // namespace
}  // namespace hullpack
