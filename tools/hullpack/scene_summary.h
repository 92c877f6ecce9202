// Whole-scene figures for reports: counts, attribute presence and the topology of every mesh
// added up (a scene is closed when each of its meshes is).
#ifndef HULLPACK_TOOLS_HULLPACK_SCENE_SUMMARY_H_
#define HULLPACK_TOOLS_HULLPACK_SCENE_SUMMARY_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesh/topology.h"
#include "scene/scene.h"

namespace hullpack {

struct SceneSummary {
  size_t meshes = 0, triangles = 0, vertices = 0, file_vertices = 0;
  bool normals = false, tangents = false, colors = false, skin = false;
  size_t max_uv_sets = 0;
  size_t max_morph_targets = 0;
  std::vector<TopologyReport> mesh_topology;  // one per mesh
  TopologyReport total;                       // sums; closed/genus/orientation over all meshes
};

SceneSummary Summarize(const Scene& scene);
nlohmann::json SummaryToJson(const Scene& scene, const SceneSummary& summary);
std::string SummaryToText(const Scene& scene, const SceneSummary& summary);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_SCENE_SUMMARY_H_
