#include "pipeline/error_budget.h"

#include <gtest/gtest.h>

#include "test_torus.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mesh/split.h"

namespace hullpack {
namespace {

// A long thin torus (x stretched 6x, z squashed): extents far from a cube, so the three grids
// differ.
Mesh Elongated() {
  Mesh m = testing::TorusMesh(48, 16);
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    m.positions[v * 3] *= 6;
    m.positions[v * 3 + 2] *= 0.5f;
  }
  m.normals.clear();
  return m;
}

// Largest distance between vertex i of `a` and vertex i of `b` (same order: keep_order).
double PerVertexError(const Mesh& a, const Mesh& b) {
  double worst = 0;
  for (size_t v = 0; v < a.vertex_count(); ++v) {
    double d = 0;
    for (int k = 0; k < 3; ++k)
      d += std::pow(double(a.positions[v * 3 + k]) - b.positions[v * 3 + k], 2);
    worst = std::max(worst, std::sqrt(d));
  }
  return worst;
}

TEST(ErrorBudget, GuaranteedBitsFollowTheBoundOfEachGrid) {
  const std::array<double, 3> extent = {1, 0.1, 0.1};
  // uniform: sqrt(3)/2 * 1 / 0.0005 = 1732 cells -> 11 bits; per-axis: |e|/2 / 0.0005 = 1010 -> 10;
  // diagonal: sqrt(3)/2 * |e| / 0.0005 = 1749 -> 11.
  EXPECT_EQ(GuaranteedPositionBits(o3dgc::RangeMode::kUniform, extent, 0.0005), 11);
  EXPECT_EQ(GuaranteedPositionBits(o3dgc::RangeMode::kPerAxis, extent, 0.0005), 10);
  EXPECT_EQ(GuaranteedPositionBits(o3dgc::RangeMode::kDiagonal, extent, 0.0005), 11);
  EXPECT_EQ(GuaranteedPositionBits(o3dgc::RangeMode::kUniform, {0, 0, 0}, 0.0005), 1);
  EXPECT_EQ(GuaranteedPositionBits(o3dgc::RangeMode::kUniform, extent, 1e-12), 30);
  EXPECT_STREQ(RangeModeName(o3dgc::RangeMode::kPerAxis), "per-axis");
}

TEST(ErrorBudget, EveryGridKeepsItsGuarantee) {
  const Mesh mesh = Elongated();
  const double budget = 0.0005 * BoundingBoxDiagonal(mesh);
  for (o3dgc::RangeMode mode :
       {o3dgc::RangeMode::kUniform, o3dgc::RangeMode::kPerAxis, o3dgc::RangeMode::kDiagonal}) {
    MeshCodecSettings s;
    s.keep_order = true;
    s.position_range = mode;
    s.position_bits = GuaranteedPositionBits(mode, PositionExtent(mesh), budget);
    Result<EncodedMesh> e = EncodeMesh(mesh, {}, s);
    ASSERT_TRUE(e.ok());
    Result<Mesh> d = DecodeMesh(e->stream.data(), e->stream.size(), nullptr, "t");
    ASSERT_TRUE(d.ok());
    EXPECT_LE(PerVertexError(mesh, d.value()), budget) << RangeModeName(mode);
  }
}

// What a decoder reads from `stream`, and its triangle groups.
Mesh Decoded(const EncodedMesh& stream, std::vector<uint32_t>* groups = nullptr) {
  Result<Mesh> m = DecodeMesh(stream.stream.data(), stream.stream.size(), groups, "t");
  EXPECT_TRUE(m.ok()) << m.status().ToString();
  return m.ok() ? std::move(m.value()) : Mesh();
}

TEST(ErrorBudget, ChoosesTheSmallestStreamWithinTheBudget) {
  const Mesh mesh = Elongated();
  const double budget = 0.0005 * BoundingBoxDiagonal(mesh);
  MeshCodecSettings s;
  s.keep_order = true;
  Result<BudgetedEncoding> chosen = EncodeWithinError(mesh, {}, s, budget);
  ASSERT_TRUE(chosen.ok()) << chosen.status().ToString();
  EXPECT_GE(chosen->streams_tried, 2);
  EXPECT_LE(chosen->max_error, budget);
  EXPECT_LE(PerVertexError(mesh, Decoded(chosen->streams[0])),
            budget);  // per vertex, not only as point sets
  // Never larger than the plain uniform grid at its guaranteed bits (what a fixed rule would pick).
  s.position_bits =
      GuaranteedPositionBits(o3dgc::RangeMode::kUniform, PositionExtent(mesh), budget);
  Result<EncodedMesh> uniform = EncodeMesh(mesh, {}, s);
  ASSERT_TRUE(uniform.ok());
  EXPECT_LE(chosen->streams[0].stream.size(), uniform->stream.size());
  // On this stretched shape the per-axis grid needs fewer bits than the cube of the largest extent.
  EXPECT_LT(GuaranteedPositionBits(o3dgc::RangeMode::kPerAxis, PositionExtent(mesh), budget),
            s.position_bits);
}

// The candidates share one o3dgc::GridEncoder: the chosen stream is, byte for byte, the one a
// whole encode at its grid gives, with normals and triangle groups, on any number of threads.
TEST(ErrorBudget, TheChosenStreamIsAWholeEncodeOfItsGrid) {
  const Mesh mesh = testing::TorusMesh(40, 14);
  ASSERT_FALSE(mesh.normals.empty());
  std::vector<uint32_t> groups(mesh.triangle_count());
  for (size_t t = 0; t < groups.size(); ++t)
    groups[t] = static_cast<uint32_t>(t * 3 / groups.size());
  const double budget = 0.001 * BoundingBoxDiagonal(mesh);
  for (int threads : {1, 3}) {
    Result<BudgetedEncoding> chosen =
        EncodeWithinError(mesh, groups, MeshCodecSettings(), budget, threads);
    ASSERT_TRUE(chosen.ok()) << chosen.status().ToString();
    MeshCodecSettings s;
    s.position_bits = chosen->position_bits;
    s.position_range = chosen->position_range;
    Result<EncodedMesh> whole = EncodeMesh(mesh, groups, s);
    ASSERT_TRUE(whole.ok());
    EXPECT_EQ(chosen->streams[0].stream, whole->stream) << threads << " threads";
    EXPECT_EQ(chosen->streams[0].gltf_attributes, whole->gltf_attributes);
    EXPECT_EQ(chosen->streams[0].info.positions, whole->info.positions);
    std::vector<uint32_t> decoded_groups;
    Decoded(chosen->streams[0], &decoded_groups);
    EXPECT_EQ(decoded_groups.size(), groups.size());
  }
}

// In parts, each chosen stream is the whole encode of its part (SplitTriangles, MeshPart) at the
// grid that coded the first part smallest, over the whole mesh's box, and the parts' error is the
// whole mesh's.
TEST(ErrorBudget, PartsAreWholeEncodesOfThePartsOnTheMeshGrid) {
  const Mesh mesh = testing::TorusMesh(40, 14);
  std::vector<uint32_t> groups(mesh.triangle_count());
  for (size_t t = 0; t < groups.size(); ++t) groups[t] = static_cast<uint32_t>(t % 3);
  const double budget = 0.001 * BoundingBoxDiagonal(mesh);
  Result<BudgetedEncoding> whole = EncodeWithinError(mesh, groups, MeshCodecSettings(), budget);
  ASSERT_TRUE(whole.ok());
  const TriangleParts split = SplitTriangles(mesh, 400);
  ASSERT_EQ(split.count(), 3u);  // 1120 triangles
  for (int threads : {1, 3}) {
    Result<BudgetedEncoding> chosen =
        EncodeWithinError(mesh, groups, MeshCodecSettings(), budget, threads, 400);
    ASSERT_TRUE(chosen.ok()) << chosen.status().ToString();
    ASSERT_EQ(chosen->streams.size(), 3u);
    // The same grids tried (the first part on each, the others on the one it chose).
    EXPECT_EQ(chosen->streams_tried, whole->streams_tried);
    EXPECT_GT(chosen->streams_tried, 1);
    EXPECT_EQ(chosen->max_error,
              PositionGridError(mesh, chosen->position_range, chosen->position_bits));
    EXPECT_LE(chosen->max_error, budget);
    // Parts cost bytes: the vertices along the cuts are coded twice, and each stream's models
    // learn from scratch (much of the bytes of parts this small).
    EXPECT_GT(StreamBytes(chosen.value()), StreamBytes(whole.value()));
    EXPECT_LT(StreamBytes(chosen.value()), StreamBytes(whole.value()) * 2);
    MeshCodecSettings s;
    s.position_bits = chosen->position_bits;
    s.position_range = chosen->position_range;
    s.position_box = PositionBox(mesh);
    for (size_t p = 0; p < split.count(); ++p) {
      const std::vector<uint32_t> triangles = split.Triangles(p, mesh.triangle_count());
      const Mesh part = MeshPart(mesh, triangles);
      std::vector<uint32_t> part_groups;
      for (uint32_t t : triangles) part_groups.push_back(groups[t]);
      Result<EncodedMesh> alone = EncodeMesh(part, part_groups, s);
      ASSERT_TRUE(alone.ok());
      EXPECT_EQ(chosen->streams[p].stream, alone->stream) << p << ", " << threads;
      std::vector<uint32_t> decoded_groups;
      EXPECT_EQ(Decoded(chosen->streams[p], &decoded_groups).triangle_count(), triangles.size());
      EXPECT_EQ(decoded_groups.size(), triangles.size());
    }
  }
}

TEST(ErrorBudget, TriesFewerBitsWhenTheMeasuredErrorLeavesRoom) {
  // A cube's corners are the ends of the per-axis and uniform grids' ranges, so they decode
  // exactly at any bit count: the measured error stays 0 and the search walks down to 1 bit, far
  // below the guarantee. (With unequal sides the uniform grid's corners are inexact, and its
  // stream at 8 bits may be the smallest.)
  Mesh box;
  for (int c = 0; c < 8; ++c)
    box.positions.insert(box.positions.end(),
                         {c & 1 ? 7.0f : 0.0f, c & 2 ? 7.0f : 0.0f, c & 4 ? 7.0f : 0.0f});
  box.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  Result<BudgetedEncoding> chosen = EncodeWithinError(box, {}, MeshCodecSettings(), 0.01);
  ASSERT_TRUE(chosen.ok()) << chosen.status().ToString();
  EXPECT_EQ(chosen->max_error, 0);
  EXPECT_EQ(chosen->position_bits, 1);
  EXPECT_GT(GuaranteedPositionBits(chosen->position_range, PositionExtent(box), 0.01), 8);
}

TEST(ErrorBudget, BadBudgetsAreErrors) {
  const Mesh mesh = Elongated();
  for (double bad : {0.0, -1.0, std::nan(""), double(INFINITY)}) {
    Result<BudgetedEncoding> r = EncodeWithinError(mesh, {}, MeshCodecSettings(), bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.status().code(), StatusCode::kInvalidArgument);
  }
}

TEST(ErrorBudget, ZeroSizeMeshesMeetAZeroBudget) {
  // What PackScene asks for a mesh whose diagonal is 0: max_error x 0 (found by tests/stability).
  Mesh point;
  point.positions = {1, 2, 3, 1, 2, 3, 1, 2, 3};
  point.indices = {0, 1, 2};
  for (const Mesh& mesh : {point, Mesh()}) {
    Result<BudgetedEncoding> r = EncodeWithinError(mesh, {}, MeshCodecSettings(), 0.0);
    ASSERT_TRUE(r.ok()) << r.status().ToString();
    EXPECT_EQ(r->max_error, 0);
    // The point's triangle is degenerate: the codec leaves it out, and its vertices with it.
    const Mesh decoded = Decoded(r->streams[0]);
    EXPECT_EQ(decoded.triangle_count(), 0u);
    EXPECT_EQ(decoded.vertex_count(), 0u);
    for (size_t i = 0; i < decoded.positions.size(); ++i)
      EXPECT_EQ(decoded.positions[i], point.positions[i % 3]);
  }
}

}  // namespace
}  // namespace hullpack
