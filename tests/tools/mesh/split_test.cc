#include "mesh/split.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "test_meshes.h"

namespace hullpack {
namespace {

// The triangles of `m` as their corners' positions, with their material id.
std::multiset<std::array<float, 10>> TriangleSet(const Mesh& m) {
  std::multiset<std::array<float, 10>> out;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    std::array<float, 10> key{};
    for (int k = 0; k < 3; ++k) {
      for (int a = 0; a < 3; ++a) key[3 * k + a] = m.positions[3 * m.indices[3 * t + k] + a];
    }
    key[9] = m.material_ids.empty() ? -1.0f : static_cast<float>(m.material_ids[t]);
    out.insert(key);
  }
  return out;
}

Mesh Tori() {
  Mesh mesh;
  testing_meshes::AddTorus(mesh, 0, 2, 0.5f, 48, 24);
  testing_meshes::AddTorus(mesh, 6, 2, 0.5f, 24, 12);
  mesh.normals.assign(mesh.positions.size(), 0.5f);
  mesh.uv_sets.push_back(std::vector<float>(2 * mesh.vertex_count()));
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    mesh.uv_sets[0][2 * v] = mesh.positions[3 * v];
    mesh.uv_sets[0][2 * v + 1] = mesh.positions[3 * v + 1];
  }
  for (size_t t = 0; t < mesh.triangle_count(); ++t) mesh.material_ids.push_back(t % 3);
  return mesh;
}

std::vector<Mesh> Parts(const Mesh& mesh, size_t max_triangles) {
  std::vector<Mesh> parts;
  const TriangleParts split = SplitTriangles(mesh, max_triangles);
  for (size_t p = 0; p < split.count(); ++p)
    parts.push_back(MeshPart(mesh, split.Triangles(p, mesh.triangle_count())));
  return parts;
}

TEST(SplitTriangles, PartsHoldEveryTriangleOnceWithItsAttributes) {
  const Mesh mesh = Tori();
  const std::vector<Mesh> parts = Parts(mesh, 500);
  ASSERT_GE(parts.size(), 5u);
  std::multiset<std::array<float, 10>> all;
  size_t vertices = 0;
  for (const Mesh& p : parts) {
    EXPECT_LE(p.triangle_count(), 500u);
    EXPECT_GE(p.triangle_count(), 250u);
    EXPECT_EQ(p.name, mesh.name);
    ASSERT_EQ(p.normals.size(), p.positions.size());
    ASSERT_EQ(p.uv_sets.size(), 1u);
    ASSERT_EQ(p.material_ids.size(), p.triangle_count());
    for (size_t v = 0; v < p.vertex_count(); ++v) {
      // The attributes stay with their vertex (here the UV is the position's x and y).
      EXPECT_EQ(p.uv_sets[0][2 * v], p.positions[3 * v]);
      EXPECT_EQ(p.uv_sets[0][2 * v + 1], p.positions[3 * v + 1]);
    }
    for (uint32_t i : p.indices) EXPECT_LT(i, p.vertex_count());
    vertices += p.vertex_count();
    const auto set = TriangleSet(p);
    all.insert(set.begin(), set.end());
  }
  EXPECT_EQ(all, TriangleSet(mesh));
  // Compact parts: the vertices copied into several parts are few.
  EXPECT_LT(vertices, mesh.vertex_count() * 13 / 10);
  // The same parts every time.
  const std::vector<Mesh> again = Parts(mesh, 500);
  ASSERT_EQ(again.size(), parts.size());
  for (size_t i = 0; i < parts.size(); ++i) {
    EXPECT_EQ(again[i].positions, parts[i].positions);
    EXPECT_EQ(again[i].indices, parts[i].indices);
  }
}

// Over 256 parts the part of a triangle takes four bytes instead of one: the same split either way.
TEST(SplitTriangles, ManyPartsHoldEveryTriangleOnceInAscendingOrder) {
  const Mesh mesh = Tori();
  const size_t n = mesh.triangle_count();
  for (size_t max_triangles : {n / 200, size_t{4}}) {
    const TriangleParts split = SplitTriangles(mesh, max_triangles);
    EXPECT_EQ(split.count(), (n + max_triangles - 1) / max_triangles);
    std::vector<int> seen(n, 0);
    for (size_t p = 0; p < split.count(); ++p) {
      const std::vector<uint32_t> triangles = split.Triangles(p, n);
      EXPECT_GE(triangles.size(), 1u);
      EXPECT_LE(triangles.size(), max_triangles);
      EXPECT_TRUE(std::is_sorted(triangles.begin(), triangles.end()));
      for (uint32_t t : triangles) {
        ++seen[t];
        EXPECT_EQ(split.Of(t), p);
      }
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(n));
  }
  EXPECT_GT(SplitTriangles(mesh, 4).count(), 256u);
  EXPECT_LE(SplitTriangles(mesh, n / 200).count(), 256u);
}

