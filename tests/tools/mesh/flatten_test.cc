#include "mesh/merge.h"

#include <gtest/gtest.h>

#include <vector>

#include "test_meshes.h"

namespace hullpack {
namespace {

using testing_meshes::UnitCube;

Mesh CubeWith(bool normals, bool uvs, bool colors, bool skin, bool materials, uint32_t material) {
  Mesh mesh = UnitCube();
  const size_t n = mesh.vertex_count();
  if (normals) mesh.normals.assign(3 * n, 0.5f);
  if (uvs) mesh.uv_sets.assign(2, std::vector<float>(2 * n, 0.25f));
  if (colors) mesh.colors.assign(4 * n, 1.0f);
  if (skin) {
    mesh.joints.assign(4 * n, 1);
    mesh.weights.assign(4 * n, 0.25f);
  }
  if (materials) mesh.material_ids.assign(mesh.triangle_count(), material);
  return mesh;
}

TEST(MergeMeshesTest, AppendsVerticesAndOffsetsIndices) {
  Scene scene;
  scene.meshes = {UnitCube(), UnitCube()};
  const Mesh all = MergeMeshes(scene);
  const Mesh cube = UnitCube();
  ASSERT_EQ(all.vertex_count(), 2 * cube.vertex_count());
  ASSERT_EQ(all.triangle_count(), 2 * cube.triangle_count());
  for (size_t i = 0; i < cube.indices.size(); ++i) {
    EXPECT_EQ(all.indices[i], cube.indices[i]);
    EXPECT_EQ(all.indices[cube.indices.size() + i], cube.indices[i] + cube.vertex_count());
  }
  EXPECT_EQ(std::vector<float>(all.positions.begin() + cube.positions.size(), all.positions.end()),
            cube.positions);
}

TEST(MergeMeshesTest, KeepsAVertexAttributeOnlyWhenEveryMeshHasIt) {
  Scene scene;
  scene.meshes = {CubeWith(true, true, true, true, false, 0),
                  CubeWith(true, false, true, false, false, 0)};
  const Mesh all = MergeMeshes(scene);
  EXPECT_EQ(all.normals.size(), 3 * all.vertex_count());
  EXPECT_EQ(all.colors.size(), 4 * all.vertex_count());
  EXPECT_TRUE(all.uv_sets.empty());
  EXPECT_TRUE(all.joints.empty());
  EXPECT_TRUE(all.weights.empty());
}

TEST(MergeMeshesTest, KeepsTheFirstUvSetAndTheSkin) {
  Scene scene;
  scene.meshes = {CubeWith(false, true, false, true, false, 0),
                  CubeWith(false, true, false, true, false, 0)};
  const Mesh all = MergeMeshes(scene);
  ASSERT_EQ(all.uv_sets.size(), 1u);
  EXPECT_EQ(all.uv_sets[0].size(), 2 * all.vertex_count());
  EXPECT_EQ(all.joints.size(), 4 * all.vertex_count());
  EXPECT_EQ(all.weights.size(), 4 * all.vertex_count());
  EXPECT_TRUE(all.normals.empty());
}

TEST(MergeMeshesTest, MaterialIdsAreKeptWhenAnyMeshHasThemAndZeroElsewhere) {
  Scene scene;
  scene.meshes = {CubeWith(false, false, false, false, false, 0),
                  CubeWith(false, false, false, false, true, 3)};
  const Mesh all = MergeMeshes(scene);
  const size_t per_cube = UnitCube().triangle_count();
  ASSERT_EQ(all.material_ids.size(), 2 * per_cube);
  for (size_t t = 0; t < per_cube; ++t) {
    EXPECT_EQ(all.material_ids[t], 0u);
    EXPECT_EQ(all.material_ids[per_cube + t], 3u);
  }
}

TEST(MergeMeshesTest, AnEmptySceneGivesAnEmptyMesh) {
  const Mesh all = MergeMeshes(Scene{});
  EXPECT_EQ(all.vertex_count(), 0u);
  EXPECT_TRUE(all.indices.empty());
  EXPECT_TRUE(all.uv_sets.empty());
  EXPECT_TRUE(all.material_ids.empty());
}

}  // namespace
}  // namespace hullpack
