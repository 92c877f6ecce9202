// The packed-GLB reader on hostile JSON: members of the wrong JSON type in the parts only the
// inflater reads (accessors it fills, stream bufferViews, the extension object) give a parse error
// that names the file, never an exception out of the reader (which would terminate the process, as
// a fuzzed file with "normalized": 1 showed). Fuzz findings in tests/fuzz/regressions/ are replayed
// here.
#include <gtest/gtest.h>

#include <dirent.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../pipeline/packed_glb_test_util.h"
#include "../pipeline/test_torus.h"
#include "gltf/glb_reader.h"
#include "gltf/gltf_document.h"
#include "gltf/packed_glb_reader.h"
#include "pipeline/pack.h"

namespace hullpack {
namespace {

std::vector<uint8_t> PackedTorus() { return testing::PackWithoutHulls(testing::TorusMesh(12, 8)); }

// `edit` changes the JSON of `glb`, which is serialized again.
template <typename Edit>
std::vector<uint8_t> Rewrite(const std::vector<uint8_t>& glb, Edit edit) {
  return testing::RewriteGlb(glb, [&](GltfDocument& doc) { edit(doc.json()); });
}

// The accessors and bufferView the packed primitive's extension fills from its stream.
struct PackedRefs {
  int64_t position_accessor = -1;
  int64_t index_accessor = -1;
  int64_t stream_view = -1;
};

PackedRefs FindPackedRefs(const nlohmann::json& json) {
  PackedRefs refs;
  const nlohmann::json& primitive = json["meshes"][0]["primitives"][0];
  refs.position_accessor = primitive["attributes"]["POSITION"].get<int64_t>();
  refs.index_accessor = primitive["indices"].get<int64_t>();
  for (const auto& ext : primitive["extensions"]) {
    if (ext.contains("bufferView")) refs.stream_view = ext["bufferView"].get<int64_t>();
  }
  return refs;
}

void ExpectParseErrorNamingFile(const std::vector<uint8_t>& glb, const std::string& what) {
  ASSERT_FALSE(glb.empty()) << what;
  Result<Scene> scene = ReadPackedGltf(glb.data(), glb.size(), "hostile.glb", "", nullptr);
  ASSERT_FALSE(scene.ok()) << what;
  EXPECT_EQ(scene.status().code(), StatusCode::kParseError)
      << what << ": " << scene.status().ToString();
  EXPECT_NE(scene.status().message().find("hostile.glb"), std::string::npos)
      << scene.status().ToString();
}

TEST(PackedGlbReader, UntouchedFileReadsBack) {
  const std::vector<uint8_t> glb = PackedTorus();
  ASSERT_FALSE(glb.empty());
  Result<GltfDocument> doc = DecodeGlbDocument(glb.data(), glb.size(), "torus.glb");
  ASSERT_TRUE(doc.ok()) << doc.status().ToString();
  const PackedRefs refs = FindPackedRefs(doc->json());
  EXPECT_GE(refs.position_accessor, 0);
  EXPECT_GE(refs.index_accessor, 0);
  EXPECT_GE(refs.stream_view, 0);
  Result<Scene> scene = ReadPackedGltf(glb.data(), glb.size(), "torus.glb", "", nullptr);
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  EXPECT_EQ(scene->meshes.at(0).triangle_count(), 12u * 8u * 2u);
}

TEST(PackedGlbReader, AccessorMembersOfTheWrongTypeAreParseErrors) {
  const std::vector<uint8_t> glb = PackedTorus();
  const std::vector<std::pair<const char*, nlohmann::json>> cases = {
      {"normalized", 1},
      {"normalized", "yes"},
      {"componentType", "float"},
      {"componentType", -5126},
      {"componentType", 5126.5},
      {"type", 3},
      {"type", nlohmann::json::array({"VEC3"})}};
  for (bool indices : {false, true}) {
    for (const auto& [key, value] : cases) {
      const std::string what =
          std::string(indices ? "index" : "position") + " accessor " + key + " = " + value.dump();
      ExpectParseErrorNamingFile(
          Rewrite(glb,
                  [&, key = key, value = value](nlohmann::json& json) {
                    const PackedRefs refs = FindPackedRefs(json);
                    json["accessors"][indices ? refs.index_accessor : refs.position_accessor][key] =
                        value;
                  }),
          what);
    }
  }
}

TEST(PackedGlbReader, StreamViewAndExtensionMembersOfTheWrongTypeAreParseErrors) {
  const std::vector<uint8_t> glb = PackedTorus();
  for (const char* key : {"byteOffset", "byteLength"}) {
    for (const nlohmann::json& value :
         {nlohmann::json("0"), nlohmann::json(-1), nlohmann::json(0.5), nlohmann::json::object()}) {
      ExpectParseErrorNamingFile(
          Rewrite(glb,
                  [&](nlohmann::json& json) {
                    json["bufferViews"][FindPackedRefs(json).stream_view][key] = value;
                  }),
          std::string("stream bufferView ") + key + " = " + value.dump());
    }
  }
  ExpectParseErrorNamingFile(
      Rewrite(glb,
              [](nlohmann::json& json) {
                for (auto& ext : json["meshes"][0]["primitives"][0]["extensions"]) {
                  ext["group"] = 0;
                  ext["compactVertices"] = "true";
                }
              }),
      "compactVertices = \"true\"");
}

// Every file the fuzzers once crashed on must now give a Status (or a scene), in this build too.
TEST(PackedGlbReader, FuzzFindingsAreHandled) {
  const std::string dir =
      std::string(HULLPACK_SOURCE_DIR) + "/tests/fuzz/regressions/packed_glb_fuzzer";
  DIR* d = opendir(dir.c_str());
  ASSERT_NE(d, nullptr) << dir;
  int files = 0;
  while (dirent* e = readdir(d)) {
    if (e->d_name[0] == '.') continue;
    std::ifstream in(dir + "/" + e->d_name, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    ASSERT_FALSE(bytes.empty()) << e->d_name;
    Result<Scene> scene = ReadPackedGltf(bytes.data(), bytes.size(), e->d_name, "", nullptr);
    if (!scene.ok()) {
      EXPECT_NE(scene.status().message().find(e->d_name), std::string::npos)
          << scene.status().ToString();
    }
    ++files;
  }
  closedir(d);
  EXPECT_GE(files, 1);
}

}  // namespace
}  // namespace hullpack
