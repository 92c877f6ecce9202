#include "pipeline/mesh_codec.h"

#include <gtest/gtest.h>

#include "test_torus.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace hullpack {
namespace {

// A torus with every attribute the codec carries.
Mesh FullTorus(int rings = 24, int sides = 12) {
  Mesh m = testing::TorusMesh(rings, sides);
  m.uv_sets.resize(2);
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      m.uv_sets[0].insert(m.uv_sets[0].end(), {float(i) / rings, float(j) / sides});
      m.uv_sets[1].insert(m.uv_sets[1].end(), {float(j) / sides, float(i) / rings});
      m.colors.insert(m.colors.end(), {float(i) / rings, 0.5f, float(j) / sides, 1});
      m.joints.insert(m.joints.end(), {uint16_t(i % 3), uint16_t(j % 5), 7, 0});
      m.weights.insert(m.weights.end(), {0.5f, 0.25f, 0.25f, 0});
    }
  }
  return m;
}

TEST(MeshCodec, RoundTripKeepsEveryAttributeWithinItsBits) {
  const Mesh in = FullTorus();
  MeshCodecSettings s;
  s.keep_order = true;
  Result<EncodedMesh> enc = EncodeMesh(in, {}, s);
  ASSERT_TRUE(enc.ok()) << enc.status().ToString();
  const std::vector<std::pair<std::string, int>> expect = {
      {"POSITION", 0}, {"NORMAL", 1},    {"TEXCOORD_0", 2}, {"TEXCOORD_1", 3},
      {"COLOR_0", 4},  {"WEIGHTS_0", 5}, {"JOINTS_0", 6}};
  EXPECT_EQ(enc->gltf_attributes, expect);
  Result<Mesh> dec = DecodeMesh(enc->stream.data(), enc->stream.size(), nullptr, "t");
  ASSERT_TRUE(dec.ok()) << dec.status().ToString();
  EXPECT_EQ(dec->indices, in.indices);  // keep_order
  EXPECT_EQ(dec->joints, in.joints);
  ASSERT_EQ(dec->uv_sets.size(), 2u);
  const double step = PositionRange(in) / ((1 << s.position_bits) - 1);
  for (size_t i = 0; i < in.positions.size(); ++i)
    EXPECT_LE(std::fabs(dec->positions[i] - in.positions[i]), step / 2 + 1e-6);
  for (size_t i = 0; i < in.uv_sets[1].size(); ++i)
    EXPECT_LE(std::fabs(dec->uv_sets[1][i] - in.uv_sets[1][i]), 1.0 / 4095 / 2 + 1e-6);
  for (size_t i = 0; i < in.colors.size(); ++i)
    EXPECT_NEAR(dec->colors[i], in.colors[i], 1.0 / 1023);
  for (size_t i = 0; i < in.weights.size(); ++i)
    EXPECT_NEAR(dec->weights[i], in.weights[i], 1.0 / 1023);
  EXPECT_LE(MaxVertexDistance(in, dec.value()), std::sqrt(3.0) * step / 2 + 1e-6);
}

// The bytes of `mesh` with every UV set quantized on `range`, nothing else tried.
size_t BytesWithUvRange(const Mesh& mesh, o3dgc::RangeMode range) {
  MeshCodecSettings s;
  s.uv_range = range;
  CodecInput in;
  EXPECT_TRUE(MakeCodecInput(mesh, {}, s, &in).ok());
  std::vector<uint8_t> stream;
  EXPECT_EQ(o3dgc::Encode(in.view, in.params, &stream), o3dgc::Status::kOk);
  return stream.size();
}

// A torus whose UVs unroll it at its own scale: u along the ring (length 2 pi), v around the
// tube (2 pi 0.3), so the u extent is over three times the v extent.
Mesh UnrolledTorus(int rings = 48, int sides = 24) {
  Mesh m = testing::TorusMesh(rings, sides);
  const double pi = std::acos(-1.0);
  m.uv_sets.resize(1);
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      m.uv_sets[0].insert(m.uv_sets[0].end(),
                          {float(2 * pi * i / rings), float(2 * pi * 0.3 * j / sides)});
    }
  }
  return m;
}

