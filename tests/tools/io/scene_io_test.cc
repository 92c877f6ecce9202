// Dispatch, atomic writes, and bad input in every supported format.
#include "io/scene_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "../gltf/draco_square.h"
#include "common/file_util.h"
#include "gltf/gltf_document.h"
#include "io_test_util.h"

namespace hullpack {
namespace {

using testing::TempDir;
using testing::TorusScene;

TEST(SceneIo, FormatFromExtension) {
  EXPECT_EQ(FormatFromExtension("a/b.OBJ"), FileFormat::kObj);
  EXPECT_EQ(FormatFromExtension("x.glb"), FileFormat::kGlb);
  EXPECT_EQ(FormatFromExtension("x.tar.gz"), FileFormat::kUnknown);
  EXPECT_EQ(FormatFromExtension("dir.obj/noext"), FileFormat::kUnknown);
}

TEST(SceneIo, WriteThenReadEveryWrittenFormat) {
  TempDir dir;
  const Scene in = TorusScene();
  for (const char* ext : {"obj", "off", "wrl", "ply"}) {
    const std::string path = dir.File(std::string("t.") + ext);
    ASSERT_TRUE(WriteScene(in, path).ok()) << ext;
    Result<Scene> out = ReadScene(path);
    ASSERT_TRUE(out.ok()) << out.status().ToString();
    EXPECT_EQ(out->triangle_count(), in.triangle_count()) << ext;
  }
}

// Formats without a hierarchy name their root node after the file; the folders it was read from
// must not travel into what is written (a packed GLB would carry the packer's local paths).
TEST(SceneIo, RootNodeNamedAfterTheFileNotItsPath) {
  TempDir dir;
  for (const char* ext : {"obj", "off", "wrl"}) {
    const std::string path = dir.File(std::string("named.") + ext);
    ASSERT_TRUE(WriteScene(TorusScene(), path).ok()) << ext;
    Result<Scene> out = ReadScene(path);
    ASSERT_TRUE(out.ok()) << out.status().ToString();
    ASSERT_FALSE(out->nodes.empty()) << ext;
    EXPECT_EQ(out->nodes[0].name, std::string("named.") + ext);
  }
}

TEST(SceneIo, FormatsThroughAssimp) {
  TempDir dir;
  const Scene in = TorusScene(8, 6);
  struct Case {
    const char* assimp_id;
    const char* ext;
  } cases[] = {
      {"collada", "dae"}, {"stlb", "stl"}, {"fbxa", "fbx"}, {"glb2", "glb"}, {"plyb", "ply"}};
  for (const Case& c : cases) {
    const std::vector<uint8_t> bytes = testing::ExportWithAssimp(in, c.assimp_id);
    ASSERT_FALSE(bytes.empty()) << c.assimp_id;
    const std::string path = dir.File(std::string("in.") + c.ext);
    testing::WriteBytes(path, bytes.data(), bytes.size());
    Result<Scene> out = ReadScene(path);
    ASSERT_TRUE(out.ok()) << c.ext << ": " << out.status().ToString();
    EXPECT_EQ(out->triangle_count(), in.triangle_count()) << c.ext;
    // STL has no index buffer: the reader welds identical corners back into shared vertices.
    if (std::string(c.ext) == "stl") {
      EXPECT_EQ(out->meshes[0].vertex_count(), in.meshes[0].vertex_count());
    }
    // STL and PLY hold no materials: assimp's stand-in default material is not read as one
    // (packing reported it as left out, unused, on every STL file).
    if (std::string(c.ext) == "stl" || std::string(c.ext) == "ply") {
      EXPECT_TRUE(out->materials.empty()) << c.ext;
    }
  }
}

// glTF-Transform writes a Draco .gltf with its streams in the .bin beside it: the buffer is read
// in before the streams are decoded. Without the .bin the error names it.
// `gltf` refers to the Draco square's streams (doc's binary chunk) in the file `streams` of `dir`:
// without it the error names it; with it written the square reads.
void ExpectSquareReadsOnceItsStreamsAreThere(const TempDir& dir, const std::string& gltf,
                                             const std::string& streams, const GltfDocument& doc) {
  Result<Scene> missing = ReadScene(gltf);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find(streams), std::string::npos)
      << missing.status().message();
  testing::WriteBytes(dir.File(streams), doc.binary().data(), doc.binary().size());
  Result<Scene> s = ReadScene(gltf);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->meshes.size(), 1u);
  EXPECT_EQ(s->meshes[0].triangle_count(), 2u);
  EXPECT_EQ(s->meshes[0].uv_sets.size(), 1u);
}

TEST(SceneIo, DracoGltfWithItsStreamsInTheBinBesideIt) {
  TempDir dir;
  const GltfDocument doc = DracoDocument(EncodeSquare(), 4);
  Result<std::string> json = doc.SerializeJson("square streams.bin");
  ASSERT_TRUE(json.ok()) << json.status().ToString();
  const std::string gltf = dir.File("square.gltf");
  testing::WriteBytes(gltf, json->data(), json->size());
  ExpectSquareReadsOnceItsStreamsAreThere(dir, gltf, "square streams.bin", doc);
}

