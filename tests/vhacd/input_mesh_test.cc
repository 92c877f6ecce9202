// ReadMesh: welding, dropped triangles, closedness, sources, float and double input alike.
#include "input_mesh.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "test_meshes.h"

namespace {

using vhacd::internal::InputMesh;
using vhacd::internal::ReadMesh;

InputMesh Read(const vhacd_test::Mesh& m, bool keep_sources = true) {
  vhacd::internal::Context ctx(nullptr, 1);
  InputMesh out;
  std::string why;
  EXPECT_EQ(ReadMesh(vhacd::MeshView::FromDouble(m.points.data(), m.point_count(), m.indices.data(),
                                                 m.indices.size() / 3),
                     &ctx, &out, &why, keep_sources),
            vhacd::Status::kOk)
      << why;
  return out;
}

TEST(ReadMesh, ClosedOnlyWhenEveryEdgeHasTwoTriangles) {
  const vhacd_test::Mesh box = vhacd_test::Box(0, 0, 0, 1, 2, 3);
  EXPECT_TRUE(Read(box).closed);
  EXPECT_TRUE(Read(vhacd_test::Torus(2, 0.5, 12, 8)).closed);
  vhacd_test::Mesh open = box;
  open.indices.resize(open.indices.size() - 3);  // one triangle less: a hole
  EXPECT_FALSE(Read(open).closed);
  // A third triangle on an edge of a closed box (non-manifold).
  vhacd_test::Mesh fin = box;
  fin.points.insert(fin.points.end(), {5, 5, 5});
  fin.AddTriangle(box.indices[0], box.indices[1], static_cast<uint32_t>(fin.point_count() - 1));
  EXPECT_FALSE(Read(fin).closed);
}

// Over a million edges, the closedness check takes the vertices in ranges: a hole is found in any.
TEST(ReadMesh, ClosednessOfALargeMeshIsCheckedInEveryRangeOfVertices) {
  const vhacd_test::Mesh torus = vhacd_test::Torus(2, 0.5, 1000, 400);
  ASSERT_GT(torus.indices.size(), size_t{2} << 20);
  EXPECT_TRUE(Read(torus, false).closed);
  for (const size_t hole : {size_t{0}, torus.indices.size() / 2, torus.indices.size() - 3}) {
    vhacd_test::Mesh open = torus;
    open.indices.erase(open.indices.begin() + static_cast<std::ptrdiff_t>(hole),
                       open.indices.begin() + static_cast<std::ptrdiff_t>(hole) + 3);
    EXPECT_FALSE(Read(open, false).closed) << "hole at triangle " << hole / 3;
  }
}

TEST(ReadMesh, WeldsEqualPointsAndDropsDegenerateAndRepeatedTriangles) {
  vhacd_test::Mesh m;
  m.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 7, 7, 7};  // point 3 = point 1; 4 unused
  m.AddTriangle(0, 1, 2);
  m.AddTriangle(0, 3, 2);  // the first again once welded
  m.AddTriangle(2, 1, 0);  // the same vertex set, other winding
  m.AddTriangle(0, 1, 3);  // degenerate once welded
  const InputMesh in = Read(m);
  ASSERT_EQ(in.points.size(), 3u);
  ASSERT_EQ(in.triangles.size(), 1u);
  EXPECT_EQ(in.triangle_source, std::vector<uint32_t>{0});
  ASSERT_EQ(in.point_source.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(in.points[i][k], m.points[3 * in.point_source[i] + k]);
  }
  const InputMesh lean = Read(m, /*keep_sources=*/false);
  EXPECT_TRUE(lean.point_source.empty());
  EXPECT_TRUE(lean.triangle_source.empty());
  EXPECT_EQ(lean.points, in.points);
  EXPECT_EQ(lean.triangles, in.triangles);
}

TEST(ReadMesh, FloatInputReadsAsItsDoubleValues) {
  const vhacd_test::Mesh m = vhacd_test::Sphere(1.3, 16, 9);
  std::vector<float> f(m.points.begin(), m.points.end());
  std::vector<double> d(f.begin(), f.end());
  vhacd::internal::Context ctx(nullptr, 1);
  InputMesh a, b;
  std::string why;
  ASSERT_EQ(ReadMesh(vhacd::MeshView::FromFloat(f.data(), m.point_count(), m.indices.data(),
                                                m.indices.size() / 3),
                     &ctx, &a, &why),
            vhacd::Status::kOk);
  ASSERT_EQ(ReadMesh(vhacd::MeshView::FromDouble(d.data(), m.point_count(), m.indices.data(),
                                                 m.indices.size() / 3),
                     &ctx, &b, &why),
            vhacd::Status::kOk);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.point_source, b.point_source);
  EXPECT_EQ(a.closed, b.closed);
  f[4] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(ReadMesh(vhacd::MeshView::FromFloat(f.data(), m.point_count(), m.indices.data(),
                                                m.indices.size() / 3),
                     &ctx, &a, &why),
            vhacd::Status::kInvalidMesh);
}

}  // namespace
