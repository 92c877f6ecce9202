#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <thread>

#include "test_meshes.h"
#include "vhacd/vhacd.h"

namespace {

using vhacd_test::Mesh;

vhacd::Parameters Fast(vhacd::Mode mode = vhacd::Mode::kVoxel) {
  vhacd::Parameters p;
  p.resolution = 30000;
  p.num_threads = 2;
  p.mode = mode;
  return p;
}

// The tests both modes must pass: voxels (0) and tetrahedra (1).
class ModeTest : public ::testing::TestWithParam<vhacd::Mode> {
 protected:
  vhacd::Parameters Fast() const { return ::Fast(GetParam()); }
};

TEST_P(ModeTest, CubeGivesOneHullEqualToTheCube) {
  const Mesh cube = vhacd_test::Box(-1, -2, -3, 1, 2, 3);
  const vhacd::Result r = vhacd::Decompose(cube.View(), Fast());
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.hulls.size(), 1u);
  const vhacd::ConvexHull& h = r.hulls[0];
  EXPECT_EQ(h.vertex_count(), 8u);
  EXPECT_NEAR(h.volume, 2 * 4 * 6, 1e-9);
  for (size_t i = 0; i < h.vertex_count(); ++i) {
    EXPECT_NEAR(std::fabs(h.points[3 * i]), 1, 1e-10);
    EXPECT_NEAR(std::fabs(h.points[3 * i + 1]), 2, 1e-10);
    EXPECT_NEAR(std::fabs(h.points[3 * i + 2]), 3, 1e-10);
  }
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-9), "");
  EXPECT_TRUE(r.report.closed_input);
  EXPECT_GT(r.report.volume_iou, 0.97);
  EXPECT_LT(r.report.concavity, 0.01);
}

TEST_P(ModeTest, SeparateComponentsAndTwoSidedFaces) {
  // Two cubes far apart, every face also present with the opposite winding.
  Mesh m = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  m.Append(vhacd_test::Box(3, 0.5, 0, 4, 1.5, 1));
  const size_t n = m.triangle_count();
  for (size_t t = 0; t < n; ++t)
    m.AddTriangle(m.indices[3 * t], m.indices[3 * t + 2], m.indices[3 * t + 1]);
  const vhacd::Result r = vhacd::Decompose(m.View(), Fast());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(r.report.closed_input);  // duplicates are dropped before the topology check
  ASSERT_EQ(r.hulls.size(), 2u);
  for (const auto& h : r.hulls) {
    EXPECT_EQ(h.vertex_count(), 8u);
    EXPECT_NEAR(h.volume, 1.0, 1e-9);
  }
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-9), "");
}

double LBlockIoU(const std::vector<vhacd::ConvexHull>& hulls, double scale) {
  int inter = 0, uni = 0;
  const int n = 60;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n / 2; ++k) {
        const double x = 2.0 * (i + 0.5) / n, y = 2.0 * (j + 0.5) / n,
                     z = 1.0 * (k + 0.5) / (n / 2);
        const bool s = vhacd_test::InsideLBlock(x, y, z);
        const bool h =
            vhacd_test::InsideAnyHull(hulls, x * scale, y * scale, z * scale, 1e-9 * scale);
        inter += s && h;
        uni += s || h;
      }
  return static_cast<double>(inter) / uni;
}

TEST_P(ModeTest, SeparateObjectsKeepTheirOwnHullsUnderADistanceTarget) {
  // Six unit boxes in a row, a unit apart: a hull over two neighbours sticks out by half the gap,
  // within 0.08 of the row's diagonal, yet it would fill the space between them.
  Mesh row;
  for (int i = 0; i < 6; ++i) row.Append(vhacd_test::Box(2 * i, 0, 0, 2 * i + 1, 1, 1));
  vhacd::Parameters p = Fast();
  p.max_concavity = 0.08;
  const vhacd::Result r = vhacd::Decompose(row.View(), p);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.hulls.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    EXPECT_TRUE(vhacd_test::InsideAnyHull(r.hulls, 2 * i + 0.5, 0.5, 0.5, 1e-9)) << i;
    if (i < 5) EXPECT_FALSE(vhacd_test::InsideAnyHull(r.hulls, 2 * i + 1.5, 0.5, 0.5, 1e-9)) << i;
  }
  EXPECT_GT(r.report.volume_iou, 0.9);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-9), "");
  p.num_threads = 1;
  const vhacd::Result one_thread = vhacd::Decompose(row.View(), p);
  ASSERT_EQ(one_thread.hulls.size(), r.hulls.size());
  for (size_t h = 0; h < r.hulls.size(); ++h)
    EXPECT_EQ(one_thread.hulls[h].points, r.hulls[h].points);
  // A hull budget still merges across the gaps.
  p.max_convex_hulls = 3;
  const vhacd::Result budget = vhacd::Decompose(row.View(), p);
  ASSERT_TRUE(budget.ok()) << budget.message;
  EXPECT_EQ(budget.hulls.size(), 3u);
}

