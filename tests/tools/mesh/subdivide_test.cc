#include "mesh/subdivide.h"

#include <gtest/gtest.h>

#include "test_meshes.h"

namespace hullpack {
namespace {

using testing_meshes::IsClosed;

TEST(SubdivideMidpoint, SplitsEveryTriangleInFourAndKeepsAClosedMeshClosed) {
  // The split cube: 24 vertices, closed only by position; welded first, it shares its midpoints.
  const Mesh cube = testing_meshes::SplitCube();
  const Mesh once = SubdivideMidpoint(cube, 1);
  EXPECT_EQ(once.triangle_count(), 4 * cube.triangle_count());
  EXPECT_EQ(once.vertex_count(), 8u + 18u);  // corners + one midpoint per edge
  EXPECT_TRUE(IsClosed(once));
  const Mesh twice = SubdivideMidpoint(cube, 2);
  EXPECT_EQ(twice.triangle_count(), 16 * cube.triangle_count());
  EXPECT_TRUE(IsClosed(twice));
  // Midpoints of a flat face stay on it: every position is still on the cube's surface.
  for (float p : twice.positions) EXPECT_TRUE(p >= 0 && p <= 1) << p;
  EXPECT_EQ(SubdivideMidpoint(cube, 0).triangle_count(), cube.triangle_count());
}

}  // namespace
}  // namespace hullpack