TEST(MeshCodec, UvCellsAreSquareByDefault) {
  const Mesh in = UnrolledTorus();
  ASSERT_TRUE(UvExtentsDiffer(in));
  // Square cells keep the shape-based UV prediction's perpendicular one, and spend no extra bits
  // on the shorter axis.
  const size_t uniform = BytesWithUvRange(in, o3dgc::RangeMode::kUniform);
  EXPECT_LT(uniform, BytesWithUvRange(in, o3dgc::RangeMode::kPerAxis) * 9 / 10);
  Result<EncodedMesh> enc = EncodeMesh(in, {}, MeshCodecSettings());
  ASSERT_TRUE(enc.ok()) << enc.status().ToString();
  EXPECT_EQ(enc->stream.size(), uniform);
  Result<Mesh> dec = DecodeMesh(enc->stream.data(), enc->stream.size(), nullptr, "t");
  ASSERT_TRUE(dec.ok()) << dec.status().ToString();
  float lo = in.uv_sets[0][0], hi = lo;
  for (float x : in.uv_sets[0]) lo = std::min(lo, x), hi = std::max(hi, x);
  ASSERT_EQ(dec->uv_sets.size(), 1u);
  ASSERT_EQ(dec->vertex_count(), in.vertex_count());
  // The decoded vertices come in another order: match them by position.
  for (size_t i = 0; i < dec->vertex_count(); ++i) {
    size_t best = 0;
    double best_d = 1e30;
    for (size_t j = 0; j < in.vertex_count(); ++j) {
      double d = 0;
      for (int k = 0; k < 3; ++k) {
        const double e = dec->positions[3 * i + k] - in.positions[3 * j + k];
        d += e * e;
      }
      if (d < best_d) best_d = d, best = j;
    }
    for (int k = 0; k < 2; ++k) {
      EXPECT_LE(std::fabs(dec->uv_sets[0][2 * i + k] - in.uv_sets[0][2 * best + k]),
                (hi - lo) / 4095 / 2 + 1e-5);
    }
  }
}

TEST(MeshCodec, PerAxisUvCellsAreKeptWhereSmaller) {
  // Palette UVs: each quad of the torus takes one of two texels at the ends of the u and v
  // ranges, whose extents differ.
  Mesh in = testing::TorusMesh(24, 12);
  in.uv_sets.resize(1);
  for (size_t i = 0; i < in.vertex_count(); ++i) {
    const bool a = (i / 12) % 3 == 0;
    in.uv_sets[0].insert(in.uv_sets[0].end(), {a ? 0.125f : 0.75f, a ? 0.25f : 0.5f});
  }
  ASSERT_TRUE(UvExtentsDiffer(in));
  Result<EncodedMesh> enc = EncodeMesh(in, {}, MeshCodecSettings());
  ASSERT_TRUE(enc.ok()) << enc.status().ToString();
  EXPECT_EQ(enc->stream.size(), std::min(BytesWithUvRange(in, o3dgc::RangeMode::kUniform),
                                         BytesWithUvRange(in, o3dgc::RangeMode::kPerAxis)));
}

TEST(MeshCodec, GroupsRoundTripAndExtract) {
  Mesh in = FullTorus(8, 6);
  std::vector<uint32_t> groups(in.triangle_count());
  for (size_t t = 0; t < groups.size(); ++t) groups[t] = t < groups.size() / 2 ? 3 : 9;
  Result<EncodedMesh> enc = EncodeMesh(in, groups, {});
  ASSERT_TRUE(enc.ok());
  std::vector<uint32_t> decoded_groups;
  Result<Mesh> dec = DecodeMesh(enc->stream.data(), enc->stream.size(), &decoded_groups, "t");
  ASSERT_TRUE(dec.ok());
  ASSERT_EQ(decoded_groups.size(), in.triangle_count());
  const Mesh a = ExtractGroup(dec.value(), decoded_groups, 3);
  const Mesh b = ExtractGroup(dec.value(), decoded_groups, 9);
  EXPECT_EQ(a.triangle_count() + b.triangle_count(), in.triangle_count());
  EXPECT_EQ(a.triangle_count(), in.triangle_count() / 2);
  for (uint32_t i : a.indices) EXPECT_LT(i, a.vertex_count());
  EXPECT_EQ(a.joints.size(), a.vertex_count() * 4);
  EXPECT_EQ(ExtractGroup(dec.value(), decoded_groups, 42).triangle_count(), 0u);
}