TEST_P(ModeTest, LBlockGivesTwoHullsWithHighIoU) {
  const Mesh l = vhacd_test::LBlock();
  const vhacd::Result r = vhacd::Decompose(l.View(), Fast());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.hulls.size(), 2u);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-9), "");
  EXPECT_GT(LBlockIoU(r.hulls, 1.0), 0.98);
  EXPECT_GT(r.report.volume_iou, 0.95);
}

TEST_P(ModeTest, TorusCentreIsOutsideEveryHull) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3);
  const vhacd::Result r = vhacd::Decompose(torus.View(), Fast());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_GE(r.hulls.size(), 4u);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-6 * 2.7), "");
  EXPECT_FALSE(vhacd_test::InsideAnyHull(r.hulls, 0, 0, 0, 0.0));
  // The hole stays mostly open: points within radius 0.5 of the axis are outside the hulls.
  int inside = 0, total = 0;
  for (int i = -10; i <= 10; ++i)
    for (int j = -10; j <= 10; ++j) {
      const double x = 0.05 * i, y = 0.05 * j;
      if (x * x + y * y > 0.25) continue;
      ++total;
      inside += vhacd_test::InsideAnyHull(r.hulls, x, y, 0, 0.0);
    }
  EXPECT_LT(inside, total / 10);
}

TEST_P(ModeTest, ThickBowlCavityStaysMostlyEmpty) {
  const Mesh bowl = vhacd_test::ThickBowl(1.0, 1.0, 0.1);
  const vhacd::Result r = vhacd::Decompose(bowl.View(), Fast());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(r.report.closed_input);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-6 * 2.5), "");
  int inside = 0, total = 0;
  for (int i = -8; i <= 8; ++i)
    for (int j = -8; j <= 8; ++j)
      for (int k = 1; k <= 8; ++k) {
        const double x = 0.1 * i, y = 0.1 * j, z = 0.1 + 0.1 * k;
        if (x * x + y * y > 0.75 * 0.75 || z > 0.95) continue;
        ++total;
        inside += vhacd_test::InsideAnyHull(r.hulls, x, y, z, 0.0);
      }
  EXPECT_LT(inside, total / 5) << inside << " of " << total;
  // And the wall is covered.
  EXPECT_TRUE(vhacd_test::InsideAnyHull(r.hulls, 0.95, 0, 0.5, 1e-3));
  EXPECT_TRUE(vhacd_test::InsideAnyHull(r.hulls, 0, 0, 0.05, 1e-3));
}

TEST_P(ModeTest, SphereWithHolesIsNotHollowedOut) {
  const Mesh sphere = vhacd_test::Sphere(1.0, 48, 24, /*holes=*/true);
  const vhacd::Result r = vhacd::Decompose(sphere.View(), Fast());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_FALSE(r.report.closed_input);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-6 * 3.5), "");
  int inside = 0, total = 0;
  for (int i = -9; i <= 9; ++i)
    for (int j = -9; j <= 9; ++j)
      for (int k = -9; k <= 9; ++k) {
        const double x = 0.1 * i, y = 0.1 * j, z = 0.1 * k;
        if (x * x + y * y + z * z > 0.9 * 0.9 || z < -0.85) continue;  // below the opening
        ++total;
        inside += vhacd_test::InsideAnyHull(r.hulls, x, y, z, 1e-9);
      }
  EXPECT_GE(inside, total * 9 / 10) << inside << " of " << total;
}

