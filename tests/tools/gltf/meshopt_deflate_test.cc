#include "gltf/meshopt_deflate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "gltf/buffer_compaction.h"
#include "gltf/meshopt_inflate.h"

namespace hullpack {
namespace {

// The bytes of bufferView `view` once the document is inflated (its data in the binary chunk).
std::vector<uint8_t> ViewBytes(const GltfDocument& doc, int view) {
  const nlohmann::json& v = doc.json()["bufferViews"][view];
  const size_t offset = v["byteOffset"].get<size_t>();
  const size_t length = v["byteLength"].get<size_t>();
  return std::vector<uint8_t>(doc.binary().begin() + offset,
                              doc.binary().begin() + offset + length);
}

TEST(MeshoptDeflate, EachFilterRoundTripsThroughTheReaderWithinItsBound) {
  // Quaternions along a turn (not exactly unit), translations of mixed scale, exact key times.
  std::vector<float> turns, moves, times;
  for (int k = 0; k < 300; ++k) {
    const double a = 0.01 * k;
    turns.insert(turns.end(),
                 {float(0.3 * std::sin(a)), 0.1f, float(std::sin(a)), float(1.0001 * std::cos(a))});
    moves.insert(moves.end(), {float(100 * std::cos(a)), float(0.001 * k), -2.5f});
    times.push_back(float(k) / 30.0f + 0.0001f);
  }
  GltfDocument doc;
  const int unrelated = doc.AddBufferView(std::vector<uint8_t>(10, 7), 4);
  auto add = [&doc](const std::vector<uint8_t>& stored, size_t stride, MeshoptFilter filter) {
    return AddMeshoptBufferView(doc, EncodeMeshoptAttributes(stored, stride),
                                stored.size() / stride, stride, filter);
  };
  const int rot = add(ApplyMeshoptFilter(MeshoptFilter::kQuaternion, turns.data(), 300, 8), 8,
                      MeshoptFilter::kQuaternion);
  const int pos = add(ApplyMeshoptFilter(MeshoptFilter::kExponential, moves.data(), 300, 12), 12,
                      MeshoptFilter::kExponential);
  std::vector<uint8_t> raw(times.size() * 4);
  std::memcpy(raw.data(), times.data(), raw.size());
  const int key = add(raw, 4, MeshoptFilter::kNone);
  EXPECT_EQ(doc.json()["extensionsRequired"], nlohmann::json({"EXT_meshopt_compression"}));
  EXPECT_EQ(doc.json()["buffers"][1]["byteLength"], 300 * (8 + 12 + 4));
  // Smaller than the data: the codec and the filters do their job on smooth key frames.
  EXPECT_LT(doc.binary().size(), 300 * (8 + 12 + 4) / 2);

  // The unrelated view goes, the compressed bytes move, and the reader still finds them.
  doc.json()["bufferViews"][unrelated]["byteLength"] = 10;
  nlohmann::json& refs = doc.json()["accessors"];
  refs = nlohmann::json::array();
  for (int v : {rot, pos, key}) refs.push_back({{"bufferView", v}});
  ASSERT_TRUE(CompactBufferViews(doc).ok());
  ASSERT_EQ(doc.json()["bufferViews"].size(), 3u);
  const Status inflated = InflateMeshoptBufferViews(doc, "filters.glb");
  ASSERT_TRUE(inflated.ok()) << inflated.ToString();
  EXPECT_EQ(doc.json()["buffers"].size(), 1u);

  const std::vector<uint8_t> q = ViewBytes(doc, 0);
  ASSERT_EQ(q.size(), 300u * 8);
  for (size_t k = 0; k < 300; ++k) {
    int16_t s[4];
    std::memcpy(s, &q[8 * k], 8);
    const float* f = &turns[4 * k];
    const double n = std::sqrt(double(f[0]) * f[0] + double(f[1]) * f[1] + double(f[2]) * f[2] +
                               double(f[3]) * f[3]);
    // The quaternion or its opposite (the same rotation), within 1/32767 per component.
    const double sign = s[3] * f[3] < 0 ? -1 : 1;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(sign * s[c] / 32767.0, f[c] / n, 1.0 / 32767) << k;
  }
  const std::vector<uint8_t> t = ViewBytes(doc, 1);
  ASSERT_EQ(t.size(), 300u * 12);
  for (size_t k = 0; k < 300; ++k) {
    float v[3];
    std::memcpy(v, &t[12 * k], 12);
    const float* f = &moves[3 * k];
    const double largest = std::max({std::fabs(f[0]), std::fabs(f[1]), std::fabs(f[2])});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], f[c], largest * std::ldexp(1.0, -15)) << k;
  }
  EXPECT_EQ(ViewBytes(doc, 2), raw);  // no filter: exact
}

TEST(MeshoptDeflate, UndoGivesWhatTheReaderGets) {
  const std::vector<float> values = {1.5f, -0.25f, 3e-5f, 7.0f, 0.0f, -1e6f};
  std::vector<uint8_t> stored =
      ApplyMeshoptFilter(MeshoptFilter::kExponential, values.data(), 2, 12);
  ASSERT_EQ(stored.size(), 24u);
  UndoMeshoptFilter(MeshoptFilter::kExponential, &stored, 12);
  float back[6];
  std::memcpy(back, stored.data(), 24);
  EXPECT_EQ(back[0], 1.5f);  // a few mantissa bits: exact
  EXPECT_EQ(back[4], 0.0f);
  EXPECT_NEAR(back[5], -1e6, 1e6 * std::ldexp(1.0, -15));
  EXPECT_TRUE(ApplyMeshoptFilter(MeshoptFilter::kNone, values.data(), 6, 4).empty());
}

}  // namespace
}  // namespace hullpack
