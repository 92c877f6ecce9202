// vectors/ holds `hullpack pack cup.obj` outputs of the last release before o3dgc stream format 1.0
// (its render mesh and its hulls are HULLPACK_mesh_compression streams of the development format
// 7), in the OMI and the KHR_physics form. The promise starts at format 1.0
// (docs/o3dgc-stream-format.md): such files are refused with an error that names the stream and
// the version problem, never misread.
#include <gtest/gtest.h>

#include <cmath>
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

// torus_format_1_0.glb: `hullpack pack samples/torus.obj --hulls 4` of the release that wrote
// o3dgc stream format 1.0 (the current encoder writes a later minor version): still read, to the
// same mesh (the whole-stream equality is Conformance.* in tests/o3dgc).
TEST(PackedGlbVectors, Format10FilesAreRead) {
  const std::vector<uint8_t> glb = Vector("torus_format_1_0.glb");
  ASSERT_FALSE(glb.empty());
  GltfDocument doc;
  Result<Scene> scene = ReadPackedGltf(glb.data(), glb.size(), "torus_format_1_0.glb", "", &doc);
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  // The render mesh; the four hulls are meshes of points.
  const Mesh* render = nullptr;
  for (const Mesh& mesh : scene->meshes) {
    if (mesh.triangle_count() == 0) continue;
    ASSERT_EQ(render, nullptr);
    render = &mesh;
  }
  ASSERT_NE(render, nullptr);
  EXPECT_EQ(scene->meshes.size(), 5u);
  const Mesh& m = *render;
  EXPECT_EQ(m.triangle_count(), 1024u);
  EXPECT_EQ(m.vertex_count(), 512u);
  EXPECT_EQ(m.normals.size(), m.positions.size());
  for (size_t i = 0; i < m.positions.size(); i += 3) {
    // The torus of samples/torus.obj: tube radius 0.35 around a circle of radius 1.
    const double r = std::hypot(m.positions[i], m.positions[i + 1]) - 1.0;
    EXPECT_NEAR(std::hypot(r, double(m.positions[i + 2])), 0.35, 2e-3) << "vertex " << i / 3;
  }
}

}  // namespace
}  // namespace hullpack