TEST_P(ModeTest, SmallHoleInTheBaseIsFilled) {
  // A hole in its base (the bunny's case; 0.12 of the diagonal, below min_opening): the hulls must
  // fill the inside, not only line the wall. (A base open over its whole width is an upside-down
  // pot and stays empty: decompose_target_test.cc.)
  const Mesh cyl = vhacd_test::OpenBottomCylinder(1.0, 1.5, 48, 8, 0.2);
  const vhacd::Result r = vhacd::Decompose(cyl.View(), Fast());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_FALSE(r.report.closed_input);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-6 * 3), "");
  int inside = 0, total = 0;
  for (int i = -10; i <= 10; ++i)
    for (int j = -10; j <= 10; ++j)
      for (int k = 0; k < 15; ++k) {
        const double x = 0.095 * i, y = 0.095 * j, z = 0.05 + 0.1 * k;
        if (x * x + y * y > 0.95 * 0.95) continue;
        ++total;
        inside += vhacd_test::InsideAnyHull(r.hulls, x, y, z, 1e-9);
      }
  EXPECT_GE(inside, total * 9 / 10) << inside << " of " << total;
  EXPECT_GE(r.report.solid_coverage, 0.9);
}

TEST_P(ModeTest, OpenAndNonManifoldMeshesGiveValidHulls) {
  // An open box (no top), a second box sharing an edge with it, a dangling triangle, a
  // duplicated face with the opposite orientation and a degenerate triangle.
  Mesh m = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  m.indices.resize(m.indices.size() - 0);
  m.indices.erase(m.indices.begin() + 6, m.indices.begin() + 12);  // drop the top face
  m.Append(vhacd_test::Box(1, 1, 0, 2, 2, 1));
  const uint32_t a = m.AddPoint(0, 0, 1), b = m.AddPoint(-1, 0, 2), c = m.AddPoint(0, -1, 2);
  m.AddTriangle(a, b, c);
  m.AddTriangle(a, c, b);
  m.AddTriangle(a, a, b);
  const vhacd::Result r = vhacd::Decompose(m.View(), Fast());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_FALSE(r.report.closed_input);
  EXPECT_GE(r.hulls.size(), 2u);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-6 * 4), "");
  // A flat single square also works (a one-voxel-thick slab).
  Mesh sq;
  sq.AddQuad(sq.AddPoint(0, 0, 0), sq.AddPoint(1, 0, 0), sq.AddPoint(1, 1, 0),
             sq.AddPoint(0, 1, 0));
  const vhacd::Result r2 = vhacd::Decompose(sq.View(), Fast());
  ASSERT_TRUE(r2.ok()) << r2.message;
  EXPECT_EQ(r2.hulls.size(), 1u);
  EXPECT_EQ(vhacd_test::CheckHulls(r2.hulls, 1e-6), "");
}

TEST_P(ModeTest, RandomTriangleSoupsGiveValidHulls) {
  uint32_t seed = 12345;
  auto next = [&]() {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / 16777216.0;
  };
  for (int trial = 0; trial < 4; ++trial) {
    Mesh m;
    for (int t = 0; t < 60; ++t) {
      const double cx = next(), cy = next(), cz = next() * (trial == 3 ? 1e-3 : 1.0);
      const uint32_t a = m.AddPoint(cx, cy, cz);
      const uint32_t b = m.AddPoint(cx + 0.2 * next(), cy + 0.2 * next(), cz + 0.2 * next());
      const uint32_t c = m.AddPoint(cx + 0.2 * next(), cy + 0.2 * next(), cz + 0.2 * next());
      m.AddTriangle(a, b, c);
      if (t % 7 == 0) m.AddTriangle(a, c, b);  // two-sided
    }
    vhacd::Parameters p = Fast();
    p.resolution = 10000;
    const vhacd::Result r = vhacd::Decompose(m.View(), p);
    ASSERT_TRUE(r.ok()) << trial << " " << r.message;
    EXPECT_GE(r.hulls.size(), 1u);
    EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-6 * 2), "") << trial;
    EXPECT_TRUE(std::isfinite(r.report.concavity));
  }
}

bool SameHulls(const std::vector<vhacd::ConvexHull>& a, const std::vector<vhacd::ConvexHull>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].points != b[i].points || a[i].triangles != b[i].triangles) return false;
  return true;
}

