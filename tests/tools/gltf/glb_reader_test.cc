// The reader on general glTF 2.0 that the project's writer does not produce.
#include "gltf/glb_reader.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include "gltf/gltf_document.h"

namespace hullpack {
namespace {

using nlohmann::json;

template <typename T>
void Put(std::vector<uint8_t>& bin, std::initializer_list<T> values) {
  for (T v : values) {
    uint8_t b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    bin.insert(bin.end(), b, b + sizeof(T));
  }
}

void Pad4(std::vector<uint8_t>& bin) {
  while (bin.size() % 4 != 0) bin.push_back(0);
}

Result<Scene> Decode(const json& j, const std::vector<uint8_t>& bin,
                     const std::string& name = "test.glb") {
  GltfDocument doc(j, bin, !bin.empty(), 0);
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  EXPECT_TRUE(glb.ok());
  return DecodeGlb(glb->data(), glb->size(), name);
}

bool Contains(const std::vector<std::string>& lines, const std::string& needle) {
  for (const std::string& l : lines) {
    if (l.find(needle) != std::string::npos) return true;
  }
  return false;
}

// A triangle with UVs (0,0) (1,0) (0,1) whose two primitives use `materials` 0 and 1 in turn.
json TransformedUvDocument(const json& materials, bool share_vertices, std::vector<uint8_t>* bin) {
  bin->clear();
  Put<float>(*bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});  // 0: POSITION
  Put<float>(*bin, {0, 0, 1, 0, 0, 1});           // 36: TEXCOORD_0
  json prim0 = {{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"material", 0}};
  json prim1 = prim0;
  prim1["material"] = 1;
  if (!share_vertices) prim1["attributes"]["TEXCOORD_0"] = 2;  // same data, its own accessor
  return {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_texture_transform"}},
      {"buffers", {{{"byteLength", bin->size()}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
        {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", gltf::kFloat}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", gltf::kFloat}, {"count", 3}, {"type", "VEC2"}},
        {{"bufferView", 1}, {"componentType", gltf::kFloat}, {"count", 3}, {"type", "VEC2"}}}},
      {"images", {{{"uri", "a.png"}}}},
      {"textures", {{{"source", 0}}}},
      {"materials", materials},
      {"meshes", {{{"primitives", {prim0, prim1}}}}},
      {"nodes", {{{"mesh", 0}}}},
  };
}

json TextureWith(const json& transform) {
  json info = {{"index", 0}};
  if (!transform.is_null()) info["extensions"] = {{"KHR_texture_transform", transform}};
  return info;
}

TEST(GlbReaderTest, TextureTransformsAreBakedIntoTheUvs) {
  // Material 0: offset (0.5, 0.25), scale (0.5, 2); material 1: a quarter turn. The second
  // primitive has its own UV accessor, so each gets its own transform.
  const json offset_scale = {{"offset", {0.5, 0.25}}, {"scale", {0.5, 2}}};
  const json quarter_turn = {{"rotation", M_PI / 2}};
  const json materials = {
      {{"pbrMetallicRoughness", {{"baseColorTexture", TextureWith(offset_scale)}}}},
      {{"emissiveTexture", TextureWith(quarter_turn)}}};
  std::vector<uint8_t> bin;
  Result<Scene> s = Decode(TransformedUvDocument(materials, false, &bin), bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  const std::vector<float>& uv = s->meshes[0].uv_sets.at(0);
  ASSERT_EQ(uv.size(), 12u);
  // uv' = offset + rotate(scale * uv): (0,0) -> (0.5,0.25), (1,0) -> (1,0.25), (0,1) -> (0.5,2.25).
  const float first[6] = {0.5f, 0.25f, 1.0f, 0.25f, 0.5f, 2.25f};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(uv[i], first[i], 1e-6) << i;
  // A quarter turn as viewers apply it: u' = v, v' = -u.
  const float second[6] = {0, 0, 0, -1, 1, 0};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(uv[6 + i], second[i], 1e-6) << i;
  EXPECT_FALSE(Contains(s->dropped, "KHR_texture_transform"));  // understood, not ignored
}

TEST(GlbReaderTest, TextureTransformsThatCannotBeBakedAreReported) {
  const json shift = {{"offset", {0.5, 0}}};
  // One material whose two textures sample TEXCOORD_0 with different transforms.
  json conflicting = {{{"pbrMetallicRoughness", {{"baseColorTexture", TextureWith(shift)}}},
                       {"normalTexture", TextureWith(nullptr)}},
                      json::object()};
  std::vector<uint8_t> bin;
  Result<Scene> s = Decode(TransformedUvDocument(conflicting, false, &bin), bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_TRUE(Contains(s->dropped, "different KHR_texture_transforms"))
      << ::testing::PrintToString(s->dropped);
  EXPECT_NEAR(s->meshes[0].uv_sets[0][2], 1.0f, 1e-6);  // kept as stored
  // Two primitives sharing vertices, only one transformed: the first one's bake stays.
  json split = {{{"pbrMetallicRoughness", {{"baseColorTexture", TextureWith(shift)}}}},
                {{"pbrMetallicRoughness", {{"baseColorTexture", TextureWith(nullptr)}}}}};
  s = Decode(TransformedUvDocument(split, true, &bin), bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_TRUE(Contains(s->dropped, "shares its vertices")) << ::testing::PrintToString(s->dropped);
  EXPECT_NEAR(s->meshes[0].uv_sets[0][0], 0.5f, 1e-6);
}

TEST(GlbReaderTest, NormalizedAndQuantizedAttributes) {
  std::vector<uint8_t> bin;
  Put<int16_t>(bin, {0, 0, 0, 100, 0, 0, 0, -200, 0, 0});  // 0: POSITION SHORT (+pad)
  Put<int8_t>(bin,
              {0, 0, 127, 0, 0, 0, -127, 0, -128, 0, 0, 0});  // 20: NORMAL BYTE norm (stride 4)
  Put<uint16_t>(bin, {0, 65535, 65535, 0, 32768, 0});         // 32: TEXCOORD USHORT norm
  Pad4(bin);
  Put<uint8_t>(
      bin, {255, 0, 0, 0, 0, 255, 0, 0, 0, 51, 102, 0});  // 44: COLOR VEC3 UBYTE norm (stride 4)
  Put<uint8_t>(bin, {255, 0, 0, 0, 128, 127, 0, 0, 0, 0, 0, 255});  // 56: WEIGHTS UBYTE norm
  Put<uint8_t>(bin, {0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0});          // 68: JOINTS UBYTE
  json j = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_mesh_quantization"}},
      {"extensionsRequired", {"KHR_mesh_quantization"}},
      {"buffers", {{{"byteLength", bin.size()}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 20}, {"byteStride", 8}},
        {{"buffer", 0}, {"byteOffset", 20}, {"byteLength", 12}, {"byteStride", 4}},
        {{"buffer", 0}, {"byteOffset", 32}, {"byteLength", 12}},
        {{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 12}, {"byteStride", 4}},
        {{"buffer", 0}, {"byteOffset", 56}, {"byteLength", 24}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", gltf::kShort}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 1},
         {"componentType", gltf::kByte},
         {"normalized", true},
         {"count", 3},
         {"type", "VEC3"}},
        {{"bufferView", 2},
         {"componentType", gltf::kUnsignedShort},
         {"normalized", true},
         {"count", 3},
         {"type", "VEC2"}},
        {{"bufferView", 3},
         {"componentType", gltf::kUnsignedByte},
         {"normalized", true},
         {"count", 3},
         {"type", "VEC3"}},
        {{"bufferView", 4},
         {"componentType", gltf::kUnsignedByte},
         {"normalized", true},
         {"count", 3},
         {"type", "VEC4"}},
        {{"bufferView", 4},
         {"byteOffset", 12},
         {"componentType", gltf::kUnsignedByte},
         {"count", 3},
         {"type", "VEC4"}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes",
             {{"POSITION", 0},
              {"NORMAL", 1},
              {"TEXCOORD_0", 2},
              {"COLOR_0", 3},
              {"WEIGHTS_0", 4},
              {"JOINTS_0", 5}}}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
  };
  // The SHORT positions use a stride of 8: (0,0,0) (100,0,0) (0,-200,0) at offsets 0, 8, 16... but
  // the view holds 20 bytes, so element 2 starts at 16 and its 6 bytes end at 22 > 20: rejected.
  Result<Scene> too_short = Decode(j, bin);
  ASSERT_FALSE(too_short.ok());
  EXPECT_EQ(too_short.status().code(), StatusCode::kParseError);
  EXPECT_NE(too_short.status().message().find("accessors[0]"), std::string::npos)
      << too_short.status().ToString();
  // With a 6-byte element pitch the layout is tight (the stride is dropped): (0,0,0) (100,0,0)
  // (0,-200,0)
  j["bufferViews"][0].erase("byteStride");
  j["bufferViews"][0]["byteLength"] = 18;
  Result<Scene> s = Decode(j, bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  const Mesh& m = s->meshes[0];
  EXPECT_EQ(m.positions, std::vector<float>({0, 0, 0, 100, 0, 0, 0, -200, 0}));
  // BYTE -128 normalizes to -1 (clamped), per the spec's max(c / 127, -1).
  EXPECT_EQ(m.normals, std::vector<float>({0, 0, 1, 0, 0, -1, -1, 0, 0}));
  ASSERT_EQ(m.uv_sets.size(), 1u);
  EXPECT_FLOAT_EQ(m.uv_sets[0][1], 1.0f);
  EXPECT_FLOAT_EQ(m.uv_sets[0][4], 32768.0f / 65535.0f);
  EXPECT_EQ(m.colors.size(), 12u);
  EXPECT_FLOAT_EQ(m.colors[0], 1.0f);
  EXPECT_FLOAT_EQ(m.colors[3], 1.0f);  // VEC3 colour gets alpha 1
  EXPECT_FLOAT_EQ(m.colors[9], 0.2f);
  EXPECT_FLOAT_EQ(m.colors[10], 0.4f);
  EXPECT_FLOAT_EQ(m.weights[4], 128.0f / 255.0f);
  EXPECT_EQ(m.joints, std::vector<uint16_t>({0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0}));
  EXPECT_EQ(m.indices, std::vector<uint32_t>({0, 1, 2}));  // non-indexed triangles
  EXPECT_FALSE(Contains(s->dropped, "KHR_mesh_quantization"));
}

TEST(GlbReaderTest, NormalBytesClampAtMinusOne) {
  std::vector<uint8_t> bin;
  Put<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  Put<int8_t>(bin, {-128, 0, 0, 0, 0, -127, 0, 0, 0, 127, 0, 0});
  json j = {{"asset", {{"version", "2.0"}}},
            {"buffers", {{{"byteLength", bin.size()}}}},
            {"bufferViews",
             {{{"buffer", 0}, {"byteLength", 36}},
              {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 12}, {"byteStride", 4}}}},
            {"accessors",
             {{{"bufferView", 0}, {"componentType", gltf::kFloat}, {"count", 3}, {"type", "VEC3"}},
              {{"bufferView", 1},
               {"componentType", gltf::kByte},
               {"normalized", true},
               {"count", 3},
               {"type", "VEC3"}}}},
            {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}}}}}}}};
  Result<Scene> s = Decode(j, bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->meshes[0].normals, std::vector<float>({-1, 0, 0, 0, -1, 0, 0, 1, 0}));
}

