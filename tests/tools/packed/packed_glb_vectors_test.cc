// vectors/ holds `hullpack pack cup.obj` outputs of the last release before o3dgc stream format 1.0
// (its render mesh and its hulls are HULLPACK_mesh_compression streams of the development format
// 7), in the OMI and the KHR_physics form. The promise starts at format 1.0
// (docs/o3dgc-stream-format.md): such files are refused with an error that names the stream and
// the version problem, never misread.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "packed/packed_glb_reader.h"

namespace hullpack {
namespace {

std::vector<uint8_t> Vector(const std::string& name) {
  std::ifstream in(std::string(HULLPACK_SOURCE_DIR) + "/tests/tools/packed/vectors/" + name,
                   std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void ExpectRefusedAsPre10(const std::string& name) {
  const std::vector<uint8_t> glb = Vector(name);
  ASSERT_FALSE(glb.empty()) << name;
  GltfDocument doc;
  Result<Scene> scene = ReadPackedGltf(glb.data(), glb.size(), name, "", &doc);
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.status().message().find("HULLPACK_mesh_compression"), std::string::npos)
      << scene.status().ToString();
  EXPECT_NE(scene.status().message().find("bad_version"), std::string::npos)
      << scene.status().ToString();
}

TEST(PackedGlbVectors, PreFormat10FilesAreRefusedOmiForm) {
  ExpectRefusedAsPre10("cup_hulls_in_stream_omi.glb");
}

TEST(PackedGlbVectors, PreFormat10FilesAreRefusedKhrForm) {
  ExpectRefusedAsPre10("cup_hulls_in_stream_khr.glb");
}

}  // namespace
}  // namespace hullpack
