#include "mesh/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_meshes.h"

namespace hullpack {
namespace {

using namespace testing_meshes;

constexpr double kPi = 3.14159265358979323846;

TEST(TopologyTest, UnitCubeIsClosedGenusZeroWithUnitVolume) {
  const TopologyReport r = AnalyzeTopology(UnitCube());
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.referenced_vertices, 8u);
  EXPECT_EQ(r.unique_positions, 8u);
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_EQ(r.edges, 18u);
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.non_manifold_vertices, 0u);
  EXPECT_EQ(r.inconsistent_edges, 0u);
  EXPECT_TRUE(r.consistently_oriented);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.components_by_vertex, 1u);
  EXPECT_EQ(r.closed_manifold_components, 1u);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.genus, 0);
  EXPECT_NEAR(r.area, 6.0, 1e-12);
  EXPECT_NEAR(r.volume, 1.0, 1e-12);
  EXPECT_EQ(r.bbox_min, (std::array<float, 3>{0, 0, 0}));
  EXPECT_EQ(r.bbox_max, (std::array<float, 3>{1, 1, 1}));
}

TEST(TopologyTest, VolumeIsSignedAndIndependentOfPlacement) {
  Mesh far;
  AddCube(far, 1000, -2000, 3000, 2);
  EXPECT_NEAR(AnalyzeTopology(far).volume, 8.0, 1e-9);
  // Reversing every triangle turns the volume inside out.
  for (size_t t = 0; t < far.triangle_count(); ++t)
    std::swap(far.indices[3 * t + 1], far.indices[3 * t + 2]);
  const TopologyReport r = AnalyzeTopology(far);
  EXPECT_NEAR(r.volume, -8.0, 1e-9);
  EXPECT_TRUE(r.consistently_oriented);
}

TEST(TopologyTest, TorusHasGenusOne) {
  Mesh torus;
  AddTorus(torus, 0, 2.0f, 0.5f);
  const TopologyReport r = AnalyzeTopology(torus);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.consistently_oriented);
  EXPECT_EQ(r.non_manifold_vertices, 0u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.genus, 1);
  // A 48 x 24 polygon torus is within a few percent of the smooth one.
  EXPECT_NEAR(r.volume, 2 * kPi * kPi * 2.0 * 0.25, 0.03 * 2 * kPi * kPi * 2.0 * 0.25);
  EXPECT_NEAR(r.area, 4 * kPi * kPi * 2.0 * 0.5, 0.03 * 4 * kPi * kPi * 2.0 * 0.5);
}

TEST(TopologyTest, GenusSumsOverComponents) {
  Mesh mesh;
  AddTorus(mesh, 0, 2.0f, 0.5f, 16, 8);
  AddTorus(mesh, 10, 2.0f, 0.5f, 16, 8);
  AddCube(mesh, -10, 0, 0);
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_EQ(r.components, 3u);
  EXPECT_EQ(r.closed_manifold_components, 3u);
  EXPECT_EQ(r.genus, 2);
}

TEST(TopologyTest, OpenBoxHasFourBoundaryEdgesAndNoGenus) {
  Mesh box;
  AddCube(box, 0, 0, 0, 1, 5);
  const TopologyReport r = AnalyzeTopology(box);
  EXPECT_EQ(r.triangles, 10u);
  EXPECT_EQ(r.boundary_edges, 4u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.non_manifold_vertices, 0u);  // the rim vertices are half-disks
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.closed_components, 0u);
  EXPECT_EQ(r.genus, -1);
  EXPECT_EQ(r.volume, 0.0);  // only closed parts contribute
  EXPECT_NEAR(r.area, 5.0, 1e-12);
}

TEST(TopologyTest, TwoDisjointCubesAreTwoComponents) {
  Mesh mesh;
  AddCube(mesh, 0, 0, 0);
  AddCube(mesh, 3, 0, 0);
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.components_by_vertex, 2u);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.genus, 0);
  EXPECT_NEAR(r.volume, 2.0, 1e-12);
  EXPECT_EQ(r.bbox_max[0], 4.0f);
}

TEST(TopologyTest, VolumeCountsOnlyClosedComponents) {
  Mesh mesh;
  AddCube(mesh, 0, 0, 0, 2);
  AddCube(mesh, 5, 0, 0, 1, 5);  // open box: no volume
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.closed_components, 1u);
  EXPECT_NEAR(r.volume, 8.0, 1e-12);
  EXPECT_EQ(r.genus, -1);
}

TEST(TopologyTest, BowTieHasOneNonManifoldVertex) {
  Mesh mesh;
  const uint32_t shared = AddVertex(mesh, 0, 0, 0);
  AddTriangle(mesh, shared, AddVertex(mesh, 1, 0, 0), AddVertex(mesh, 1, 1, 0));
  AddTriangle(mesh, shared, AddVertex(mesh, -1, 0, 0), AddVertex(mesh, -1, -1, 0));
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.boundary_edges, 6u);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.components_by_vertex, 1u);
}

TEST(TopologyTest, CubesTouchingAtACornerAreClosedButNotManifold) {
  Mesh mesh;
  AddCube(mesh, 0, 0, 0);
  AddCube(mesh, 1, 1, 1);  // shares the point (1, 1, 1), as a separate vertex index
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.components_by_vertex, 1u);
  EXPECT_EQ(r.closed_components, 2u);
  EXPECT_EQ(r.closed_manifold_components, 0u);
  EXPECT_EQ(r.genus, -1);
  EXPECT_NEAR(r.volume, 2.0, 1e-12);
}

