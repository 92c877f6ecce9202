#include "pipeline/assemble.h"

namespace hullpack {

Result<std::vector<uint8_t>> AssemblePackedGlb(Scene scene, std::vector<PackedMesh> packed,
                                               const PackedGlbOptions& options,
                                               PackedGlbStats* stats) {
  const size_t n = packed.size();
  // Everything but the meshes goes to the file as the scene has it; the meshes are the decoded
  // ones.
  Scene decoded = std::move(scene);
  decoded.meshes.clear();
  PackedStreams streams;
  for (size_t i = 0; i < n; ++i) {
    MeshSource source;
    source.stream = static_cast<int>(streams.streams.size());
    source.grouped = packed[i].grouped;
    streams.streams.push_back(std::move(packed[i].stream));
    streams.sources.push_back(source);
    decoded.meshes.push_back(std::move(packed[i].decoded));
  }
  streams.hulls_of.resize(n);
  for (size_t i = 0; i < n; ++i) {
    if (!packed[i].has_hulls) continue;
    for (size_t h = 0; h < packed[i].hulls.size(); ++h) {
      streams.hulls_of[i].push_back(static_cast<int>(decoded.meshes.size()));
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
