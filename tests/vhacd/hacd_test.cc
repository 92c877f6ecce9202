// Tests of vhacd::DecomposeHacd (include/vhacd/hacd.h), on meshes generated in code.
#include "vhacd/hacd.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "common/test_shapes.h"
#include "test_meshes.h"

namespace {

using vhacd_test::Mesh;

vhacd::HacdParameters Recommended() {
  vhacd::HacdParameters p = vhacd::HacdParameters::Recommended();
  p.compute_report = false;
  p.num_threads = 1;
  return p;
}

// The upper half of a UV sphere (the shared test sphere without its southern rows), one open sheet.
Mesh Hemisphere(double radius, int slices, int stacks) {
  return vhacd_test::FromShape(test_shapes::Sphere(
      radius, slices, stacks, [stacks](int row, int) { return row <= stacks / 2; }));
}

Mesh Dumbbell() {
  Mesh m = vhacd_test::Box(0, 0, 0, 2, 2, 2);
  m.Append(vhacd_test::Box(4, 0, 0, 6, 2, 2));
  m.Append(vhacd_test::Box(2, 0.9, 0.9, 4, 1.1, 1.1));
  return m;
}

// `size`: the mesh's size (the convexity tolerance is relative to it).
void ExpectValid(const vhacd::Result& r, double size = 1.0) {
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(vhacd_test::CheckHulls(r.hulls, 1e-9 * size), "");
  for (const auto& h : r.hulls) {
    EXPECT_GT(h.volume, 0.0);
    for (double v : h.points) EXPECT_TRUE(std::isfinite(v));
  }
}

TEST(HacdTest, CubeGivesOneHull) {
  const Mesh cube = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  vhacd::HacdParameters p;
  p.num_threads = 1;
  const vhacd::Result r = vhacd::DecomposeHacd(cube.View(), p);
  ExpectValid(r);
  ASSERT_EQ(r.hulls.size(), 1u);
  EXPECT_NEAR(r.hulls[0].volume, 1.0, 1e-9);
  EXPECT_GE(r.report.concavity, 0.0);  // the report is filled
  EXPECT_LT(r.report.concavity, 0.02);
}

TEST(HacdTest, TwoBoxesJoinedByABarGiveThreeHulls) {
  const vhacd::Result r = vhacd::DecomposeHacd(Dumbbell().View(), Recommended());
  ExpectValid(r);
  EXPECT_EQ(r.hulls.size(), 3u);
  // Nothing spans the gap around the bar.
  EXPECT_FALSE(vhacd_test::InsideAnyHull(r.hulls, 3.0, 1.6, 1.0, 1e-9));
  EXPECT_FALSE(vhacd_test::InsideAnyHull(r.hulls, 3.0, 1.0, 0.4, 1e-9));
}

TEST(HacdTest, BowlKeepsItsCavityEmpty) {
  const Mesh bowl = vhacd_test::ThickBowl(1.0, 1.0, 0.1);
  const vhacd::Result r = vhacd::DecomposeHacd(bowl.View(), Recommended());
  ExpectValid(r);
  EXPECT_GT(r.hulls.size(), 1u);
  for (double z : {0.4, 0.6, 0.9})
    EXPECT_FALSE(vhacd_test::InsideAnyHull(r.hulls, 0.0, 0.0, z, 1e-9)) << "z " << z;
}

TEST(HacdTest, OpenHemisphereIsOneHull) {
  vhacd::HacdParameters p = Recommended();
  p.min_clusters = 1;
  const vhacd::Result r = vhacd::DecomposeHacd(Hemisphere(1.0, 32, 16).View(), p);
  ExpectValid(r);
  EXPECT_EQ(r.hulls.size(), 1u);
}

TEST(HacdTest, TorusGivesSeveralHulls) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3);
  const vhacd::Result r = vhacd::DecomposeHacd(torus.View(), Recommended());
  ExpectValid(r);
  EXPECT_GE(r.hulls.size(), 4u);
  EXPECT_FALSE(vhacd_test::InsideAnyHull(r.hulls, 0.0, 0.0, 0.0, 1e-9));  // the hole stays open
}