// Four vertices, interleaved POSITION+NORMAL (stride 24), and three primitives.
json InterleavedQuad(std::vector<uint8_t>* bin) {
  for (int v = 0; v < 4; ++v) {
    Put<float>(*bin,
               {static_cast<float>(v & 1), static_cast<float>(v >> 1), 0.0f, 0.0f, 0.0f, 1.0f});
  }
  Put<uint8_t>(*bin, {0, 1, 2, 3});   // 96: strip
  Put<uint16_t>(*bin, {0, 1, 3, 2});  // 100: fan
  Put<uint32_t>(*bin, {0, 1, 3});     // 108: triangles
  return {{"asset", {{"version", "2.0"}}},
          {"buffers", {{{"byteLength", bin->size()}}}},
          {"bufferViews",
           {{{"buffer", 0}, {"byteLength", 96}, {"byteStride", 24}, {"target", gltf::kArrayBuffer}},
            {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 24}}}},
          {"accessors",
           {{{"bufferView", 0}, {"componentType", gltf::kFloat}, {"count", 4}, {"type", "VEC3"}},
            {{"bufferView", 0},
             {"byteOffset", 12},
             {"componentType", gltf::kFloat},
             {"count", 4},
             {"type", "VEC3"}},
            {{"bufferView", 1},
             {"componentType", gltf::kUnsignedByte},
             {"count", 4},
             {"type", "SCALAR"}},
            {{"bufferView", 1},
             {"byteOffset", 4},
             {"componentType", gltf::kUnsignedShort},
             {"count", 4},
             {"type", "SCALAR"}},
            {{"bufferView", 1},
             {"byteOffset", 12},
             {"componentType", gltf::kUnsignedInt},
             {"count", 3},
             {"type", "SCALAR"}}}},
          {"materials", {{{"name", "red"}}}},
          {"meshes",
           {{{"name", "quad"},
             {"primitives",
              {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}},
                {"indices", 2},
                {"mode", 5},
                {"material", 0}},
               {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 3}, {"mode", 6}},
               {{"attributes", {{"POSITION", 0}}}, {"indices", 4}, {"material", 0}}}}}}},
          {"nodes",
           {{{"mesh", 0},
             {"translation", {1, 2, 3}},
             {"rotation", {0, 0, std::sqrt(0.5), std::sqrt(0.5)}},
             {"scale", {2, 2, 2}}}}}};
}

