#include "pipeline/assemble.h"

namespace hullpack {

Result<std::vector<uint8_t>> AssemblePackedGlb(Scene scene, std::vector<PackedMesh> packed,
                                               const PackedGlbOptions& options,
                                               PackedGlbStats* stats) {
  const size_t n = packed.size();
  // Everything but the meshes goes to the file as the scene has it; the meshes are the decoded
  // ones, a mesh coded in parts as one mesh per part on the mesh's nodes.
  Scene decoded = std::move(scene);
  decoded.meshes.clear();
  PackedStreams streams;
  std::vector<std::vector<int>> parts_of(n);
  bool split = false;
  for (size_t i = 0; i < n; ++i) {
    split |= packed[i].streams.size() > 1;
    for (size_t p = 0; p < packed[i].streams.size(); ++p) {
      MeshSource source;
      source.stream = static_cast<int>(streams.streams.size());
      source.grouped = packed[i].grouped;
      streams.streams.push_back(std::move(packed[i].streams[p]));
      streams.sources.push_back(source);
      parts_of[i].push_back(static_cast<int>(decoded.meshes.size()));
      decoded.meshes.push_back(std::move(packed[i].decoded[p]));
    }
  }
  if (split) {
    // Without nodes the writer gives each mesh one; a mesh in parts needs one node for them all.
    if (decoded.nodes.empty()) {
      for (size_t i = 0; i < n; ++i) {
        Node node;
        node.name = packed[i].report.name;
        node.meshes.push_back(static_cast<int>(i));
        decoded.nodes.push_back(std::move(node));
      }
    }
    for (Node& node : decoded.nodes) {
      std::vector<int> meshes;
      for (int m : node.meshes) {
        const std::vector<int>& parts = parts_of[static_cast<size_t>(m)];
        meshes.insert(meshes.end(), parts.begin(), parts.end());
      }
      node.meshes = std::move(meshes);
    }
  }
  // A mesh's hulls go with its first part.
  const size_t num_render = decoded.meshes.size();
  streams.hulls_of.resize(num_render);
  for (size_t i = 0; i < n; ++i) {
    if (!packed[i].has_hulls || parts_of[i].empty()) continue;
    const size_t first = static_cast<size_t>(parts_of[i][0]);
    for (size_t h = 0; h < packed[i].hulls.size(); ++h) {
      streams.hulls_of[first].push_back(static_cast<int>(decoded.meshes.size()));
      decoded.meshes.push_back(std::move(packed[i].hulls[h]));
      MeshSource source;
      source.hull = true;
      source.hull_grid = std::move(packed[i].hull_grids[h]);
      streams.sources.push_back(std::move(source));
    }
  }
  streams.hulls_of.resize(decoded.meshes.size());
  return WritePackedGlb(std::move(decoded), streams, options, stats);
}

}  // namespace hullpack
