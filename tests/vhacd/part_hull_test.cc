#include "part_hull.h"

#include <gtest/gtest.h>

#include "test_meshes.h"

namespace vhacd {
namespace internal {
namespace {

TEST(PartHullTest, ClipTriangleToBox) {
  std::vector<Vec3> out;
  // Fully inside: unchanged.
  ClipTriangleToBox(Vec3(1, 1, 1), Vec3(2, 1, 1), Vec3(1, 2, 1), Vec3(0, 0, 0), Vec3(3, 3, 3),
                    &out);
  EXPECT_EQ(out.size(), 3u);
  // Outside: nothing.
  out.clear();
  ClipTriangleToBox(Vec3(5, 5, 5), Vec3(6, 5, 5), Vec3(5, 6, 5), Vec3(0, 0, 0), Vec3(3, 3, 3),
                    &out);
  EXPECT_TRUE(out.empty());
  // A big triangle in z = 1 covering the box's section: clipped to the square [0,3]^2.
  out.clear();
  ClipTriangleToBox(Vec3(-10, -10, 1), Vec3(30, -10, 1), Vec3(-10, 30, 1), Vec3(0, 0, 0),
                    Vec3(3, 3, 3), &out);
  ASSERT_EQ(out.size(), 4u);
  for (const Vec3& p : out) {
    EXPECT_TRUE(p.x() == 0 || p.x() == 3);
    EXPECT_TRUE(p.y() == 0 || p.y() == 3);
    EXPECT_EQ(p.z(), 1);
  }
}

TEST(PartHullTest, HullOfAPartHugsTheSurfaceInsideItsBox) {
  // A box mesh [2.3, 7.6] x [2.2, 5.9] x [2.1, 4.8] in grid units; the part holds voxels x < 5.
  const vhacd_test::Mesh box = vhacd_test::Box(2.3, 2.2, 2.1, 7.6, 5.9, 4.8);
  GridMesh g;
  for (size_t i = 0; i < box.point_count(); ++i)
    g.points.emplace_back(box.points[3 * i], box.points[3 * i + 1], box.points[3 * i + 2]);
  for (size_t t = 0; t < box.triangle_count(); ++t)
    g.triangles.push_back({box.indices[3 * t], box.indices[3 * t + 1], box.indices[3 * t + 2]});
  const int dims[3] = {10, 8, 7};
  Part part;
  for (int z = 2; z <= 4; ++z)
    for (int y = 2; y <= 5; ++y)
      for (int x = 2; x <= 4; ++x) {
        Voxel v;
        v.c[0] = static_cast<uint16_t>(x);
        v.c[1] = static_cast<uint16_t>(y);
        v.c[2] = static_cast<uint16_t>(z);
        v.surface = (x == 2 || y == 2 || y == 5 || z == 2 || z == 4);
        part.voxels.push_back(v);
      }
  part.ComputeBounds();
  const TriangleIndex index(g, dims, 4);
  const HullMesh h = BuildPartHull(part, index);
  ASSERT_FALSE(h.empty());
  // The mesh box clipped to x <= 5: [2.3, 5] x [2.2, 5.9] x [2.1, 4.8].
  EXPECT_NEAR(h.Volume(), (5 - 2.3) * (5.9 - 2.2) * (4.8 - 2.1), 1e-9);
}

TEST(PartHullTest, TheSameHullAfterManyPartsOnOneThread) {
  // A part's hull does not depend on the parts built before it on the same thread, also once
  // the per-thread marks of the triangles and vertices seen have wrapped (every few hundred
  // parts).
  const vhacd_test::Mesh box = vhacd_test::Box(1.3, 1.2, 1.1, 6.6, 4.9, 3.8);
  GridMesh g;
  for (size_t i = 0; i < box.point_count(); ++i)
    g.points.emplace_back(box.points[3 * i], box.points[3 * i + 1], box.points[3 * i + 2]);
  for (size_t t = 0; t < box.triangle_count(); ++t)
    g.triangles.push_back({box.indices[3 * t], box.indices[3 * t + 1], box.indices[3 * t + 2]});
  const int dims[3] = {8, 6, 5};
  auto voxel = [](int x, int y, int z) {
    Voxel v;
    v.c[0] = static_cast<uint16_t>(x);
    v.c[1] = static_cast<uint16_t>(y);
    v.c[2] = static_cast<uint16_t>(z);
    v.surface = true;
    return v;
  };
  Part whole;  // every voxel: the whole mesh lies inside the part's box
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) whole.voxels.push_back(voxel(x, y, z));
  whole.ComputeBounds();
  Part corner;  // one voxel that no triangle reaches
  corner.voxels.push_back(voxel(0, 0, 0));
  corner.ComputeBounds();
  const TriangleIndex index(g, dims, 4);
  const HullMesh first = BuildPartHull(whole, index);
  ASSERT_FALSE(first.empty());
  EXPECT_NEAR(first.Volume(), (6.6 - 1.3) * (4.9 - 1.2) * (3.8 - 1.1), 1e-9);
  for (int others = 0; others < 600; ++others) {
    for (int k = 0; k < others; ++k) BuildPartHull(corner, index);
    const HullMesh again = BuildPartHull(whole, index);
    ASSERT_EQ(again.vertices, first.vertices) << "after " << others << " other parts";
    ASSERT_EQ(again.triangles, first.triangles) << "after " << others << " other parts";
  }
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
