#include "gltf/glb_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "gltf/glb_reader.h"
#include "gltf/gltf_document.h"
#include "gltf/meshopt_inflate.h"
#include "gltf_test_scenes.h"

namespace hullpack {
namespace {

using nlohmann::json;
using testing_gltf::ExpectScenesEqual;

GltfDocument Parse(const std::vector<uint8_t>& glb) {
  Result<GltfDocument> doc = DecodeGlbDocument(glb.data(), glb.size(), "test.glb");
  EXPECT_TRUE(doc.ok()) << doc.status().ToString();
  return doc.ok() ? std::move(doc).value() : GltfDocument();
}

TEST(GlbWriterTest, RichSceneRoundTripsExactly) {
  const Scene scene = testing_gltf::MakeRichScene();
  Result<std::vector<uint8_t>> glb = EncodeGlb(scene);
  ASSERT_TRUE(glb.ok()) << glb.status().ToString();
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "rich.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  ExpectScenesEqual(scene, back.value());
  EXPECT_TRUE(back->dropped.empty());
}

TEST(GlbWriterTest, RichSceneJsonLayout) {
  const Scene scene = testing_gltf::MakeRichScene();
  Result<std::vector<uint8_t>> glb = EncodeGlb(scene);
  ASSERT_TRUE(glb.ok());
  const GltfDocument doc = Parse(glb.value());
  const json& j = doc.json();
  EXPECT_EQ(j["asset"]["version"], "2.0");
  EXPECT_EQ(j["asset"]["generator"], "hullpack");
  // Mesh 0: one primitive per material, sharing the vertex accessors; 2 UV sets, colour, skin.
  const json& prims = j["meshes"][0]["primitives"];
  ASSERT_EQ(prims.size(), 2u);
  EXPECT_EQ(prims[0]["material"], 0);
  EXPECT_EQ(prims[1]["material"], 1);
  EXPECT_EQ(prims[0]["attributes"], prims[1]["attributes"]);
  EXPECT_NE(prims[0]["indices"], prims[1]["indices"]);
  for (const char* a : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "TEXCOORD_1", "COLOR_0",
                        "JOINTS_0", "WEIGHTS_0"}) {
    EXPECT_TRUE(prims[0]["attributes"].contains(a)) << a;
  }
  const json& pos = j["accessors"][prims[0]["attributes"]["POSITION"].get<int>()];
  ASSERT_TRUE(pos.contains("min") && pos.contains("max"));
  EXPECT_EQ(pos["min"], json({-1.0, 0.125, 0.0}));
  EXPECT_EQ(pos["max"][0], 1.0);
  const json& joints = j["accessors"][prims[0]["attributes"]["JOINTS_0"].get<int>()];
  EXPECT_EQ(joints["componentType"], gltf::kUnsignedByte);
  const json& idx = j["accessors"][prims[0]["indices"].get<int>()];
  EXPECT_EQ(idx["componentType"], gltf::kUnsignedShort);
  EXPECT_EQ(idx["count"], 30);
  // Mesh 1 (no material ids): one primitive without a material; collides=false in extras.
  ASSERT_EQ(j["meshes"][1]["primitives"].size(), 1u);
  EXPECT_FALSE(j["meshes"][1]["primitives"][0].contains("material"));
  EXPECT_EQ(j["meshes"][1]["extras"]["hullpack"]["collides"], false);
  // Images: embedded with bufferView + mimeType, external as uri.
  EXPECT_TRUE(j["images"][0].contains("bufferView"));
  EXPECT_EQ(j["images"][0]["mimeType"], "image/png");
  EXPECT_EQ(j["images"][1]["uri"], "textures/wood%20dark.png");
  EXPECT_EQ(j["materials"][0]["normalTexture"]["texCoord"], 1);
  EXPECT_FALSE(j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"].contains("texCoord"));
  // Nodes: identity matrices omitted; node 4's second mesh in an appended child.
  EXPECT_FALSE(j["nodes"][1].contains("matrix"));
  EXPECT_TRUE(j["nodes"][0].contains("matrix"));
  ASSERT_EQ(j["nodes"].size(), 6u);
  EXPECT_EQ(j["nodes"][4]["children"], json({5}));
  EXPECT_EQ(j["nodes"][5]["mesh"], 2);
  EXPECT_EQ(j["scenes"][0]["nodes"], json({0, 3, 4}));
  // Mesh 2 has no UVs but its material samples sets 0 and 1: zero-filled accessors without bytes,
  // and a note for the reader to drop them.
  const json& tetra = j["meshes"][2];
  EXPECT_EQ(tetra["extras"]["hullpack"]["uv_sets"], 0);
  for (const char* uv : {"TEXCOORD_0", "TEXCOORD_1"}) {
    const json& a = j["accessors"][tetra["primitives"][0]["attributes"][uv].get<int>()];
    EXPECT_FALSE(a.contains("bufferView")) << uv;
    EXPECT_EQ(a["count"], 4) << uv;
  }
  // Mesh 0's two morph targets: accessors shared by both primitives, names and default weights.
  EXPECT_EQ(j["meshes"][0]["extras"], json({{"targetNames", {"bulge", ""}}}));
  EXPECT_EQ(j["meshes"][0]["weights"], json({0.25, 0.0}));
  const json& targets = j["meshes"][0]["primitives"][0]["targets"];
  ASSERT_EQ(targets.size(), 2u);
  EXPECT_EQ(j["meshes"][0]["primitives"][1]["targets"], targets);
  const json& bulge = j["accessors"][targets[0]["POSITION"].get<int>()];
  EXPECT_EQ(bulge["max"], json({0.0, 0.0, 0.5}));  // glTF wants bounds on target positions
  EXPECT_TRUE(targets[1].contains("NORMAL"));
  EXPECT_EQ(j["skins"][0]["joints"], json({1, 2}));
  EXPECT_EQ(j["accessors"][j["skins"][0]["inverseBindMatrices"].get<int>()]["type"], "MAT4");
  // Every bufferView starts 4-aligned and fits the buffer.
  const size_t buffer_length = j["buffers"][0]["byteLength"].get<size_t>();
  EXPECT_LE(buffer_length, doc.binary().size());
  EXPECT_LT(doc.binary().size() - buffer_length, 4u);  // only the chunk's zero padding
  for (const json& v : j["bufferViews"]) {
    EXPECT_EQ(v.value("byteOffset", 0u) % 4, 0u);
    EXPECT_LE(v.value("byteOffset", 0u) + v["byteLength"].get<size_t>(), buffer_length);
  }
}

TEST(GlbWriterTest, MaterialsKeepAlphaSamplersAndExtensions) {
  const Scene scene = testing_gltf::MakeRichScene();
  Result<std::vector<uint8_t>> glb = EncodeGlb(scene);
  ASSERT_TRUE(glb.ok());
  const GltfDocument doc = Parse(glb.value());
  const json& j = doc.json();
  const json& m = j["materials"];
  EXPECT_EQ(m[0]["alphaMode"], "MASK");
  EXPECT_EQ(m[0]["alphaCutoff"], 0.25);
  EXPECT_EQ(m[0]["normalTexture"]["scale"], 0.5);
  EXPECT_EQ(m[1]["alphaMode"], "BLEND");
  EXPECT_FALSE(m[1].contains("alphaCutoff"));
  EXPECT_EQ(m[1]["occlusionTexture"]["strength"], 0.75);
  EXPECT_EQ(m[1]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"], 4.0);
  EXPECT_TRUE(m[2]["extensions"].contains("KHR_materials_unlit"));
  EXPECT_FALSE(m[2].contains("alphaMode"));
  EXPECT_EQ(j["extensionsUsed"], json({"KHR_materials_emissive_strength", "KHR_materials_unlit",
                                       "KHR_lights_punctual"}));
  EXPECT_FALSE(j.contains("extensionsRequired"));
  // Image 0 is sampled nearest and clamped by one slot and with the defaults by three others: two
  // textures for it, one sampler; image 1 has one texture.
  ASSERT_EQ(j["samplers"].size(), 1u);
  EXPECT_EQ(j["samplers"][0],
            json({{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33648}}));
  ASSERT_EQ(j["textures"].size(), 3u);
  const int base = m[0]["pbrMetallicRoughness"]["baseColorTexture"]["index"];
  EXPECT_EQ(j["textures"][base]["sampler"], 0);
  EXPECT_EQ(m[0]["normalTexture"]["index"],
            m[2]["pbrMetallicRoughness"]["baseColorTexture"]["index"]);
}

TEST(GlbWriterTest, AnimationsDriveTrsNodesAndShareKeyTimes) {
  Scene scene = testing_gltf::MakeRichScene();
  // A node given as a matrix that an animation drives is written as TRS, as glTF requires.
  scene.animations[0].channels.push_back({0, 4, AnimationPath::kRotation});
  Result<std::vector<uint8_t>> glb = EncodeGlb(scene);
  ASSERT_TRUE(glb.ok()) << glb.status().ToString();
  const GltfDocument doc = Parse(glb.value());
  const json& j = doc.json();
  EXPECT_EQ(j["nodes"][2]["translation"], json({0, 1.5, 0}));
  EXPECT_EQ(j["nodes"][2]["rotation"], json({0, 0, 0.6, 0.8}));
  EXPECT_FALSE(j["nodes"][2].contains("matrix"));
  EXPECT_FALSE(j["nodes"][4].contains("matrix"));
  EXPECT_EQ(j["nodes"][4]["scale"], json({2, 2, 2}));
  EXPECT_TRUE(j["nodes"][0].contains("matrix"));  // not animated: kept as the scene has it
  ASSERT_EQ(j["animations"].size(), 1u);
  const json& a = j["animations"][0];
  EXPECT_EQ(a["name"], "wave");
  ASSERT_EQ(a["samplers"].size(), 4u);
  // Morph weights: one SCALAR per target and key, on a node whose transform keeps its form.
  const json& weights = j["accessors"][a["samplers"][3]["output"].get<int>()];
  EXPECT_EQ(weights["type"], "SCALAR");
  EXPECT_EQ(weights["count"], 6);
  EXPECT_EQ(a["channels"][3]["target"]["path"], "weights");
  EXPECT_EQ(a["samplers"][0]["input"], a["samplers"][1]["input"]);
  EXPECT_NE(a["samplers"][0]["input"], a["samplers"][2]["input"]);
  EXPECT_FALSE(a["samplers"][0].contains("interpolation"));
  EXPECT_EQ(a["samplers"][1]["interpolation"], "STEP");
  EXPECT_EQ(a["samplers"][2]["interpolation"], "CUBICSPLINE");
  const json& times = j["accessors"][a["samplers"][0]["input"].get<int>()];
  EXPECT_EQ(times["min"], json({0.0}));
  EXPECT_EQ(times["max"], json({1.0}));
  EXPECT_EQ(j["accessors"][a["samplers"][2]["output"].get<int>()]["count"], 6);
  ASSERT_EQ(a["channels"].size(), 5u);
  EXPECT_EQ(a["channels"][4]["target"], json({{"node", 4}, {"path", "rotation"}}));
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "animated.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  for (size_t k = 0; k < 16; ++k)
    EXPECT_NEAR(back->nodes[4].local_transform[k], scene.nodes[4].local_transform[k], 1e-12) << k;
}

TEST(GlbWriterTest, RotationsQuantizedToNormalizedShortsOnRequest) {
  const Scene scene = testing_gltf::MakeRichScene();
  GlbWriteOptions options;
  options.quantize_rotations = true;
  Result<std::vector<uint8_t>> glb = EncodeGlb(scene, options);
  ASSERT_TRUE(glb.ok()) << glb.status().ToString();
  const GltfDocument doc = Parse(glb.value());
  const json& j = doc.json();
  const json& rotation = j["accessors"][j["animations"][0]["samplers"][0]["output"].get<int>()];
  EXPECT_EQ(rotation["componentType"], gltf::kShort);
  EXPECT_TRUE(rotation["normalized"].get<bool>());
  // One bufferView per kind of element for all of the clip's arrays: times, scalars (the
  // weights), VEC3 (translation and cubic-spline scale) and rotations.
  std::set<int> views;
  for (const json& s : j["animations"][0]["samplers"]) {
    views.insert(j["accessors"][s["input"].get<int>()]["bufferView"].get<int>());
    views.insert(j["accessors"][s["output"].get<int>()]["bufferView"].get<int>());
  }
  EXPECT_EQ(views.size(), 4u);
  for (const json& e : j["extensionsUsed"]) EXPECT_NE(e, "EXT_meshopt_compression");
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "quantized.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  const std::vector<float>& in = scene.animations[0].samplers[0].values;
  const std::vector<float>& out = back->animations[0].samplers[0].values;
  ASSERT_EQ(in.size(), out.size());
  for (size_t k = 0; k < in.size(); ++k) EXPECT_NEAR(in[k], out[k], 0.5 / 32767) << k;
  EXPECT_NE(in, out);  // 0.6 and 0.8 are not multiples of 1/32767
}

// The rich scene's clip with 240 keys per track (a smooth turn, hop, swell and blend), so that
// compressing it pays; key times that no filter could keep exactly (they must come back bit for
// bit), and the cubic spline's tangents.
Scene LongClipScene() {
  Scene scene = testing_gltf::MakeRichScene();
  Animation& a = scene.animations[0];
  for (size_t si = 0; si < a.samplers.size(); ++si) {
    AnimationSampler& s = a.samplers[si];
    const size_t width = ChannelWidth(scene, a.channels[si]);
    const size_t per_key = (s.interpolation == Interpolation::kCubicSpline ? 3 : 1) * width;
    s.times.clear();
    s.values.clear();
    for (int k = 0; k < 240; ++k) {
      s.times.push_back(float(k) / 30.0f + 0.013f * float(si));
      const double x = 0.02 * k;
      for (size_t v = 0; v < per_key; ++v) {
        if (a.channels[si].path == AnimationPath::kRotation) {
          const float q[4] = {float(0.3 * std::sin(x)), 0.0f, float(std::sin(x) * 0.9),
                              float(std::cos(x))};
          const double n = std::sqrt(q[0] * q[0] + q[2] * q[2] + q[3] * q[3]);
          s.values.push_back(float(q[v % 4] / n));
        } else {
          s.values.push_back(float((1 + v) * std::sin(x + 0.1 * double(v)) + 2.0));
        }
      }
    }
  }
  return scene;
}

TEST(GlbWriterTest, CompressedAnimationsDecodeWithinTheirFilters) {
  GlbWriteOptions options;
  options.quantize_rotations = true;
  options.compress_animations = true;
  {  // A clip of a few keys is smaller plain: nothing is compressed, nothing required.
    Result<std::vector<uint8_t>> small = EncodeGlb(testing_gltf::MakeRichScene(), options);
    ASSERT_TRUE(small.ok()) << small.status().ToString();
    const GltfDocument plain = Parse(small.value());  // kept alive for the loop below
    for (const json& e : plain.json()["extensionsUsed"]) EXPECT_NE(e, "EXT_meshopt_compression");
  }
  const Scene scene = LongClipScene();
  Result<std::vector<uint8_t>> glb = EncodeGlb(scene, options);
  ASSERT_TRUE(glb.ok()) << glb.status().ToString();
  const GltfDocument doc = Parse(glb.value());
  const json& j = doc.json();
  EXPECT_EQ(j["extensionsRequired"], json({"EXT_meshopt_compression"}));
  ASSERT_EQ(j["buffers"].size(), 2u);
  EXPECT_TRUE(j["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"].get<bool>());
  // Every view of the clip is compressed, each with the filter of its kind of element.
  std::map<std::string, int> filters;
  for (const json& s : j["animations"][0]["samplers"]) {
    for (const char* end : {"input", "output"}) {
      const json& view =
          j["bufferViews"][j["accessors"][s[end].get<int>()]["bufferView"].get<int>()];
      ASSERT_EQ(view["buffer"], 1);
      const json& ext = view["extensions"]["EXT_meshopt_compression"];
      EXPECT_EQ(ext["mode"], "ATTRIBUTES");
      EXPECT_LT(ext["byteLength"].get<size_t>(), view["byteLength"].get<size_t>() + 64);
      ++filters[ext.value("filter", std::string("NONE"))];
    }
  }
  EXPECT_GT(filters["NONE"], 0);
  EXPECT_GT(filters["QUATERNION"], 0);
  EXPECT_GT(filters["EXPONENTIAL"], 0);
  GltfDocument inflated = Parse(glb.value());
  const Status s = InflateMeshoptBufferViews(inflated, "compressed.glb");
  ASSERT_TRUE(s.ok()) << s.ToString();
  Result<Scene> back = DecodeGltfDocument(inflated, "compressed.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  ASSERT_EQ(back->animations.size(), 1u);
  const Animation& in = scene.animations[0];
  const Animation& out = back->animations[0];
  ASSERT_EQ(in.samplers.size(), out.samplers.size());
  for (size_t k = 0; k < in.samplers.size(); ++k) {
    const AnimationSampler& a = in.samplers[k];
    const AnimationSampler& b = out.samplers[k];
    EXPECT_EQ(a.times, b.times) << k;
    ASSERT_EQ(a.values.size(), b.values.size()) << k;
    const size_t width = ChannelWidth(scene, in.channels[k]);
    const size_t element = width == 0 || in.channels[k].path == AnimationPath::kWeights ? 1 : width;
    for (size_t e = 0; e < a.values.size(); e += element) {
      double largest = 0;
      for (size_t c = 0; c < element; ++c)
        largest = std::max(largest, std::fabs(double(a.values[e + c])));
      // Quaternions within 1/32767 per component, up to their sign (the filter makes the
      // largest component positive: the same rotation, and glTF interpolates along the shorter
      // arc); the exponential filter within 2^-15 of the element's largest component.
      const bool quaternion = in.channels[k].path == AnimationPath::kRotation &&
                              a.interpolation != Interpolation::kCubicSpline;
      double dot = 0;
      for (size_t c = 0; c < element; ++c) dot += double(a.values[e + c]) * b.values[e + c];
      const double sign = quaternion && dot < 0 ? -1 : 1;
      const double bound = quaternion ? 1.0 / 32767 : largest * std::ldexp(1.0, -15);
      for (size_t c = 0; c < element; ++c)
        EXPECT_NEAR(a.values[e + c], sign * b.values[e + c], bound) << k << " " << e + c;
    }
  }
}

TEST(GlbWriterTest, WeightsChannelsDriveEveryMeshOfTheirNode) {
  // Node 3 shows a second mesh with as many morph targets (assimp splits a mesh by material):
  // the clip's weights drive both, in the file and after reading it back.
  Scene scene = testing_gltf::MakeRichScene();
  Node& node = scene.nodes[3];
  ASSERT_EQ(node.meshes.size(), 1u);
  Mesh second = scene.meshes[static_cast<size_t>(node.meshes[0])];
  second.name = "second";
  ASSERT_EQ(second.morph_targets.size(), 2u);
  node.meshes.push_back(static_cast<int>(scene.meshes.size()));
  scene.meshes.push_back(second);
  Result<std::vector<uint8_t>> glb = EncodeGlb(scene);
  ASSERT_TRUE(glb.ok()) << glb.status().ToString();
  const GltfDocument doc = Parse(glb.value());
  const json& j = doc.json();
  std::vector<json> weights;
  for (const json& c : j["animations"][0]["channels"]) {
    if (c["target"]["path"] == "weights") weights.push_back(c);
  }
  ASSERT_EQ(weights.size(), 2u);
  EXPECT_EQ(weights[0]["target"]["node"], 3);
  EXPECT_EQ(weights[0]["sampler"], weights[1]["sampler"]);
  const json& child = j["nodes"][weights[1]["target"]["node"].get<int>()];
  EXPECT_EQ(child["mesh"], scene.meshes.size() - 1);
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "two_meshes.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  ExpectScenesEqual(scene, back.value());
}

TEST(GlbWriterTest, RejectsInvalidAnimations) {
  const Scene good = testing_gltf::MakeRichScene();
  auto rejected = [&](const std::function<void(Scene&)>& edit, const std::string& needle) {
    Scene s = good;
    edit(s);
    Result<std::vector<uint8_t>> glb = EncodeGlb(s);
    ASSERT_FALSE(glb.ok()) << needle;
    EXPECT_NE(glb.status().message().find(needle), std::string::npos) << glb.status().ToString();
  };
  rejected([](Scene& s) { s.animations[0].channels[0].node = 9; }, "targets node 9");
  rejected([](Scene& s) { s.animations[0].channels[0].sampler = 5; }, "uses sampler 5");
  rejected([](Scene& s) { s.animations[0].samplers[0].times[1] = 0.0f; }, "not ascending");
  rejected([](Scene& s) { s.animations[0].samplers[0].values.pop_back(); }, "values for 3 keys");
  rejected([](Scene& s) { s.animations[0].channels.push_back(s.animations[0].channels[0]); },
           "repeats the node and path");
  rejected([](Scene& s) { s.animations[0].channels[1].sampler = 0; }, "another width");
  rejected(
      [](Scene& s) {
        s.nodes[0].local_transform[4] = 0.5;  // shear
        s.animations[0].channels.push_back({1, 0, AnimationPath::kTranslation});
      },
      "no translation-rotation-scale form");
  rejected([](Scene& s) { s.materials[0].alpha_cutoff = -1; }, "alpha cutoff");
  rejected([](Scene& s) { s.cameras[0].znear = 0; }, "camera 0 has invalid");
  rejected([](Scene& s) { s.lights[0].inner_cone_angle = 1; }, "light 0 has invalid");
  rejected([](Scene& s) { s.nodes[1].light = 3; }, "references light 3");
  rejected([](Scene& s) { s.nodes[1].camera = 2; }, "references camera 2");
}

TEST(GlbWriterTest, LargeMeshUsesUnsignedIntIndices) {
  const Scene scene = testing_gltf::MakeLargeScene();
  ASSERT_GT(scene.meshes[0].vertex_count(), 65535u);
  Result<std::vector<uint8_t>> glb = EncodeGlb(scene);
  ASSERT_TRUE(glb.ok()) << glb.status().ToString();
  const GltfDocument doc = Parse(glb.value());
  const json& prim = doc.json()["meshes"][0]["primitives"][0];
  EXPECT_EQ(doc.json()["accessors"][prim["indices"].get<int>()]["componentType"],
            gltf::kUnsignedInt);
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "large.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  ExpectScenesEqual(scene, back.value());
}

TEST(GlbWriterTest, IndexTypeSwitchesExactlyAt65536Vertices) {
  for (size_t vc : {65535u, 65536u}) {
    Scene s;
    Mesh m;
    for (size_t v = 0; v < vc; ++v)
      m.positions.insert(m.positions.end(), {static_cast<float>(v), 0, 0});
    m.indices = {0, 1, static_cast<uint32_t>(vc - 1)};
    s.meshes.push_back(m);
    Result<std::vector<uint8_t>> glb = EncodeGlb(s);
    ASSERT_TRUE(glb.ok());
    const GltfDocument doc = Parse(glb.value());
    const int idx = doc.json()["meshes"][0]["primitives"][0]["indices"].get<int>();
    EXPECT_EQ(doc.json()["accessors"][idx]["componentType"],
              vc < 65536 ? gltf::kUnsignedShort : gltf::kUnsignedInt);
    Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "edge.glb");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->meshes[0].indices, m.indices);
  }
}

TEST(GlbWriterTest, InterleavedMaterialIdsAreGroupedStably) {
  Scene s;
  s.materials.resize(3);
  Mesh m = testing_gltf::MakeGrid(3, 1, 1, 0.0f);  // 6 triangles
  m.material_ids = {2, 0, 2, 1, 0, 2};
  s.meshes.push_back(m);
  GltfDocument doc;
  GltfSceneLayout layout;
  ASSERT_TRUE(BuildGltfDocument(s, {}, &doc, &layout).ok());
  ASSERT_EQ(layout.meshes.size(), 1u);
  const std::vector<uint32_t> expected_order = {1, 4, 3, 0, 2, 5};
  EXPECT_EQ(layout.meshes[0].triangle_order, expected_order);
  ASSERT_EQ(layout.meshes[0].primitives.size(), 3u);
  EXPECT_EQ(layout.meshes[0].primitives[0].material, 0);
  EXPECT_EQ(layout.meshes[0].primitives[2].triangle_count, 3u);
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  ASSERT_TRUE(glb.ok());
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "grouped.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  const Mesh& b = back->meshes[0];
  ASSERT_EQ(b.triangle_count(), 6u);
  for (size_t t = 0; t < 6; ++t) {
    const uint32_t src = expected_order[t];
    EXPECT_EQ(b.material_ids[t], m.material_ids[src]);
    for (size_t c = 0; c < 3; ++c) EXPECT_EQ(b.indices[3 * t + c], m.indices[3 * src + c]);
  }
  EXPECT_EQ(b.positions, m.positions);
}

TEST(GlbWriterTest, SceneWithoutNodesGetsOneNodePerMesh) {
  Scene s;
  s.meshes.push_back(testing_gltf::MakeGrid(1, 1, 0, 0.0f));
  s.meshes.push_back(testing_gltf::MakeGrid(2, 1, 0, 1.0f));
  s.meshes[1].name = "second";
  Result<std::vector<uint8_t>> glb = EncodeGlb(s);
  ASSERT_TRUE(glb.ok());
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "nodes.glb");
  ASSERT_TRUE(back.ok());
  ASSERT_EQ(back->nodes.size(), 2u);
  EXPECT_EQ(back->nodes[0].meshes, std::vector<int>({0}));
  EXPECT_EQ(back->nodes[1].meshes, std::vector<int>({1}));
  EXPECT_EQ(back->nodes[1].name, "second");
  EXPECT_EQ(back->nodes[1].parent, -1);
}

TEST(GlbWriterTest, WideJointIndicesUseUnsignedShort) {
  Scene s = testing_gltf::MakeRichScene();
  // A skin with 300 joints: every node 5.. is a child of joint1.
  for (int i = 0; i < 298; ++i) {
    Node n;
    n.name = "extra joint " + std::to_string(i);
    n.parent = 2;
    s.nodes[2].children.push_back(static_cast<int>(s.nodes.size()));
    s.skins[0].joints.push_back(static_cast<int>(s.nodes.size()));
    s.nodes.push_back(n);
  }
  s.skins[0].inverse_bind_matrices.clear();
  s.meshes[0].joints[1] = 299;
  Result<std::vector<uint8_t>> glb = EncodeGlb(s);
  ASSERT_TRUE(glb.ok()) << glb.status().ToString();
  const GltfDocument doc = Parse(glb.value());
  const int acc = doc.json()["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"].get<int>();
  EXPECT_EQ(doc.json()["accessors"][acc]["componentType"], gltf::kUnsignedShort);
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "joints.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  ExpectScenesEqual(s, back.value());
}

TEST(GlbWriterTest, RejectsInconsistentScenes) {
  const Scene good = testing_gltf::MakeRichScene();
  struct Case {
    const char* what;
    void (*mutate)(Scene&);
    StatusCode code;
  };
  const Case cases[] = {
      {"index out of range", [](Scene& s) { s.meshes[0].indices[4] = 1000; },
       StatusCode::kInvalidMesh},
      {"short normals", [](Scene& s) { s.meshes[0].normals.pop_back(); }, StatusCode::kInvalidMesh},
      {"uv set size", [](Scene& s) { s.meshes[0].uv_sets[1].resize(3); }, StatusCode::kInvalidMesh},
      {"NaN position", [](Scene& s) { s.meshes[1].positions[0] = std::nanf(""); },
       StatusCode::kInvalidMesh},
      {"material id", [](Scene& s) { s.meshes[0].material_ids[0] = 7; }, StatusCode::kInvalidMesh},
      {"no triangles", [](Scene& s) { s.meshes[2].indices.clear(); }, StatusCode::kInvalidMesh},
      {"weights without joints", [](Scene& s) { s.meshes[0].joints.clear(); },
       StatusCode::kInvalidMesh},
      {"texture image", [](Scene& s) { s.materials[0].normal_texture.image = 9; },
       StatusCode::kInvalidArgument},
      {"skin joint", [](Scene& s) { s.skins[0].joints.push_back(42); },
       StatusCode::kInvalidArgument},
      {"ibm count", [](Scene& s) { s.skins[0].inverse_bind_matrices.resize(20); },
       StatusCode::kInvalidArgument},
      {"joint index vs skin", [](Scene& s) { s.meshes[0].joints[0] = 5; },
       StatusCode::kInvalidArgument},
      {"child parent mismatch", [](Scene& s) { s.nodes[2].parent = 0; },
       StatusCode::kInvalidArgument},
      {"cycle",
       [](Scene& s) {
         s.nodes[0].parent = 2;
         s.nodes[2].children.push_back(0);
       },
       StatusCode::kInvalidArgument},
      {"node mesh", [](Scene& s) { s.nodes[4].meshes.push_back(3); }, StatusCode::kInvalidArgument},
      {"image without data", [](Scene& s) { s.images[0].bytes.clear(); },
       StatusCode::kInvalidArgument},
  };
  for (const Case& c : cases) {
    Scene s = good;
    c.mutate(s);
    Result<std::vector<uint8_t>> glb = EncodeGlb(s);
    ASSERT_FALSE(glb.ok()) << c.what;
    EXPECT_EQ(glb.status().code(), c.code) << c.what << ": " << glb.status().ToString();
  }
}

TEST(GlbWriterTest, ImageUrisAreMadeValidWithoutDoubleEncoding) {
  Scene s;
  s.meshes.push_back(testing_gltf::MakeGrid(1, 1, 1, 0.0f));
  for (const char* uri :
       {"tex\\my wood.png", "a%20b.png", "caf\xC3\xA9|{x}.jpg", "plain/ok-_.~!$&'()*+,;=:@.png"}) {
    Image img;
    img.uri = uri;
    s.images.push_back(img);
  }
  Result<std::vector<uint8_t>> glb = EncodeGlb(s);
  ASSERT_TRUE(glb.ok());
  const GltfDocument doc = Parse(glb.value());
  const json& images = doc.json()["images"];
  EXPECT_EQ(images[0]["uri"], "tex/my%20wood.png");
  EXPECT_EQ(images[1]["uri"], "a%20b.png");
  EXPECT_EQ(images[2]["uri"], "caf%C3%A9%7C%7Bx%7D.jpg");
  EXPECT_EQ(images[3]["uri"], "plain/ok-_.~!$&'()*+,;=:@.png");
}

TEST(GlbWriterTest, OptionsChangeGeneratorAndJointType) {
  GlbWriteOptions options;
  options.generator = "hullpack test 1.2";
  options.compact_joints = false;
  Result<std::vector<uint8_t>> glb = EncodeGlb(testing_gltf::MakeRichScene(), options);
  ASSERT_TRUE(glb.ok());
  const GltfDocument doc = Parse(glb.value());
  EXPECT_EQ(doc.json()["asset"]["generator"], "hullpack test 1.2");
  const int acc = doc.json()["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"].get<int>();
  EXPECT_EQ(doc.json()["accessors"][acc]["componentType"], gltf::kUnsignedShort);
}

TEST(GlbWriterTest, PackerCanExtendTheDocument) {
  // What the packaging stage does: build the plain document, add a compressed stream and
  // extensions.
  const Scene scene = testing_gltf::MakeRichScene();
  GltfDocument doc;
  GltfSceneLayout layout;
  ASSERT_TRUE(BuildGltfDocument(scene, {}, &doc, &layout).ok());
  const std::vector<uint8_t> stream = {1, 2, 3, 4, 5};
  const int view = doc.AddBufferView(stream, 8);
  json& prim = doc.json()["meshes"][layout.meshes[2].gltf_mesh]["primitives"][0];
  prim["extensions"]["EXT_hullpack_test"] = {{"bufferView", view}};
  doc.json()["nodes"][layout.mesh_nodes[0][0]]["extensions"]["EXT_hullpack_body"] = {{"mass", 2}};
  doc.json()["extensions"]["EXT_hullpack_body"] = {{"shapes", json::array()}};
  doc.UseExtension("EXT_hullpack_test", true);
  doc.UseExtension("EXT_hullpack_body", false);
  doc.UseExtension("EXT_hullpack_test", true);
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  ASSERT_TRUE(glb.ok());
  const GltfDocument parsed = Parse(glb.value());
  EXPECT_EQ(parsed.json()["extensionsUsed"],
            json({"KHR_materials_emissive_strength", "KHR_materials_unlit", "KHR_lights_punctual",
                  "EXT_hullpack_test", "EXT_hullpack_body"}));
  EXPECT_EQ(parsed.json()["extensionsRequired"], json({"EXT_hullpack_test"}));
  const json& v = parsed.json()["bufferViews"][view];
  EXPECT_EQ(v["byteOffset"].get<size_t>() % 8, 0u);
  EXPECT_EQ(0,
            std::memcmp(parsed.binary().data() + v["byteOffset"].get<size_t>(), stream.data(), 5));
  // The plain reader refuses the unknown required extension unless the caller handles it.
  Result<Scene> plain = DecodeGltfDocument(parsed, "ext.glb");
  ASSERT_FALSE(plain.ok());
  EXPECT_EQ(plain.status().code(), StatusCode::kUnsupported);
  EXPECT_NE(plain.status().message().find("EXT_hullpack_test"), std::string::npos);
  GltfReadOptions options;
  options.handled_extensions = {"EXT_hullpack_test", "EXT_hullpack_body"};
  Result<Scene> handled = DecodeGltfDocument(parsed, "ext.glb", options);
  ASSERT_TRUE(handled.ok()) << handled.status().ToString();
  ExpectScenesEqual(scene, handled.value());
  EXPECT_TRUE(handled->dropped.empty());
}

}  // namespace
}  // namespace hullpack
