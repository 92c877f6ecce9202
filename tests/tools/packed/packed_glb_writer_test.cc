// The packed-GLB writer: what a stream holds is not also written as plain data (unless the file
// is a fallback one), and a mesh attribute its stream lacks is an error, not a silent loss.
#include "packed/packed_glb_writer.h"

#include <gtest/gtest.h>

#include "gltf/gltf_document.h"
#include "pipeline/mesh_codec.h"

namespace hullpack {
namespace {

Mesh NormalQuad() {
  Mesh m;
  m.name = "quad";
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  return m;
}

// `decoded` as the only mesh of a scene with one node, its stream the encoding of `coded`.
Result<std::vector<uint8_t>> Write(const Mesh& decoded, const Mesh& coded, bool fallback) {
  Result<EncodedMesh> encoded = EncodeMesh(coded, {}, MeshCodecSettings());
  if (!encoded.ok()) return encoded.status();
  Scene scene;
  scene.meshes.push_back(decoded);
  AddRootNodeForAllMeshes(scene, "root");
  PackedStreams streams;
  streams.streams.push_back(std::move(encoded.value()));
  MeshSource source;
  source.stream = 0;
  streams.sources.push_back(source);
  streams.hulls_of.resize(1);
  PackedGlbOptions options;
  options.fallback = fallback;
  return WritePackedGlb(std::move(scene), streams, options);
}

TEST(PackedGlbWriter, StreamedAttributesHaveNoPlainDataUnlessFallback) {
  for (const bool fallback : {false, true}) {
    const Result<std::vector<uint8_t>> glb = Write(NormalQuad(), NormalQuad(), fallback);
    ASSERT_TRUE(glb.ok()) << glb.status().ToString();
    Result<GltfDocument> doc = ParseGlb(glb->data(), glb->size(), "quad.glb");
    ASSERT_TRUE(doc.ok()) << doc.status().ToString();
    const nlohmann::json& json = doc->json();
    const nlohmann::json& prim = json["meshes"][0]["primitives"][0];
    ASSERT_TRUE(prim["extensions"].contains("HULLPACK_mesh_compression"));
    for (const char* name : {"POSITION", "NORMAL"}) {
      const nlohmann::json& accessor = json["accessors"][prim["attributes"][name].get<int>()];
      EXPECT_EQ(accessor.contains("bufferView"), fallback) << name;
      EXPECT_EQ(accessor["count"], 4);
    }
    const nlohmann::json& position = json["accessors"][prim["attributes"]["POSITION"].get<int>()];
    EXPECT_EQ(position["max"], nlohmann::json::array({1.0, 1.0, 0.0}));
    EXPECT_EQ(json["accessors"][prim["indices"].get<int>()].contains("bufferView"), fallback);
    // Without fallback the binary chunk holds the stream alone.
    if (!fallback) {
      EXPECT_EQ(json["bufferViews"].size(), 1u);
    }
  }
}

TEST(PackedGlbWriter, AnAttributeItsStreamLacksIsAnError) {
  Mesh without_normals = NormalQuad();
  without_normals.normals.clear();
  const Result<std::vector<uint8_t>> glb = Write(NormalQuad(), without_normals, false);
  ASSERT_FALSE(glb.ok());
  EXPECT_NE(glb.status().message().find("NORMAL"), std::string::npos) << glb.status().ToString();
  // A fallback file keeps the plain normals: nothing is lost.
  EXPECT_TRUE(Write(NormalQuad(), without_normals, true).ok());
}

}  // namespace
}  // namespace hullpack