// glTF-Transform's `partition` gives each mesh its own .bin: the streams lie in buffer 1, after a
// buffer 0 of other data, and a data: buffer follows (its index moves down when buffer 1 joins
// the binary chunk).
TEST(SceneIo, DracoGltfWithItsStreamsInASecondBufferFile) {
  TempDir dir;
  const GltfDocument doc = DracoDocument(EncodeSquare(), 4);
  Result<std::string> text = doc.SerializeJson("streams.bin");
  ASSERT_TRUE(text.ok()) << text.status().ToString();
  nlohmann::json json = nlohmann::json::parse(text.value());
  nlohmann::json& buffers = json["buffers"];
  buffers.insert(buffers.begin(), nlohmann::json{{"uri", "first.bin"}, {"byteLength", 5}});
  buffers.push_back(
      nlohmann::json{{"uri", "data:application/octet-stream;base64,AAAA"}, {"byteLength", 3}});
  for (nlohmann::json& view : json["bufferViews"]) view["buffer"] = 1;
  const std::string gltf = dir.File("square.gltf");
  const std::string dumped = json.dump();
  testing::WriteBytes(gltf, dumped.data(), dumped.size());
  const uint8_t first[5] = {1, 2, 3, 4, 5};
  testing::WriteBytes(dir.File("first.bin"), first, sizeof(first));
  ExpectSquareReadsOnceItsStreamsAreThere(dir, gltf, "streams.bin", doc);
}

TEST(SceneIo, MissingFileAndUnknownFormat) {
  Result<Scene> missing = ReadScene("/nonexistent/dir/mesh.obj");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().code(), StatusCode::kIoError);
  EXPECT_NE(missing.status().message().find("/nonexistent/dir/mesh.obj"), std::string::npos);
  Result<Scene> unknown = ReadScene("model.xyz");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.status().code(), StatusCode::kUnknownFormat);
  EXPECT_NE(unknown.status().message().find("'.xyz'"), std::string::npos);
}

TEST(SceneIo, EmptyRandomAndTruncatedFilesGiveErrorsInEveryFormat) {
  TempDir dir;
  const Scene in = TorusScene(8, 6);
  struct Case {
    const char* ext;
    std::vector<uint8_t> valid;
  };
  std::vector<Case> cases;
  for (const char* ext : {"obj", "off", "wrl", "ply"}) {
    Result<std::vector<uint8_t>> bytes =
        EncodeScene(in, FormatFromExtension(std::string("x.") + ext));
    ASSERT_TRUE(bytes.ok());
    cases.push_back({ext, bytes.value()});
  }
  cases.push_back({"stl", testing::ExportWithAssimp(in, "stlb")});
  cases.push_back({"dae", testing::ExportWithAssimp(in, "collada")});
  cases.push_back({"fbx", testing::ExportWithAssimp(in, "fbxa")});
  cases.push_back({"glb", testing::ExportWithAssimp(in, "glb2")});
  cases.push_back({"gltf", testing::ExportWithAssimp(in, "gltf2")});
  for (const Case& c : cases) {
    ASSERT_FALSE(c.valid.empty()) << c.ext;
    const std::string path = dir.File(std::string("bad.") + c.ext);
    // Empty.
    testing::WriteBytes(path, "", 0);
    Result<Scene> r = ReadScene(path);
    EXPECT_FALSE(r.ok()) << c.ext << " empty";
    // Random bytes.
    for (uint32_t seed = 1; seed <= 3; ++seed) {
      const std::vector<uint8_t> noise = testing::RandomBytes(4096, seed);
      testing::WriteBytes(path, noise.data(), noise.size());
      r = ReadScene(path);
      EXPECT_FALSE(r.ok()) << c.ext << " random seed " << seed;
      if (!r.ok()) {
        EXPECT_EQ(r.status().message().rfind(path, 0), 0u) << r.status().message();
      }
    }
    // Truncated to a third: every format either errors or, at worst, holds fewer triangles.
    testing::WriteBytes(path, c.valid.data(), c.valid.size() / 3);
    r = ReadScene(path);
    if (r.ok()) {
      EXPECT_LT(r->triangle_count(), in.triangle_count()) << c.ext << " truncated";
    } else {  // NOLINT
      EXPECT_EQ(r.status().message().rfind(path, 0), 0u) << r.status().message();
    }
  }
}

TEST(SceneIo, WriteIsAtomicAndReportsUnwritableTargets) {
  TempDir dir;
  const std::string path = dir.File("out.obj");
  ASSERT_TRUE(WriteScene(TorusScene(), path).ok());
  // No temporary file is left behind.
  const std::string listing = dir.File("");
  EXPECT_TRUE(SameFile(path, path));
  Status bad = WriteScene(TorusScene(), "/nonexistent/dir/out.obj");
  EXPECT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("/nonexistent/dir/out.obj"), std::string::npos);
  Status unknown = WriteScene(TorusScene(), dir.File("out.xyz"));
  EXPECT_EQ(unknown.code(), StatusCode::kUnknownFormat);
}

}  // namespace
}  // namespace hullpack
