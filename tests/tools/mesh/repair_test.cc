#include "mesh/repair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mesh/topology.h"
#include "mesh/validate.h"
#include "test_meshes.h"

namespace hullpack {
namespace {

using namespace testing_meshes;

TEST(RepairTest, CleanMeshIsUntouched) {
  Mesh cube = UnitCube();
  const Mesh before = cube;
  const RepairReport r = RepairMesh(cube);
  EXPECT_FALSE(r.changed());
  EXPECT_EQ(cube.positions, before.positions);
  EXPECT_EQ(cube.indices, before.indices);
  EXPECT_EQ(DescribeRepairs(r), "no repairs needed");
}

TEST(RepairTest, WeldsSplitCubeIntoEightVertices) {
  Mesh cube = SplitCube();
  const RepairReport r = RepairMesh(cube);
  EXPECT_EQ(r.welded_vertices, 16u);
  EXPECT_EQ(cube.vertex_count(), 8u);
  EXPECT_EQ(cube.triangle_count(), 12u);
  ASSERT_TRUE(ValidateMesh(cube).ok());
  // Now closed by index as well as by position, with the shape unchanged.
  const TopologyReport t = AnalyzeTopology(cube, {Connectivity::kVertexIndices});
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.genus, 0);
  EXPECT_NEAR(t.volume, 1.0, 1e-12);
}

TEST(RepairTest, WeldKeepsNormalSeams) {
  Mesh cube = SplitCube();
  // One flat normal per face: corners of different faces differ, corners of one face do not
  // (but they are at different positions).
  for (size_t face = 0; face < 6; ++face) {
    for (int k = 0; k < 4; ++k) cube.normals.insert(cube.normals.end(), {float(face), 0, 0});
  }
  const RepairReport r = RepairMesh(cube);
  EXPECT_EQ(r.welded_vertices, 0u);
  EXPECT_EQ(cube.vertex_count(), 24u);
}

TEST(RepairTest, WeldComparesEveryAttributeAndCompactsThemAll) {
  Mesh mesh;
  // Vertices 0..3; 4 duplicates 0 in every attribute, 5 duplicates 1 except for its UV.
  for (int v = 0; v < 6; ++v) {
    const int same = v == 4 ? 0 : (v == 5 ? 1 : v);
    AddVertex(mesh, float(same), float(same * same), 0);
    mesh.normals.insert(mesh.normals.end(), {0, 0, 1});
    mesh.tangents.insert(mesh.tangents.end(), {1, 0, 0, 1});
    mesh.colors.insert(mesh.colors.end(), {float(same) / 4, 0, 0, 1});
    mesh.joints.insert(mesh.joints.end(), {uint16_t(same), 0, 0, 0});
    mesh.weights.insert(mesh.weights.end(), {1, 0, 0, 0});
  }
  mesh.uv_sets = {{0, 0, 1, 0, 2, 0, 3, 0, 0, 0, 9, 9}};
  AddTriangle(mesh, 0, 1, 2);
  AddTriangle(mesh, 4, 2, 3);  // becomes 0, 2, 3
  AddTriangle(mesh, 5, 3, 2);  // keeps its own vertex: different UV
  mesh.material_ids = {7, 8, 9};
  ASSERT_TRUE(ValidateMesh(mesh).ok());

  const RepairReport r = RepairMesh(mesh);
  EXPECT_EQ(r.welded_vertices, 1u);
  ASSERT_TRUE(ValidateMesh(mesh).ok());
  ASSERT_EQ(mesh.vertex_count(), 5u);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 4, 3, 2}));
  EXPECT_EQ(mesh.material_ids, (std::vector<uint32_t>{7, 8, 9}));
  // The former vertex 5 is now vertex 4, with all of its own attributes.
  EXPECT_EQ(mesh.positions[3 * 4], 1.0f);
  EXPECT_EQ(mesh.uv_sets[0][2 * 4], 9.0f);
  EXPECT_EQ(mesh.joints[4 * 4], 1u);
  EXPECT_EQ(mesh.colors[4 * 4], 0.25f);
  EXPECT_EQ(mesh.colors[4 * 3], 0.75f);
  EXPECT_EQ(mesh.tangents.size(), 4u * 5);
  EXPECT_EQ(mesh.weights.size(), 4u * 5);
}

