#include "pipeline/collision.h"

#include <gtest/gtest.h>

#include "mesh/topology.h"

namespace hullpack {
namespace {

// An L-shaped block: two boxes [0,2]x[0,1]x[0,1] and [0,1]x[1,2]x[0,1] fused, as one closed mesh.
Mesh LBlock() {
  Mesh m;
  m.name = "lblock";
  // Profile in the xy plane (counter-clockwise), extruded along z.
  const float profile[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (float z : {0.0f, 1.0f}) {
    for (const auto& p : profile) m.positions.insert(m.positions.end(), {p[0], p[1], z});
  }
  // Bottom (z=0, facing -z) and top (z=1, facing +z), fan-triangulated from the inner corner 3.
  const uint32_t fan[4][3] = {{3, 0, 1}, {3, 1, 2}, {3, 4, 5}, {3, 5, 0}};
  for (const auto& t : fan) {
    m.indices.insert(m.indices.end(), {t[0], t[2], t[1]});
    m.indices.insert(m.indices.end(), {t[0] + 6, t[1] + 6, t[2] + 6});
  }
  for (uint32_t i = 0; i < 6; ++i) {
    const uint32_t j = (i + 1) % 6;
    m.indices.insert(m.indices.end(), {i, j, j + 6, i, j + 6, i + 6});
  }
  return m;
}

TEST(Collision, LBlockGivesClosedConvexHullsInMeshCoordinates) {
  const Mesh mesh = LBlock();
  ASSERT_TRUE(AnalyzeTopology(mesh).closed);
  vhacd::Parameters p;
  p.resolution = 20000;
  Result<HullSet> set = DecomposeMesh(mesh, p, nullptr);
  ASSERT_TRUE(set.ok()) << set.status().ToString();
  ASSERT_GE(set->hulls.size(), 2u);
  for (const Mesh& hull : set->hulls) {
    const TopologyReport t = AnalyzeTopology(hull);
    EXPECT_TRUE(t.closed);
    EXPECT_GT(t.volume, 0);
    for (float c : hull.positions) {
      EXPECT_GE(c, -1e-3f);
      EXPECT_LE(c, 2.001f);
    }
  }
  EXPECT_GT(set->report.volume_iou, 0.9);
}

TEST(Collision, HacdMethodGivesClosedConvexHullsInMeshCoordinates) {
  const Mesh mesh = LBlock();
  CollisionSettings settings;
  settings.method = DecompositionMethod::kHacd;
  EXPECT_EQ(settings.hacd_parameters.min_clusters, 2u);  // the recommended line
  EXPECT_EQ(settings.hacd_parameters.max_vertices_per_hull, 24u);
  Result<HullSet> set = DecomposeMesh(mesh, settings, nullptr);
  ASSERT_TRUE(set.ok()) << set.status().ToString();
  ASSERT_GE(set->hulls.size(), 2u);
  for (const Mesh& hull : set->hulls) {
    const TopologyReport t = AnalyzeTopology(hull);
    EXPECT_TRUE(t.closed);
    EXPECT_GT(t.volume, 0);
    EXPECT_LE(hull.vertex_count(), 24u);
    for (float c : hull.positions) {
      EXPECT_GE(c, -1e-3f);
      EXPECT_LE(c, 2.001f);
    }
  }
  EXPECT_GE(set->report.volume_iou, 0.9);
  settings.hacd_parameters.concavity = -1;
  EXPECT_FALSE(DecomposeMesh(mesh, settings, nullptr).ok());
}

TEST(Collision, PolicyDecidesWhichMeshesGetHulls) {
  Mesh m = LBlock();
  CollisionSettings s;
  EXPECT_EQ(WhyNoHulls(m, s), "");
  s.policy = HullPolicy::kNone;
  EXPECT_NE(WhyNoHulls(m, s), "");
  s.policy = HullPolicy::kAuto;
  m.name = "Tree_Leaves-NoCol";
  EXPECT_NE(WhyNoHulls(m, s), "");
  m.name = "crate";
  m.collides = false;
  EXPECT_NE(WhyNoHulls(m, s), "");
  m.collides = true;
  m.joints.assign(m.vertex_count() * 4, 0);
  m.weights.assign(m.vertex_count() * 4, 0.25f);
  EXPECT_NE(WhyNoHulls(m, s), "");
  s.skinned_meshes = true;
  EXPECT_EQ(WhyNoHulls(m, s), "");
  s.policy = HullPolicy::kAll;
  m.name = "decal_nocol";
  EXPECT_EQ(WhyNoHulls(m, s), "");
}

TEST(Collision, ErrorsAreStatuses) {
  Mesh empty;
  empty.name = "empty";
  Result<HullSet> r = DecomposeMesh(empty, vhacd::Parameters(), nullptr);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("empty"), std::string::npos);
}

}  // namespace
}  // namespace hullpack
