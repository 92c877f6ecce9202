#include "hullpack/scene_summary.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hullpack {
namespace {

void Accumulate(TopologyReport& total, const TopologyReport& t, bool first) {
  total.vertices += t.vertices;
  total.referenced_vertices += t.referenced_vertices;
  total.unique_positions += t.unique_positions;
  total.triangles += t.triangles;
  total.degenerate_triangles += t.degenerate_triangles;
  total.duplicate_triangles += t.duplicate_triangles;
  total.opposite_triangle_pairs += t.opposite_triangle_pairs;
  total.edges += t.edges;
  total.boundary_edges += t.boundary_edges;
  total.non_manifold_edges += t.non_manifold_edges;
  total.non_manifold_vertices += t.non_manifold_vertices;
  total.inconsistent_edges += t.inconsistent_edges;
  total.components += t.components;
  total.components_by_vertex += t.components_by_vertex;
  total.closed_components += t.closed_components;
  total.closed_manifold_components += t.closed_manifold_components;
  total.area += t.area;
  total.volume += t.volume;
  if (first) {
    total.closed = t.closed;
    total.genus = t.genus;
    total.consistently_oriented = t.consistently_oriented;
    total.bbox_min = t.bbox_min;
    total.bbox_max = t.bbox_max;
    return;
  }
  total.closed = total.closed && t.closed;
  total.genus = (total.genus < 0 || t.genus < 0) ? -1 : total.genus + t.genus;
  total.consistently_oriented = total.consistently_oriented && t.consistently_oriented;
  for (int k = 0; k < 3; ++k) {
    total.bbox_min[k] = std::min(total.bbox_min[k], t.bbox_min[k]);
    total.bbox_max[k] = std::max(total.bbox_max[k], t.bbox_max[k]);
  }
}

std::string Attributes(bool normals, size_t uv_sets, bool colors, bool tangents, bool skin,
                       size_t morph_targets) {
  std::string s = "positions";
  if (normals) s += ", normals";
  if (tangents) s += ", tangents";
  if (uv_sets == 1) s += ", uv";
  if (uv_sets > 1) s += ", uv x" + std::to_string(uv_sets);
  if (colors) s += ", colors";
  if (skin) s += ", joints/weights";
  if (morph_targets > 0) s += ", morph targets x" + std::to_string(morph_targets);
  return s;
}

std::string TopologyLine(const TopologyReport& t) {
  std::ostringstream o;
  if (t.closed) {
    o << "closed";
  } else {
    o << "open (" << t.boundary_edges << " boundary edges)";
  }
  const bool manifold = t.non_manifold_edges == 0 && t.non_manifold_vertices == 0;
  o << ", " << (manifold ? "manifold" : "non-manifold");
  if (!manifold)
    o << " (" << t.non_manifold_edges << " edges, " << t.non_manifold_vertices << " vertices)";
  o << ", " << t.components << (t.components == 1 ? " component" : " components");
  if (t.genus >= 0) o << ", genus " << t.genus;
  o << ", "
    << (t.consistently_oriented
            ? "consistently oriented"
            : "inconsistent orientation (" + std::to_string(t.inconsistent_edges) + " edges)");
  return o.str();
}

nlohmann::json TopologyJson(const TopologyReport& t) {
  return {{"closed", t.closed},
          {"manifold", t.non_manifold_edges == 0 && t.non_manifold_vertices == 0},
          {"boundary_edges", t.boundary_edges},
          {"non_manifold_edges", t.non_manifold_edges},
          {"non_manifold_vertices", t.non_manifold_vertices},
          {"inconsistent_edges", t.inconsistent_edges},
          {"consistently_oriented", t.consistently_oriented},
          {"components", t.components},
          {"genus", t.genus},
          {"degenerate_triangles", t.degenerate_triangles},
          {"duplicate_triangles", t.duplicate_triangles},
          {"opposite_triangle_pairs", t.opposite_triangle_pairs},
          {"area", t.area},
          {"volume", t.volume}};
}

}  // namespace

SceneSummary Summarize(const Scene& scene) {
  SceneSummary s;
  s.meshes = scene.meshes.size();
  s.file_vertices = scene.source_vertex_records;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& m = scene.meshes[i];
    s.triangles += m.triangle_count();
    s.vertices += m.vertex_count();
    s.normals |= !m.normals.empty();
    s.tangents |= !m.tangents.empty();
    s.colors |= !m.colors.empty();
    s.skin |= m.has_skin();
    s.max_uv_sets = std::max(s.max_uv_sets, m.uv_sets.size());
    s.max_morph_targets = std::max(s.max_morph_targets, m.morph_targets.size());
    s.mesh_topology.push_back(AnalyzeTopology(m));
    Accumulate(s.total, s.mesh_topology.back(), i == 0);
  }
  if (s.file_vertices == 0) s.file_vertices = s.vertices;
  return s;
}

