#include "gltf/meshopt_inflate.h"

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <cstring>
#include <string>
#include <vector>

#include "gltf/glb_reader.h"

namespace hullpack {
namespace {

// A quad of two triangles: float positions, octahedral-filtered byte normals (as gltfpack stores
// them), indices; each bufferView compressed, with a fallback buffer as the extension specifies.
struct Quad {
  std::vector<float> positions = {0, 0, 0, 2, 0, 0, 2, 3, 0, 0, 3, 0};
  std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
};

std::vector<uint8_t> EncodeVertices(const void* data, size_t count, size_t stride) {
  std::vector<uint8_t> out(meshopt_encodeVertexBufferBound(count, stride));
  out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, count, stride));
  return out;
}

std::vector<uint8_t> EncodeTriangles(const std::vector<uint32_t>& indices, size_t vertices) {
  std::vector<uint8_t> out(meshopt_encodeIndexBufferBound(indices.size(), vertices));
  out.resize(meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), indices.size()));
  return out;
}

// The document gltfpack would write: compressed bytes in buffer 0, views on fallback buffer 1.
GltfDocument MeshoptDocument(const Quad& quad, bool corrupt_indices = false) {
  GltfDocument doc;
  const std::vector<uint8_t> positions = EncodeVertices(quad.positions.data(), 4, 12);
  std::vector<uint8_t> indices = EncodeTriangles(quad.indices, 4);
  if (corrupt_indices) indices.resize(indices.size() / 2);
  // Normals (0.6, 0, 0.8) as octahedral bytes (a plain byte vector would read differently).
  const float normal[4] = {0.6f, 0, 0.8f, 0};
  std::vector<float> unit;
  for (int v = 0; v < 4; ++v) unit.insert(unit.end(), normal, normal + 4);
  std::vector<int8_t> normals(16);
  meshopt_encodeFilterOct(normals.data(), 4, 4, 8, unit.data());
  const std::vector<uint8_t> packed_normals = EncodeVertices(normals.data(), 4, 4);

  nlohmann::json views = nlohmann::json::array();
  size_t fallback = 0;
  auto compressed = [&](const std::vector<uint8_t>& bytes, size_t stride, size_t count,
                        const char* mode, const char* filter) {
    const int at = doc.AddBufferView(bytes, 4);
    const nlohmann::json source = doc.json()["bufferViews"][at];
    nlohmann::json ext = {{"buffer", 0},
                          {"byteOffset", source["byteOffset"]},
                          {"byteLength", bytes.size()},
                          {"byteStride", stride},
                          {"count", count},
                          {"mode", mode}};
    if (filter) ext["filter"] = filter;
    nlohmann::json view = {{"buffer", 1},
                           {"byteOffset", fallback},
                           {"byteLength", stride * count},
                           {"extensions", {{kMeshoptExtension, ext}}}};
    if (std::string(mode) == "ATTRIBUTES") view["byteStride"] = stride;
    fallback += stride * count;
    views.push_back(view);
  };
  compressed(positions, 12, 4, "ATTRIBUTES", nullptr);
  compressed(packed_normals, 4, 4, "ATTRIBUTES", "OCTAHEDRAL");
  compressed(indices, 4, 6, "TRIANGLES", nullptr);
  nlohmann::json& json = doc.json();
  json["bufferViews"] = views;
  json["buffers"] = nlohmann::json::array(
      {{{"byteLength", doc.binary().size()}},
       {{"byteLength", fallback}, {"extensions", {{kMeshoptExtension, {{"fallback", true}}}}}}});
  auto accessor = [&](int view, int ctype, const char* type, size_t count, bool normalized) {
    AccessorDesc d;
    d.buffer_view = view;
    d.component_type = ctype;
    d.type = type;
    d.count = count;
    d.normalized = normalized;
    return doc.AddAccessor(d);
  };
  const int pos = accessor(0, gltf::kFloat, "VEC3", 4, false);
  json["accessors"][pos]["min"] = {0, 0, 0};
  json["accessors"][pos]["max"] = {2, 3, 0};
  const int nrm = accessor(1, gltf::kByte, "VEC3", 4, true);
  const int idx = accessor(2, gltf::kUnsignedInt, "SCALAR", 6, false);
  nlohmann::json prim = {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}, {"indices", idx}};
  doc.Append("meshes", {{"primitives", nlohmann::json::array({prim})}});
  doc.Append("nodes", {{"mesh", 0}});
  json["scenes"] = nlohmann::json::array({{{"nodes", {0}}}});
  doc.UseExtension(kMeshoptExtension, true);
  doc.UseExtension("KHR_mesh_quantization", true);
  return doc;
}

