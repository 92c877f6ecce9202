#include "pipeline/prune.h"

#include <gtest/gtest.h>

#include "attributed_quad.h"

namespace hullpack {
namespace {

Scene OneQuadScene() {
  Scene s;
  s.meshes.push_back(testing::AttributedQuad());
  s.materials.resize(1);
  s.materials[0].name = "plain";
  AddRootNodeForAllMeshes(s, "root");
  return s;
}

TEST(Prune, UntexturedMeshLosesUvsAndTangentsAndFoldsConstantColour) {
  Scene s = OneQuadScene();
  const PruneReport r = LeaveOutUnused(s);
  const Mesh& m = s.meshes[0];
  EXPECT_TRUE(m.uv_sets.empty());
  EXPECT_TRUE(m.tangents.empty());
  EXPECT_TRUE(m.colors.empty());
  EXPECT_FALSE(m.normals.empty());  // lighting needs them
  EXPECT_EQ(r.uv_sets_removed, 2u);
  EXPECT_EQ(r.tangent_sets_removed, 1u);
  EXPECT_EQ(r.constant_color_sets_folded, 1u);
  // The constant colour now tints a copy of the material; the untinted original is unreferenced.
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_FLOAT_EQ(s.materials[0].base_color[0], 0.5f);
  EXPECT_EQ(m.material_ids[0], 0u);
  EXPECT_EQ(r.materials_removed, 1u);
  EXPECT_FALSE(r.lines.empty());
}

TEST(Prune, TexturedMeshKeepsTheUvSetsItsTexturesSample) {
  Scene s = OneQuadScene();
  s.images.resize(2);
  s.materials[0].base_color_texture = {0, 0, {}};
  s.materials[0].normal_texture = {1, 1, {}};
  s.meshes[0].colors[0] = 0.25f;  // not constant any more
  const PruneReport r = LeaveOutUnused(s);
  EXPECT_EQ(s.meshes[0].uv_sets.size(), 2u);
  EXPECT_FALSE(s.meshes[0].tangents.empty());
  EXPECT_FALSE(s.meshes[0].colors.empty());
  EXPECT_EQ(s.images.size(), 2u);
  EXPECT_EQ(r.uv_sets_removed + r.tangent_sets_removed + r.images_removed, 0u);
}

TEST(Prune, TrailingUnusedUvSetGoes) {
  Scene s = OneQuadScene();
  s.images.resize(1);
  s.materials[0].base_color_texture = {0, 0, {}};
  LeaveOutUnused(s);
  EXPECT_EQ(s.meshes[0].uv_sets.size(), 1u);
}

TEST(Prune, UnreferencedMeshesMaterialsAndImagesGoAndIndicesAreRemapped) {
  Scene s = OneQuadScene();
  s.meshes.insert(s.meshes.begin(), testing::AttributedQuad());  // mesh 0: shown by no node
  s.nodes[0].meshes = {1};
  s.materials.resize(3);
  s.materials[2].name = "used";
  s.materials[2].base_color_texture = {1, 0, {}};
  s.images.resize(2);
  s.images[1].name = "kept";
  s.meshes[1].material_ids = {2, 2};
  s.meshes[1].colors.clear();
  const PruneReport r = LeaveOutUnused(s);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.nodes[0].meshes, std::vector<int>{0});
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "used");
  EXPECT_EQ(s.meshes[0].material_ids, (std::vector<uint32_t>{0, 0}));
  ASSERT_EQ(s.images.size(), 1u);
  EXPECT_EQ(s.images[0].name, "kept");
  EXPECT_EQ(s.materials[0].base_color_texture.image, 0);
  EXPECT_EQ(r.meshes_removed, 1u);
  EXPECT_EQ(r.materials_removed, 2u);
  EXPECT_EQ(r.images_removed, 1u);
}

TEST(Prune, MeshesWithoutTrianglesGoAndIndicesAreRemapped) {
  Scene s = OneQuadScene();
  s.meshes.insert(s.meshes.begin(), Mesh());  // every triangle dropped by the repairs
  s.nodes[0].meshes = {0, 1};
  const PruneReport r = LeaveOutUnused(s);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangle_count(), 2u);
  EXPECT_EQ(s.nodes[0].meshes, std::vector<int>{0});
  EXPECT_EQ(r.empty_meshes_removed, 1u);
  EXPECT_EQ(r.meshes_removed, 0u);
}

TEST(Prune, SkinDataWithoutASkinnedNodeGoes) {
  Scene s = OneQuadScene();
  s.meshes[0].joints.assign(16, 0);
  s.meshes[0].weights.assign(16, 0.25f);
  Scene skinned = s;
  skinned.skins.resize(1);
  skinned.nodes[0].skin = 0;
  LeaveOutUnused(s);
  LeaveOutUnused(skinned);
  EXPECT_TRUE(s.meshes[0].joints.empty());
  EXPECT_FALSE(skinned.meshes[0].joints.empty());
}

// Two vertices that differ only in a UV set nothing samples are one vertex once the set is gone.
TEST(Prune, VerticesEqualOnceAnAttributeIsLeftOutAreWelded) {
  Scene s = OneQuadScene();
  Mesh& m = s.meshes[0];
  m.tangents.clear();
  m.colors.clear();
  m.uv_sets.resize(1);
  // Vertex 4: vertex 0 again with other texture coordinates (a UV seam).
  m.positions.insert(m.positions.end(), {0, 0, 0});
  m.normals.insert(m.normals.end(), {0, 0, 1});
  m.uv_sets[0].insert(m.uv_sets[0].end(), {0.5f, 0.5f});
  m.indices[3] = 4;
  const PruneReport r = LeaveOutUnused(s);
  EXPECT_TRUE(s.meshes[0].uv_sets.empty());
  EXPECT_EQ(s.meshes[0].vertex_count(), 4u);
  EXPECT_EQ(s.meshes[0].indices[3], 0u);
  EXPECT_EQ(r.repairs.welded_vertices, 1u);
}

}  // namespace
}  // namespace hullpack
