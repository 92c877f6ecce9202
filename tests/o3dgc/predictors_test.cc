// The coding orders of parallelogram-predicted values (CodingOrder): which vertex comes next and
// which of its wedges count as parallelograms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "predictors.h"
#include "test_meshes.h"

namespace {

using namespace o3dgc;

WedgeTable WedgesOf(const o3dgc_test::TestMesh& t) {
  WedgeTable wedges;
  wedges.Build(t.indices, uint32_t(t.nv()), o3dgc_test::OppositeCorners(t.indices), true);
  return wedges;
}

// Runs `kind` over `wedges`; returns the visit order and checks, at every visit, that the listed
// parallelograms are exactly the wedges of c whose u, w and x were visited before c.
std::vector<uint32_t> Traverse(const WedgeTable& wedges, CodingOrder::Kind kind,
                               size_t* parallelograms) {
  const uint32_t n = wedges.num_vertices();
  std::vector<uint32_t> order, rank(n, UINT32_MAX);
  CodingOrder t(wedges, kind);
  *parallelograms = 0;
  for (uint32_t c; (c = t.Next()) != kNoVertex;) {
    EXPECT_LT(c, n);
    if (c >= n || rank[c] != UINT32_MAX) {
      ADD_FAILURE() << "vertex " << c << " returned twice";
      break;
    }
    EXPECT_EQ(t.previous(), order.empty() ? kNoVertex : order.back());
    const int n_par = t.Visit(c);
    rank[c] = uint32_t(order.size());
    order.push_back(c);
    std::vector<const Wedge*> expected;
    for (const Wedge* w = wedges.begin(c); w != wedges.end(c); ++w) {
      if (rank[w->u] < rank[c] && rank[w->w] < rank[c] && w->x != c && rank[w->x] < rank[c]) {
        expected.push_back(w);
      }
    }
    EXPECT_EQ(std::vector<const Wedge*>(t.parallelograms(), t.parallelograms() + n_par), expected)
        << "vertex " << c;
    for (uint32_t v = 0; v < n; ++v) EXPECT_EQ(t.done()[v] != 0, rank[v] != UINT32_MAX);
    *parallelograms += size_t(n_par);
  }
  EXPECT_EQ(order.size(), size_t(n));
  return order;
}

TEST(CodingOrder, VertexIdOrderVisitsTheIdsInIncreasingOrder) {
  for (const auto& mesh :
       {o3dgc_test::Torus(20, 12), o3dgc_test::Sphere(16, 10), o3dgc_test::Awkward()}) {
    const WedgeTable wedges = WedgesOf(mesh);
    size_t parallelograms = 0;
    const std::vector<uint32_t> order = Traverse(wedges, CodingOrder::kVertexId, &parallelograms);
    for (uint32_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], i);
  }
}

TEST(CodingOrder, GreedyOrderVisitsEveryVertexOnceAndFindsMoreParallelograms) {
  // A torus whose ids are shuffled: in id order a wedge is a parallelogram when c happens to be the
  // largest of its four ids (1.5 of 6 wedges per vertex), while the greedy order follows the
  // surface whatever the ids.
  o3dgc_test::TestMesh torus = o3dgc_test::Torus(20, 12);
  const uint32_t n = uint32_t(torus.nv());
  std::vector<uint32_t> id(n);
  std::iota(id.begin(), id.end(), 0u);
  std::shuffle(id.begin(), id.end(), std::mt19937(3));
  for (uint32_t& v : torus.indices) v = id[v];
  const WedgeTable wedges = WedgesOf(torus);
  size_t greedy = 0, by_id = 0;
  const std::vector<uint32_t> order = Traverse(wedges, CodingOrder::kGreedy, &greedy);
  Traverse(wedges, CodingOrder::kVertexId, &by_id);
  EXPECT_EQ(order[0], 0u);  // a new component starts at the lowest uncoded id
  EXPECT_GT(greedy, by_id * 5 / 4) << greedy << " against " << by_id;  // 479 against 364
  // Nearly every vertex of a closed surface has two or more parallelograms in the greedy order.
  EXPECT_GT(greedy, size_t(2 * n) * 9 / 10);
}

// Component ends only spare the search for a next vertex when a part is done: the greedy order
// is the same with them as without, on parts with boundaries (searches mid-part) and closed ones.
TEST(CodingOrder, ComponentEndsDoNotChangeTheGreedyOrder) {
  std::vector<uint32_t> ends;
  const o3dgc_test::TestMesh t = o3dgc_test::Concatenated(
      {o3dgc_test::Grid(7, 4), o3dgc_test::Torus(10, 6), o3dgc_test::PocketPlate(2, 1),
       o3dgc_test::Grid(1, 1), o3dgc_test::Sphere(8, 5)},
      &ends);
  const std::vector<uint32_t> corners = o3dgc_test::OppositeCorners(t.indices);
  std::vector<uint32_t> opposite_vertices(corners.size(), 0xFFFFFFFFu);
  for (size_t c = 0; c < corners.size(); ++c) {
    if (corners[c] != 0xFFFFFFFFu) opposite_vertices[c] = t.indices[corners[c]];
  }
  WedgeTable with, without;
  with.BuildFromOppositeVertices(t.indices, uint32_t(t.nv()), opposite_vertices, nullptr, &ends);
  without.BuildFromOppositeVertices(t.indices, uint32_t(t.nv()), opposite_vertices);
  ASSERT_EQ(with.component_ends(), &ends);
  EXPECT_EQ(without.component_ends(), nullptr);
  size_t p_with = 0, p_without = 0;
  EXPECT_EQ(Traverse(with, CodingOrder::kGreedy, &p_with),
            Traverse(without, CodingOrder::kGreedy, &p_without));
  EXPECT_EQ(p_with, p_without);
}

TEST(CodingOrder, EmptyTable) {
  const WedgeTable wedges = WedgesOf(o3dgc_test::TestMesh());
  for (const CodingOrder::Kind kind : {CodingOrder::kGreedy, CodingOrder::kVertexId}) {
    CodingOrder t(wedges, kind);
    EXPECT_EQ(t.Next(), kNoVertex);
  }
}

}  // namespace