TEST(MeshoptInflate, CompressedViewsBecomePlainDataThatTheReaderTakes) {
  const Quad quad;
  GltfDocument doc = MeshoptDocument(quad);
  const Status inflated = InflateMeshoptBufferViews(doc, "quad.glb");
  ASSERT_TRUE(inflated.ok()) << inflated.message();
  const nlohmann::json& json = doc.json();
  EXPECT_EQ(json["extensionsRequired"], nlohmann::json::array({"KHR_mesh_quantization"}));
  ASSERT_EQ(json["buffers"].size(), 1u);  // the fallback buffer went
  EXPECT_EQ(json["buffers"][0]["byteLength"], doc.binary().size());
  for (const auto& view : json["bufferViews"]) {
    EXPECT_EQ(view["buffer"], 0);
    EXPECT_FALSE(view.contains("extensions"));
  }

  Result<Scene> scene = DecodeGltfDocument(doc, "quad.glb");
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  ASSERT_EQ(scene->meshes.size(), 1u);
  const Mesh& m = scene->meshes[0];
  EXPECT_EQ(m.positions, quad.positions);
  EXPECT_EQ(m.indices, quad.indices);
  ASSERT_EQ(m.normals.size(), 12u);
  for (size_t v = 0; v < 4; ++v) {
    EXPECT_NEAR(m.normals[v * 3], 0.6, 0.01);
    EXPECT_NEAR(m.normals[v * 3 + 1], 0, 0.01);
    EXPECT_NEAR(m.normals[v * 3 + 2], 0.8, 0.01);
  }
}

TEST(MeshoptInflate, HostileViewsAreErrorsNamingTheView) {
  const Quad quad;
  {  // truncated index data
    GltfDocument doc = MeshoptDocument(quad, true);
    const Status s = InflateMeshoptBufferViews(doc, "cut.glb");
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.message().find("cut.glb: bufferViews[2]"), std::string::npos) << s.message();
  }
  {  // a filter that does not fit the stride, an unknown mode, a huge count
    auto broken = [&](const char* key, nlohmann::json value) {
      GltfDocument doc = MeshoptDocument(quad);
      doc.json()["bufferViews"][0]["extensions"][kMeshoptExtension][key] = value;
      return InflateMeshoptBufferViews(doc, "bad.glb");
    };
    EXPECT_FALSE(broken("filter", "QUATERNION").ok());
    EXPECT_FALSE(broken("mode", "POINTS").ok());
    EXPECT_FALSE(broken("byteStride", 6).ok());
    EXPECT_EQ(broken("count", uint64_t(1) << 40).code(), StatusCode::kUnsupported);
    EXPECT_FALSE(broken("byteOffset", 1u << 30).ok());
  }
  {  // every truncation and flipped byte of the compressed data: an error or data, never a crash
    const GltfDocument base = MeshoptDocument(quad);
    for (size_t i = 0; i < base.binary().size(); ++i) {
      GltfDocument doc = MeshoptDocument(quad);
      doc.binary()[i] ^= 0xA5;
      (void)InflateMeshoptBufferViews(doc, "flip.glb");
    }
  }
}

TEST(MeshoptInflate, ADocumentWithoutTheExtensionIsUnchanged) {
  GltfDocument doc;
  doc.AddBufferView(std::vector<uint8_t>(12, 0), 4);
  const nlohmann::json before = doc.json();
  ASSERT_TRUE(InflateMeshoptBufferViews(doc, "plain.glb").ok());
  EXPECT_EQ(doc.json(), before);
}

}  // namespace
}  // namespace hullpack
