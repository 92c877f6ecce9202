#include "mesh/flatten.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
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

TEST(FlattenSceneTest, AppendsVerticesAndOffsetsIndices) {
  Scene scene;
  scene.meshes = {UnitCube(), UnitCube()};
  const Mesh all = FlattenScene(scene);
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

TEST(FlattenSceneTest, KeepsAVertexAttributeOnlyWhenEveryMeshHasIt) {
  Scene scene;
  scene.meshes = {CubeWith(true, true, true, true, false, 0),
                  CubeWith(true, false, true, false, false, 0)};
  const Mesh all = FlattenScene(scene);
  EXPECT_EQ(all.normals.size(), 3 * all.vertex_count());
  EXPECT_EQ(all.colors.size(), 4 * all.vertex_count());
  EXPECT_TRUE(all.uv_sets.empty());
  EXPECT_TRUE(all.joints.empty());
  EXPECT_TRUE(all.weights.empty());
}

TEST(FlattenSceneTest, KeepsTheFirstUvSetAndTheSkin) {
  Scene scene;
  scene.meshes = {CubeWith(false, true, false, true, false, 0),
                  CubeWith(false, true, false, true, false, 0)};
  const Mesh all = FlattenScene(scene);
  ASSERT_EQ(all.uv_sets.size(), 1u);
  EXPECT_EQ(all.uv_sets[0].size(), 2 * all.vertex_count());
  EXPECT_EQ(all.joints.size(), 4 * all.vertex_count());
  EXPECT_EQ(all.weights.size(), 4 * all.vertex_count());
  EXPECT_TRUE(all.normals.empty());
}

TEST(FlattenSceneTest, MaterialIdsAreKeptWhenAnyMeshHasThemAndZeroElsewhere) {
  Scene scene;
  scene.meshes = {CubeWith(false, false, false, false, false, 0),
                  CubeWith(false, false, false, false, true, 3)};
  const Mesh all = FlattenScene(scene);
  const size_t per_cube = UnitCube().triangle_count();
  ASSERT_EQ(all.material_ids.size(), 2 * per_cube);
  for (size_t t = 0; t < per_cube; ++t) {
    EXPECT_EQ(all.material_ids[t], 0u);
    EXPECT_EQ(all.material_ids[per_cube + t], 3u);
  }
}

void ExpectSameMesh(const Mesh& a, const Mesh& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.tangents, b.tangents);
  EXPECT_EQ(a.uv_sets, b.uv_sets);
  EXPECT_EQ(a.colors, b.colors);
  EXPECT_EQ(a.joints, b.joints);
  EXPECT_EQ(a.weights, b.weights);
  EXPECT_EQ(a.material_ids, b.material_ids);
  EXPECT_EQ(a.morph_targets.size(), b.morph_targets.size());
  EXPECT_EQ(a.morph_weights, b.morph_weights);
  EXPECT_EQ(a.collides, b.collides);
}

TEST(FlattenSceneTest, AMovedSceneGivesTheSameMesh) {
  Mesh rich = CubeWith(true, true, true, true, true, 2);
  rich.name = "rich";
  rich.tangents.assign(4 * rich.vertex_count(), 1.0f);
  rich.morph_targets.resize(1);
  rich.morph_targets[0].positions.assign(rich.positions.size(), 0.0f);
  rich.morph_weights = {0.5f};
  rich.collides = false;
  Mesh joints_only = UnitCube();
  joints_only.joints.assign(4 * joints_only.vertex_count(), 1);
  Matrix4 moved = kIdentity;
  moved[12] = 3;
  for (const Mesh& mesh : {rich, joints_only}) {
    // Not shown, shown once as stored, shown once moved, shown twice; and beside a second mesh.
    for (int shape = 0; shape < 5; ++shape) {
      Scene scene;
      scene.meshes = {mesh};
      if (shape == 4) scene.meshes.push_back(UnitCube());
      Node node;
      node.meshes = {0};
      if (shape == 2) node.local_transform = moved;
      if (shape >= 1) scene.nodes.push_back(node);
      if (shape == 3) scene.nodes.push_back(node);
      SCOPED_TRACE(shape);
      const Mesh copied = FlattenScene(scene);
      ExpectSameMesh(FlattenScene(std::move(scene)), copied);
    }
  }
}

TEST(FlattenSceneTest, AnEmptySceneGivesAnEmptyMesh) {
  const Mesh all = FlattenScene(Scene{});
  EXPECT_EQ(all.vertex_count(), 0u);
  EXPECT_TRUE(all.indices.empty());
  EXPECT_TRUE(all.uv_sets.empty());
  EXPECT_TRUE(all.material_ids.empty());
}

// A node transform moves, scales and rotates its meshes' instances; a parent's applies too; one
// mesh shown by two nodes appears twice; a mesh no node shows comes last, untransformed.
TEST(FlattenSceneTest, AppliesNodeTransformsToEveryInstance) {
  Scene scene;
  scene.meshes = {CubeWith(true, false, false, false, false, 0),
                  CubeWith(true, false, false, false, false, 0)};
  Node parent, child, other;
  parent.local_transform = kIdentity;
  parent.local_transform[12] = 10;  // translate x by 10
  parent.children = {1};
  child.parent = 0;
  // Rotate 90 degrees about z (x -> y, y -> -x), then scale by 2.
  child.local_transform = {0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1};
  child.meshes = {0};
  other.meshes = {0};  // the same mesh again, as stored
  scene.nodes = {parent, child, other};
  const Mesh cube = scene.meshes[0];
  const Mesh all = FlattenScene(scene);
  const size_t n = cube.vertex_count();
  ASSERT_EQ(all.vertex_count(), 3 * n);
  ASSERT_EQ(all.triangle_count(), 3 * cube.triangle_count());
  for (size_t v = 0; v < n; ++v) {
    const float* p = &cube.positions[v * 3];
    EXPECT_FLOAT_EQ(all.positions[v * 3], 10 - 2 * p[1]) << v;
    EXPECT_FLOAT_EQ(all.positions[v * 3 + 1], 2 * p[0]) << v;
    EXPECT_FLOAT_EQ(all.positions[v * 3 + 2], 2 * p[2]) << v;
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(all.positions[(n + v) * 3 + k], p[k]);      // node 2: as stored
      EXPECT_EQ(all.positions[(2 * n + v) * 3 + k], p[k]);  // mesh 1: no node shows it
    }
  }
  // Normals turn with the instance and stay unit length.
  EXPECT_NEAR(all.normals[1], 0.5f / std::sqrt(0.75f) * 1.0f, 1e-6);
}

// A mirroring transform reverses the winding, so a closed mesh keeps a positive volume.
TEST(FlattenSceneTest, AMirroredInstanceKeepsItsTrianglesFacingOut) {
  Scene scene;
  scene.meshes = {UnitCube()};
  Node mirror;
  mirror.local_transform = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  mirror.meshes = {0};
  scene.nodes = {mirror};

  const Mesh all = FlattenScene(scene);
  EXPECT_GT(testing_meshes::SignedVolume(UnitCube()), 0);
  EXPECT_NEAR(testing_meshes::SignedVolume(all), testing_meshes::SignedVolume(UnitCube()), 1e-9);
  EXPECT_EQ(all.positions[0], -UnitCube().positions[0]);
}

}  // namespace
}  // namespace hullpack
