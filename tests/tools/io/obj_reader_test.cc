#include "io/obj_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace hullpack {
namespace {

Result<Scene> Parse(const std::string& text) {
  return ParseObj(text.data(), text.size(), "test.obj");
}

TEST(ObjReader, MixedCornerFormatsUnifyIntoVertices) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\n"
      "vn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1\n"
      "f 2 4 3\n"
      "f 2//1 4//1 3//1\n";
  Result<Scene> s = Parse(text);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->meshes.size(), 1u);
  const Mesh& m = s->meshes[0];
  EXPECT_EQ(m.triangle_count(), 3u);
  // (1/1/1) (2/2/1) (3/3/1) (2) (4) (3) (2//1) (4//1) (3//1): nine distinct triples, numbered in
  // (v, vt, vn) order: 1/1/1, 2, 2//1, 2/2/1, 3, 3//1, 3/3/1, 4, 4//1.
  EXPECT_EQ(m.vertex_count(), 9u);
  ASSERT_EQ(m.uv_sets.size(), 1u);
  EXPECT_FLOAT_EQ(m.uv_sets[0][2 * 3 + 0], 1.0f);  // 2/2/1 has vt 1 0
  EXPECT_FLOAT_EQ(m.uv_sets[0][2 * 6 + 1],
                  0.0f);  // 3/3/1 has vt 0 1, flipped to the glTF convention
  EXPECT_EQ(m.indices[0], 0u);
  EXPECT_EQ(s->source_vertex_records, 4u);
  EXPECT_FALSE(s->dropped.empty());  // corners without vt/vn are reported
}

// An object whose positions lie far apart in a large pool keeps the (v, vt, vn) order too.
TEST(ObjReader, VerticesFollowTheFileOrderWhereverTheirPositionsAre) {
  std::string text;
  for (int i = 1; i <= 3000; ++i) text += "v " + std::to_string(i) + " 0 0\n";
  text += "vt 0 0\nvt 1 0\n";
  text += "o spread\nf 3000 2 1500/2\nf 1500/1 2 3000/1\nf 2/2 1500/2 3000\n";
  Result<Scene> s = Parse(text);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->meshes.size(), 1u);
  const Mesh& m = s->meshes[0];
  // 2, 2/2, 1500/1, 1500/2, 3000, 3000/1.
  ASSERT_EQ(m.vertex_count(), 6u);
  const float x[] = {2, 2, 1500, 1500, 3000, 3000};
  for (size_t v = 0; v < 6; ++v) EXPECT_EQ(m.positions[3 * v], x[v]) << "vertex " << v;
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{4, 0, 3, 2, 0, 5, 1, 3, 4}));
}

TEST(ObjReader, PolygonsNegativeIndicesObjectsAndMaterials) {
  const std::string text =
      "o first\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl red\nf -4 -3 -2 -1\n"
      "o second\nv 0 0 1\nv 1 0 1\nv 1 1 1\nusemtl blue\nf 5 6 7\nusemtl red\nf 7 6 5\n";
  Result<Scene> s = Parse(text);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->meshes.size(), 2u);
  EXPECT_EQ(s->meshes[0].name, "first");
  EXPECT_EQ(s->meshes[0].triangle_count(), 2u);
  ASSERT_EQ(s->materials.size(), 2u);
  EXPECT_EQ(s->materials[0].name, "red");
  EXPECT_EQ(s->meshes[1].material_ids, (std::vector<uint32_t>{1, 0}));
}

// Faces before the first `usemtl`, and an object with none, get a material of their own; a file
// without materials has no material ids.
TEST(ObjReader, FacesWithoutAMaterialGetOneOfTheirOwn) {
  const std::string text =
      "o plain\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"
      "o later\nf 3 2 1\nf 1 3 2\nusemtl red\nf 2 1 3\n";
  Result<Scene> s = Parse(text);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->meshes.size(), 2u);
  ASSERT_EQ(s->materials.size(), 2u);
  EXPECT_EQ(s->materials[0].name, "red");
  EXPECT_EQ(s->materials[1].name, "(no material)");
  EXPECT_EQ(s->meshes[0].material_ids, (std::vector<uint32_t>{1}));
  EXPECT_EQ(s->meshes[1].material_ids, (std::vector<uint32_t>{1, 1, 0}));
  Result<Scene> none = Parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 3 2 1\n");
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->materials.empty());
  EXPECT_TRUE(none->meshes[0].material_ids.empty());
}

TEST(ObjReader, VertexColorsAndUnreferencedVertices) {
  Result<Scene> s = Parse("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 5 5 5 1 1 1\nf 1 2 3\n");
  ASSERT_TRUE(s.ok());
  const Mesh& m = s->meshes[0];
  ASSERT_EQ(m.colors.size(), 12u);
  EXPECT_FLOAT_EQ(m.colors[4 + 1], 1.0f);
  EXPECT_FLOAT_EQ(m.colors[3], 1.0f);  // alpha
  ASSERT_EQ(s->dropped.size(), 1u);
  EXPECT_NE(s->dropped[0].find("1 unreferenced"), std::string::npos);
}

