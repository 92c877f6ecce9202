#include "voxel_islands.h"

#include <gtest/gtest.h>

#include <vector>

#include "test_grid_mesh.h"

namespace vhacd {
namespace internal {
namespace {

using vhacd_test::VoxelAt;

TEST(VoxelIslandsTest, CornersJoinAndGapsSeparate) {
  Part root;
  // Island 0: a 2x2x2 block and a voxel touching it at a corner only.
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) root.voxels.push_back(VoxelAt(x, y, z, x == 0));
  root.voxels.push_back(VoxelAt(2, 2, 2, true));
  // Island 1: a line one empty voxel away.
  for (int x = 4; x < 8; ++x) root.voxels.push_back(VoxelAt(x, 0, 0, true));
  // Island 2: a lone voxel at the grid's far corner.
  root.voxels.push_back(VoxelAt(9, 9, 9, false));
  const int dims[3] = {10, 10, 10};
  const VoxelIslands islands(root, dims);
  ASSERT_EQ(islands.count(), 3u);
  EXPECT_EQ(islands.Of(root.voxels[0]), 0u);
  EXPECT_EQ(islands.Of(VoxelAt(2, 2, 2, true)), 0u);
  EXPECT_EQ(islands.Of(VoxelAt(5, 0, 0, true)), 1u);
  EXPECT_EQ(islands.Of(VoxelAt(9, 9, 9, false)), 2u);
  const std::vector<Part> parts = islands.Split(root);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0].voxels.size(), 9u);
  EXPECT_EQ(parts[1].voxels.size(), 4u);
  EXPECT_EQ(parts[2].voxels.size(), 1u);
  EXPECT_EQ(parts[1].bmin[0], 4);
  EXPECT_EQ(parts[1].bmax[0], 7);
  EXPECT_EQ(parts[0].bmax[2], 2);
}

TEST(VoxelIslandsTest, HullShareTellsObjectsApartFromNestedOnes) {
  const int dims[3] = {12, 12, 1};
  // Two blocks far apart: their hulls hold a small share of the hull over both.
  Part apart;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      apart.voxels.push_back(VoxelAt(x, y, 0, true));
      apart.voxels.push_back(VoxelAt(10 + x, 10 + y, 0, true));
    }
  apart.ComputeBounds();
  const VoxelIslands two(apart, dims);
  ASSERT_EQ(two.count(), 2u);
  EXPECT_LT(two.HullShare(apart, 1.0), 0.25);
  // A square frame around a lone voxel: the frame's hull is the whole's, so more than all of it.
  Part nested;
  for (int i = 0; i < 9; ++i) {
    nested.voxels.push_back(VoxelAt(i, 0, 0, true));
    nested.voxels.push_back(VoxelAt(i, 8, 0, true));
    if (i > 0 && i < 8) {
      nested.voxels.push_back(VoxelAt(0, i, 0, true));
      nested.voxels.push_back(VoxelAt(8, i, 0, true));
    }
  }
  nested.voxels.push_back(VoxelAt(4, 4, 0, true));
  nested.ComputeBounds();
  const VoxelIslands frame(nested, dims);
  ASSERT_EQ(frame.count(), 2u);
  EXPECT_GT(frame.HullShare(nested, 2.0), 1.0);
}

TEST(VoxelIslandsTest, SplitKeepsEachSurfaceVoxelsCell) {
  // Tetrahedron mode: one cell per surface voxel, in order; the split must keep them paired.
  Part root;
  root.tetra = true;
  const int xs[5] = {0, 1, 5, 6, 7};
  for (int i = 0; i < 5; ++i) {
    root.voxels.push_back(VoxelAt(xs[i], 0, 0, i != 1));
    if (i != 1) {
      SurfaceCell c;
      c.volume = 0.1f * static_cast<float>(i + 1);
      root.cells.push_back(c);
    }
  }
  const int dims[3] = {8, 1, 1};
  const std::vector<Part> parts = VoxelIslands(root, dims).Split(root);
  ASSERT_EQ(parts.size(), 2u);
  ASSERT_EQ(parts[0].cells.size(), 1u);
  EXPECT_FLOAT_EQ(parts[0].cells[0].volume, 0.1f);
  ASSERT_EQ(parts[1].cells.size(), 3u);
  EXPECT_FLOAT_EQ(parts[1].cells[0].volume, 0.3f);
  EXPECT_FLOAT_EQ(parts[1].cells[2].volume, 0.5f);
  EXPECT_TRUE(parts[1].tetra);
  EXPECT_NEAR(parts[1].cell_volume, 1.2, 1e-6);
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
