#include "pipeline/check_and_repair.h"

#include <gtest/gtest.h>

#include "attributed_quad.h"

namespace hullpack {
namespace {

Scene OneQuadScene() {
  Scene s;
  s.meshes.push_back(testing::AttributedQuad());
  s.materials.resize(1);
  AddRootNodeForAllMeshes(s, "root");
  return s;
}

TEST(CheckAndRepair, SkinWeightsSumToOneAndJointsWithoutWeightAreCleared) {
  Scene s = OneQuadScene();
  s.skins.resize(1);
  s.nodes[0].skin = 0;
  s.meshes[0].weights = {1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0.1f, 0.1f, 0, 0, 0.6f, 0.3f, 0.3f, 0};
  s.meshes[0].joints = {3, 7, 0, 5, 1, 2, 0, 0, 1, 2, 0, 0, 1, 2, 3, 4};
  Result<CheckRepairReport> checked = CheckAndRepair(s);
  ASSERT_TRUE(checked.ok());
  const CheckRepairReport& r = checked.value();
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

TEST(CheckAndRepair, RepairsRemoveDegenerateAndDuplicateTrianglesAndUnusedVertices) {
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
  Result<CheckRepairReport> checked = CheckAndRepair(s);
  ASSERT_TRUE(checked.ok());
  const CheckRepairReport& r = checked.value();
  EXPECT_EQ(s.meshes[0].triangle_count(), 2u);
  EXPECT_EQ(s.meshes[0].vertex_count(), 4u);
  EXPECT_EQ(r.repairs.duplicate_triangles_removed, 1u);
  EXPECT_EQ(r.repairs.degenerate_triangles_removed, 1u);
  EXPECT_EQ(r.repairs.unused_vertices_removed, 1u);
}

TEST(CheckAndRepair, AnInvalidMeshIsAnErrorNamingIt) {
  Scene s = OneQuadScene();
  s.meshes.push_back(s.meshes[0]);
  s.meshes[1].indices[2] = 99;
  Result<CheckRepairReport> r = CheckAndRepair(s, {}, 2);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("mesh 1"), std::string::npos) << r.status().message();
}

TEST(CheckAndRepair, TheResultDoesNotDependOnTheThreadCount) {
  Scene a = OneQuadScene();
  for (int i = 0; i < 5; ++i) a.meshes.push_back(a.meshes[0]);
  for (Mesh& m : a.meshes) {
    m.indices.insert(m.indices.end(), {0, 1, 2, 3, 3, 1});  // a duplicate and a degenerate
    m.material_ids.insert(m.material_ids.end(), {0, 0});
  }
  Scene b = a;
  ASSERT_TRUE(CheckAndRepair(a, {}, 1).ok());
  ASSERT_TRUE(CheckAndRepair(b, {}, 3).ok());
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices);
    EXPECT_EQ(a.meshes[i].positions, b.meshes[i].positions);
  }
}

}  // namespace
}  // namespace hullpack
