// The format's decode rule: skin weights come out of every packed stream summing to 1.
#include "packed/packed_glb_format.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/mesh_codec.h"

namespace hullpack {
namespace {

Mesh SkinnedQuad() {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  m.indices = {0, 1, 2, 0, 2, 3};
  // Sums that quantization cannot keep at 1 (quarters on 63 steps), and a vertex without weights.
  m.weights = {0.25f, 0.25f, 0.25f, 0.25f, 0.7f, 0.1f, 0.1f, 0.1f, 0, 0, 0, 0, 0.5f, 0.5f, 0, 0};
  m.joints = {0, 1, 2, 0, 0, 1, 2, 3, 0, 0, 0, 0, 1, 2, 0, 0};
  return m;
}

TEST(PackedGlbFormat, DecodedStreamsCarryWeightsThatSumToOne) {
  MeshCodecSettings settings;
  settings.weight_bits = 6;  // coarse: the raw decoded sums are off by far more than float epsilon
  settings.keep_order = true;
  Result<EncodedMesh> encoded = EncodeMesh(SkinnedQuad(), {}, settings);
  ASSERT_TRUE(encoded.ok()) << encoded.status().ToString();
  o3dgc::DecodedMesh raw;
  ASSERT_EQ(
      o3dgc::Decode(encoded->stream.data(), encoded->stream.size(), o3dgc::DecodeOptions(), &raw),
      o3dgc::Status::kOk);
  o3dgc::DecodedMesh ruled;
  ASSERT_EQ(DecodePackedStream(encoded->stream.data(), encoded->stream.size(), &ruled),
            o3dgc::Status::kOk);
  ASSERT_EQ(ruled.float_attributes.size(), 1u);
  const std::vector<float>& w = ruled.float_attributes[0].values;
  const std::vector<float>& r = raw.float_attributes[0].values;
  bool raw_off = false;
  for (size_t v = 0; v < 4; ++v) {
    const float sum = w[v * 4] + w[v * 4 + 1] + w[v * 4 + 2] + w[v * 4 + 3];
    const float raw_sum = r[v * 4] + r[v * 4 + 1] + r[v * 4 + 2] + r[v * 4 + 3];
    if (raw_sum == 0) {
      EXPECT_EQ(sum, 0);  // no weights stay no weights
    } else {
      EXPECT_NEAR(sum, 1.0f, 4e-7f) << v;
      raw_off |= std::fabs(raw_sum - 1.0f) > 1e-3f;
    }
  }
  EXPECT_TRUE(raw_off);  // the rule had work to do
  // DecodeMesh (the codec stage's decoder) applies the same rule.
  Result<Mesh> mesh = DecodeMesh(encoded->stream.data(), encoded->stream.size(), nullptr, "q");
  ASSERT_TRUE(mesh.ok());
  EXPECT_EQ(mesh->weights, w);
}

}  // namespace
}  // namespace hullpack
