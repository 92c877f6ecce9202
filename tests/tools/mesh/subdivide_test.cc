#include "mesh/subdivide.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "test_meshes.h"

namespace hullpack {
namespace {

// Each directed edge of a closed mesh appears once, and its reverse once.
bool Closed(const Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) ++edges[{m.indices[t * 3 + k], m.indices[t * 3 + (k + 1) % 3]}];
  for (const auto& [e, count] : edges) {
    auto reverse = edges.find({e.second, e.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) return false;
  }
  return true;
}

TEST(SubdivideMidpoint, SplitsEveryTriangleInFourAndKeepsAClosedMeshClosed) {
  // The split cube: 24 vertices, closed only by position; welded first, it shares its midpoints.
  const Mesh cube = testing_meshes::SplitCube();
  const Mesh once = SubdivideMidpoint(cube, 1);
  EXPECT_EQ(once.triangle_count(), 4 * cube.triangle_count());
  EXPECT_EQ(once.vertex_count(), 8u + 18u);  // corners + one midpoint per edge
  EXPECT_TRUE(Closed(once));
  const Mesh twice = SubdivideMidpoint(cube, 2);
  EXPECT_EQ(twice.triangle_count(), 16 * cube.triangle_count());
  EXPECT_TRUE(Closed(twice));
  // Midpoints of a flat face stay on it: every position is still on the cube's surface.
  for (float p : twice.positions) EXPECT_TRUE(p >= 0 && p <= 1) << p;
  EXPECT_EQ(SubdivideMidpoint(cube, 0).triangle_count(), cube.triangle_count());
}

}  // namespace
}  // namespace hullpack
