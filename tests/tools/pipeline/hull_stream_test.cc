#include "pipeline/hull_stream.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/test_shapes.h"
#include "mesh/topology.h"

namespace hullpack {
namespace {

// The closed box [x0, x1] x [0, 1] x [0, h], outward triangles.
Mesh Box(float x0, float x1, float h) {
  Mesh m;
  test_shapes::AppendTo(test_shapes::Box(x0, 0, 0, x1, 1, h), &m);
  return m;
}

// A row of boxes of different heights that touch along x: neighbours share the corners of their
// common face up to the lower box's height, as the hulls of a decomposition meet on their cuts.
std::vector<Mesh> Row(int n) {
  std::vector<Mesh> hulls;
  for (int i = 0; i < n; ++i)
    hulls.push_back(Box(float(i), float(i + 1), 1.0f + 0.25f * float(i % 3)));
  return hulls;
}

TEST(HullStream, WeldingSharesCornersOnlyAcrossHulls) {
  std::vector<Mesh> hulls = Row(3);
  // A hull with two corners at one place (as quantization can make them) keeps both.
  hulls[2].positions[3 * 7 + 0] = hulls[2].positions[3 * 6 + 0];
  std::vector<uint32_t> groups;
  const Mesh welded = WeldAcrossHulls(hulls, &groups);
  ASSERT_EQ(groups.size(), 36u);
  EXPECT_EQ(groups[0], 0u);
  EXPECT_EQ(groups[35], 2u);
  // Box 0/1 share 2 bottom corners (box 0 is lower: its top corners at height 1 differ from box
  // 1's at 1.25), box 1/2 share 2 more. Box 2's duplicated corner stays a separate vertex.
  EXPECT_EQ(welded.vertex_count(), 24u - 4u);
  for (size_t t = 0; t < welded.triangle_count(); ++t) {
    const uint32_t* c = &welded.indices[t * 3];
    EXPECT_TRUE(c[0] != c[1] && c[1] != c[2] && c[0] != c[2]) << "triangle " << t;
  }
}

TEST(HullStream, HullsDecodeClosedWithinTheBudgetAndWeldedWhenSmaller) {
  const std::vector<Mesh> hulls = Row(12);
  const double budget = 0.002 * std::sqrt(12.0 * 12.0 + 1 + 1.5 * 1.5);
  Result<EncodedHulls> e = EncodeHulls(hulls, MeshCodecSettings(), budget);
  ASSERT_TRUE(e.ok()) << e.status().ToString();
  ASSERT_EQ(e->decoded.size(), hulls.size());
  EXPECT_LE(e->max_error, budget);
  for (size_t h = 0; h < hulls.size(); ++h) {
    EXPECT_EQ(e->decoded[h].vertex_count(), 8u) << h;
    EXPECT_EQ(e->decoded[h].triangle_count(), 12u) << h;
    EXPECT_TRUE(AnalyzeTopology(e->decoded[h]).closed) << h;
    EXPECT_LE(MaxVertexDistance(hulls[h], e->decoded[h]), budget) << h;
  }
  // 12 boxes share 2 corners with each neighbour (4 with a neighbour of the same height).
  EXPECT_TRUE(e->welded);
  EXPECT_LT(e->stream_vertices, 96u);
  // A decoder sees the same hulls: group h of the stream, compacted.
  std::vector<uint32_t> groups;
  Result<Mesh> all =
      DecodeMesh(e->encoded.stream.data(), e->encoded.stream.size(), &groups, "hulls");
  ASSERT_TRUE(all.ok());
  for (size_t h = 0; h < hulls.size(); ++h) {
    EXPECT_EQ(ExtractGroup(all.value(), groups, uint32_t(h)).positions, e->decoded[h].positions)
        << h;
  }
}

TEST(HullStream, NoHullsIsAnError) {
  EXPECT_FALSE(EncodeHulls({}, MeshCodecSettings(), 0.01).ok());
  EXPECT_FALSE(EncodeHulls(Row(2), MeshCodecSettings(), 0).ok());
}

}  // namespace
}  // namespace hullpack