TEST(HacdTest, ScaledMeshGivesScaledHulls) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 32, 16);
  const vhacd::Result r1 = vhacd::DecomposeHacd(torus.View(), Recommended());
  ASSERT_TRUE(r1.ok());
  for (double s : {1e-6, 1e6}) {
    const vhacd::Result rs = vhacd::DecomposeHacd(torus.Scaled(s).View(), Recommended());
    ExpectValid(rs, s);
    ASSERT_EQ(rs.hulls.size(), r1.hulls.size()) << "scale " << s;
    for (size_t h = 0; h < r1.hulls.size(); ++h) {
      ASSERT_EQ(rs.hulls[h].points.size(), r1.hulls[h].points.size());
      EXPECT_NEAR(rs.hulls[h].volume / (s * s * s), r1.hulls[h].volume, 1e-9 * r1.hulls[h].volume);
      for (size_t i = 0; i < r1.hulls[h].points.size(); ++i)
        EXPECT_NEAR(rs.hulls[h].points[i] / s, r1.hulls[h].points[i], 1e-9);
    }
  }
}

TEST(HacdTest, SameOutputForAnyThreadCount) {
  // 38400 triangles, decimated to 2000 first: the simplifier's set-up and its first phase (slabs
  // decimated side by side) run on the threads too.
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 240, 80);
  vhacd::HacdParameters p = Recommended();
  ASSERT_GT(torus.indices.size() / 3, p.target_triangles);
  p.num_threads = 1;
  const vhacd::Result r1 = vhacd::DecomposeHacd(torus.View(), p);
  p.num_threads = 3;
  const vhacd::Result r3 = vhacd::DecomposeHacd(torus.View(), p);
  ASSERT_TRUE(r1.ok() && r3.ok());
  ASSERT_EQ(r1.hulls.size(), r3.hulls.size());
  for (size_t h = 0; h < r1.hulls.size(); ++h) {
    EXPECT_EQ(r1.hulls[h].points, r3.hulls[h].points);
    EXPECT_EQ(r1.hulls[h].triangles, r3.hulls[h].triangles);
  }
}

TEST(HacdTest, AnySoupWorks) {
  // Several components, one of them inverted, a duplicated face and a non-manifold fin.
  Mesh m = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  Mesh flipped = vhacd_test::Box(2, 0, 0, 3, 1, 1);
  for (size_t t = 0; t < flipped.indices.size(); t += 3)
    std::swap(flipped.indices[t + 1], flipped.indices[t + 2]);
  m.Append(flipped);
  m.AddTriangle(0, 1, 2);
  const uint32_t fin = m.AddPoint(0.5, -1.0, 0.0);
  m.AddTriangle(0, 1, fin);
  const vhacd::Result r = vhacd::DecomposeHacd(m.View(), Recommended());
  ExpectValid(r);
  EXPECT_GE(r.hulls.size(), 2u);
}

class CancelFlag : public vhacd::Observer {
 public:
  std::atomic<bool> flag{false};
  std::atomic<int> progress_calls{0};
  bool IsCancelled() override { return flag.load(); }
  void OnProgress(double, double, double, const char*, const char*) override { ++progress_calls; }
};

TEST(HacdTest, CancelFromAnotherThread) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 192, 96);
  vhacd::HacdParameters p = Recommended();
  p.target_triangles = 0;  // cluster all 36864 triangles
  p.concavity = 1e6;
  p.min_clusters = 1;
  CancelFlag obs;
  std::chrono::steady_clock::time_point cancelled_at;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    cancelled_at = std::chrono::steady_clock::now();
    obs.flag.store(true);
  });
  const vhacd::Result r = vhacd::DecomposeHacd(torus.View(), p, &obs);
  const auto returned_at = std::chrono::steady_clock::now();
  canceller.join();
  EXPECT_EQ(r.status, vhacd::Status::kCancelled);
  EXPECT_TRUE(r.hulls.empty());
  EXPECT_GT(obs.progress_calls.load(), 0);
  EXPECT_LT(std::chrono::duration<double>(returned_at - cancelled_at).count(), 5.0);
}

