#include "pipeline/prune.h"

#include <algorithm>
#include <array>
#include <set>

#include "pipeline/check_and_repair.h"
#include "pipeline/still_tracks.h"

namespace hullpack {
namespace {

std::array<const TextureRef*, 5> TextureSlots(const Material& m) {
  return {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture,
          &m.occlusion_texture, &m.emissive_texture};
}

// Materials a mesh's triangles use; with no material ids, none.
std::set<uint32_t> MaterialsOf(const Mesh& mesh) {
  return std::set<uint32_t>(mesh.material_ids.begin(), mesh.material_ids.end());
}

void RemoveUnusedUvSets(Scene& scene, Mesh& mesh, PruneReport& report) {
  int highest_used = -1;
  for (uint32_t id : MaterialsOf(mesh)) {
    if (id >= scene.materials.size()) continue;
    for (const TextureRef* t : TextureSlots(scene.materials[id])) {
      if (t->used()) highest_used = std::max(highest_used, t->uv_set);
    }
  }
  // Only trailing sets can go: texture slots name sets by index.
  const size_t keep = static_cast<size_t>(highest_used + 1);
  if (mesh.uv_sets.size() > keep) {
    report.uv_sets_removed += mesh.uv_sets.size() - keep;
    mesh.uv_sets.resize(keep);
  }
}

void RemoveUnusedTangents(const Scene& scene, Mesh& mesh, PruneReport& report) {
  if (mesh.tangents.empty()) return;
  for (uint32_t id : MaterialsOf(mesh)) {
    if (id < scene.materials.size() && scene.materials[id].normal_texture.used()) return;
  }
  mesh.tangents = {};
  ++report.tangent_sets_removed;
}

// COLOR_0 multiplies the base colour: a constant one is the same as a material whose base colour
// is multiplied by it. Each material the mesh uses is copied so other meshes are not affected.
void FoldConstantColors(Scene& scene, Mesh& mesh, PruneReport& report) {
  if (mesh.colors.size() < 4) return;
  for (size_t i = 4; i < mesh.colors.size(); ++i) {
    if (mesh.colors[i] != mesh.colors[i % 4]) return;
  }
  const float c[4] = {mesh.colors[0], mesh.colors[1], mesh.colors[2], mesh.colors[3]};
  mesh.colors = {};
  ++report.constant_color_sets_folded;
  if (c[0] == 1 && c[1] == 1 && c[2] == 1 && c[3] == 1) return;
  if (mesh.material_ids.empty()) {
    Material m;
    m.name = mesh.name + "_color";
    scene.materials.push_back(m);
    mesh.material_ids.assign(mesh.triangle_count(),
                             static_cast<uint32_t>(scene.materials.size() - 1));
  }
  std::vector<std::pair<uint32_t, uint32_t>> copies;  // old id -> tinted copy
  for (uint32_t& id : mesh.material_ids) {
    auto it =
        std::find_if(copies.begin(), copies.end(), [&](const auto& p) { return p.first == id; });
    if (it == copies.end()) {
      Material tinted = id < scene.materials.size() ? scene.materials[id] : Material();
      for (int k = 0; k < 4; ++k) tinted.base_color[k] *= c[k];
      scene.materials.push_back(tinted);
      copies.emplace_back(id, static_cast<uint32_t>(scene.materials.size() - 1));
      it = copies.end() - 1;
    }
    id = it->second;
  }
}

// Vertex attribute arrays present (UV sets count one each).
size_t VertexAttributeCount(const Mesh& m) {
  return !m.normals.empty() + !m.tangents.empty() + !m.colors.empty() + !m.joints.empty() +
         !m.weights.empty() + m.uv_sets.size();
}

void RemoveUnusedSkinData(const Scene& scene, size_t mesh_index, Mesh& mesh, PruneReport& report) {
  if (mesh.joints.empty() && mesh.weights.empty()) return;
  for (const Node& node : scene.nodes) {
    if (node.skin >= 0 && std::find(node.meshes.begin(), node.meshes.end(),
                                    static_cast<int>(mesh_index)) != node.meshes.end())
      return;
  }
  mesh.joints = {};
  mesh.weights = {};
  ++report.skin_data_removed;
}

void RemoveUnreferencedMeshes(Scene& scene, PruneReport& report) {
  if (scene.nodes.empty()) return;
  std::vector<bool> shown(scene.meshes.size(), false);
  for (const Node& node : scene.nodes) {
    for (int m : node.meshes) {
      if (m >= 0 && static_cast<size_t>(m) < scene.meshes.size()) shown[m] = true;
    }
  }
  report.meshes_removed += KeepMeshes(scene, shown);
}

// A mesh whose every triangle the repairs dropped (all degenerate: a collapsed helper object, or
// coordinates too far out for float precision) has nothing to draw or to collide with, and glTF
// has no empty meshes.
void RemoveEmptyMeshes(Scene& scene, PruneReport& report) {
  std::vector<bool> has_triangles(scene.meshes.size());
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    has_triangles[i] = scene.meshes[i].triangle_count() > 0;
  report.empty_meshes_removed += KeepMeshes(scene, has_triangles);
}

void RemoveUnreferencedMaterials(Scene& scene, PruneReport& report) {
  std::vector<int> new_index(scene.materials.size(), -1);
  for (const Mesh& mesh : scene.meshes) {
    for (uint32_t id : mesh.material_ids) {
      if (id < new_index.size()) new_index[id] = 0;
    }
  }
  std::vector<Material> kept;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (new_index[i] < 0) continue;
    new_index[i] = static_cast<int>(kept.size());
    kept.push_back(std::move(scene.materials[i]));
  }
  report.materials_removed += scene.materials.size() - kept.size();
  scene.materials = std::move(kept);
  for (Mesh& mesh : scene.meshes) {
    for (uint32_t& id : mesh.material_ids) {
      if (id < new_index.size()) id = static_cast<uint32_t>(new_index[id]);
    }
  }
}

void RemoveUnreferencedImages(Scene& scene, PruneReport& report) {
  std::vector<int> new_index(scene.images.size(), -1);
  for (const Material& m : scene.materials) {
    for (const TextureRef* t : TextureSlots(m)) {
      if (t->used() && static_cast<size_t>(t->image) < new_index.size()) new_index[t->image] = 0;
    }
  }
  std::vector<Image> kept;
  for (size_t i = 0; i < scene.images.size(); ++i) {
    if (new_index[i] < 0) continue;
    new_index[i] = static_cast<int>(kept.size());
    kept.push_back(std::move(scene.images[i]));
  }
  report.images_removed += scene.images.size() - kept.size();
  scene.images = std::move(kept);
  for (Material& m : scene.materials) {
    for (TextureRef* t : {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture,
                          &m.occlusion_texture, &m.emissive_texture}) {
      if (t->used())
        t->image = static_cast<size_t>(t->image) < new_index.size() ? new_index[t->image] : -1;
    }
  }
}

}  // namespace