TEST(RepairTest, WeldComparesMorphTargetOffsetsAndCompactsThem) {
  Mesh mesh;
  // Vertex 3 duplicates 0 in everything; vertex 4 duplicates 1 but moves otherwise when morphed.
  const int same[] = {0, 1, 2, 0, 1};
  MorphTarget t;
  for (int v = 0; v < 5; ++v) {
    AddVertex(mesh, float(same[v]), float(same[v] * same[v]), 0);
    mesh.normals.insert(mesh.normals.end(), {0, 0, 1});
    t.positions.insert(t.positions.end(), {0, 0, v == 4 ? 2.0f : float(same[v])});
    t.normals.insert(t.normals.end(), {0, 0, 0});
  }
  mesh.morph_targets = {t};
  mesh.morph_weights = {0.5f};
  AddTriangle(mesh, 0, 1, 2);
  AddTriangle(mesh, 3, 2, 4);
  ASSERT_TRUE(ValidateMesh(mesh).ok());
  const RepairReport r = RepairMesh(mesh);
  EXPECT_EQ(r.welded_vertices, 1u);
  ASSERT_TRUE(ValidateMesh(mesh).ok());
  ASSERT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(mesh.morph_targets[0].positions.size(), 12u);
  EXPECT_EQ(mesh.morph_targets[0].positions[3 * 3 + 2], 2.0f);  // the former vertex 4
  EXPECT_EQ(mesh.morph_targets[0].normals.size(), 12u);
}

TEST(RepairTest, WeldingCanMakeTrianglesDegenerate) {
  Mesh mesh = UnitCube();
  const uint32_t copy_of_0 = AddVertex(mesh, 0, 0, 0);
  AddTriangle(mesh, 0, copy_of_0, 7);
  AddTriangle(mesh, 1, 1, 2);
  mesh.material_ids.assign(12, 1);
  mesh.material_ids.insert(mesh.material_ids.end(), {2, 3});

  const RepairReport r = RepairMesh(mesh);
  EXPECT_EQ(r.welded_vertices, 1u);
  EXPECT_EQ(r.degenerate_triangles_removed, 2u);
  EXPECT_EQ(mesh.triangle_count(), 12u);
  EXPECT_EQ(mesh.material_ids, std::vector<uint32_t>(12, 1));
  EXPECT_EQ(DescribeRepairs(r), "welded 1 duplicate vertex, removed 2 degenerate triangles");
}

TEST(RepairTest, ZeroAreaTrianglesOnlyWhenAsked) {
  Mesh mesh = UnitCube();
  AddTriangle(mesh, 0, 1, AddVertex(mesh, 2, 0, 0));  // collinear along x
  Mesh copy = mesh;

  RepairReport r = RepairMesh(mesh);
  EXPECT_EQ(r.zero_area_triangles_removed, 0u);
  EXPECT_EQ(mesh.triangle_count(), 13u);

  RepairOptions options;
  options.remove_zero_area_triangles = true;
  r = RepairMesh(copy, options);
  EXPECT_EQ(r.zero_area_triangles_removed, 1u);
  EXPECT_EQ(r.unused_vertices_removed, 1u);
  EXPECT_EQ(copy.triangle_count(), 12u);
  EXPECT_EQ(copy.vertex_count(), 8u);
}

TEST(RepairTest, RemovesSameWindingCopiesKeepsTwoSidedFaces) {
  Mesh mesh = UnitCube();
  AddTriangle(mesh, mesh.indices[1], mesh.indices[2], mesh.indices[0]);  // triangle 0 rotated
  AddTriangle(mesh, mesh.indices[0], mesh.indices[1], mesh.indices[2]);  // triangle 0 again
  AddTriangle(mesh, mesh.indices[3], mesh.indices[5], mesh.indices[4]);  // triangle 1 flipped
  const std::vector<uint32_t> original(mesh.indices.begin(), mesh.indices.begin() + 36);
  Mesh copy = mesh;

  RepairReport r = RepairMesh(mesh);
  EXPECT_EQ(r.duplicate_triangles_removed, 2u);
  EXPECT_EQ(r.opposite_triangle_pairs, 1u);
  EXPECT_EQ(r.opposite_triangles_removed, 0u);
  ASSERT_EQ(mesh.triangle_count(), 13u);
  EXPECT_TRUE(std::equal(original.begin(), original.end(), mesh.indices.begin()));
  EXPECT_EQ(DescribeRepairs(r), "removed 2 duplicate triangles, kept 1 two-sided face");

  RepairOptions options;
  options.remove_opposite_duplicates = true;
  r = RepairMesh(copy, options);
  EXPECT_EQ(r.duplicate_triangles_removed, 2u);
  EXPECT_EQ(r.opposite_triangles_removed, 1u);
  EXPECT_EQ(copy.indices, original);
  EXPECT_TRUE(AnalyzeTopology(copy).closed);
}