TEST(GlbReaderTest, StridesStripsFansAndMixedPrimitives) {
  std::vector<uint8_t> bin;
  const json j = InterleavedQuad(&bin);
  Result<Scene> s = Decode(j, bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  const Mesh& m = s->meshes[0];
  EXPECT_EQ(m.name, "quad");
  // Primitives 1 and 2 share (POSITION 0, NORMAL 1); primitive 3 has a different set, so its
  // vertices are appended and get zero normals.
  ASSERT_EQ(m.vertex_count(), 8u);
  EXPECT_EQ(std::vector<float>(m.positions.begin(), m.positions.begin() + 12),
            std::vector<float>({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}));
  EXPECT_EQ(m.normals[2], 1.0f);
  EXPECT_EQ(m.normals[3 * 4 + 2], 0.0f);
  const std::vector<uint32_t> expected = {0, 1, 2, 1, 3, 2,  // strip 0 1 2 3 -> (0 1 2) (1 3 2)
                                          1, 3, 0, 3, 2, 0,  // fan 0 1 3 2 -> (1 3 0) (3 2 0)
                                          4, 5, 7};  // triangles, offset by the appended block
  EXPECT_EQ(m.indices, expected);
  // The primitive without a material gets an added default material.
  ASSERT_EQ(s->materials.size(), 2u);
  EXPECT_EQ(s->materials[1].name, "default");
  EXPECT_EQ(m.material_ids, std::vector<uint32_t>({0, 0, 1, 1, 0}));
  // TRS -> column-major matrix: rotate 90 degrees about z, scale 2, translate (1,2,3).
  const Matrix4& t = s->nodes[0].local_transform;
  const double expected_m[16] = {0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1};
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(t[static_cast<size_t>(i)], expected_m[i], 1e-12) << i;
}

TEST(GlbReaderTest, CamerasAndLightsArePlacedByTheirNodes) {
  std::vector<uint8_t> bin;
  json j = InterleavedQuad(&bin);
  j["cameras"] =
      json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}},
                   {{"type", "orthographic"},
                    {"name", "plan"},
                    {"orthographic", {{"xmag", 2}, {"ymag", 1}, {"znear", 0}, {"zfar", 50}}}}});
  j["extensionsUsed"] = {"KHR_lights_punctual"};
  j["extensions"]["KHR_lights_punctual"]["lights"] =
      json::array({{{"type", "spot"}, {"color", {1, 0.5, 0}}, {"spot", {{"outerConeAngle", 0.5}}}},
                   {{"type", "directional"}, {"intensity", 3}}});
  j["nodes"][0]["camera"] = 1;
  j["nodes"][0]["extensions"]["KHR_lights_punctual"] = {{"light", 0}};
  Result<Scene> s = Decode(j, bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_TRUE(s->dropped.empty());
  ASSERT_EQ(s->cameras.size(), 2u);
  EXPECT_TRUE(s->cameras[0].perspective);
  EXPECT_EQ(s->cameras[0].yfov, 0.5);
  EXPECT_EQ(s->cameras[0].zfar, 0);  // infinite
  EXPECT_FALSE(s->cameras[1].perspective);
  EXPECT_EQ(s->cameras[1].name, "plan");
  EXPECT_EQ(s->cameras[1].zfar, 50);
  ASSERT_EQ(s->lights.size(), 2u);
  EXPECT_EQ(s->lights[0].type, LightType::kSpot);
  EXPECT_EQ(s->lights[0].outer_cone_angle, 0.5f);
  EXPECT_EQ(s->lights[0].color[1], 0.5f);
  EXPECT_EQ(s->lights[1].intensity, 3.0f);
  EXPECT_EQ(s->nodes[0].camera, 1);
  EXPECT_EQ(s->nodes[0].light, 0);
  // Invalid values and references are errors naming the object.
  json bad = j;
  bad["cameras"][0]["perspective"]["znear"] = 0;
  EXPECT_FALSE(Decode(bad, bin).ok());
  bad = j;
  bad["extensions"]["KHR_lights_punctual"]["lights"][0]["spot"]["innerConeAngle"] = 0.6;
  EXPECT_FALSE(Decode(bad, bin).ok());
  bad = j;
  bad["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 2;
  Result<Scene> missing = Decode(bad, bin);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("light 2 does not exist"), std::string::npos);
  bad = j;
  bad["nodes"][0]["camera"] = 5;
  EXPECT_FALSE(Decode(bad, bin).ok());
}

