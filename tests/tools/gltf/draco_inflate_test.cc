#include "gltf/draco_inflate.h"

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gltf/glb_reader.h"

namespace hullpack {
namespace {

// A square of two triangles with UVs and a normalized byte colour, as Draco streams it.
struct DracoSquare {
  std::vector<uint8_t> stream;
  int position_id = -1, uv_id = -1, color_id = -1;
};

DracoSquare EncodeSquare() {
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const uint8_t color[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {9, 9, 9, 9}};
  const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(2);
  const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int tex = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  const int col = builder.AddAttribute(draco::GeometryAttribute::COLOR, 4, draco::DT_UINT8);
  for (int f = 0; f < 2; ++f) {
    const int* c = faces[f];
    builder.SetAttributeValuesForFace(pos, draco::FaceIndex(f), p[c[0]], p[c[1]], p[c[2]]);
    builder.SetAttributeValuesForFace(tex, draco::FaceIndex(f), uv[c[0]], uv[c[1]], uv[c[2]]);
    builder.SetAttributeValuesForFace(col, draco::FaceIndex(f), color[c[0]], color[c[1]],
                                      color[c[2]]);
  }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  mesh->attribute(col)->set_normalized(true);
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  draco::EncoderBuffer buffer;
  EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
  DracoSquare out;
  out.stream.assign(buffer.data(), buffer.data() + buffer.size());
  out.position_id = mesh->attribute(pos)->unique_id();
  out.uv_id = mesh->attribute(tex)->unique_id();
  out.color_id = mesh->attribute(col)->unique_id();
  return out;
}

// A GLB document whose one primitive is the Draco square, as glTF-Transform writes it: accessors
// without bufferViews, the stream in a bufferView of the binary chunk.
GltfDocument DracoDocument(const DracoSquare& square, size_t points, bool required = true) {
  GltfDocument doc;
  const int view = doc.AddBufferView(square.stream, 4);
  auto accessor = [&](int ctype, size_t count, const char* type, bool normalized) {
    AccessorDesc d;
    d.component_type = ctype;
    d.count = count;
    d.type = type;
    d.normalized = normalized;
    return doc.AddAccessor(d);
  };
  const int position = accessor(gltf::kFloat, points, "VEC3", false);
  const int uv = accessor(gltf::kFloat, points, "VEC2", false);
  const int color = accessor(gltf::kUnsignedByte, points, "VEC4", true);
  const int indices = accessor(gltf::kUnsignedShort, 6, "SCALAR", false);
  nlohmann::json prim = {
      {"attributes", {{"POSITION", position}, {"TEXCOORD_0", uv}, {"COLOR_0", color}}},
      {"indices", indices},
      {"extensions",
       {{kDracoExtension,
         {{"bufferView", view},
          {"attributes",
           {{"POSITION", square.position_id},
            {"TEXCOORD_0", square.uv_id},
            {"COLOR_0", square.color_id}}}}}}}};
  doc.Append("meshes", {{"primitives", nlohmann::json::array({prim})}});
  doc.Append("nodes", {{"mesh", 0}});
  doc.json()["scenes"] = nlohmann::json::array({{{"nodes", {0}}}});
  doc.UseExtension(kDracoExtension, required);
  doc.json()["buffers"] = nlohmann::json::array({{{"byteLength", doc.binary().size()}}});
  return doc;
}

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