TEST(RepairTest, CountsTwoSidedFacesAfterRemovingCopies) {
  Mesh mesh;
  const uint32_t a = AddVertex(mesh, 0, 0, 0), b = AddVertex(mesh, 1, 0, 0),
                 c = AddVertex(mesh, 0, 1, 0);
  for (int copy = 0; copy < 2; ++copy) {
    AddTriangle(mesh, a, b, c);
    AddTriangle(mesh, a, c, b);
  }
  const RepairReport r = RepairMesh(mesh);
  EXPECT_EQ(r.duplicate_triangles_removed, 2u);
  EXPECT_EQ(r.opposite_triangle_pairs, 1u);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{a, b, c, a, c, b}));
  EXPECT_EQ(AnalyzeTopology(mesh).opposite_triangle_pairs, r.opposite_triangle_pairs);
}

// Copies are found among the triangles that share their smallest vertex: many share the apex of a
// fan, and a copy may list its corners in any rotation.
TEST(RepairTest, FindsCopiesAmongTheManyTrianglesOfAFanApex) {
  Mesh mesh;
  const uint32_t apex = AddVertex(mesh, 0, 0, 0);
  constexpr int kRing = 40;
  for (int i = 0; i < kRing; ++i) {
    const double angle = 2 * 3.141592653589793 * i / kRing;
    AddVertex(mesh, static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)), 0);
  }
  for (uint32_t i = 1; i <= kRing; ++i) AddTriangle(mesh, apex, i, i % kRing + 1);
  const std::vector<uint32_t> fan = mesh.indices;
  AddTriangle(mesh, 8, apex, 7);    // triangle 6, rotated
  AddTriangle(mesh, 31, 32, apex);  // triangle 30, rotated
  AddTriangle(mesh, apex, 8, 7);    // triangle 6, flipped
  AddTriangle(mesh, 20, apex, 21);  // triangle 19, flipped
  AddTriangle(mesh, 21, 20, apex);  // triangle 19 (a later copy of the same winding)
  Mesh copy = mesh;

  RepairReport r = RepairMesh(mesh);
  EXPECT_EQ(r.duplicate_triangles_removed, 3u);
  EXPECT_EQ(r.opposite_triangle_pairs, 2u);
  std::vector<uint32_t> expected = fan;
  expected.insert(expected.end(), {apex, 8, 7, 20, apex, 21});
  EXPECT_EQ(mesh.indices, expected);

  RepairOptions options;
  options.remove_opposite_duplicates = true;
  r = RepairMesh(copy, options);
  EXPECT_EQ(r.duplicate_triangles_removed, 3u);
  EXPECT_EQ(r.opposite_triangles_removed, 2u);
  EXPECT_EQ(copy.indices, fan);
}

TEST(RepairTest, OppositeRemovalLeavesSameWindingCopiesWhenTheyAreKept) {
  Mesh mesh;
  const uint32_t a = AddVertex(mesh, 0, 0, 0), b = AddVertex(mesh, 1, 0, 0),
                 c = AddVertex(mesh, 0, 1, 0);
  AddTriangle(mesh, a, b, c);
  AddTriangle(mesh, a, b, c);
  AddTriangle(mesh, a, c, b);
  RepairOptions options;
  options.remove_duplicate_triangles = false;
  options.remove_opposite_duplicates = true;
  const RepairReport r = RepairMesh(mesh, options);
  EXPECT_EQ(r.duplicate_triangles_removed, 0u);
  EXPECT_EQ(r.opposite_triangles_removed, 1u);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{a, b, c, a, b, c}));
}

