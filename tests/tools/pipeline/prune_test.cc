#include "pipeline/prune.h"

#include <gtest/gtest.h>

namespace hullpack {
namespace {

// Two triangles sharing an edge, with every optional attribute present.
Mesh Quad() {
  Mesh m;
  m.name = "quad";
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  m.tangents = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  m.uv_sets = {{0, 0, 1, 0, 1, 1, 0, 1}, {0, 0, 1, 0, 1, 1, 0, 1}};
  m.colors = {0.5f, 1, 1, 1, 0.5f, 1, 1, 1, 0.5f, 1, 1, 1, 0.5f, 1, 1, 1};
  m.material_ids = {0, 0};
  return m;
}

Scene OneQuadScene() {
  Scene s;
  s.meshes.push_back(Quad());
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
  s.materials[0].base_color_texture = {0, 0};
  s.materials[0].normal_texture = {1, 1};
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
  s.materials[0].base_color_texture = {0, 0};
  LeaveOutUnused(s);
  EXPECT_EQ(s.meshes[0].uv_sets.size(), 1u);
}

TEST(Prune, UnreferencedMeshesMaterialsAndImagesGoAndIndicesAreRemapped) {
  Scene s = OneQuadScene();
  s.meshes.insert(s.meshes.begin(), Quad());  // mesh 0: shown by no node
  s.nodes[0].meshes = {1};
  s.materials.resize(3);
  s.materials[2].name = "used";
  s.materials[2].base_color_texture = {1, 0};
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

TEST(Prune, SkinWeightsSumToOneAndJointsWithoutWeightAreCleared) {
  Scene s = OneQuadScene();
  s.skins.resize(1);
  s.nodes[0].skin = 0;
  s.meshes[0].weights = {1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0.1f, 0.1f, 0, 0, 0.6f, 0.3f, 0.3f, 0};
  s.meshes[0].joints = {3, 7, 0, 5, 1, 2, 0, 0, 1, 2, 0, 0, 1, 2, 3, 4};
  const PruneReport r = LeaveOutUnused(s);
  EXPECT_EQ(r.skin_weights_normalized, 2u);
  EXPECT_EQ(r.unweighted_joints_cleared, 3u);  // joints 7 and 5 of vertex 0, 4 of vertex 3
  EXPECT_EQ(s.meshes[0].joints,
            std::vector<uint16_t>({3, 0, 0, 0, 1, 2, 0, 0, 1, 2, 0, 0, 1, 2, 3, 0}));
  const std::vector<float>& w = s.meshes[0].weights;
  EXPECT_FLOAT_EQ(w[8], 0.5f);
  EXPECT_FLOAT_EQ(w[12], 0.5f);
  EXPECT_FLOAT_EQ(w[13], 0.25f);
  bool reported = false;
  for (const std::string& line : r.lines)
    reported |= line.find("renormalized the skin weights of 2 vertices") != std::string::npos;
  EXPECT_TRUE(reported);
}

TEST(Prune, RepairsRemoveDegenerateAndDuplicateTrianglesAndUnusedVertices) {
  Scene s = OneQuadScene();
  Mesh& m = s.meshes[0];
  m.positions.insert(m.positions.end(), {9, 9, 9});  // unused vertex 4
  for (int k = 0; k < 3; ++k) {
    m.normals.push_back(0);
    m.uv_sets[0].push_back(0);
    m.uv_sets[1].push_back(0);
  }
  m.uv_sets[0].pop_back();
  m.uv_sets[1].pop_back();
  m.colors.insert(m.colors.end(), {0.5f, 1, 1, 1});
  m.tangents.insert(m.tangents.end(), {1, 0, 0, 1});
  m.indices.insert(m.indices.end(), {0, 1, 2, 0, 0, 1});  // a duplicate and a degenerate
  m.material_ids.insert(m.material_ids.end(), {0, 0});
  const PruneReport r = LeaveOutUnused(s);
  EXPECT_EQ(s.meshes[0].triangle_count(), 2u);
  EXPECT_EQ(s.meshes[0].vertex_count(), 4u);
  EXPECT_EQ(r.repairs.duplicate_triangles_removed, 1u);
  EXPECT_EQ(r.repairs.degenerate_triangles_removed, 1u);
  EXPECT_EQ(r.repairs.unused_vertices_removed, 1u);
}

}  // namespace
}  // namespace hullpack