TEST(ObjReader, MaterialLibraryIsReadThroughTheCallback) {
  ObjParseOptions options;
  options.load_material_library = [](const std::string& name) -> Result<std::string> {
    if (name != "a.mtl") return Status(StatusCode::kIoError, "missing");
    return std::string("newmtl skin\nKd 0.5 0.25 1\nd 0.5\nmap_Kd -bm 1 tex/skin.png\n");
  };
  const std::string text =
      "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl skin\nf 1/1 2/1 3/1\n";
  Result<Scene> s = ParseObj(text.data(), text.size(), "t.obj", options);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s->materials.size(), 1u);
  EXPECT_FLOAT_EQ(s->materials[0].base_color[1], 0.25f);
  EXPECT_FLOAT_EQ(s->materials[0].base_color[3], 0.5f);
  EXPECT_EQ(s->materials[0].alpha_mode, AlphaMode::kBlend);
  ASSERT_TRUE(s->materials[0].base_color_texture.used());
  EXPECT_EQ(s->images[0].uri, "tex/skin.png");
}

TEST(ObjReader, OpacityBlendsOnlyWhenPartial) {
  auto material = [](const std::string& mtl) {
    ObjParseOptions options;
    options.load_material_library = [mtl](const std::string&) -> Result<std::string> {
      return mtl;
    };
    const std::string text = "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n";
    Result<Scene> s = ParseObj(text.data(), text.size(), "t.obj", options);
    EXPECT_TRUE(s.ok());
    return s.ok() && !s->materials.empty() ? s->materials[0] : Material();
  };
  EXPECT_EQ(material("newmtl m\nTr 0.25\n").alpha_mode, AlphaMode::kBlend);
  EXPECT_FLOAT_EQ(material("newmtl m\nTr 0.25\n").base_color[3], 0.75f);
  EXPECT_EQ(material("newmtl m\nd 1\n").alpha_mode, AlphaMode::kOpaque);
  // `Tr` written with the meaning of `d`: 1 means opaque to such exporters, read as 0 opacity.
  const Material misread = material("newmtl m\nTr 1\n");
  EXPECT_EQ(misread.alpha_mode, AlphaMode::kOpaque);
  EXPECT_FLOAT_EQ(misread.base_color[3], 1.0f);
}

TEST(ObjReader, ErrorsNameTheLineAndTheProblem) {
  struct Case {
    const char* text;
    const char* expect;
  } cases[] = {
      {"v 0 0 0\nv 1 0 0\nf 1 2 3\n", "line 3: face refers to vertex 3 but only 2"},
      {"v 0 0\n", "line 1: vertex needs at least 3"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n", "line 4: malformed"},
      {"v 0 0 0\nhello world\n", "line 2: unknown statement 'hello'"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "refers to vertex 0"},
      {"v 0 0 0\n\0v", "NUL"},
  };
  for (const Case& c : cases) {
    const std::string text(c.text, c.text + std::char_traits<char>::length(c.text) +
                                       (std::string(c.expect) == "NUL" ? 2 : 0));
    Result<Scene> s = Parse(text);
    ASSERT_FALSE(s.ok()) << c.text;
    EXPECT_EQ(s.status().code(), StatusCode::kParseError);
    EXPECT_NE(s.status().message().find("test.obj"), std::string::npos);
    EXPECT_NE(s.status().message().find(c.expect), std::string::npos) << s.status().message();
  }
}

TEST(ObjReader, CommentsBlankLinesAndCrLf) {
  Result<Scene> s =
      Parse("# c\r\n\r\nv 0 0 0 # trailing\r\nv 1 0 0\r\nv 0 1 0\r\ns off\r\ng grp\r\nf 1 2 3\r\n");
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->meshes[0].triangle_count(), 1u);
}

// A text of a few megabytes with every kind of line: v (with colours and w), vt, vn, faces with
// all corner forms, negative indices, polygons, objects, comments.
std::string LargeText(size_t blocks) {
  std::string text = "# large\n";
  for (size_t b = 0; b < blocks; ++b) {
    const float x = 0.001f * static_cast<float>(b);
    text += "o part" + std::to_string(b % 7) + "\n";
    text += "v " + std::to_string(x) + " 0 0 0.5 0.25 1\nv 1 " + std::to_string(x) + " 0\nv 0 1 " +
            std::to_string(x) + " 1\nv 1 1 0.5\n";
    text += "vt 0 0\nvt 1 0 0\nvt " + std::to_string(x) + "\nvn 0 0 1\n";
    text += "f -4/-3/-1 -3/-2/-1 -2/-1/-1\n  f -3 -1 -2 # comment\nf -4//-1 -3//-1 -1//-1 -2//-1\n";
    text += "f -4/-3 -1/-1 -2/-2\n\n";
  }
  return text;
}