TEST(RepairTest, RemovesUnusedVerticesAndRemaps) {
  Mesh mesh;
  AddVertex(mesh, 9, 9, 9);  // unused
  const uint32_t a = AddVertex(mesh, 0, 0, 0);
  AddVertex(mesh, 8, 8, 8);  // unused
  const uint32_t b = AddVertex(mesh, 1, 0, 0), c = AddVertex(mesh, 0, 1, 0);
  AddTriangle(mesh, a, b, c);
  mesh.uv_sets = {{0, 0, 0.1f, 0, 0, 0, 0.3f, 0, 0.4f, 0}};
  Mesh kept = mesh;

  const RepairReport r = RepairMesh(mesh);
  EXPECT_EQ(r.unused_vertices_removed, 2u);
  EXPECT_EQ(mesh.positions, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(mesh.uv_sets[0], (std::vector<float>{0.1f, 0, 0.3f, 0, 0.4f, 0}));
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(DescribeRepairs(r), "removed 2 unused vertices");

  RepairOptions options;
  options.remove_unused_vertices = false;
  EXPECT_FALSE(RepairMesh(kept, options).changed());
  EXPECT_EQ(kept.vertex_count(), 5u);
}

TEST(RepairTest, OptionsTurnRepairsOff) {
  Mesh mesh = SplitCube();
  AddTriangle(mesh, 0, 0, 1);
  RepairOptions off;
  off.weld_duplicate_vertices = false;
  off.remove_degenerate_triangles = false;
  off.remove_duplicate_triangles = false;
  off.remove_unused_vertices = false;
  EXPECT_FALSE(RepairMesh(mesh, off).changed());
  EXPECT_EQ(mesh.vertex_count(), 24u);
  EXPECT_EQ(mesh.triangle_count(), 13u);
}

TEST(RepairTest, EmptyMesh) {
  Mesh mesh;
  EXPECT_FALSE(RepairMesh(mesh).changed());
}

}  // namespace
}  // namespace hullpack

namespace hullpack {
namespace {

// The sorts and the degenerate-triangle pass run on several threads for large meshes: the
// repaired mesh and the counts are the same.
TEST(RepairMesh, TheResultDoesNotDependOnTheThreadCount) {
  constexpr uint32_t n = 70000;
  Mesh m;
  for (uint32_t i = 0; i < n; ++i) {
    // Positions repeat every 1000 vertices (welds); a few triangles repeat (duplicates).
    const float x = static_cast<float>(i % 1000);
    m.positions.insert(m.positions.end(), {x, x * 0.5f + static_cast<float>(i % 1000 % 7),
                                           static_cast<float>(i % 1000 % 13)});
  }
  // Three distinct collinear points for zero-area triangles.
  m.positions.insert(m.positions.end(), {2000, 2000, 2000, 2001, 2001, 2001, 2002, 2002, 2002});
  for (uint32_t t = 0; t + 2 < n; ++t) {
    const uint32_t a = (t * 7919u) % n, b = (t * 104729u + 1) % n, c = (t + 5) % n;
    m.indices.insert(m.indices.end(), {a, b, c});
    if (t % 97 == 0) m.indices.insert(m.indices.end(), {b, c, a});
    if (t % 101 == 0) m.indices.insert(m.indices.end(), {a, a, c});
    if (t % 103 == 0) m.indices.insert(m.indices.end(), {n, n + 1 + t % 2, n + 2 - t % 2});
  }
  Mesh one = m, many = m;
  RepairOptions single, threaded;
  single.remove_zero_area_triangles = threaded.remove_zero_area_triangles = true;
  threaded.threads = 3;
  const RepairReport r1 = RepairMesh(one, single);
  const RepairReport r3 = RepairMesh(many, threaded);
  EXPECT_GT(r1.welded_vertices, 0u);
  EXPECT_GT(r1.duplicate_triangles_removed, 0u);
  EXPECT_GT(r1.degenerate_triangles_removed, 0u);
  EXPECT_GT(r1.zero_area_triangles_removed, 0u);
  EXPECT_EQ(r1.welded_vertices, r3.welded_vertices);
  EXPECT_EQ(r1.duplicate_triangles_removed, r3.duplicate_triangles_removed);
  EXPECT_EQ(r1.degenerate_triangles_removed, r3.degenerate_triangles_removed);
  EXPECT_EQ(r1.zero_area_triangles_removed, r3.zero_area_triangles_removed);
  EXPECT_EQ(one.positions, many.positions);
  EXPECT_EQ(one.indices, many.indices);
}

}  // namespace
}  // namespace hullpack