TEST_P(ModeTest, IdenticalOutputForAnyThreadCountAndRun) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.35, 40, 20);
  vhacd::Parameters p = Fast();
  p.num_threads = 1;
  const vhacd::Result r1 = vhacd::Decompose(torus.View(), p);
  p.num_threads = 2;
  const vhacd::Result r2 = vhacd::Decompose(torus.View(), p);
  p.num_threads = 5;
  const vhacd::Result r3 = vhacd::Decompose(torus.View(), p);
  ASSERT_TRUE(r1.ok() && r2.ok() && r3.ok());
  EXPECT_TRUE(SameHulls(r1.hulls, r2.hulls));
  EXPECT_TRUE(SameHulls(r1.hulls, r3.hulls));
  EXPECT_EQ(r1.report.concavity, r2.report.concavity);
}

// A clean input in a local order keeps it inside (its triangles are not copied); a scrambled one,
// or one with an unused point, is renumbered in the lexicographic order of positions: no order
// shows in the hulls.
TEST_P(ModeTest, TheOrderOfThePointsDoesNotChangeTheHulls) {
  // Over 20001 points, so that the report samples every second vertex or fewer.
  const Mesh torus = vhacd_test::Torus(1.0, 0.35, 200, 101);
  ASSERT_GT(torus.point_count(), 20001u);
  auto renumbered = [&](const std::vector<uint32_t>& to) {
    Mesh m = torus;
    for (uint32_t i = 0; i < to.size(); ++i)
      for (int k = 0; k < 3; ++k) m.points[3 * to[i] + k] = torus.points[3 * i + k];
    for (uint32_t& v : m.indices) v = to[v];
    return m;
  };
  std::vector<uint32_t> to(torus.point_count());
  for (uint32_t i = 0; i < to.size(); ++i) to[i] = static_cast<uint32_t>(to.size() - 1 - i);
  const Mesh reversed = renumbered(to);  // still local: kept
  std::shuffle(to.begin(), to.end(), std::mt19937(7));
  const Mesh shuffled = renumbered(to);
  const Mesh unused = [&] {
    Mesh m = torus;
    m.AddPoint(5, 5, 5);
    return m;
  }();
  const vhacd::Parameters p = Fast();
  const vhacd::Result a = vhacd::Decompose(torus.View(), p);
  ASSERT_TRUE(a.ok());
  // points_in_place reads the kept orders' points from the view, mapped on every read: the same
  // hulls too, bit for bit (the shuffled and the unused point are copied either way).
  const vhacd::Parameters in_place = [&] {
    vhacd::Parameters q = p;
    q.points_in_place = true;
    return q;
  }();
  const std::vector<std::pair<const Mesh*, const vhacd::Parameters*>> runs = {
      {&reversed, &p}, {&shuffled, &p}, {&unused, &p}, {&torus, &in_place}, {&reversed, &in_place}};
  for (const auto& [m, q] : runs) {
    const vhacd::Result r = vhacd::Decompose(m->View(), *q);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(SameHulls(a.hulls, r.hulls));
    EXPECT_EQ(a.report.concavity, r.report.concavity);
    EXPECT_EQ(a.report.hausdorff_mesh_to_hulls, r.report.hausdorff_mesh_to_hulls);
    EXPECT_EQ(a.report.hausdorff_hulls_to_mesh, r.report.hausdorff_hulls_to_mesh);
  }
}

class CancelAfter : public vhacd::Observer {
 public:
  std::atomic<bool> flag{false};
  bool IsCancelled() override { return flag.load(); }
};

TEST_P(ModeTest, CancelFromAnotherThreadReturnsPromptly) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 96, 48);
  vhacd::Parameters p;
  p.mode = GetParam();
  p.resolution = 3000000;
  p.concavity = 0.0001;
  p.num_threads = 2;
  CancelAfter obs;
  std::chrono::steady_clock::time_point cancelled_at;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    cancelled_at = std::chrono::steady_clock::now();
    obs.flag.store(true);
  });
  const vhacd::Result r = vhacd::Decompose(torus.View(), p, &obs);
  const auto returned_at = std::chrono::steady_clock::now();
  canceller.join();
  EXPECT_EQ(r.status, vhacd::Status::kCancelled);
  EXPECT_TRUE(r.hulls.empty());
  // Loose on purpose (a loaded 2-core machine or a sanitized build takes ~1 s): what it guards is a
  // stage that forgets to poll, which shows as the rest of a run at 3M voxels (minutes).
  EXPECT_LT(std::chrono::duration<double>(returned_at - cancelled_at).count(), 5.0);
}

