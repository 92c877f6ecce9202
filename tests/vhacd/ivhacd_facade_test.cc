#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "test_meshes.h"
#include "vhacd/ivhacd.h"

namespace {

class Callback : public VHACD::IVHACD::IUserCallback {
 public:
  int calls = 0;
  void Update(const double overall, const double, const double, const char* const stage,
              const char* const operation) override {
    ++calls;
    EXPECT_GE(overall, 0.0);
    EXPECT_LE(overall, 100.0);
    EXPECT_NE(stage, nullptr);
    EXPECT_NE(operation, nullptr);
  }
};

class Logger : public VHACD::IVHACD::IUserLogger {
 public:
  std::string text;
  void Log(const char* const msg) override { text += msg; }
};

TEST(IVHACDTest, ComputeDoubleAndFloatAndReadHulls) {
  const vhacd_test::Mesh l = vhacd_test::LBlock();
  std::vector<int> tris(l.indices.begin(), l.indices.end());
  std::vector<float> pf(l.points.begin(), l.points.end());
  VHACD::IVHACD::Parameters params;
  params.m_resolution = 20000;
  Callback cb;
  Logger log;
  params.m_callback = &cb;
  params.m_logger = &log;
  VHACD::IVHACD* v = VHACD::CreateVHACD();
  ASSERT_TRUE(v->Compute(l.points.data(), 3, static_cast<unsigned>(l.point_count()), tris.data(), 3,
                         static_cast<unsigned>(l.triangle_count()), params));
  EXPECT_EQ(v->GetNConvexHulls(), 2u);
  EXPECT_GT(cb.calls, 0);
  EXPECT_FALSE(log.text.empty());
  double volume = 0.0;
  for (unsigned p = 0; p < v->GetNConvexHulls(); ++p) {
    VHACD::IVHACD::ConvexHull ch;
    v->GetConvexHull(p, ch);
    ASSERT_GE(ch.m_nPoints, 4u);
    ASSERT_GE(ch.m_nTriangles, 4u);
    for (unsigned t = 0; t < 3 * ch.m_nTriangles; ++t) {
      EXPECT_GE(ch.m_triangles[t], 0);
      EXPECT_LT(static_cast<unsigned>(ch.m_triangles[t]), ch.m_nPoints);
    }
    volume += ch.m_volume;
  }
  EXPECT_NEAR(volume, 3.0, 0.05);
  VHACD::IVHACD::ConvexHull none;
  v->GetConvexHull(99, none);
  EXPECT_EQ(none.m_nPoints, 0u);

  ASSERT_TRUE(v->Compute(pf.data(), 3, static_cast<unsigned>(l.point_count()), tris.data(), 3,
                         static_cast<unsigned>(l.triangle_count()), params));
  EXPECT_EQ(v->GetNConvexHulls(), 2u);
  v->Clean();
  EXPECT_EQ(v->GetNConvexHulls(), 0u);
  v->Release();
}

TEST(IVHACDTest, ErrorsAreReportedNotThrown) {
  const vhacd_test::Mesh cube = vhacd_test::Box(0, 0, 0, 1, 1, 1);
  std::vector<int> tris(cube.indices.begin(), cube.indices.end());
  tris[0] = -1;
  VHACD::IVHACD::Parameters params;
  VHACD::IVHACD* v = VHACD::CreateVHACD();
  EXPECT_FALSE(v->Compute(cube.points.data(), 3, 8, tris.data(), 3, 12, params));
  EXPECT_EQ(v->GetStatus(), vhacd::Status::kIndexOutOfRange);
  EXPECT_EQ(v->GetNConvexHulls(), 0u);
  EXPECT_FALSE(v->Compute(static_cast<const double*>(nullptr), 3, 0, nullptr, 3, 0, params));
  EXPECT_EQ(v->GetStatus(), vhacd::Status::kEmptyMesh);
  params.m_depth = 100;
  tris[0] = 0;
  EXPECT_FALSE(v->Compute(cube.points.data(), 3, 8, tris.data(), 3, 12, params));
  EXPECT_EQ(v->GetStatus(), vhacd::Status::kInvalidParameter);
  v->Release();
}

TEST(IVHACDTest, CancelFromAnotherThread) {
  const vhacd_test::Mesh torus = vhacd_test::Torus(1.0, 0.3, 96, 48);
  std::vector<int> tris(torus.indices.begin(), torus.indices.end());
  VHACD::IVHACD::Parameters params;
  params.m_resolution = 3000000;
  params.m_concavity = 0.0001;
  VHACD::IVHACD* v = VHACD::CreateVHACD();
  std::atomic<bool> started{false};
  std::thread t([&] {
    started = true;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    v->Cancel();
  });
  const bool ok = v->Compute(torus.points.data(), 3, static_cast<unsigned>(torus.point_count()),
                             tris.data(), 3, static_cast<unsigned>(torus.triangle_count()), params);
  t.join();
  EXPECT_FALSE(ok);
  EXPECT_EQ(v->GetStatus(), vhacd::Status::kCancelled);
  v->Release();
}

}  // namespace