nlohmann::json SummaryToJson(const Scene& scene, const SceneSummary& s) {
  const TopologyReport& t = s.total;
  nlohmann::json j = {{"meshes", s.meshes},
                      {"triangles", s.triangles},
                      {"vertices", s.file_vertices},
                      {"render_vertices", s.vertices},
                      {"materials", scene.materials.size()},
                      {"images", scene.images.size()},
                      {"skins", scene.skins.size()},
                      {"nodes", scene.nodes.size()},
                      {"animations", scene.animations.size()},
                      {"has_normals", s.normals},
                      {"has_tangents", s.tangents},
                      {"uv_sets", s.max_uv_sets},
                      {"has_uv", s.max_uv_sets > 0},
                      {"has_colors", s.colors},
                      {"has_skin", s.skin},
                      {"morph_targets", s.max_morph_targets},
                      {"bbox", {{"min", t.bbox_min}, {"max", t.bbox_max}}},
                      {"topology", TopologyJson(t)},
                      {"dropped", scene.dropped}};
  nlohmann::json meshes = nlohmann::json::array();
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& m = scene.meshes[i];
    meshes.push_back(
        {{"name", m.name},
         {"triangles", m.triangle_count()},
         {"vertices", m.vertex_count()},
         {"attributes", Attributes(!m.normals.empty(), m.uv_sets.size(), !m.colors.empty(),
                                   !m.tangents.empty(), m.has_skin(), m.morph_targets.size())},
         {"topology", TopologyJson(s.mesh_topology[i])}});
  }
  j["mesh_list"] = meshes;
  return j;
}

std::string SummaryToText(const Scene& scene, const SceneSummary& s) {
  const TopologyReport& t = s.total;
  std::ostringstream o;
  o << "  meshes " << s.meshes << ", triangles " << s.triangles << ", vertices " << s.file_vertices;
  if (s.vertices != s.file_vertices)
    o << " in the file (" << s.vertices << " after attribute unification)";
  o << "\n  materials " << scene.materials.size() << ", images " << scene.images.size()
    << ", skins " << scene.skins.size() << ", nodes " << scene.nodes.size() << ", animations "
    << scene.animations.size();
  if (!scene.cameras.empty()) o << ", cameras " << scene.cameras.size();
  if (!scene.lights.empty()) o << ", lights " << scene.lights.size();
  o << "\n";
  o << "  attributes: "
    << Attributes(s.normals, s.max_uv_sets, s.colors, s.tangents, s.skin, s.max_morph_targets)
    << "\n";
  const double dx = double(t.bbox_max[0]) - t.bbox_min[0],
               dy = double(t.bbox_max[1]) - t.bbox_min[1],
               dz = double(t.bbox_max[2]) - t.bbox_min[2];
  o << "  bounds: min (" << t.bbox_min[0] << ", " << t.bbox_min[1] << ", " << t.bbox_min[2]
    << ") max (" << t.bbox_max[0] << ", " << t.bbox_max[1] << ", " << t.bbox_max[2]
    << "), diagonal " << std::sqrt(dx * dx + dy * dy + dz * dz) << "\n";
  o << "  topology: " << TopologyLine(t) << "\n";
  o << "  area " << t.area;
  if (t.closed_components > 0) o << ", volume " << t.volume << " (closed parts)";
  o << "\n";
  if (t.degenerate_triangles || t.duplicate_triangles || t.opposite_triangle_pairs) {
    o << "  triangles: " << t.degenerate_triangles << " degenerate, " << t.duplicate_triangles
      << " duplicate, " << t.opposite_triangle_pairs << " two-sided pairs\n";
  }
  if (scene.meshes.size() > 1) {
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
      const Mesh& m = scene.meshes[i];
      o << "  mesh " << i << " '" << m.name << "': " << m.triangle_count() << " triangles, "
        << m.vertex_count() << " vertices; " << TopologyLine(s.mesh_topology[i]) << "\n";
    }
  }
  for (const std::string& d : scene.dropped) o << "  not kept: " << d << "\n";
  return o.str();
}

}  // namespace hullpack
