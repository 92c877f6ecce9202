// The packed-GLB reader on hostile JSON: members of the wrong JSON type in the parts only the
// inflater reads (accessors it fills, stream bufferViews, the extension object) give a parse error
// that names the file, never an exception out of the reader (which would terminate the process, as
// a fuzzed file with "normalized": 1 showed). Fuzz findings in tests/fuzz/regressions/ are replayed
// here.
#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>

#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "../pipeline/test_torus.h"
#include "gltf/glb_reader.h"
#include "gltf/gltf_document.h"
#include "packed/packed_glb_reader.h"
#include "packed_glb_test_util.h"
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

TEST(PackedGlbReader, MorphTargetsComeFromTheStreamAndHostileMapsAreParseErrors) {
  Mesh torus = testing::TorusMesh(12, 8);
  MorphTarget swell;
  swell.name = "swell";
  for (float p : torus.positions) swell.positions.push_back(0.5f * p);
  torus.morph_targets = {swell};
  const std::vector<uint8_t> glb = testing::PackWithoutHulls(torus);
  Result<Scene> scene = ReadPackedGltf(glb.data(), glb.size(), "morph.glb", "", nullptr);
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  ASSERT_EQ(scene->meshes[0].morph_targets.size(), 1u);
  EXPECT_EQ(scene->meshes[0].morph_targets[0].name, "swell");
  float largest = 0, source_largest = 0;
  for (float d : scene->meshes[0].morph_targets[0].positions) largest = std::max(largest, d);
  for (float d : swell.positions) source_largest = std::max(source_largest, d);
  EXPECT_GT(source_largest, 0.5f);
  EXPECT_NEAR(largest, source_largest, 0.01f);

  auto edit_targets =
      [&](const std::function<void(nlohmann::json & ext, nlohmann::json & prim)>& f) {
        return Rewrite(glb, [&](nlohmann::json& json) {
          nlohmann::json& prim = json["meshes"][0]["primitives"][0];
          f(prim["extensions"][kMeshCompressionExtension], prim);
        });
      };
  ExpectParseErrorNamingFile(edit_targets([](nlohmann::json& ext, nlohmann::json&) {
                               ext["targets"][0]["POSITION"] = 99;
                             }),
                             "a target naming a stream attribute the stream lacks");
  ExpectParseErrorNamingFile(edit_targets([](nlohmann::json& ext, nlohmann::json&) {
                               ext["targets"].push_back(ext["targets"][0]);
                             }),
                             "more extension targets than the primitive has");
  ExpectParseErrorNamingFile(
      edit_targets([](nlohmann::json& ext, nlohmann::json&) { ext["targets"] = "all"; }),
      "targets that are not an array");
  ExpectParseErrorNamingFile(edit_targets([](nlohmann::json& ext, nlohmann::json& prim) {
                               prim["targets"][0]["POSITION"] = 999;
                               (void)ext;
                             }),
                             "a target accessor that does not exist");
}

// Every file the fuzzers once crashed on must now give a Status (or a scene), in this build too.
// The hulls of a packed torus, read through ReadCollisionHulls after `edit` changed the JSON.
Result<std::vector<CollisionHull>> HullsAfter(const std::function<void(nlohmann::json&)>& edit) {
  Scene scene;
  scene.meshes.push_back(testing::TorusMesh(24, 12));
  AddRootNodeForAllMeshes(scene, "torus");
  PackOptions options;
  options.collision.parameters.resolution = 20000;
  Result<PackResult> packed = PackScene(std::move(scene), options);
  if (!packed.ok()) return packed.status();
  const std::vector<uint8_t> glb =
      testing::RewriteGlb(packed->glb, [&](GltfDocument& d) { edit(d.json()); });
  GltfDocument doc;
  Result<Scene> read = ReadPackedGltf(glb.data(), glb.size(), "hostile.glb", "", &doc);
  if (!read.ok()) return read.status();
  return ReadCollisionHulls(doc, "hostile.glb");
}

TEST(PackedGlbReader, CollisionHullsOfHostileFilesAreParseErrors) {
  Result<std::vector<CollisionHull>> intact = HullsAfter([](nlohmann::json&) {});
  ASSERT_TRUE(intact.ok()) << intact.status().ToString();
  ASSERT_GT(intact->size(), 1u);
  const int collider = intact->at(0).collider_node;
  const int mesh = intact->at(0).gltf_mesh;
  const std::vector<std::pair<std::string, std::function<void(nlohmann::json&)>>> edits = {
      {"shape out of range",
       [&](nlohmann::json& j) {
         j["nodes"][collider]["extensions"]["OMI_physics_body"]["collider"]["shape"] = 999;
       }},
      {"mesh out of range",
       [&](nlohmann::json& j) {
         j["extensions"]["OMI_physics_shape"]["shapes"][0]["convex"]["mesh"] = 999;
       }},
      {"accessor beyond its bufferView",
       [&](nlohmann::json& j) {
         const int a = j["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"];
         j["accessors"][a]["byteOffset"] = 1u << 30;
       }},
      {"accessor count too large",
       [&](nlohmann::json& j) {
         const int a = j["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"];
         j["accessors"][a]["count"] = 1u << 28;
       }},
      {"POSITION not VEC3",
       [&](nlohmann::json& j) {
         const int a = j["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"];
         j["accessors"][a]["type"] = "VEC2";
       }},
  };
  for (const auto& [what, edit] : edits) {
    Result<std::vector<CollisionHull>> hulls = HullsAfter(edit);
    ASSERT_FALSE(hulls.ok()) << what;
    EXPECT_EQ(hulls.status().code(), StatusCode::kParseError) << what;
    EXPECT_NE(hulls.status().message().find("hostile.glb"), std::string::npos)
        << hulls.status().ToString();
  }
}

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
