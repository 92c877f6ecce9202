#include "oriented_cuts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "shape_gen.h"
#include "test_grid_mesh.h"
#include "vhacd/vhacd.h"

namespace vhacd {
namespace internal {
namespace {

// An L of voxels in the xy plane (arms along x and y, 3 thick), 2 voxels deep in z.
Part VoxelL() {
  Part part;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 12; ++x)
        if (x < 3 || y < 3) part.voxels.push_back(vhacd_test::VoxelAt(x, y, z));
  part.ComputeBounds();
  return part;
}

CutDirection Diagonal(const Part& part) {
  CutDirection dir;
  dir.n = Vec3(1, -1, 0).normalized();
  dir.axis = 0;
  dir.lo = 1e30;
  dir.hi = -1e30;
  for (const Voxel& v : part.voxels) {
    const double p = dir.n.dot(Vec3(v.c[0] + 0.5, v.c[1] + 0.5, v.c[2] + 0.5));
    dir.lo = std::min(dir.lo, p);
    dir.hi = std::max(dir.hi, p);
  }
  return dir;
}

TEST(OrientedCutsTest, SplitPutsAVoxelOnTheSideOfItsCentre) {
  CutDirection dir;
  dir.n = Vec3(0.8, 0.36, -0.48);  // unit length, largest along x
  dir.axis = 0;
  for (double d : {-3.3, 0.0, 2.5, 7.77})
    for (int z = 0; z < 9; ++z)
      for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 9; ++x) {
          const uint16_t c[3] = {static_cast<uint16_t>(x), static_cast<uint16_t>(y),
                                 static_cast<uint16_t>(z)};
          const double s = dir.n.dot(Vec3(x + 0.5, y + 0.5, z + 0.5)) - d;
          if (std::fabs(s) < 1e-9) continue;  // on the plane: either side will do
          const bool below = s < 0;
          EXPECT_EQ(OrientedLeft(dir, d, c), below) << x << " " << y << " " << z << " " << d;
        }
}

TEST(OrientedCutsTest, DirectionsAreUnitOffTheGridAxesAndNotRepeated) {
  const Part part = VoxelL();
  const std::vector<CutDirection> dirs = OrientedCutDirections(part);
  ASSERT_FALSE(dirs.empty());
  bool diagonal = false;
  for (size_t i = 0; i < dirs.size(); ++i) {
    EXPECT_NEAR(dirs[i].n.norm(), 1.0, 1e-12);
    EXPECT_GT(dirs[i].n[dirs[i].axis], 0.0);
    EXPECT_LT(dirs[i].n.cwiseAbs().maxCoeff(), 0.99);
    EXPECT_LT(dirs[i].lo, dirs[i].hi);
    for (size_t j = 0; j < i; ++j) EXPECT_LT(std::fabs(dirs[i].n.dot(dirs[j].n)), 0.99);
    // The L is symmetric about x = y: its principal axes are the diagonals.
    diagonal =
        diagonal || std::fabs(std::fabs(dirs[i].n.dot(Vec3(1, -1, 0).normalized())) - 1) < 1e-9;
  }
  EXPECT_TRUE(diagonal);
}

TEST(OrientedCutsTest, CostIsTheConcavityOfTheTwoVoxelSets) {
  const Part part = VoxelL();
  const CutDirection dir = Diagonal(part);
  const AxisLines lines = BuildAxisLines(part, dir.axis);
  CutWeights w;
  w.volume0 = 200.0;
  const RevolutionHint no_hint;
  for (double d : {-4.0, -1.2, 0.0, 0.3, 5.0}) {
    // By hand: the hulls of the voxel cubes on each side.
    std::vector<Vec3> side[2];
    double count[2] = {0, 0};
    for (const Voxel& v : part.voxels) {
      const int s = OrientedLeft(dir, d, v.c) ? 0 : 1;
      ++count[s];
      for (int k = 0; k < 8; ++k)
        side[s].emplace_back(v.c[0] + (k & 1), v.c[1] + ((k >> 1) & 1), v.c[2] + ((k >> 2) & 1));
    }
    double expected = w.alpha * std::fabs(count[0] - count[1]) / w.volume0;
    for (int s = 0; s < 2; ++s)
      expected += std::max(0.0, ExactHullVolume(side[s]) - count[s]) / w.volume0;
    EXPECT_NEAR(OrientedCutCost(part, lines, dir, d, 1, w, no_hint, 0.0), expected, 1e-12) << d;
  }
}

TEST(OrientedCutsTest, ClipPolygonKeepsTheSideBelowEachPlane) {
  const std::vector<Vec3> square = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)};
  const CutPlane slanted{Vec3(0.6, 0.8, 0), 1.2};  // through (2, 0) and (0, 1.5)
  std::vector<Vec3> out;
  ClipPolygonToCuts(square, {slanted}, &out);
  ASSERT_EQ(out.size(), 3u);  // a vertex on the plane is kept once
  for (const Vec3& p : out) EXPECT_LE(slanted.n.dot(p), slanted.d + 1e-12);
  EXPECT_NEAR(out[2].y(), 1.5, 1e-12);
  // ... and x >= 1 too: a smaller triangle.
  out.clear();
  ClipPolygonToCuts(square, {slanted, CutPlane{-Vec3::UnitX(), -1}}, &out);
  ASSERT_EQ(out.size(), 3u);
  for (const Vec3& p : out) EXPECT_GE(p.x(), 1 - 1e-12);
  out.clear();
  ClipPolygonToCuts(square, {CutPlane{Vec3::UnitX(), -1}}, &out);
  EXPECT_TRUE(out.empty());
}