TEST(TopologyTest, ThreeTrianglesOnOneEdgeMakeANonManifoldEdge) {
  Mesh mesh;
  const uint32_t a = AddVertex(mesh, 0, 0, 0);
  const uint32_t b = AddVertex(mesh, 1, 0, 0);
  AddTriangle(mesh, a, b, AddVertex(mesh, 0.5f, 1, 0));
  AddTriangle(mesh, b, a, AddVertex(mesh, 0.5f, -1, 0));
  AddTriangle(mesh, b, a, AddVertex(mesh, 0.5f, 0, 1));
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_EQ(r.edges, 7u);
  EXPECT_EQ(r.non_manifold_edges, 1u);
  EXPECT_EQ(r.boundary_edges, 6u);
  EXPECT_EQ(r.non_manifold_vertices, 2u);  // both ends of the fin edge
  EXPECT_EQ(r.components, 1u);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.inconsistent_edges, 0u);  // only two-triangle edges are judged
}

TEST(TopologyTest, CubeWithOneFlippedFaceIsInconsistent) {
  Mesh cube = UnitCube();
  // Face 0 is triangles 0 and 1; reversing both keeps their shared diagonal consistent and
  // breaks the four edges around the face.
  for (size_t t = 0; t < 2; ++t) std::swap(cube.indices[3 * t + 1], cube.indices[3 * t + 2]);
  const TopologyReport r = AnalyzeTopology(cube);
  EXPECT_EQ(r.inconsistent_edges, 4u);
  EXPECT_FALSE(r.consistently_oriented);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.genus, 0);
  // Taken about the centre, each face adds 1/6; the flipped one subtracts it instead.
  EXPECT_NEAR(r.volume, 4.0 / 6.0, 1e-12);
}

TEST(TopologyTest, SplitCubeIsClosedByPositionButNotByIndex) {
  const Mesh cube = SplitCube();
  const TopologyReport welded = AnalyzeTopology(cube);
  EXPECT_EQ(welded.vertices, 24u);
  EXPECT_EQ(welded.unique_positions, 8u);
  EXPECT_TRUE(welded.closed);
  EXPECT_TRUE(welded.consistently_oriented);
  EXPECT_EQ(welded.components, 1u);
  EXPECT_EQ(welded.genus, 0);
  EXPECT_NEAR(welded.volume, 1.0, 1e-12);

  const TopologyReport by_index = AnalyzeTopology(cube, {Connectivity::kVertexIndices});
  EXPECT_FALSE(by_index.closed);
  EXPECT_EQ(by_index.boundary_edges, 24u);
  EXPECT_EQ(by_index.components, 6u);
  EXPECT_EQ(by_index.unique_positions, 8u);
  EXPECT_EQ(by_index.genus, -1);
}

TEST(TopologyTest, NegativeZeroIsTheSamePointAsZero) {
  Mesh mesh;
  AddTriangle(mesh, AddVertex(mesh, 0, 0, 0), AddVertex(mesh, 1, 0, 0), AddVertex(mesh, 0, 1, 0));
  AddTriangle(mesh, AddVertex(mesh, -0.0f, 0, 0), AddVertex(mesh, 0, -1, 0),
              AddVertex(mesh, 1, 0, 0));
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_EQ(r.unique_positions, 4u);
  EXPECT_EQ(r.edges, 5u);
  EXPECT_EQ(r.boundary_edges, 4u);
}

TEST(TopologyTest, CountsDegenerateDuplicateAndOppositeTriangles) {
  Mesh mesh = UnitCube();
  AddTriangle(mesh, 0, 0, 1);                                            // degenerate by index
  AddTriangle(mesh, AddVertex(mesh, 0, 0, 0), 0, 7);                     // degenerate by position
  AddTriangle(mesh, mesh.indices[1], mesh.indices[2], mesh.indices[0]);  // triangle 0, rotated
  AddTriangle(mesh, mesh.indices[3], mesh.indices[5], mesh.indices[4]);  // triangle 1, flipped
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_EQ(r.triangles, 16u);
  EXPECT_EQ(r.degenerate_triangles, 2u);
  EXPECT_EQ(r.duplicate_triangles, 1u);
  EXPECT_EQ(r.opposite_triangle_pairs, 1u);
  EXPECT_EQ(r.referenced_vertices, 9u);
  EXPECT_EQ(r.unique_positions, 8u);
  // Every side of triangles 0 and 1 (five edges, the diagonal shared) now has 3+ users.
  EXPECT_EQ(r.non_manifold_edges, 5u);
  EXPECT_FALSE(r.closed);
}

TEST(TopologyTest, UnreferencedVerticesStayOutOfBoundsAndCounts) {
  Mesh mesh = UnitCube();
  AddVertex(mesh, 100, 100, 100);
  const TopologyReport r = AnalyzeTopology(mesh);
  EXPECT_EQ(r.vertices, 9u);
  EXPECT_EQ(r.referenced_vertices, 8u);
  EXPECT_EQ(r.bbox_max, (std::array<float, 3>{1, 1, 1}));
  EXPECT_TRUE(r.closed);
}

TEST(TopologyTest, EmptyMeshIsNotClosed) {
  const TopologyReport r = AnalyzeTopology(Mesh{});
  EXPECT_EQ(r.triangles, 0u);
  EXPECT_EQ(r.components, 0u);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.genus, -1);
  EXPECT_EQ(r.area, 0.0);
}

}  // namespace
}  // namespace hullpack