TEST(MeshCodec, BitsForAnErrorBudgetMeetTheBudget) {
  for (double budget : {0.1, 0.01, 0.0005, 1e-6}) {
    const int bits = PositionBitsForMaxError(1.0, budget);
    const double step = 1.0 / ((1 << bits) - 1);
    EXPECT_LE(std::sqrt(3.0) * step / 2, budget) << budget;
    if (bits > 1) {  // and one bit fewer would not
      const double coarser = 1.0 / ((1 << (bits - 1)) - 1);
      EXPECT_GT(std::sqrt(3.0) * coarser / 2, budget) << budget;
    }
  }
  EXPECT_EQ(PositionBitsForMaxError(0, 0.1), 14);  // degenerate input: the default
}

TEST(MeshCodec, MaxVertexDistanceIsSymmetricAndOrderFree) {
  Mesh a;
  a.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  Mesh b;
  b.positions = {0, 1, 0, 0, 0, 0.25f, 1, 0, 0};
  EXPECT_NEAR(MaxVertexDistance(a, b), 0.25, 1e-7);
  EXPECT_NEAR(MaxVertexDistance(b, a), 0.25, 1e-7);
  Mesh far = b;
  far.positions[0] = 1e6f;
  EXPECT_GT(MaxVertexDistance(a, far), 9e5);
}

// A stream of the original Open3DGC tool (tests/o3dgc/vectors) holds OBJ texture coordinates; the
// mesh comes out in the scene model's convention, so writing it as OBJ gives the original's vt
// back.
TEST(MeshCodec, OriginalOpen3dgcStreamUvsComeOutInSceneConvention) {
  const std::string path = std::string(HULLPACK_SOURCE_DIR) + "/tests/o3dgc/vectors/fox.binary.s3d";
  std::ifstream file(path, std::ios::binary);
  ASSERT_TRUE(file.good()) << path;
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                   std::istreambuf_iterator<char>());
  o3dgc::DecodedMesh raw;
  ASSERT_EQ(o3dgc::Decode(bytes.data(), bytes.size(), o3dgc::DecodeOptions(), &raw),
            o3dgc::Status::kOk);
  ASSERT_FALSE(raw.float_attributes.empty());
  const std::vector<float>& obj_uv = raw.float_attributes[0].values;
  o3dgc::StreamInfo info;
  Result<Mesh> dec = DecodeMesh(bytes.data(), bytes.size(), nullptr, "fox", &info);
  ASSERT_TRUE(dec.ok()) << dec.status().ToString();
  EXPECT_EQ(info.format, o3dgc::StreamFormat::kOpen3dgc2013);
  ASSERT_EQ(dec->uv_sets.size(), 1u);
  ASSERT_EQ(dec->uv_sets[0].size(), obj_uv.size());
  size_t differing = 0;
  for (size_t i = 0; i < obj_uv.size(); i += 2) {
    EXPECT_EQ(dec->uv_sets[0][i], obj_uv[i]);
    EXPECT_EQ(dec->uv_sets[0][i + 1], 1.0f - obj_uv[i + 1]);
    differing += obj_uv[i + 1] != 0.5f;
  }
  EXPECT_GT(differing, 0u);  // the flip is visible on this mesh
  // A native stream's texture coordinates come back unflipped.
  const Mesh in = FullTorus(6, 4);
  Result<EncodedMesh> enc = EncodeMesh(in, {}, {});
  ASSERT_TRUE(enc.ok());
  Result<Mesh> native = DecodeMesh(enc->stream.data(), enc->stream.size(), nullptr, "t");
  ASSERT_TRUE(native.ok());
  float min_v = 1, max_v = 0;
  for (size_t i = 1; i < native->uv_sets[0].size(); i += 2) {
    min_v = std::min(min_v, native->uv_sets[0][i]);
    max_v = std::max(max_v, native->uv_sets[0][i]);
  }
  EXPECT_NEAR(min_v, 0.0f, 1e-3);  // the torus's v runs 0 .. 3/4
  EXPECT_NEAR(max_v, 0.75f, 1e-3);
}

TEST(MeshCodec, BadStreamsGiveErrors) {
  const Mesh in = FullTorus(6, 4);
  Result<EncodedMesh> enc = EncodeMesh(in, {}, {});
  ASSERT_TRUE(enc.ok());
  for (size_t cut : {size_t(0), size_t(5), enc->stream.size() / 2, enc->stream.size() - 1}) {
    EXPECT_FALSE(DecodeMesh(enc->stream.data(), cut, nullptr, "cut").ok()) << cut;
  }
  EXPECT_FALSE(EncodeMesh(in, std::vector<uint32_t>(3, 0), {}).ok());  // wrong group count
}

}  // namespace
}  // namespace hullpack