TEST_P(ModeTest, InvalidInputsGiveErrors) {
  const Mesh cube = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  vhacd::MeshView empty;
  EXPECT_EQ(vhacd::Decompose(empty, Fast()).status, vhacd::Status::kEmptyMesh);
  vhacd::MeshView no_tris = cube.View();
  no_tris.triangle_count = 0;
  EXPECT_EQ(vhacd::Decompose(no_tris, Fast()).status, vhacd::Status::kEmptyMesh);

  Mesh nan = cube;
  nan.points[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(vhacd::Decompose(nan.View(), Fast()).status, vhacd::Status::kInvalidMesh);
  Mesh inf = cube;
  inf.points[0] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(vhacd::Decompose(inf.View(), Fast()).status, vhacd::Status::kInvalidMesh);

  Mesh bad_index = cube;
  bad_index.indices[5] = 8;
  const vhacd::Result r = vhacd::Decompose(bad_index.View(), Fast());
  EXPECT_EQ(r.status, vhacd::Status::kIndexOutOfRange);
  EXPECT_FALSE(r.message.empty());

  vhacd::MeshView null_points = cube.View();
  null_points.points_d = nullptr;
  EXPECT_EQ(vhacd::Decompose(null_points, Fast()).status, vhacd::Status::kInvalidMesh);
  vhacd::MeshView bad_stride = cube.View();
  bad_stride.point_stride = 2;
  EXPECT_EQ(vhacd::Decompose(bad_stride, Fast()).status, vhacd::Status::kInvalidMesh);

  Mesh point;  // every vertex at the same place
  point.AddTriangle(point.AddPoint(1, 1, 1), point.AddPoint(1, 1, 1), point.AddPoint(1, 1, 1));
  EXPECT_EQ(vhacd::Decompose(point.View(), Fast()).status, vhacd::Status::kEmptyMesh);
  Mesh line;
  line.AddTriangle(line.AddPoint(0, 0, 0), line.AddPoint(1, 0, 0), line.AddPoint(2, 0, 0));
  const vhacd::Result rl = vhacd::Decompose(line.View(), Fast());
  EXPECT_TRUE(rl.ok() || rl.status == vhacd::Status::kInvalidMesh) << vhacd::StatusName(rl.status);
  EXPECT_EQ(vhacd_test::CheckHulls(rl.hulls, 1e-6), "");
}

TEST(DecomposeTest, OutOfRangeParametersAreRejected) {
  const Mesh cube = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  auto status = [&](auto change) {
    vhacd::Parameters p = Fast();
    change(p);
    return vhacd::Decompose(cube.View(), p).status;
  };
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.resolution = 100; }),
            vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.resolution = 64000001; }),
            vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.depth = 0; }), vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.depth = 33; }), vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.concavity = -0.1; }),
            vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.concavity = NAN; }),
            vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.plane_downsampling = 17; }),
            vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.convexhull_downsampling = 0; }),
            vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.alpha = 2; }), vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.gamma = 1.5; }), vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.max_vertices_per_hull = 3; }),
            vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.min_volume_per_hull = 0.5; }),
            vhacd::Status::kInvalidParameter);
  EXPECT_EQ(status([](vhacd::Parameters& p) { p.mode = static_cast<vhacd::Mode>(7); }),
            vhacd::Status::kInvalidParameter);
  std::string why;
  EXPECT_EQ(vhacd::ValidateParameters(vhacd::Parameters(), &why), vhacd::Status::kOk);
  EXPECT_EQ(vhacd::ValidateParameters(vhacd::Parameters::High(), &why), vhacd::Status::kOk);
}

TEST_P(ModeTest, ScaledMeshGivesScaledHulls) {
  const Mesh l = vhacd_test::LBlock();
  const vhacd::Result r = vhacd::Decompose(l.View(), Fast());
  ASSERT_TRUE(r.ok());
  for (double s : {1e-6, 1e6}) {
    const Mesh ls = l.Scaled(s);
    const vhacd::Result rs = vhacd::Decompose(ls.View(), Fast());
    ASSERT_TRUE(rs.ok()) << s;
    ASSERT_EQ(rs.hulls.size(), r.hulls.size()) << s;
    for (size_t h = 0; h < r.hulls.size(); ++h) {
      ASSERT_EQ(rs.hulls[h].points.size(), r.hulls[h].points.size());
      EXPECT_EQ(rs.hulls[h].triangles, r.hulls[h].triangles);
      for (size_t i = 0; i < r.hulls[h].points.size(); ++i)
        EXPECT_NEAR(rs.hulls[h].points[i] / s, r.hulls[h].points[i], 1e-9);
      EXPECT_NEAR(rs.hulls[h].volume / (s * s * s), r.hulls[h].volume, 1e-9);
    }
    EXPECT_NEAR(rs.report.concavity, r.report.concavity, 1e-9);
  }
}