vhacd::MeshView ViewOf(const hullpack::shapes::NamedShape& shape) {
  const auto& m = shape.mesh;
  return vhacd::MeshView::FromDouble(m.points.data(), m.point_count(), m.indices.data(),
                                     m.triangle_count());
}

bool IsRotatedL(const hullpack::shapes::NamedShape& shape) {
  return shape.name == "rot_l_30_45" || shape.name == "rot_l_45_30";
}

// A rotated L: two convex arms whose joint no axis-aligned plane can follow. With two hulls, cuts
// along the part's own axes separate the arms; voxel slices leave a hull over the inner corner.
TEST(OrientedCutsTest, RotatedLInTwoHullsIsCloseWithOrientedCuts) {
  for (const auto& shape : hullpack::shapes::RotatedShapes()) {
    if (!IsRotatedL(shape)) continue;
    vhacd::Parameters p;
    p.num_threads = 2;
    p.hull_count = 2;
    p.oriented_cuts = vhacd::OrientedCuts::kOff;
    const vhacd::Result slices = vhacd::Decompose(ViewOf(shape), p);
    p.oriented_cuts = vhacd::OrientedCuts::kAlways;
    const vhacd::Result r = vhacd::Decompose(ViewOf(shape), p);
    ASSERT_EQ(r.hulls.size(), 2u) << shape.name;
    EXPECT_LT(r.report.concavity, 0.015) << shape.name;
    EXPECT_LT(r.report.concavity, 0.5 * slices.report.concavity) << shape.name;
    // Independent of the thread count.
    p.num_threads = 1;
    const vhacd::Result one = vhacd::Decompose(ViewOf(shape), p);
    ASSERT_EQ(one.hulls.size(), r.hulls.size());
    for (size_t h = 0; h < r.hulls.size(); ++h) EXPECT_EQ(one.hulls[h].points, r.hulls[h].points);
  }
}

// Without any flag (OrientedCuts::kAuto) --hulls tries both ways and keeps the closer: the rotated
// L comes out as close as with oriented cuts forced on, and identically for any thread count.
TEST(OrientedCutsTest, RotatedLInTwoHullsIsCloseByDefault) {
  for (const auto& shape : hullpack::shapes::RotatedShapes()) {
    if (!IsRotatedL(shape)) continue;
    vhacd::Parameters p;
    p.num_threads = 2;
    p.hull_count = 2;
    const vhacd::Result automatic = vhacd::Decompose(ViewOf(shape), p);
    p.oriented_cuts = vhacd::OrientedCuts::kOff;
    const vhacd::Result slices = vhacd::Decompose(ViewOf(shape), p);
    ASSERT_EQ(automatic.hulls.size(), 2u) << shape.name;
    EXPECT_LT(automatic.report.concavity, 0.015) << shape.name;
    EXPECT_LT(automatic.report.concavity, 0.5 * slices.report.concavity) << shape.name;
    p.oriented_cuts = vhacd::OrientedCuts::kAuto;
    for (uint32_t threads : {1u, 3u}) {
      p.num_threads = threads;
      const vhacd::Result other = vhacd::Decompose(ViewOf(shape), p);
      ASSERT_EQ(other.hulls.size(), automatic.hulls.size()) << threads;
      for (size_t h = 0; h < other.hulls.size(); ++h)
        EXPECT_EQ(other.hulls[h].points, automatic.hulls[h].points) << threads;
    }
  }
}

// The automatic choice is never farther than voxel slices alone, and under max_concavity, when the
// slices reach D, it reaches D too with no more hulls.
TEST(OrientedCutsTest, AutomaticChoiceIsNeverWorseThanSlices) {
  for (const auto& shape : hullpack::shapes::RotatedShapes()) {
    for (const bool count : {true, false}) {
      vhacd::Parameters p;
      p.num_threads = 2;
      // The choice keeps the closer of the two runs at any grid; a coarse one keeps the sanitized
      // build's run short.
      p.resolution = 30000;
      if (count)
        p.hull_count = 4;
      else
        p.max_concavity = 0.02;
      const vhacd::Result automatic = vhacd::Decompose(ViewOf(shape), p);
      p.oriented_cuts = vhacd::OrientedCuts::kOff;
      const vhacd::Result slices = vhacd::Decompose(ViewOf(shape), p);
      const std::string what = shape.name + (count ? " --hulls 4" : " --max-concavity 0.02");
      ASSERT_EQ(automatic.status, vhacd::Status::kOk) << what;
      if (!count && slices.report.target_reached) {
        EXPECT_TRUE(automatic.report.target_reached) << what;
        EXPECT_LE(automatic.hulls.size(), slices.hulls.size()) << what;
      }
      EXPECT_LE(automatic.report.concavity, slices.report.concavity) << what;
    }
  }
}

}  // namespace
}  // namespace internal
}  // namespace vhacd
