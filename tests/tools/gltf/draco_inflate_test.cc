#include "gltf/draco_inflate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "draco_square.h"
#include "gltf/glb_reader.h"

namespace hullpack {
namespace {

TEST(DracoInflate, ADracoPrimitiveBecomesPlainAccessorsThatTheReaderTakes) {
  const DracoSquare square = EncodeSquare();
  GltfDocument doc = DracoDocument(square, 4);
  const Status inflated = InflateDracoPrimitives(doc, "square.glb");
  ASSERT_TRUE(inflated.ok()) << inflated.message();
  EXPECT_FALSE(doc.json().contains("extensionsRequired"));
  EXPECT_FALSE(doc.json().contains("extensionsUsed"));
  EXPECT_FALSE(doc.json()["meshes"][0]["primitives"][0].contains("extensions"));
  // The stream's own bufferView is gone; the four accessors have one each.
  EXPECT_EQ(doc.json()["bufferViews"].size(), 4u);

  Result<Scene> scene = DecodeGltfDocument(doc, "square.glb");
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  ASSERT_EQ(scene->meshes.size(), 1u);
  const Mesh& m = scene->meshes[0];
  ASSERT_EQ(m.vertex_count(), 4u);
  ASSERT_EQ(m.triangle_count(), 2u);
  ASSERT_EQ(m.uv_sets.size(), 1u);
  ASSERT_EQ(m.colors.size(), 16u);
  // Every decoded corner is one of the square's corners, with its UV and colour.
  double area = 0;
  for (size_t t = 0; t < 2; ++t) {
    const float* a = &m.positions[m.indices[t * 3] * 3];
    const float* b = &m.positions[m.indices[t * 3 + 1] * 3];
    const float* c = &m.positions[m.indices[t * 3 + 2] * 3];
    area += 0.5 * std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  }
  EXPECT_NEAR(area, 1.0, 1e-3);
  for (size_t v = 0; v < 4; ++v) {
    const float x = m.positions[v * 3], y = m.positions[v * 3 + 1];
    EXPECT_NEAR(m.uv_sets[0][v * 2], x, 1e-3);
    EXPECT_NEAR(m.uv_sets[0][v * 2 + 1], y, 1e-3);
    const bool corner3 = x < 0.5f && y > 0.5f;
    EXPECT_NEAR(m.colors[v * 4 + 3], corner3 ? 9 / 255.0 : 1.0, 1e-6);  // the colour survived
  }
}

TEST(DracoInflate, HostileDocumentsAreErrorsNamingThePrimitive) {
  const DracoSquare square = EncodeSquare();
  {  // the accessor's count disagrees with the stream
    GltfDocument doc = DracoDocument(square, 5);
    const Status s = InflateDracoPrimitives(doc, "bad.glb");
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.message().find("bad.glb: meshes[0].primitives[0]"), std::string::npos)
        << s.message();
  }
  {  // a stream attribute that does not exist
    GltfDocument doc = DracoDocument(square, 4);
    doc.json()["meshes"][0]["primitives"][0]["extensions"][kDracoExtension]["attributes"]
              ["POSITION"] = 77;
    EXPECT_FALSE(InflateDracoPrimitives(doc, "bad.glb").ok());
  }
  {  // every truncation and a flipped byte of the stream: an error or a mesh, never a crash
    for (size_t cut = 0; cut < square.stream.size(); cut += 3) {
      DracoSquare broken = square;
      broken.stream.resize(cut);
      GltfDocument doc = DracoDocument(broken, 4);
      EXPECT_FALSE(InflateDracoPrimitives(doc, "cut.glb").ok()) << cut;
    }
    for (size_t i = 0; i < square.stream.size(); ++i) {
      DracoSquare broken = square;
      broken.stream[i] ^= 0x5A;
      GltfDocument doc = DracoDocument(broken, 4);
      (void)InflateDracoPrimitives(doc, "flip.glb");
    }
  }
  {  // an external buffer file is not read
    GltfDocument doc = DracoDocument(square, 4);
    doc.json()["buffers"] = nlohmann::json::array({{{"uri", "square.bin"}, {"byteLength", 1000}}});
    const Status s = InflateDracoPrimitives(doc, "square.gltf");
    EXPECT_EQ(s.code(), StatusCode::kUnsupported) << s.message();
  }
}

TEST(DracoInflate, ADocumentWithoutDracoIsUnchanged) {
  GltfDocument doc;
  doc.Append("meshes",
             {{"primitives", nlohmann::json::array({{{"attributes", {{"POSITION", 0}}}}})}});
  const nlohmann::json before = doc.json();
  ASSERT_TRUE(InflateDracoPrimitives(doc, "plain.glb").ok());
  EXPECT_EQ(doc.json(), before);
}

}  // namespace
}  // namespace hullpack