TEST(GlbReaderTest, ReportsWhatItDrops) {
  std::vector<uint8_t> bin;
  json j = InterleavedQuad(&bin);
  // An animation of the morph-target weights of a mesh without morph targets.
  j["animations"] = json::array(
      {{{"samplers", {{{"input", 0}, {"output", 0}}}},
        {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}}}}});
  j["scenes"] = json::array({{{"nodes", {0}}}, json::object()});
  j["extensionsUsed"] = {"KHR_materials_variants", "KHR_texture_transform"};
  j["meshes"][0]["primitives"][0]["attributes"]["COLOR_1"] = 0;
  j["meshes"][0]["primitives"][0]["attributes"]["_TEMPERATURE"] = 0;
  j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 1}});
  Result<Scene> s = Decode(j, bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  const auto& d = s->dropped;
  EXPECT_TRUE(Contains(d, "1 animation channels of morph-target weights"));
  EXPECT_TRUE(Contains(d, "1 animations left without a channel"));
  EXPECT_TRUE(Contains(d, "ignored extensions: KHR_materials_variants"));
  EXPECT_FALSE(Contains(d, "KHR_texture_transform"));  // baked into the UVs, not ignored
  EXPECT_TRUE(Contains(d, "1 point/line primitives"));
  EXPECT_TRUE(Contains(d, "COLOR_1"));
  EXPECT_TRUE(Contains(d, "_TEMPERATURE"));
  EXPECT_TRUE(Contains(d, "extra scenes"));
  EXPECT_EQ(s->meshes[0].triangle_count(), 5u);
}

