// Formats are promises: packed files written by earlier releases keep reading. vectors/ holds
// `hullpack pack cup.obj` outputs of the release whose hulls were HULLPACK_mesh_compression streams
// (one group per hull, compactVertices), in the OMI and the KHR_physics form.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "mesh/topology.h"
#include "packed/packed_glb_reader.h"

namespace hullpack {
namespace {

std::vector<uint8_t> Vector(const std::string& name) {
  std::ifstream in(std::string(HULLPACK_SOURCE_DIR) + "/tests/tools/packed/vectors/" + name,
                   std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void ExpectCupWithTenHulls(const std::string& name) {
  const std::vector<uint8_t> glb = Vector(name);
  ASSERT_FALSE(glb.empty()) << name;
  GltfDocument doc;
  Result<Scene> scene = ReadPackedGltf(glb.data(), glb.size(), name, "", &doc);
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  ASSERT_EQ(scene->meshes.size(), 11u);  // the cup, then its 10 hulls
  EXPECT_EQ(scene->meshes[0].triangle_count(), 188u);
  Result<std::vector<CollisionHull>> hulls = ReadCollisionHulls(doc, name);
  ASSERT_TRUE(hulls.ok()) << hulls.status().ToString();
  ASSERT_EQ(hulls->size(), 10u);
  for (const CollisionHull& h : hulls.value()) {
    EXPECT_EQ(h.body_node, 0);
    EXPECT_GE(h.hull.vertex_count(), 4u);
    EXPECT_TRUE(AnalyzeTopology(h.hull).closed);
    for (size_t v = 0; v < h.hull.vertex_count(); ++v) {  // the cup's box + the hull budget
      EXPECT_LE(std::abs(h.hull.positions[v * 3]), 0.0504f);
      EXPECT_GE(h.hull.positions[v * 3 + 2], -0.0004f);
      EXPECT_LE(h.hull.positions[v * 3 + 2], 0.1204f);
    }
  }
}

TEST(PackedGlbVectors, HullsInsideTheExtensionOmiForm) {
  ExpectCupWithTenHulls("cup_hulls_in_stream_omi.glb");
}

TEST(PackedGlbVectors, HullsInsideTheExtensionKhrForm) {
  ExpectCupWithTenHulls("cup_hulls_in_stream_khr.glb");
}

}  // namespace
}  // namespace hullpack