TEST(SplitTriangles, SmallSkinnedAndMorphedMeshesStayWhole) {
  Mesh mesh = Tori();
  EXPECT_EQ(SplitTriangles(mesh, mesh.triangle_count()).count(), 1u);
  EXPECT_EQ(Parts(mesh, mesh.triangle_count()).front().indices, mesh.indices);
  Mesh skinned = mesh;
  skinned.joints.assign(4 * mesh.vertex_count(), 0);
  skinned.weights.assign(4 * mesh.vertex_count(), 0.25f);
  EXPECT_FALSE(CanSplitMesh(skinned));
  EXPECT_EQ(SplitTriangles(skinned, 100).count(), 1u);
  Mesh morphed = mesh;
  morphed.morph_targets.resize(1);
  morphed.morph_targets[0].positions.assign(mesh.positions.size(), 0.0f);
  EXPECT_FALSE(CanSplitMesh(morphed));
  EXPECT_EQ(SplitTriangles(morphed, 100).count(), 1u);
}

TEST(PositionBox, HoldsEveryPosition) {
  const Mesh mesh = Tori();
  const std::array<float, 6> box = PositionBox(mesh);
  EXPECT_FLOAT_EQ(box[0], -2.5f);
  EXPECT_FLOAT_EQ(box[3], 8.5f);
  EXPECT_EQ(PositionBox(Mesh()), (std::array<float, 6>{0, 0, 0, 0, 0, 0}));
}

// Past 16 parts ForEachPart groups the triangles once instead of a pass per part: the same parts.
TEST(ForEachPart, ManyPartsAreTheSplitsParts) {
  const Mesh mesh = Tori();
  const TriangleParts split = SplitTriangles(mesh, 64);
  ASSERT_GT(split.count(), 16u);
  size_t visited = 0;
  const Status status = ForEachPart(mesh, {}, 64, [&](const PartToCode& part) {
    EXPECT_EQ(part.index, visited++);
    EXPECT_EQ(part.mesh.indices,
              MeshPart(mesh, split.Triangles(part.index, mesh.triangle_count())).indices);
    return Status::Ok();
  });
  EXPECT_TRUE(status.ok());
  EXPECT_EQ(visited, split.count());
}

TEST(ForEachPart, VisitsTheSplitPartsWithTheirGroupsOnTheWholeBox) {
  const Mesh mesh = Tori();
  std::vector<uint32_t> groups(mesh.triangle_count());
  for (size_t t = 0; t < groups.size(); ++t) groups[t] = static_cast<uint32_t>(t * 7 % 5);
  const TriangleParts split = SplitTriangles(mesh, 500);
  ASSERT_GT(split.count(), 2u);
  size_t visited = 0;
  const Status status = ForEachPart(mesh, groups, 500, [&](const PartToCode& part) {
    EXPECT_EQ(part.index, visited);
    EXPECT_EQ(part.count, split.count());
    const std::vector<uint32_t> triangles = split.Triangles(part.index, mesh.triangle_count());
    EXPECT_EQ(TriangleSet(part.mesh), TriangleSet(MeshPart(mesh, triangles)));
    EXPECT_EQ(part.groups.size(), triangles.size());
    for (size_t i = 0; i < part.groups.size(); ++i) EXPECT_EQ(part.groups[i], groups[triangles[i]]);
    EXPECT_EQ(part.box, PositionBox(mesh));
    ++visited;
    return Status::Ok();
  });
  EXPECT_TRUE(status.ok());
  EXPECT_EQ(visited, split.count());
}

TEST(ForEachPart, AWholeMeshIsVisitedOnceAsItIs) {
  const Mesh mesh = Tori();
  for (size_t max_triangles : {size_t{0}, mesh.triangle_count()}) {
    int visits = 0;
    const Status status = ForEachPart(mesh, {}, max_triangles, [&](const PartToCode& part) {
      EXPECT_EQ(&part.mesh, &mesh);
      EXPECT_TRUE(part.groups.empty());
      EXPECT_FALSE(part.box.has_value());
      ++visits;
      return Status::Ok();
    });
    EXPECT_TRUE(status.ok());
    EXPECT_EQ(visits, 1);
  }
}

TEST(ForEachPart, StopsAtTheFirstError) {
  int visits = 0;
  const Status status = ForEachPart(Tori(), {}, 500, [&](const PartToCode&) {
    ++visits;
    return Status(StatusCode::kInvalidMesh, "part refused");
  });
  EXPECT_EQ(status.code(), StatusCode::kInvalidMesh);
  EXPECT_EQ(visits, 1);
}

}  // namespace
}  // namespace hullpack
