// ReadMesh: welding, dropped triangles, closedness, sources, float and double input alike, and
// the lent triangles of a clean mesh.
#include "input_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "error_metrics.h"
#include "test_meshes.h"

namespace {

using vhacd::internal::InputMesh;
using vhacd::internal::ReadMesh;

// may_borrow reads the points in place too (ReadOptions::points_in_place).
InputMesh Read(const vhacd_test::Mesh& m, bool keep_sources = true, bool may_borrow = false) {
  vhacd::internal::Context ctx(nullptr, 1);
  InputMesh out;
  std::string why;
  vhacd::internal::ReadOptions options;
  options.keep_sources = keep_sources;
  options.may_borrow = may_borrow;
  options.points_in_place = may_borrow;
  EXPECT_EQ(ReadMesh(vhacd::MeshView::FromDouble(m.points.data(), m.point_count(), m.indices.data(),
                                                 m.indices.size() / 3),
                     &ctx, &out, &why, options),
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

TEST(ReadMesh, ACleanMeshIsReadInPlaceWhenAllowed) {
  // Over 20001 points, so that the vertex samples are every second point or sparser.
  const vhacd_test::Mesh torus = vhacd_test::Torus(2, 0.5, 200, 101);
  const InputMesh lent = Read(torus, false, /*may_borrow=*/true);
  EXPECT_TRUE(lent.points.empty());
  ASSERT_EQ(lent.point_count(), torus.point_count());
  EXPECT_EQ(lent.view_points.d, torus.points.data());
  EXPECT_TRUE(lent.triangles.borrowed());
  EXPECT_EQ(lent.triangles[0].begin(), torus.indices.data());
  for (size_t i = 0; i < lent.point_count(); ++i)
    EXPECT_EQ(lent.view_points[i],
              vhacd::internal::Vec3(torus.points[3 * i], torus.points[3 * i + 1],
                                    torus.points[3 * i + 2]));
  EXPECT_TRUE(lent.closed);
  // The same vertex samples as the lexicographic order's stride.
  const InputMesh sorted = Read(torus, false);
  EXPECT_FALSE(sorted.triangles.borrowed());
  EXPECT_TRUE(sorted.vertex_samples.empty());
  const size_t stride = vhacd::internal::VertexSampleStride(sorted.points.size());
  ASSERT_GT(stride, 1u);
  std::vector<vhacd::internal::Vec3> expected, samples;
  for (size_t i = 0; i < sorted.points.size(); i += stride) expected.push_back(sorted.points[i]);
  for (uint32_t i : lent.vertex_samples) samples.push_back(lent.view_points[i]);
  EXPECT_EQ(samples, expected);
  // A repeated triangle: the points keep their order, the triangles are copied without it.
  vhacd_test::Mesh repeated = torus;
  repeated.AddTriangle(torus.indices[0], torus.indices[1], torus.indices[2]);
  const InputMesh copied = Read(repeated, false, true);
  EXPECT_FALSE(copied.triangles.borrowed());
  EXPECT_EQ(copied.view_points.d, repeated.points.data());
  EXPECT_EQ(copied.point_count(), lent.point_count());
  EXPECT_EQ(copied.triangles, lent.triangles);
  // Equal positions or an unused point: the lexicographic order.
  vhacd_test::Mesh unused = torus;
  unused.AddPoint(9, 9, 9);
  const InputMesh renumbered = Read(unused, false, true);
  EXPECT_FALSE(renumbered.triangles.borrowed());
  EXPECT_EQ(renumbered.points, sorted.points);
  EXPECT_EQ(renumbered.triangles, sorted.triangles);
  // Without points_in_place, the points are copied in their order.
  InputMesh small;
  std::string why;
  vhacd::internal::Context ctx(nullptr, 1);
  vhacd::internal::ReadOptions options;
  options.keep_sources = false;
  options.may_borrow = true;
  options.points_in_place = false;
  ASSERT_EQ(ReadMesh(vhacd::MeshView::FromDouble(torus.points.data(), torus.point_count(),
                                                 torus.indices.data(), torus.triangle_count()),
                     &ctx, &small, &why, options),
            vhacd::Status::kOk);
  EXPECT_TRUE(small.view_points.empty());
  EXPECT_TRUE(small.triangles.borrowed());
  ASSERT_EQ(small.points.size(), torus.point_count());
  for (size_t i = 0; i < small.points.size(); ++i) EXPECT_EQ(small.points[i], lent.view_points[i]);
}

// The grid points mapped on every read from the caller's floats are those of the copy mapped in
// place (Decompose without Parameters::points_in_place), with and without a rotation.
TEST(GridPoints, MappedOnReadEqualsMappedOnce) {
  const vhacd_test::Mesh torus = vhacd_test::Torus(2, 0.5, 40, 20);
  std::vector<float> floats(torus.points.begin(), torus.points.end());
  for (float& f : floats) f = f * 3.7f + 1234.5f;  // far from the origin, off the unit scale
  const vhacd::internal::PointSource source{floats.data(), nullptr, 3, torus.point_count()};
  for (bool rotate : {false, true}) {
    vhacd::internal::GridFrame frame;
    ASSERT_TRUE(vhacd::internal::FitUnitBox(
        source.size(), [&](size_t i) { return source[i]; }, &frame.unit));
    if (rotate) {
      frame.unit.rotate = true;
      frame.unit.rotation =
          Eigen::AngleAxisd(0.7, vhacd::internal::Vec3(1, 2, 3).normalized()).toRotationMatrix();
    }
    frame.origin = vhacd::internal::Vec3(-0.61, -0.57, -0.33);
    frame.h = 0.0173;
    std::vector<vhacd::internal::Vec3> copy(source.size());
    for (size_t i = 0; i < copy.size(); ++i) copy[i] = frame.FromUnit(frame.unit.Unit(source[i]));
    const vhacd::internal::GridPoints owned(copy), mapped(source, frame);
    ASSERT_EQ(mapped.size(), owned.size());
    for (size_t i = 0; i < owned.size(); ++i) ASSERT_EQ(mapped[i], owned[i]);
  }
}

// A scrambled point order (one block of points per corner) would make every triangle's points
// far apart in memory: the lexicographic order is kept then.
TEST(ReadMesh, AScrambledPointOrderIsNotKept) {
  const vhacd_test::Mesh torus = vhacd_test::Torus(2, 0.5, 700, 300);
  std::vector<uint32_t> to(torus.point_count());
  for (uint32_t i = 0; i < to.size(); ++i) to[i] = i;
  std::shuffle(to.begin(), to.end(), std::mt19937(5));
  vhacd_test::Mesh scrambled = torus;
  for (uint32_t i = 0; i < to.size(); ++i)
    for (int k = 0; k < 3; ++k) scrambled.points[3 * to[i] + k] = torus.points[3 * i + k];
  for (uint32_t& v : scrambled.indices) v = to[v];
  EXPECT_TRUE(Read(torus, false, true).triangles.borrowed());
  const InputMesh read = Read(scrambled, false, true);
  EXPECT_FALSE(read.triangles.borrowed());
  EXPECT_TRUE(read.vertex_samples.empty());
  EXPECT_EQ(read.points, Read(scrambled, false).points);
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