TEST(HacdTest, InvalidInputsGiveErrors) {
  const Mesh cube = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  const vhacd::HacdParameters p = Recommended();
  vhacd::MeshView empty;
  EXPECT_EQ(vhacd::DecomposeHacd(empty, p).status, vhacd::Status::kEmptyMesh);
  vhacd::MeshView no_indices = cube.View();
  no_indices.indices = nullptr;
  EXPECT_EQ(vhacd::DecomposeHacd(no_indices, p).status, vhacd::Status::kInvalidMesh);
  Mesh bad_index = cube;
  bad_index.indices[4] = 99;
  const vhacd::Result r = vhacd::DecomposeHacd(bad_index.View(), p);
  EXPECT_EQ(r.status, vhacd::Status::kIndexOutOfRange);
  EXPECT_NE(r.message.find("99"), std::string::npos);
  Mesh nan = cube;
  nan.points[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(vhacd::DecomposeHacd(nan.View(), p).status, vhacd::Status::kInvalidMesh);
  Mesh one_point;  // three indices, one position: every triangle degenerate after welding
  one_point.AddTriangle(one_point.AddPoint(1, 1, 1), one_point.AddPoint(1, 1, 1),
                        one_point.AddPoint(1, 1, 1));
  EXPECT_EQ(vhacd::DecomposeHacd(one_point.View(), p).status, vhacd::Status::kEmptyMesh);

  auto bad = [&](auto change, const char* field) {
    vhacd::HacdParameters q = p;
    change(&q);
    const vhacd::Result res = vhacd::DecomposeHacd(cube.View(), q);
    EXPECT_EQ(res.status, vhacd::Status::kInvalidParameter) << field;
    EXPECT_NE(res.message.find(field), std::string::npos) << res.message;
  };
  bad([](vhacd::HacdParameters* q) { q->max_vertices_per_hull = 3; }, "max_vertices_per_hull");
  bad([](vhacd::HacdParameters* q) { q->concavity = -1; }, "concavity");
  bad([](vhacd::HacdParameters* q) { q->scale_factor = 0; }, "scale_factor");
  bad([](vhacd::HacdParameters* q) { q->min_clusters = 0; }, "min_clusters");
  bad([](vhacd::HacdParameters* q) { q->connect_distance = std::nan(""); }, "connect_distance");
  bad([](vhacd::HacdParameters* q) { q->small_cluster_threshold = 101; },
      "small_cluster_threshold");
  bad([](vhacd::HacdParameters* q) { q->max_clusters = 100001; }, "max_clusters");
  bad([](vhacd::HacdParameters* q) { q->max_concavity = 1.5; }, "max_concavity");
  bad([](vhacd::HacdParameters* q) { q->hull_count = 100001; }, "hull_count");
}

TEST(HacdTest, HullCountGivesExactlyThatMany) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 32, 16);
  for (uint32_t n : {1u, 3u, 12u, 40u}) {
    vhacd::HacdParameters p = Recommended();
    p.hull_count = n;
    const vhacd::Result r = vhacd::DecomposeHacd(torus.View(), p);
    ExpectValid(r);
    EXPECT_EQ(r.hulls.size(), n);
    EXPECT_TRUE(r.report.target_reached) << r.report.target_note;
  }
  // More clusters than triangles: as many as there are, and the report says why.
  const Mesh cube = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  vhacd::HacdParameters p = Recommended();
  p.hull_count = 50;
  const vhacd::Result r = vhacd::DecomposeHacd(cube.View(), p);
  ExpectValid(r);
  EXPECT_EQ(r.hulls.size(), 12u);
  EXPECT_FALSE(r.report.target_reached);
  EXPECT_NE(r.report.target_note.find("12 triangles"), std::string::npos) << r.report.target_note;
}

TEST(HacdTest, MaxClustersIsABudget) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 32, 16);
  const vhacd::Result free_run = vhacd::DecomposeHacd(torus.View(), Recommended());
  ASSERT_TRUE(free_run.ok());
  ASSERT_GT(free_run.hulls.size(), 3u);
  vhacd::HacdParameters p = Recommended();
  p.max_clusters = 3;
  const vhacd::Result r = vhacd::DecomposeHacd(torus.View(), p);
  ExpectValid(r);
  EXPECT_EQ(r.hulls.size(), 3u);
  p.max_clusters = 1;  // below min_clusters (2 in the recommended line): the budget wins
  EXPECT_EQ(vhacd::DecomposeHacd(torus.View(), p).hulls.size(), 1u);
}

TEST(HacdTest, MaxConcavityIsATargetTheReportChecks) {
  const Mesh torus = vhacd_test::Torus(1.0, 0.3, 32, 16);
  vhacd::HacdParameters p = Recommended();
  p.max_concavity = 0.05;
  const vhacd::Result loose = vhacd::DecomposeHacd(torus.View(), p);
  ExpectValid(loose);
  EXPECT_GE(loose.report.attempts, 1u);
  EXPECT_EQ(loose.report.target_reached, loose.report.concavity <= 0.05);
  EXPECT_LT(loose.report.concavity, 0.0);  // measured for the target, not returned
  p.max_concavity = 0.02;
  p.compute_report = true;
  const vhacd::Result tight = vhacd::DecomposeHacd(torus.View(), p);
  ExpectValid(tight);
  EXPECT_GT(tight.hulls.size(), loose.hulls.size());
  EXPECT_EQ(tight.report.target_reached, tight.report.concavity <= 0.02);
  if (!tight.report.target_reached)
    EXPECT_NE(tight.report.target_note.find("not reached"), std::string::npos);
}

}  // namespace
