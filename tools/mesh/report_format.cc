#include "mesh/report_format.h"

#include <charconv>
#include <cmath>

namespace hullpack {
namespace {

// Shortest text that reads back as the same float or double; JSON has no NaN/Inf, so those are
// null.
template <typename Float>
std::string Number(Float value) {
  if (!std::isfinite(value)) return "null";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

// Six significant digits: enough for a person reading a report.
std::string Short(double value) {
  if (!std::isfinite(value)) return std::to_string(value);
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, 6);
  return std::string(buffer, result.ptr);
}

std::string Plural(size_t count, const char* singular, const char* plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

std::string Point(const std::array<float, 3>& p) {
  return "(" + Short(p[0]) + ", " + Short(p[1]) + ", " + Short(p[2]) + ")";
}

// Builds {"key": value, ...} in insertion order.
class JsonObject {
 public:
  JsonObject& Add(const char* key, const std::string& raw_value) {
    text_ += (text_.empty() ? "{" : ", ");
    text_ += "\"" + std::string(key) + "\": " + raw_value;
    return *this;
  }
  JsonObject& Add(const char* key, size_t value) { return Add(key, std::to_string(value)); }
  JsonObject& Add(const char* key, int value) { return Add(key, std::to_string(value)); }
  JsonObject& Add(const char* key, bool value) {
    return Add(key, std::string(value ? "true" : "false"));
  }
  JsonObject& Add(const char* key, double value) { return Add(key, Number(value)); }
  JsonObject& Add(const char* key, const std::array<float, 3>& p) {
    return Add(key, "[" + Number(p[0]) + ", " + Number(p[1]) + ", " + Number(p[2]) + "]");
  }
  std::string Close() const { return text_.empty() ? "{}" : text_ + "}"; }

 private:
  std::string text_;
};

}  // namespace

std::vector<std::string> FormatTopologyReport(const TopologyReport& r) {
  std::vector<std::string> lines;
  lines.push_back(
      "triangles: " + std::to_string(r.triangles) + " (" + std::to_string(r.degenerate_triangles) +
      " degenerate, " + std::to_string(r.duplicate_triangles) + " duplicate, " +
      Plural(r.opposite_triangle_pairs, "opposite-winding pair", "opposite-winding pairs") + ")");
  lines.push_back("vertices: " + std::to_string(r.vertices) + " (" +
                  std::to_string(r.referenced_vertices) + " referenced, " +
                  Plural(r.unique_positions, "unique position", "unique positions") + ")");
  lines.push_back("edges: " + std::to_string(r.edges) + " (" + std::to_string(r.boundary_edges) +
                  " boundary, " + std::to_string(r.non_manifold_edges) + " non-manifold)");
  lines.push_back("non-manifold vertices: " + std::to_string(r.non_manifold_vertices));
  lines.push_back(std::string("orientation: ") +
                  (r.consistently_oriented
                       ? "consistent"
                       : "inconsistent (" + Plural(r.inconsistent_edges, "edge", "edges") + ")"));
  lines.push_back("components: " + std::to_string(r.components) + " by edge, " +
                  std::to_string(r.components_by_vertex) + " by vertex (" +
                  std::to_string(r.closed_components) + " closed, " +
                  std::to_string(r.closed_manifold_components) + " closed manifold)");
  std::string closed = std::string("closed: ") + (r.closed ? "yes" : "no");
  closed += r.genus >= 0 ? ", genus " + std::to_string(r.genus)
                         : ", genus unknown (not a closed manifold)";
  lines.push_back(closed);
  lines.push_back("area: " + Short(r.area));
  lines.push_back(
      "volume: " + Short(r.volume) +
      (r.closed_components == 0 ? " (no closed component)" : " (closed components only)"));
  lines.push_back("bounds: " + Point(r.bbox_min) + " to " + Point(r.bbox_max));
  return lines;
}

std::string TopologyReportToJson(const TopologyReport& r) {
  return JsonObject()
      .Add("vertices", r.vertices)
      .Add("referenced_vertices", r.referenced_vertices)
      .Add("unique_positions", r.unique_positions)
      .Add("triangles", r.triangles)
      .Add("degenerate_triangles", r.degenerate_triangles)
      .Add("duplicate_triangles", r.duplicate_triangles)
      .Add("opposite_triangle_pairs", r.opposite_triangle_pairs)
      .Add("edges", r.edges)
      .Add("boundary_edges", r.boundary_edges)
      .Add("non_manifold_edges", r.non_manifold_edges)
      .Add("non_manifold_vertices", r.non_manifold_vertices)
      .Add("inconsistent_edges", r.inconsistent_edges)
      .Add("consistently_oriented", r.consistently_oriented)
      .Add("manifold", r.non_manifold_edges == 0 && r.non_manifold_vertices == 0)
      .Add("components", r.components)
      .Add("components_by_vertex", r.components_by_vertex)
      .Add("closed_components", r.closed_components)
      .Add("closed_manifold_components", r.closed_manifold_components)
      .Add("closed", r.closed)
      .Add("genus", r.genus)
      .Add("area", r.area)
      .Add("volume", r.volume)
      .Add("bbox_min", r.bbox_min)
      .Add("bbox_max", r.bbox_max)
      .Close();
}

std::string RepairReportToJson(const RepairReport& r) {
  return JsonObject()
      .Add("welded_vertices", r.welded_vertices)
      .Add("degenerate_triangles_removed", r.degenerate_triangles_removed)
      .Add("zero_area_triangles_removed", r.zero_area_triangles_removed)
      .Add("duplicate_triangles_removed", r.duplicate_triangles_removed)
      .Add("opposite_triangle_pairs", r.opposite_triangle_pairs)
      .Add("opposite_triangles_removed", r.opposite_triangles_removed)
      .Add("unused_vertices_removed", r.unused_vertices_removed)
      .Add("changed", r.changed())
      .Close();
}

}  // namespace hullpack
