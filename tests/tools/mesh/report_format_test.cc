#include "mesh/report_format.h"

#include <gtest/gtest.h>

#include <limits>

#include "test_meshes.h"

namespace hullpack {
namespace {

using namespace testing_meshes;

TEST(ReportFormatTest, CubeLines) {
  const std::vector<std::string> lines = FormatTopologyReport(AnalyzeTopology(UnitCube()));
  const std::vector<std::string> expected = {
      "triangles: 12 (0 degenerate, 0 duplicate, 0 opposite-winding pairs)",
      "vertices: 8 (8 referenced, 8 unique positions)",
      "edges: 18 (0 boundary, 0 non-manifold)",
      "non-manifold vertices: 0",
      "orientation: consistent",
      "components: 1 by edge, 1 by vertex (1 closed, 1 closed manifold)",
      "closed: yes, genus 0",
      "area: 6",
      "volume: 1 (closed components only)",
      "bounds: (0, 0, 0) to (1, 1, 1)",
  };
  EXPECT_EQ(lines, expected);
}

TEST(ReportFormatTest, OpenInconsistentMeshLines) {
  Mesh box;
  AddCube(box, 0, 0, 0, 0.1f, 5);
  std::swap(box.indices[1], box.indices[2]);
  const std::vector<std::string> lines = FormatTopologyReport(AnalyzeTopology(box));
  ASSERT_EQ(lines.size(), 10u);
  EXPECT_EQ(lines[2], "edges: 17 (4 boundary, 0 non-manifold)");
  EXPECT_EQ(lines[4], "orientation: inconsistent (3 edges)");
  EXPECT_EQ(lines[6], "closed: no, genus unknown (not a closed manifold)");
  EXPECT_EQ(lines[8], "volume: 0 (no closed component)");
  EXPECT_EQ(lines[9], "bounds: (0, 0, 0) to (0.1, 0.1, 0.1)");
}

TEST(ReportFormatTest, TextRoundsToSixDigitsJsonKeepsEverything) {
  TopologyReport r;
  r.area = 39.47811725685738;
  r.volume = 1.0 / 3.0;
  const std::vector<std::string> lines = FormatTopologyReport(r);
  EXPECT_EQ(lines[7], "area: 39.4781");
  EXPECT_EQ(lines[8], "volume: 0.333333 (no closed component)");
  const std::string json = TopologyReportToJson(r);
  EXPECT_NE(json.find("\"area\": 39.47811725685738,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"volume\": 0.3333333333333333,"), std::string::npos) << json;
}

TEST(ReportFormatTest, TopologyJsonHasEveryFieldInOrder) {
  TopologyReport r;
  r.vertices = 10;
  r.referenced_vertices = 9;
  r.unique_positions = 8;
  r.triangles = 12;
  r.degenerate_triangles = 1;
  r.duplicate_triangles = 2;
  r.opposite_triangle_pairs = 3;
  r.edges = 18;
  r.boundary_edges = 4;
  r.non_manifold_edges = 5;
  r.non_manifold_vertices = 6;
  r.inconsistent_edges = 7;
  r.consistently_oriented = false;
  r.components = 2;
  r.components_by_vertex = 1;
  r.closed_components = 1;
  r.closed_manifold_components = 0;
  r.closed = false;
  r.genus = -1;
  r.area = 0.1;
  r.volume = -2.5e-7;
  r.bbox_min = {-1.5f, 0, 0.1f};
  r.bbox_max = {2, 3, 4};
  EXPECT_EQ(TopologyReportToJson(r),
            "{\"vertices\": 10, \"referenced_vertices\": 9, \"unique_positions\": 8, "
            "\"triangles\": 12, \"degenerate_triangles\": 1, \"duplicate_triangles\": 2, "
            "\"opposite_triangle_pairs\": 3, \"edges\": 18, \"boundary_edges\": 4, "
            "\"non_manifold_edges\": 5, \"non_manifold_vertices\": 6, \"inconsistent_edges\": 7, "
            "\"consistently_oriented\": false, \"manifold\": false, \"components\": 2, "
            "\"components_by_vertex\": 1, \"closed_components\": 1, "
            "\"closed_manifold_components\": 0, \"closed\": false, \"genus\": -1, "
            "\"area\": 0.1, \"volume\": -2.5e-07, \"bbox_min\": [-1.5, 0, 0.1], "
            "\"bbox_max\": [2, 3, 4]}");
}

TEST(ReportFormatTest, JsonWritesNonFiniteAsNull) {
  TopologyReport r;
  r.area = std::numeric_limits<double>::infinity();
  const std::string json = TopologyReportToJson(r);
  EXPECT_NE(json.find("\"area\": null"), std::string::npos) << json;
}

TEST(ReportFormatTest, RepairJson) {
  RepairReport r;
  r.welded_vertices = 12;
  r.degenerate_triangles_removed = 3;
  r.opposite_triangle_pairs = 1;
  EXPECT_EQ(RepairReportToJson(r),
            "{\"welded_vertices\": 12, \"degenerate_triangles_removed\": 3, "
            "\"zero_area_triangles_removed\": 0, \"duplicate_triangles_removed\": 0, "
            "\"opposite_triangle_pairs\": 1, \"opposite_triangles_removed\": 0, "
            "\"unused_vertices_removed\": 0, \"changed\": true}");
}

}  // namespace
}  // namespace hullpack