TEST_P(ModeTest, ExtremeScalesStayFinite) {
  const Mesh l = vhacd_test::LBlock();
  for (double s : {1e-150, 1e200}) {
    const Mesh ls = l.Scaled(s);
    const vhacd::Result r = vhacd::Decompose(ls.View(), Fast());
    ASSERT_TRUE(r.ok()) << s << " " << r.message;
    EXPECT_EQ(r.hulls.size(), 2u);
    for (const auto& h : r.hulls) {
      EXPECT_TRUE(std::isfinite(h.volume));
      for (double v : h.points) EXPECT_TRUE(std::isfinite(v));
    }
    EXPECT_TRUE(std::isfinite(r.report.concavity));
  }
}

class Recorder : public vhacd::Observer {
 public:
  std::vector<double> overall;
  int logs = 0;
  void OnProgress(double o, double s, double op, const char* stage,
                  const char* operation) override {
    EXPECT_GE(o, 0.0);
    EXPECT_LE(o, 100.0);
    EXPECT_TRUE(stage != nullptr && operation != nullptr);
    overall.push_back(o);
  }
  void OnLog(const char* message) override {
    EXPECT_NE(message, nullptr);
    ++logs;
  }
};

TEST(DecomposeTest, ProgressAndLogAreReported) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 24, 12);
  Recorder rec;
  const vhacd::Result r = vhacd::Decompose(torus.View(), Fast(), &rec);
  ASSERT_TRUE(r.ok());
  ASSERT_GT(rec.overall.size(), 5u);
  EXPECT_TRUE(std::is_sorted(rec.overall.begin(), rec.overall.end()));
  EXPECT_DOUBLE_EQ(rec.overall.back(), 100.0);
  EXPECT_GT(rec.logs, 0);
  // Stage times and the report are filled.
  EXPECT_GT(r.report.seconds_total, 0.0);
  EXPECT_EQ(r.report.hulls.size(), r.hulls.size());
  EXPECT_GE(r.report.hausdorff_mesh_to_hulls, 0.0);
  EXPECT_GE(r.report.hausdorff_hulls_to_mesh, 0.0);
}

TEST_P(ModeTest, HullBudgetAndVertexLimitAreHonoured) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3);
  vhacd::Parameters p = Fast();
  p.max_convex_hulls = 3;
  p.max_vertices_per_hull = 8;
  const vhacd::Result r = vhacd::Decompose(torus.View(), p);
  ASSERT_TRUE(r.ok());
  EXPECT_LE(r.hulls.size(), 3u);
  for (const auto& h : r.hulls) EXPECT_LE(h.vertex_count(), 8u);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-6 * 2.7), "");
}

// A flat box (2 x 2 x 0.34) with six one-sided squares floating 0.3 above it, the shape of the
// corpus' vertex_color_test. Each square is a one-voxel sheet over a gap: the hull of box + sheets
// sticks out by more than max_distance, and the downsampled plane search did not see the sheets
// from two of the three axes (they lie between its sampled voxel rows), so it cut the box into
// single voxel columns, thousands of parts, before trying the plane through the gap.
Mesh BoxWithFloatingSheets() {
  Mesh m = vhacd_test::Box(-1, -1, -0.17, 1, 1, 0.17);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      const double x = -0.78 + 0.59 * i, y = -0.76 + 0.87 * j, s = 0.46, z = 0.487;
      m.AddQuad(m.AddPoint(x, y, z), m.AddPoint(x + s, y, z), m.AddPoint(x + s, y + s, z),
                m.AddPoint(x, y + s, z));
    }
  return m;
}