// A quad whose three primitives share one morph target, given as a sparse accessor (offsets of
// vertices 1 and 3 only), with a name, default weights and a node's own weights.
json MorphQuad(std::vector<uint8_t>* bin, std::vector<uint8_t> sparse_indices = {1, 3}) {
  json j = InterleavedQuad(bin);
  const size_t at = bin->size();
  sparse_indices.resize(4, 0);
  bin->insert(bin->end(), sparse_indices.begin(), sparse_indices.end());
  Put<float>(*bin, {0, 0, 1, 0, 0, 2});
  j["buffers"][0]["byteLength"] = bin->size();
  j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 4}});
  j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at + 4}, {"byteLength", 24}});
  j["accessors"].push_back(
      {{"componentType", gltf::kFloat},
       {"count", 4},
       {"type", "VEC3"},
       {"sparse",
        {{"count", 2},
         {"indices", {{"bufferView", 2}, {"componentType", gltf::kUnsignedByte}}},
         {"values", {{"bufferView", 3}}}}}});
  for (json& prim : j["meshes"][0]["primitives"]) prim["targets"] = {{{"POSITION", 5}}};
  j["meshes"][0]["weights"] = {0.5};
  j["meshes"][0]["extras"]["targetNames"] = {"lift"};
  j["nodes"][0]["weights"] = {0.75};
  return j;
}