// The meshes' arrays and the reader's notes of two parses are the same.
void ExpectSameScene(const Scene& a, const Scene& b) {
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].positions, b.meshes[i].positions);
    EXPECT_EQ(a.meshes[i].normals, b.meshes[i].normals);
    EXPECT_EQ(a.meshes[i].uv_sets, b.meshes[i].uv_sets);
    EXPECT_EQ(a.meshes[i].colors, b.meshes[i].colors);
    EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices);
  }
  EXPECT_EQ(a.dropped, b.dropped);
}

// Large texts are read ahead on several threads: the scene is the one a single thread reads.
TEST(ObjReader, ReadingAheadOnThreadsGivesTheSameScene) {
  const std::string text = LargeText(10000);
  ASSERT_GT(text.size(), 1u << 20);  // read ahead from 1 MB
  ObjParseOptions one, many;
  one.threads = 1;
  many.threads = 3;
  Result<Scene> a = ParseObj(text.data(), text.size(), "a.obj", one);
  Result<Scene> b = ParseObj(text.data(), text.size(), "b.obj", many);
  ASSERT_TRUE(a.ok()) << a.status().ToString();
  ASSERT_TRUE(b.ok()) << b.status().ToString();
  ExpectSameScene(a.value(), b.value());
}

// An error deep in a large text is reported as a single thread reports it, line included.
TEST(ObjReader, ReadingAheadReportsTheSameErrors) {
  const std::string good = LargeText(10000);
  ASSERT_GT(good.size() / 2, 1u << 20);
  for (const std::string& bad :
       {std::string("f 1 2 x\n"), std::string("v 1 2\n"), std::string("f 1 2 999999999\n"),
        std::string("f 1/2/3/4 1 1\n"), std::string("f 1 2 99999999999\n")}) {
    std::string text = good.substr(0, good.size() / 2);
    text = text.substr(0, text.rfind('\n') + 1) + bad + good.substr(good.size() / 2);
    ObjParseOptions one, many;
    one.threads = 1;
    many.threads = 2;
    Result<Scene> a = ParseObj(text.data(), text.size(), "x.obj", one);
    Result<Scene> b = ParseObj(text.data(), text.size(), "x.obj", many);
    ASSERT_FALSE(a.ok()) << bad;
    ASSERT_FALSE(b.ok()) << bad;
    EXPECT_EQ(a.status().message(), b.status().message());
    EXPECT_NE(a.status().message().find("line "), std::string::npos);
  }
}

// A file is parsed part by part (never held whole): the scene is the one its text gives, with one
// thread (parts of at most 8 MB, so a larger file has several) and with several.
TEST(ObjReader, AFileReadPartByPartGivesTheSceneOfItsText) {
  const std::string text = LargeText(40000);
  ASSERT_GT(text.size(), size_t(8) << 20);
  const std::string path = ::testing::TempDir() + "obj_reader_parts.obj";
  ASSERT_TRUE(WriteFileAtomically(path, text.data(), text.size()).ok());
  Result<RandomAccessFile> file = RandomAccessFile::Open(path);
  ASSERT_TRUE(file.ok()) << file.status().message();
  ObjParseOptions one, many;
  one.threads = 1;
  many.threads = 3;
  Result<Scene> expected = ParseObj(text.data(), text.size(), path, one);
  ASSERT_TRUE(expected.ok()) << expected.status().ToString();
  for (const ObjParseOptions* options : {&one, &many}) {
    Result<Scene> s = ParseObjFile(file.value(), path, *options);
    ASSERT_TRUE(s.ok()) << s.status().ToString();
    ExpectSameScene(s.value(), expected.value());
  }
  std::remove(path.c_str());
}

// Errors in a later part of a file, a NUL byte among them, name the line the text gives.
TEST(ObjReader, AFileReadPartByPartReportsTheErrorsOfItsText) {
  const std::string good = LargeText(40000);
  const std::string path = ::testing::TempDir() + "obj_reader_bad_part.obj";
  for (const std::string& bad :
       {std::string("f 1 2 x\n"), std::string("v 1 2\n"), std::string("v 1 2 3\n\0\n", 10)}) {
    std::string text = good.substr(0, good.size() * 3 / 4);
    text = text.substr(0, text.rfind('\n') + 1) + bad + good.substr(good.size() * 3 / 4);
    ASSERT_TRUE(WriteFileAtomically(path, text.data(), text.size()).ok());
    Result<RandomAccessFile> file = RandomAccessFile::Open(path);
    ASSERT_TRUE(file.ok()) << file.status().message();
    ObjParseOptions one, many;
    one.threads = 1;
    many.threads = 2;
    Result<Scene> expected = ParseObj(text.data(), text.size(), "x.obj", one);
    Result<Scene> a = ParseObjFile(file.value(), "x.obj", one);
    Result<Scene> b = ParseObjFile(file.value(), "x.obj", many);
    ASSERT_FALSE(a.ok());
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(a.status().message(), expected.status().message());
    EXPECT_EQ(b.status().message(), expected.status().message());
    const bool nul = bad.find('\0') != std::string::npos;
    EXPECT_NE(a.status().message().find(nul ? "NUL" : "line "), std::string::npos)
        << a.status().message();
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace hullpack
