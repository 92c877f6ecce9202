// Writer -> reader round trips for every format the project writes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>

#include "io/obj_writer.h"
#include "io/off_format.h"
#include "io/ply_writer.h"
#include "io/scene_io.h"
#include "io/wrl_format.h"
#include "io_test_util.h"

namespace hullpack {
namespace {

using testing::TetrahedraScene;
using testing::TorusScene;

// Same triangles over the same positions, vertex order kept.
void ExpectSameGeometry(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.triangle_count(), b.triangle_count());
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.positions, b.positions);  // shortest round-trip float text: exact
}

TEST(ObjWriter, RoundTripKeepsAttributesAndMaterialGroups) {
  const Scene in = TorusScene(12, 6, /*colors=*/true, /*materials=*/true);
  const std::string text = EncodeObj(in);
  Result<Scene> out = ReadSceneFromMemory(reinterpret_cast<const uint8_t*>(text.data()),
                                          text.size(), FileFormat::kObj, "rt.obj");
  ASSERT_TRUE(out.ok()) << out.status().ToString();
  ASSERT_EQ(out->meshes.size(), 1u);
  const Mesh& a = in.meshes[0];
  const Mesh& b = out->meshes[0];
  ExpectSameGeometry(a, b);
  EXPECT_EQ(a.normals, b.normals);
  ASSERT_EQ(b.uv_sets.size(), 1u);
  for (size_t i = 0; i < a.uv_sets[0].size(); ++i)
    EXPECT_NEAR(a.uv_sets[0][i], b.uv_sets[0][i], 1e-6);
  for (size_t i = 0; i < a.colors.size(); ++i) {
    if (i % 4 != 3) {
      EXPECT_EQ(a.colors[i], b.colors[i]);
    }
  }
  ASSERT_EQ(out->materials.size(), 2u);
  EXPECT_EQ(out->materials[0].name, "outer");
  EXPECT_EQ(a.material_ids, b.material_ids);
}

TEST(ObjWriter, HullSetIsOneObjectGroupPerHull) {
  const Scene in = TetrahedraScene(3);
  const std::string text = EncodeObj(in);
  size_t groups = 0;
  for (size_t p = text.find("\no "); p != std::string::npos; p = text.find("\no ", p + 1)) ++groups;
  EXPECT_EQ(groups, 3u);
  Result<Scene> out = ReadSceneFromMemory(reinterpret_cast<const uint8_t*>(text.data()),
                                          text.size(), FileFormat::kObj, "h.obj");
  ASSERT_TRUE(out.ok());
  ASSERT_EQ(out->meshes.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(out->meshes[k].name, "hull_" + std::to_string(k));
    ExpectSameGeometry(in.meshes[k], out->meshes[k]);
  }
}

TEST(ObjWriter, InPiecesTheTextIsTheSame) {
  const Scene in = TorusScene(400, 200, /*colors=*/true, /*materials=*/true);
  const std::string whole = EncodeObj(in);
  std::string joined;
  size_t pieces = 0;
  EncodeObj(in, [&](std::string_view piece) {
    joined.append(piece.data(), piece.size());
    ++pieces;
  });
  EXPECT_GT(pieces, 1u);  // the torus's text is several megabytes
  EXPECT_EQ(joined, whole);
  // One mesh alone: the text of a scene of it without materials.
  Scene alone;
  alone.meshes = {in.meshes[0]};
  alone.meshes[0].material_ids.clear();
  std::string mesh_text;
  EncodeObjMesh(in.meshes[0],
                [&](std::string_view piece) { mesh_text.append(piece.data(), piece.size()); });
  EXPECT_EQ(mesh_text, EncodeObj(alone));
}

TEST(OffFormat, RoundTripMergesMeshes) {
  const Scene in = TetrahedraScene(2);
  const std::string text = EncodeOff(in);
  Result<Scene> out = ParseOff(text.data(), text.size(), "t.off");
  ASSERT_TRUE(out.ok()) << out.status().ToString();
  ASSERT_EQ(out->meshes.size(), 1u);
  EXPECT_EQ(out->meshes[0].triangle_count(), 8u);
  EXPECT_EQ(out->meshes[0].vertex_count(), 8u);
  EXPECT_EQ(out->meshes[0].indices[12], 4u);  // second tetrahedron's indices are offset
  EXPECT_EQ(
      std::vector<float>(out->meshes[0].positions.begin() + 12, out->meshes[0].positions.end()),
      in.meshes[1].positions);
}

TEST(OffFormat, ColorsRoundTrip) {
  const Scene in = TorusScene(6, 4, true, false);
  const std::string text = EncodeOff(in);
  ASSERT_EQ(text.rfind("COFF", 0), 0u);
  Result<Scene> out = ParseOff(text.data(), text.size(), "c.off");
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(out->meshes[0].colors, in.meshes[0].colors);
}

TEST(WrlFormat, RoundTripOneShapePerHull) {
  const Scene in = TetrahedraScene(4);
  const std::string text = EncodeWrl(in);
  ASSERT_EQ(text.rfind("#VRML V2.0 utf8", 0), 0u);
  Result<Scene> out = ParseWrl(text.data(), text.size(), "h.wrl");
  ASSERT_TRUE(out.ok()) << out.status().ToString();
  ASSERT_EQ(out->meshes.size(), 4u);
  for (int k = 0; k < 4; ++k) ExpectSameGeometry(in.meshes[k], out->meshes[k]);
}

TEST(PlyWriter, RoundTripThroughAssimp) {
  const Scene in = TorusScene(10, 6, true, false);
  const std::vector<uint8_t> bytes = EncodePly(in);
  Result<Scene> out = ReadSceneFromMemory(bytes.data(), bytes.size(), FileFormat::kPly, "t.ply");
  ASSERT_TRUE(out.ok()) << out.status().ToString();
  ASSERT_EQ(out->meshes.size(), 1u);
  const Mesh& a = in.meshes[0];
  const Mesh& b = out->meshes[0];
  ASSERT_EQ(b.triangle_count(), a.triangle_count());
  ASSERT_EQ(b.vertex_count(), a.vertex_count());
  // assimp's PLY importer may reorder corners; compare each triangle's corner positions.
  for (size_t t = 0; t < a.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(a.positions[a.indices[t * 3 + k] * 3 + c],
                  b.positions[b.indices[t * 3 + k] * 3 + c]);
      }
    }
  }
  ASSERT_EQ(b.normals.size(), a.normals.size());
  ASSERT_EQ(b.colors.size(), a.colors.size());
  for (size_t i = 0; i < a.colors.size(); ++i) EXPECT_NEAR(a.colors[i], b.colors[i], 1.0 / 255);
}

}  // namespace
}  // namespace hullpack
