// LeaveOutDegenerateTriangles: which triangles and vertices go, and that every array the view
// points into follows the kept vertices.
#include "degenerate_triangles.h"

#include <gtest/gtest.h>

#include <vector>

namespace o3dgc {
namespace {

TEST(DegenerateTriangles, NoneLeavesTheInputAlone) {
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<uint32_t> indices = {0, 1, 2};
  MeshView mesh;
  mesh.positions = positions.data();
  mesh.num_vertices = 3;
  mesh.indices = indices.data();
  mesh.num_triangles = 1;
  KeptMesh kept;
  EXPECT_FALSE(LeaveOutDegenerateTriangles(mesh, &kept));
  EXPECT_TRUE(kept.indices.empty());
}

// Interleaved rows (position, uv) with a stride; vertex 3 is a copy of vertex 0 at -0 instead of
// 0, used only by a triangle that collapses; vertex 5 is unreferenced in the input and stays.
TEST(DegenerateTriangles, LeftOutWithTheVerticesOnlyTheyUse) {
  const std::vector<float> rows = {
      0,     0, 0, 0.0f, 0.5f,  // 0
      1,     0, 0, 0.1f, 0.6f,  // 1
      0,     1, 0, 0.2f, 0.7f,  // 2
      -0.0f, 0, 0, 0.3f, 0.8f,  // 3: the position of 0
      1,     1, 0, 0.4f, 0.9f,  // 4
      5,     5, 5, 0.5f, 1.0f,  // 5: unreferenced
  };
  const std::vector<uint32_t> indices = {0, 1, 2, 3, 0, 1, 1, 4, 2, 2, 2, 4};
  const std::vector<uint32_t> groups = {7, 8, 9, 10};
  const std::vector<int32_t> joints = {10, 11, 12, 13, 14, 15};
  MeshView mesh;
  mesh.positions = rows.data();
  mesh.position_stride = 5 * sizeof(float);
  mesh.num_vertices = 6;
  mesh.indices = indices.data();
  mesh.num_triangles = 4;
  mesh.triangle_groups = groups.data();
  FloatAttributeView uv;
  uv.data = rows.data() + 3;
  uv.stride = 5 * sizeof(float);
  uv.dimension = 2;
  mesh.float_attributes.push_back(uv);
  IntAttributeView joint;
  joint.data = joints.data();
  joint.dimension = 1;
  mesh.int_attributes.push_back(joint);

  KeptMesh kept;
  ASSERT_TRUE(LeaveOutDegenerateTriangles(mesh, &kept));
  const MeshView& v = kept.view;
  ASSERT_EQ(v.num_triangles, 2u);
  EXPECT_EQ(std::vector<uint32_t>(v.indices, v.indices + 6),
            std::vector<uint32_t>({0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(std::vector<uint32_t>(v.triangle_groups, v.triangle_groups + 2),
            std::vector<uint32_t>({7, 9}));
  ASSERT_EQ(v.num_vertices, 5u);
  EXPECT_EQ(v.position_stride, 0u);
  EXPECT_EQ(std::vector<float>(v.positions, v.positions + 15),
            std::vector<float>({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 5, 5, 5}));
  EXPECT_EQ(std::vector<float>(v.float_attributes[0].data, v.float_attributes[0].data + 10),
            std::vector<float>({0.0f, 0.5f, 0.1f, 0.6f, 0.2f, 0.7f, 0.4f, 0.9f, 0.5f, 1.0f}));
  EXPECT_EQ(std::vector<int32_t>(v.int_attributes[0].data, v.int_attributes[0].data + 5),
            std::vector<int32_t>({10, 11, 12, 14, 15}));
}

// With no triangle left the group pointer stays, so the stream still says it has groups.
TEST(DegenerateTriangles, AllLeftOutKeepsTheGroupPointer) {
  const std::vector<float> positions = {1, 2, 3, 1, 2, 3, 1, 2, 3};
  const std::vector<uint32_t> indices = {0, 1, 2};
  const std::vector<uint32_t> groups = {4};
  MeshView mesh;
  mesh.positions = positions.data();
  mesh.num_vertices = 3;
  mesh.indices = indices.data();
  mesh.num_triangles = 1;
  mesh.triangle_groups = groups.data();
  KeptMesh kept;
  ASSERT_TRUE(LeaveOutDegenerateTriangles(mesh, &kept));
  EXPECT_EQ(kept.view.num_triangles, 0u);
  EXPECT_EQ(kept.view.num_vertices, 0u);
  EXPECT_EQ(kept.view.triangle_groups, groups.data());
}

}  // namespace
}  // namespace o3dgc
