#include "convex_input.h"

#include <gtest/gtest.h>

#include "test_meshes.h"

namespace vhacd {
namespace internal {
namespace {

std::vector<Vec3> Points(const vhacd_test::Mesh& m) {
  std::vector<Vec3> p;
  for (size_t i = 0; i < m.point_count(); ++i)
    p.emplace_back(m.points[3 * i], m.points[3 * i + 1], m.points[3 * i + 2]);
  return p;
}

TriangleList Triangles(const vhacd_test::Mesh& m) {
  TriangleList t;
  for (size_t k = 0; k < m.triangle_count(); ++k)
    t.push_back({m.indices[3 * k], m.indices[3 * k + 1], m.indices[3 * k + 2]});
  return t;
}

TEST(ConvexInputTest, ABoxIsItsOwnHull) {
  const vhacd_test::Mesh box = vhacd_test::Box(0, 0, 0, 1, 0.5, 0.25);
  HullMesh hull;
  ASSERT_TRUE(ConvexInputHull(Points(box), Triangles(box), 64, 1e-9, &hull));
  EXPECT_EQ(hull.vertices.size(), 8u);
  EXPECT_NEAR(hull.Volume(), 0.125, 1e-12);
}

TEST(ConvexInputTest, ADentOrAConcaveSolidIsNot) {
  const vhacd_test::Mesh box = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  std::vector<Vec3> dented = Points(box);
  dented[0] += Vec3(0.1, 0.1, 0.1);  // a corner pushed inside: still closed, no longer convex
  HullMesh hull;
  EXPECT_FALSE(ConvexInputHull(dented, Triangles(box), 64, 1e-9, &hull));
  const vhacd_test::Mesh l = vhacd_test::LBlock();
  EXPECT_FALSE(ConvexInputHull(Points(l), Triangles(l), 64, 1e-9, &hull));
}

TEST(ConvexInputTest, AHullOverTheVertexBudgetIsLeftToTheDecomposition) {
  const vhacd_test::Mesh ball = vhacd_test::Sphere(1.0, 12, 6);
  HullMesh hull;
  ASSERT_TRUE(ConvexInputHull(Points(ball), Triangles(ball), 1024, 1e-9, &hull));
  EXPECT_FALSE(
      ConvexInputHull(Points(ball), Triangles(ball), hull.vertices.size() - 1, 1e-9, &hull));
}

// Through Decompose: one exact hull, no voxels, the measures of an exact result.
TEST(ConvexInputTest, DecomposeReturnsAConvexInputAsOneExactHull) {
  const vhacd_test::Mesh box = vhacd_test::Box(2, 3, 4, 5, 7, 6);
  const Result r = Decompose(box.View(), Parameters());
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.hulls.size(), 1u);
  EXPECT_EQ(r.hulls[0].points.size(), 8u * 3);
  EXPECT_NEAR(r.hulls[0].volume, 3.0 * 4.0 * 2.0, 1e-9);
  EXPECT_EQ(r.report.voxel_count, 0u);
  EXPECT_EQ(r.report.concavity, 0.0);
  EXPECT_EQ(r.report.volume_iou, 1.0);
  const Result l = Decompose(vhacd_test::LBlock().View(), Parameters());
  ASSERT_TRUE(l.ok()) << l.message;
  EXPECT_GT(l.report.voxel_count, 0u);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