PruneReport LeaveOutUnused(Scene& scene, const PruneOptions& options) {
  PruneReport report;
  if (options.empty_meshes) RemoveEmptyMeshes(scene, report);
  if (options.unreferenced_meshes) RemoveUnreferencedMeshes(scene, report);
  report.weight_tracks_removed = RemoveWeightTracksWithoutTargets(scene);
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    Mesh& mesh = scene.meshes[i];
    const size_t attributes_before = VertexAttributeCount(mesh);
    if (options.constant_colors) FoldConstantColors(scene, mesh, report);
    if (options.unused_uv_sets) RemoveUnusedUvSets(scene, mesh, report);
    if (options.unused_tangents) RemoveUnusedTangents(scene, mesh, report);
    if (options.unused_skin_data) RemoveUnusedSkinData(scene, i, mesh, report);
    if (VertexAttributeCount(mesh) != attributes_before)
      AddRepairs(report.repairs, RepairMesh(mesh, options.reweld));
  }
  if (options.unreferenced_materials) RemoveUnreferencedMaterials(scene, report);
  if (options.unreferenced_images) RemoveUnreferencedImages(scene, report);
  if (options.still_animation_tracks) {
    const StillTrackReport still = RemoveStillTracks(scene);
    report.animation_tracks_removed = still.at_rest_removed;
    report.animation_tracks_collapsed = still.held_collapsed;
  }

  auto line = [&](size_t n, const char* what) {
    if (n) report.lines.push_back(std::to_string(n) + " " + what);
  };
  line(report.uv_sets_removed, "UV sets no texture samples");
  line(report.tangent_sets_removed, "tangent sets without a normal map");
  line(report.constant_color_sets_folded, "constant vertex colour sets (folded into the material)");
  line(report.skin_data_removed, "joint/weight sets of meshes no skinned node shows");
  line(report.empty_meshes_removed, "meshes with no triangle left (every triangle degenerate)");
  line(report.meshes_removed, "meshes no node shows");
  line(report.weight_tracks_removed, "morph weight tracks of meshes left out");
  line(report.materials_removed, "materials no triangle uses");
  line(report.images_removed, "images no material uses");
  line(report.animation_tracks_removed, "animation tracks that hold their node at rest");
  line(report.animation_tracks_collapsed, "animation tracks that hold one value (one key kept)");
  return report;
}

}  // namespace hullpack
