#include "gltf/gltf_document.h"

#include <gtest/gtest.h>

namespace hullpack {
namespace {

using nlohmann::json;

uint32_t U32(const std::vector<uint8_t>& b, size_t at) {
  return static_cast<uint32_t>(b[at]) | (static_cast<uint32_t>(b[at + 1]) << 8) |
         (static_cast<uint32_t>(b[at + 2]) << 16) | (static_cast<uint32_t>(b[at + 3]) << 24);
}

TEST(GltfDocumentTest, ComponentTables) {
  EXPECT_EQ(gltf::ComponentSize(gltf::kByte), 1u);
  EXPECT_EQ(gltf::ComponentSize(gltf::kUnsignedShort), 2u);
  EXPECT_EQ(gltf::ComponentSize(gltf::kUnsignedInt), 4u);
  EXPECT_EQ(gltf::ComponentSize(gltf::kFloat), 4u);
  EXPECT_EQ(gltf::ComponentSize(5124), 0u);  // INT is not a glTF 2.0 component type
  EXPECT_EQ(gltf::ComponentCount("VEC3"), 3);
  EXPECT_EQ(gltf::ComponentCount("MAT4"), 16);
  EXPECT_EQ(gltf::ComponentCount("vec3"), 0);
}

TEST(GltfDocumentTest, AlignedAppendsAndAccessors) {
  GltfDocument doc;
  const uint8_t three[3] = {7, 8, 9};
  EXPECT_EQ(doc.AddBufferView(three, 3, 1), 0);
  const float f[2] = {1.5f, -2.0f};
  EXPECT_EQ(doc.AddBufferView(f, sizeof f, 4, gltf::kArrayBuffer), 1);
  const uint8_t one = 42;
  EXPECT_EQ(doc.AddBufferView(&one, 1, 16, gltf::kNoTarget, 4), 2);
  const json& views = doc.json()["bufferViews"];
  EXPECT_EQ(views[0]["byteOffset"], 0);
  EXPECT_EQ(views[1]["byteOffset"], 4);
  EXPECT_EQ(views[1]["target"], gltf::kArrayBuffer);
  EXPECT_FALSE(views[0].contains("target"));
  EXPECT_EQ(views[2]["byteOffset"], 16);
  EXPECT_EQ(views[2]["byteStride"], 4);
  EXPECT_EQ(doc.binary().size(), 17u);
  EXPECT_EQ(doc.binary()[3], 0);  // zero-filled gap
  AccessorDesc a;
  a.buffer_view = 1;
  a.count = 2;
  a.min = {-2};
  a.max = {1.5};
  EXPECT_EQ(doc.AddAccessor(a), 0);
  AccessorDesc b;  // no bufferView: the accessor omits it (and byteOffset)
  b.byte_offset = 8;
  b.count = 3;
  b.type = "VEC3";
  b.normalized = true;
  b.component_type = gltf::kUnsignedByte;
  EXPECT_EQ(doc.AddAccessor(b), 1);
  const json& acc = doc.json()["accessors"];
  EXPECT_EQ(acc[0]["min"], json({-2.0}));
  EXPECT_FALSE(acc[1].contains("bufferView"));
  EXPECT_FALSE(acc[1].contains("byteOffset"));
  EXPECT_EQ(acc[1]["normalized"], true);
}

TEST(GltfDocumentTest, FloatBoundsAreWrittenWithTheDigitsAFloatNeeds) {
  GltfDocument doc;
  AccessorDesc a;
  a.count = 1;
  a.type = "VEC3";
  const float x = 0.1f, y = -1234.5678f, z = 3.0e-8f;
  a.min = {double(x), double(y), double(z)};
  a.max = {0.1, 1.0 / 3.0, 16777217.0};  // not float values: written as they are
  doc.AddAccessor(a);
  AccessorDesc indices;
  indices.component_type = gltf::kUnsignedInt;
  indices.count = 1;
  indices.min = {4294967295.0};
  indices.max = {4294967295.0};
  doc.AddAccessor(indices);
  const json& acc = doc.json()["accessors"];
  EXPECT_EQ(acc[0]["min"][0].dump(), "0.1");
  EXPECT_EQ(acc[0]["min"][1].dump(), "-1234.5677");
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(float(acc[0]["min"][k].get<double>()), float(a.min[k])) << k;
  EXPECT_EQ(acc[0]["max"][1].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(acc[0]["max"][2].get<double>(), 16777217.0);
  EXPECT_EQ(acc[1]["max"][0].get<double>(), 4294967295.0);
}

TEST(GltfDocumentTest, SerializeWritesAPaddedGlb) {
  GltfDocument doc;
  const uint8_t five[5] = {1, 2, 3, 4, 5};
  doc.AddBufferView(five, 5, 4);
  doc.json()["asset"]["generator"] = "x";  // odd JSON length forces padding
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  ASSERT_TRUE(glb.ok());
  const std::vector<uint8_t>& b = glb.value();
  EXPECT_EQ(U32(b, 0), gltf::kGlbMagic);
  EXPECT_EQ(U32(b, 4), 2u);
  EXPECT_EQ(U32(b, 8), b.size());
  const uint32_t json_len = U32(b, 12);
  EXPECT_EQ(U32(b, 16), gltf::kChunkJson);
  EXPECT_EQ(json_len % 4, 0u);
  const size_t bin_at = 20 + json_len;
  EXPECT_EQ(U32(b, bin_at), 8u);  // 5 bytes padded to 8
  EXPECT_EQ(U32(b, bin_at + 4), gltf::kChunkBin);
  EXPECT_EQ(b.size(), bin_at + 8 + 8);
  EXPECT_EQ(b[bin_at + 8 + 5], 0);
  const std::string text(b.begin() + 20, b.begin() + 20 + json_len);
  EXPECT_EQ(text[text.find_last_not_of(' ')], '}');  // the rest is space padding
  const json parsed = json::parse(text);
  EXPECT_EQ(parsed["buffers"][0]["byteLength"], 5);
  Result<GltfDocument> back = ParseGlb(b.data(), b.size(), "doc.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  EXPECT_TRUE(back->has_binary_chunk());
  EXPECT_EQ(back->binary().size(), 8u);
  EXPECT_EQ(back->json()["asset"]["generator"], "x");
  EXPECT_EQ(back->source_size(), b.size());
}

TEST(GltfDocumentTest, ParseGlbSkipsUnknownChunks) {
  GltfDocument doc;
  const uint8_t four[4] = {9, 8, 7, 6};
  doc.AddBufferView(four, 4, 4);
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  ASSERT_TRUE(glb.ok());
  // Insert an unknown 4-byte chunk between JSON and BIN.
  std::vector<uint8_t> b = glb.value();
  const size_t bin_at = 20 + U32(b, 12);
  const std::vector<uint8_t> extra = {4, 0, 0, 0, 'X', 'T', 'R', 'A', 1, 2, 3, 4};
  b.insert(b.begin() + static_cast<std::ptrdiff_t>(bin_at), extra.begin(), extra.end());
  const uint32_t total = static_cast<uint32_t>(b.size());
  for (int i = 0; i < 4; ++i)
    b[8 + static_cast<size_t>(i)] = static_cast<uint8_t>(total >> (8 * i));
  Result<GltfDocument> back = ParseGlb(b.data(), b.size(), "chunks.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  EXPECT_EQ(back->binary(), std::vector<uint8_t>({9, 8, 7, 6}));
}

TEST(GltfDocumentTest, SerializeWithoutBinaryHasNoBinChunk) {
  GltfDocument doc;
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  ASSERT_TRUE(glb.ok());
  EXPECT_EQ(U32(glb.value(), 8), glb->size());
  EXPECT_EQ(glb->size(), 20u + U32(glb.value(), 12));
  EXPECT_FALSE(json::parse(std::string(glb->begin() + 20, glb->end())).contains("buffers"));
}

TEST(GltfDocumentTest, SerializeReplacesInvalidUtf8InNames) {
  GltfDocument doc;
  doc.Append("nodes", json{{"name", std::string("bad\xff name")}});
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  ASSERT_TRUE(glb.ok());
  Result<GltfDocument> back = ParseGlb(glb->data(), glb->size(), "utf8.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  EXPECT_NE(back->json()["nodes"][0]["name"].get<std::string>().find("name"), std::string::npos);
}

TEST(GltfDocumentTest, SerializeRefusesBufferZeroWithUri) {
  GltfDocument doc;
  doc.Append("buffers", json{{"uri", "data.bin"}, {"byteLength", 4}});
  const uint8_t four[4] = {1, 2, 3, 4};
  doc.AddBufferView(four, 4, 4);
  Result<std::vector<uint8_t>> glb = doc.Serialize();
  EXPECT_FALSE(glb.ok());
  EXPECT_EQ(glb.status().code(), StatusCode::kInvalidArgument);
}

TEST(GltfDocumentTest, SerializeJsonNamesTheBufferFileAndParsesBack) {
  GltfDocument doc;
  const uint8_t five[5] = {1, 2, 3, 4, 5};
  doc.AddBufferView(five, 5, 4);
  Result<std::string> text = doc.SerializeJson("a%20b.bin");
  ASSERT_TRUE(text.ok()) << text.status().ToString();
  const json j = json::parse(text.value());
  EXPECT_EQ(j["buffers"][0]["uri"], "a%20b.bin");
  EXPECT_EQ(j["buffers"][0]["byteLength"], 5);
  Result<GltfDocument> back =
      ParseGltfBytes(reinterpret_cast<const uint8_t*>(text->data()), text->size(), "a b.gltf");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  EXPECT_FALSE(back->has_binary_chunk());
  EXPECT_EQ(back->json()["bufferViews"][0]["byteLength"], 5);
}

TEST(GltfDocumentTest, SerializeJsonRefusesAnotherBufferWithoutUri) {
  GltfDocument doc;
  doc.Append("buffers", json::object());
  doc.Append("buffers", json{{"byteLength", 8}});
  const uint8_t four[4] = {1, 2, 3, 4};
  doc.AddBufferView(four, 4, 4);
  Result<std::string> text = doc.SerializeJson("x.bin");
  EXPECT_FALSE(text.ok());
  EXPECT_EQ(text.status().code(), StatusCode::kUnsupported);
  EXPECT_NE(text.status().message().find("buffer 1"), std::string::npos);
  GltfDocument empty;
  Result<std::string> plain = empty.SerializeJson("unused.bin");
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(json::parse(plain.value()).contains("buffers"));
}

TEST(GltfDocumentTest, UseExtensionListsOnce) {
  GltfDocument doc;
  doc.UseExtension("A", false);
  doc.UseExtension("B", true);
  doc.UseExtension("A", true);
  EXPECT_EQ(doc.json()["extensionsUsed"], json({"A", "B"}));
  EXPECT_EQ(doc.json()["extensionsRequired"], json({"B", "A"}));
}

TEST(GltfDocumentTest, ParseGltfBytesDetectsJson) {
  const std::string text = R"({"asset":{"version":"2.0"},"nodes":[{}]})";
  Result<GltfDocument> doc =
      ParseGltfBytes(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "a.gltf");
  ASSERT_TRUE(doc.ok());
  EXPECT_FALSE(doc->has_binary_chunk());
  EXPECT_EQ(doc->json()["nodes"].size(), 1u);
  const std::string bad = "[1,2";
  Result<GltfDocument> broken =
      ParseGltfBytes(reinterpret_cast<const uint8_t*>(bad.data()), bad.size(), "b.gltf");
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.status().code(), StatusCode::kParseError);
  EXPECT_EQ(broken.status().message().rfind("b.gltf: ", 0), 0u);
}

}  // namespace
}  // namespace hullpack