TEST_P(ModeTest, FlatOpenMeshWithStickOutLimitKeepsFewParts) {
  const Mesh mesh = BoxWithFloatingSheets();
  vhacd::Parameters p = Fast();
  p.resolution = 100000;  // the packaging pipeline's parameters (collision.cc)
  p.gamma = 0.02;
  p.max_vertices_per_hull = 24;
  p.max_distance = 0.03;
  const vhacd::Result r = vhacd::Decompose(mesh.View(), p);
  ASSERT_TRUE(r.ok()) << r.message;
  // Slab and sheets apart take a handful of cuts (3 parts here); the columns were over 2000.
  EXPECT_LE(r.report.parts_before_merge, 32u);
  EXPECT_LE(r.hulls.size(), 16u);
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-6 * 3.0), "");
  EXPECT_LE(r.report.hausdorff_hulls_to_mesh, 0.03 + 0.02);
  // Same result with one thread.
  p.num_threads = 1;
  const vhacd::Result one = vhacd::Decompose(mesh.View(), p);
  ASSERT_TRUE(one.ok());
  ASSERT_EQ(one.hulls.size(), r.hulls.size());
  for (size_t i = 0; i < r.hulls.size(); ++i) EXPECT_EQ(one.hulls[i].points, r.hulls[i].points);
}

TEST(DecomposeTest, PresetsAndPureVolumeCriterion) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 32, 16);
  vhacd::Parameters p = Fast();
  const vhacd::Result def = vhacd::Decompose(torus.View(), p);
  p.max_distance = 0.0;  // V-HACD 2.0 behaviour: volume concavity only
  const vhacd::Result pure = vhacd::Decompose(torus.View(), p);
  vhacd::Parameters high = vhacd::Parameters::High();
  high.resolution = 100000;
  high.num_threads = 2;
  const vhacd::Result hi = vhacd::Decompose(torus.View(), high);
  ASSERT_TRUE(def.ok() && pure.ok() && hi.ok());
  for (const vhacd::Result* r : {&def, &pure, &hi}) {
    EXPECT_EQ(vhacd_test::CheckHulls(r->hulls, 1e-6 * 2.7), "");
    EXPECT_FALSE(vhacd_test::InsideAnyHull(r->hulls, 0, 0, 0, 0.0));
  }
  // The distance criterion bounds how far hulls stick out; the finer preset does better.
  EXPECT_LE(def.report.hausdorff_hulls_to_mesh, 0.03 + 0.02);
  EXPECT_LE(hi.report.concavity, def.report.concavity + 1e-9);
}

TEST(DecomposeTest, FloatInputAndStridesAndPca) {
  const Mesh l = vhacd_test::LBlock();
  std::vector<float> pf;
  for (size_t i = 0; i < l.point_count(); ++i) {
    for (int k = 0; k < 3; ++k) pf.push_back(static_cast<float>(l.points[3 * i + k]));
    pf.push_back(99.f);  // padding: stride 4
  }
  std::vector<uint32_t> idx;
  for (size_t t = 0; t < l.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) idx.push_back(l.indices[3 * t + k]);
    idx.push_back(12345);  // padding: stride 4
  }
  vhacd::MeshView v =
      vhacd::MeshView::FromFloat(pf.data(), l.point_count(), idx.data(), l.triangle_count());
  v.point_stride = 4;
  v.triangle_stride = 4;
  vhacd::Parameters p = Fast();
  const vhacd::Result r = vhacd::Decompose(v, p);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.hulls.size(), 2u);
  EXPECT_GT(LBlockIoU(r.hulls, 1.0), 0.98);
  // With PCA the symmetric L is cut along its diagonal axes: more hulls, still a tight fit.
  p.pca = true;
  const vhacd::Result rp = vhacd::Decompose(v, p);
  ASSERT_TRUE(rp.ok()) << rp.message;
  EXPECT_EQ(vhacd_test::CheckHulls(rp.hulls, 1e-6 * 3), "");
  EXPECT_GT(LBlockIoU(rp.hulls, 1.0), 0.9);
}

INSTANTIATE_TEST_SUITE_P(Modes, ModeTest,
                         ::testing::Values(vhacd::Mode::kVoxel, vhacd::Mode::kTetrahedron),
                         [](const ::testing::TestParamInfo<vhacd::Mode>& param) {
                           return param.param == vhacd::Mode::kVoxel ? std::string("Voxel")
                                                                     : std::string("Tetrahedron");
                         });

}  // namespace
