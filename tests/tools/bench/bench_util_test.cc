#include "bench/bench_util.h"

#include <gtest/gtest.h>

#include <vector>

namespace hullpack {
namespace {

// Two triangles sharing an edge, 0-1-2 and 4-3-5, whose shared corners are duplicated as across a
// UV seam: vertices 4 and 5 repeat the positions of 1 and 2.
Mesh SeamQuad() {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, /* copies of 1, 2: */ 1, 0, 0, 0, 1, 0};
  m.indices = {0, 1, 2, 4, 3, 5};
  return m;
}

TEST(MergeGeometryTest, WeldsVerticesThatDifferedOnlyInADroppedUvSet) {
  Scene scene;
  Mesh with_uvs = SeamQuad();
  with_uvs.uv_sets.push_back({0, 0, 0.5f, 0, 0, 0.5f, 1, 1, 0.75f, 0, 0, 0.75f});  // the seam
  Mesh without_uvs = SeamQuad();  // so the merged mesh has no UV set; apart from the first
  for (size_t i = 2; i < without_uvs.positions.size(); i += 3) without_uvs.positions[i] = 1;
  scene.meshes = {with_uvs, without_uvs};
  const Mesh out = MergeGeometry(scene);
  EXPECT_TRUE(out.uv_sets.empty());
  ASSERT_EQ(out.vertex_count(), 8u);  // 4 distinct positions per copy of the quad
  ASSERT_EQ(out.triangle_count(), 4u);
  // The second triangle now uses the first one's corners: the seam is closed.
  EXPECT_EQ(std::vector<uint32_t>(out.indices.begin(), out.indices.begin() + 6),
            (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(std::vector<uint32_t>(out.indices.begin() + 6, out.indices.end()),
            (std::vector<uint32_t>{4, 5, 6, 5, 7, 6}));
}

TEST(MergeGeometryTest, KeepsVerticesThatDifferInAKeptAttribute) {
  Scene scene;
  Mesh m = SeamQuad();
  m.uv_sets.push_back({0, 0, 0.5f, 0, 0, 0.5f, 1, 1, 0.75f, 0, 0, 0.75f});
  scene.meshes = {m};
  const Mesh out = MergeGeometry(scene);
  ASSERT_EQ(out.uv_sets.size(), 1u);
  EXPECT_EQ(out.vertex_count(), 6u);
  EXPECT_EQ(out.indices, m.indices);
}

TEST(MergeGeometryTest, WeldsVerticesThatDifferedOnlyInColourButRepairsNothingElse) {
  Scene scene;
  Mesh m = SeamQuad();
  m.colors.assign(4 * m.vertex_count(), 1.0f);
  m.colors[4 * 4] = 0.0f;                        // vertex 4 differs from vertex 1 in colour only
  m.indices.insert(m.indices.end(), {0, 1, 4});  // degenerate once 4 is welded to 1: kept
  m.positions.insert(m.positions.end(), {5, 5, 5});  // unreferenced: kept
  m.colors.insert(m.colors.end(), {1, 1, 1, 1});
  scene.meshes = {m};
  const Mesh out = MergeGeometry(scene);
  EXPECT_TRUE(out.colors.empty());
  EXPECT_EQ(out.vertex_count(), 5u);
  EXPECT_EQ(out.indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 0, 1, 1}));
  EXPECT_EQ(std::vector<float>(out.positions.end() - 3, out.positions.end()),
            (std::vector<float>{5, 5, 5}));
}

TEST(MergeGeometryTest, KeepsTheSkinOnlyWhenAsked) {
  Scene scene;
  Mesh m = SeamQuad();
  m.joints.assign(4 * m.vertex_count(), 0);
  m.weights.assign(4 * m.vertex_count(), 0.0f);
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    m.joints[4 * v] = uint16_t(v % 2);
    m.weights[4 * v] = 1.0f;
  }
  scene.meshes = {m};
  const Mesh kept = MergeGeometry(scene, true);
  EXPECT_TRUE(kept.has_skin());
  EXPECT_EQ(kept.joints, m.joints);
  EXPECT_EQ(kept.weights, m.weights);
  const Mesh dropped = MergeGeometry(scene);
  EXPECT_FALSE(dropped.has_skin());
  EXPECT_TRUE(dropped.joints.empty() && dropped.weights.empty());
}

}  // namespace
}  // namespace hullpack
