// libFuzzer target: the GLB reader with the packed-file decoder (what `hullpack unpack` and every
// GLB input go through), the collision-hull reader and the stream version listing (`hullpack
// info`). Any bytes give a Status or a consistent scene and hulls (indices, animation targets,
// morph targets, camera and light references in range).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "packed/packed_glb_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hullpack::Result<hullpack::GltfDocument> parsed =
      hullpack::ParseGltfBytes(data, size, "fuzz.glb");
  if (parsed.ok()) {
    for (const auto& [version, count] : hullpack::StreamVersions(parsed.value())) {
      if (count == 0 || version.empty()) std::abort();
    }
  }
  hullpack::GltfDocument doc;
  hullpack::Result<hullpack::Scene> scene =
      hullpack::ReadPackedGltf(data, size, "fuzz.glb", "", &doc);
  if (!scene.ok()) return 0;
  hullpack::Result<std::vector<hullpack::CollisionHull>> hulls =
      hullpack::ReadCollisionHulls(doc, "fuzz.glb");
  if (hulls.ok()) {
    for (const hullpack::CollisionHull& h : hulls.value()) {
      for (uint32_t index : h.hull.indices) {
        if (index >= h.hull.vertex_count()) std::abort();
      }
    }
  }
  for (const hullpack::Mesh& mesh : scene.value().meshes) {
    for (uint32_t index : mesh.indices) {
      if (index >= mesh.vertex_count()) std::abort();
    }
    for (const hullpack::MorphTarget& t : mesh.morph_targets) {
      if (t.positions.size() != 3 * mesh.vertex_count()) std::abort();
      if (!t.normals.empty() && t.normals.size() != 3 * mesh.vertex_count()) std::abort();
    }
    if (!mesh.morph_weights.empty() && mesh.morph_weights.size() != mesh.morph_targets.size())
      std::abort();
  }
  // What the writer and engines index with must be in range.
  const hullpack::Scene& sc = scene.value();
  for (const hullpack::Animation& a : sc.animations) {
    for (const hullpack::AnimationChannel& c : a.channels) {
      if (c.sampler < 0 || static_cast<size_t>(c.sampler) >= a.samplers.size()) std::abort();
      if (c.node < 0 || static_cast<size_t>(c.node) >= sc.nodes.size()) std::abort();
      if (c.path != hullpack::AnimationPath::kWeights && !sc.nodes[static_cast<size_t>(c.node)].trs)
        std::abort();
      const hullpack::AnimationSampler& s = a.samplers[static_cast<size_t>(c.sampler)];
      const size_t width = hullpack::ChannelWidth(sc, c);
      const size_t per_key = s.interpolation == hullpack::Interpolation::kCubicSpline ? 3 : 1;
      if (width == 0 || s.values.size() != s.times.size() * width * per_key) std::abort();
    }
  }
  for (const hullpack::Node& n : sc.nodes) {
    if (n.camera >= static_cast<int>(sc.cameras.size())) std::abort();
    if (n.light >= static_cast<int>(sc.lights.size())) std::abort();
  }
  return 0;
}