TEST(GlbReaderTest, MorphTargetsSparseNamedAndWeighted) {
  std::vector<uint8_t> bin;
  Result<Scene> s = Decode(MorphQuad(&bin), bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  const Mesh& m = s->meshes[0];
  ASSERT_EQ(m.morph_targets.size(), 1u);
  EXPECT_EQ(m.morph_targets[0].name, "lift");
  EXPECT_EQ(m.morph_weights, std::vector<float>({0.75f}));  // the node's weights win
  EXPECT_TRUE(m.morph_targets[0].normals.empty());
  // Two vertex blocks (the last primitive has no normals), each with its copy of the offsets.
  ASSERT_EQ(m.vertex_count(), 8u);
  ASSERT_EQ(m.morph_targets[0].positions.size(), 24u);
  for (size_t v = 0; v < 8; ++v) {
    const float dz = v % 4 == 1 ? 1.0f : v % 4 == 3 ? 2.0f : 0.0f;
    EXPECT_EQ(m.morph_targets[0].positions[3 * v + 2], dz) << v;
    EXPECT_EQ(m.morph_targets[0].positions[3 * v], 0.0f) << v;
  }
}

TEST(GlbReaderTest, MalformedMorphTargetsAreErrors) {
  std::vector<uint8_t> bin;
  json j = MorphQuad(&bin);
  j["meshes"][0]["primitives"][2].erase("targets");
  Result<Scene> s = Decode(j, bin);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("has 0 morph targets"), std::string::npos);
  bin.clear();
  j = MorphQuad(&bin, {3, 1});
  s = Decode(j, bin);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("not increasing"), std::string::npos);
  bin.clear();
  j = MorphQuad(&bin, {1, 4});
  EXPECT_FALSE(Decode(j, bin).ok());  // beyond the accessor's count
  bin.clear();
  j = MorphQuad(&bin);
  j["meshes"][0]["weights"] = {0.5, 0.5};
  s = Decode(j, bin);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("one number per morph target"), std::string::npos);
  bin.clear();
  j = MorphQuad(&bin);
  j["accessors"][5]["sparse"]["values"]["byteOffset"] = 8;  // runs past its bufferView
  EXPECT_FALSE(Decode(j, bin).ok());
  // NORMAL offsets where the primitives have no normals: dropped with a note (glTF wants a base).
  bin.clear();
  j = MorphQuad(&bin);
  for (json& prim : j["meshes"][0]["primitives"]) {
    prim["attributes"].erase("NORMAL");
    prim["targets"][0]["NORMAL"] = 5;
  }
  s = Decode(j, bin);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_TRUE(s->meshes[0].morph_targets[0].normals.empty());
  EXPECT_TRUE(Contains(s->dropped, "NORMAL offsets of a mesh without normals"));
}

TEST(GlbReaderTest, UnsupportedInputsSayWhy) {
  std::vector<uint8_t> bin;
  const json base = InterleavedQuad(&bin);
  {
    // Sparse float attributes are read; sparse indices are not.
    json j = base;
    const int indices = j["meshes"][0]["primitives"][0]["indices"];
    j["accessors"][indices]["sparse"] = {{"count", 1}};
    Result<Scene> s = Decode(j, bin);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.status().code(), StatusCode::kUnsupported);
    EXPECT_NE(s.status().message().find("sparse"), std::string::npos);
    EXPECT_EQ(s.status().message().rfind("test.glb: accessors[" + std::to_string(indices), 0), 0u)
        << s.status().message();
  }
  {
    json j = base;
    j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    Result<Scene> s = Decode(j, bin);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.status().code(), StatusCode::kUnsupported);
    EXPECT_NE(s.status().message().find("KHR_draco_mesh_compression"), std::string::npos);
  }
  {
    json j = base;
    j["asset"]["version"] = "1.0";
    Result<Scene> s = Decode(j, bin);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.status().code(), StatusCode::kUnsupported);
  }
  {
    json j = base;
    j["buffers"][0]["uri"] = "quad.bin";
    GltfDocument doc(j, {}, false, 100);
    Result<Scene> s = DecodeGltfDocument(doc, "mem.gltf");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.status().code(), StatusCode::kUnsupported);
    EXPECT_NE(s.status().message().find("quad.bin"), std::string::npos);
  }
}

std::string Base64(const std::vector<uint8_t>& in) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t v = static_cast<uint32_t>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<uint32_t>(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= in[i + 2];
    out += k[(v >> 18) & 63];
    out += k[(v >> 12) & 63];
    out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? k[v & 63] : '=';
  }
  return out;
}

class GltfFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/hullpack_gltf_XXXXXX";
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override {
    for (const std::string& f : files_) std::remove(f.c_str());
    rmdir((dir_ + "/sub").c_str());
    rmdir(dir_.c_str());
  }
  std::string Write(const std::string& name, const std::string& bytes) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    files_.push_back(path);
    return path;
  }
  std::string dir_;
  std::vector<std::string> files_;
};

TEST_F(GltfFileTest, DataUriBuffersAndImages) {
  std::vector<uint8_t> bin;
  json j = InterleavedQuad(&bin);
  j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + Base64(bin);
  j["images"] = {{{"uri", "data:image/png;base64," + Base64({0x89, 'P', 'N', 'G'})}},
                 {{"uri", "tex/a%20b.png"}}};
  const std::string path = Write("quad.gltf", j.dump());
  Result<Scene> s = ReadGltfFile(path);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->meshes[0].triangle_count(), 5u);
  ASSERT_EQ(s->images.size(), 2u);
  EXPECT_EQ(s->images[0].mime_type, "image/png");
  EXPECT_EQ(s->images[0].bytes, std::vector<uint8_t>({0x89, 'P', 'N', 'G'}));
  EXPECT_EQ(s->images[1].uri, "tex/a%20b.png");
  // Bad base64 is a parse error naming the buffer.
  j["buffers"][0]["uri"] = "data:application/octet-stream;base64,@@@@";
  Result<Scene> bad = ReadGltfFile(Write("bad.gltf", j.dump()));
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("buffers[0]"), std::string::npos)
      << bad.status().ToString();
}

TEST_F(GltfFileTest, ExternalBinNextToTheFile) {
  std::vector<uint8_t> bin;
  json j = InterleavedQuad(&bin);
  ASSERT_EQ(mkdir((dir_ + "/sub").c_str(), 0700), 0);
  Write("sub/quad data.bin", std::string(bin.begin(), bin.end()));
  j["buffers"][0]["uri"] = "sub/quad%20data.bin";
  Result<Scene> s = ReadGltfFile(Write("quad.gltf", j.dump()));
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->meshes[0].vertex_count(), 8u);
  // A byteLength larger than the file is refused before anything is allocated.
  j["buffers"][0]["byteLength"] = 1ull << 40;
  Result<Scene> big = ReadGltfFile(Write("big.gltf", j.dump()));
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.status().code(), StatusCode::kParseError);
  // URIs that would leave the folder are not followed.
  for (const char* uri :
       {"../quad.bin", "sub/../../x.bin", "/etc/passwd", "file:///etc/passwd", "%2e%2e/x.bin"}) {
    j["buffers"][0]["uri"] = uri;
    j["buffers"][0]["byteLength"] = bin.size();
    Result<Scene> esc = ReadGltfFile(Write("escape.gltf", j.dump()));
    ASSERT_FALSE(esc.ok()) << uri;
    EXPECT_EQ(esc.status().code(), StatusCode::kUnsupported)
        << uri << ": " << esc.status().ToString();
  }
  j["buffers"][0]["uri"] = "missing.bin";
  Result<Scene> missing = ReadGltfFile(Write("missing.gltf", j.dump()));
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().code(), StatusCode::kIoError);
}

TEST_F(GltfFileTest, ReadsGlbFilesAndNamesThePath) {
  std::vector<uint8_t> bin;
  const json j = InterleavedQuad(&bin);
  GltfDocument doc(j, bin, true, 0);
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  ASSERT_TRUE(glb.ok());
  const std::string path = Write("quad.glb", std::string(glb->begin(), glb->end()));
  Result<Scene> s = ReadGltfFile(path);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->meshes[0].triangle_count(), 5u);
  Result<GltfDocument> d = ReadGltfDocumentFile(path);
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->json()["meshes"][0]["name"], "quad");
  const std::string cut = Write("cut.glb", std::string(glb->begin(), glb->begin() + 40));
  Result<Scene> truncated = ReadGltfFile(cut);
  ASSERT_FALSE(truncated.ok());
  EXPECT_EQ(truncated.status().message().rfind(cut + ": ", 0), 0u) << truncated.status().message();
  Result<Scene> none = ReadGltfFile(dir_ + "/nope.glb");
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.status().code(), StatusCode::kIoError);
}

}  // namespace
}  // namespace hullpack
