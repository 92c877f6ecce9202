#include "packed/packed_glb_writer.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "gltf/buffer_compaction.h"
#include "gltf/glb_writer.h"

namespace hullpack {
namespace {

void StripData(nlohmann::json& accessor) {
  accessor.erase("bufferView");
  accessor.erase("byteOffset");
}

// Adds HULLPACK_mesh_compression to every primitive of `gltf_mesh`; without fallback the accessors
// the stream supplies lose their data.
void CompressPrimitives(GltfDocument& doc, int gltf_mesh, const MeshSource& source,
                        const EncodedMesh& stream, int stream_view,
                        const GltfSceneLayout::MeshLayout& layout, bool fallback) {
  nlohmann::json& json = doc.json();
  nlohmann::json& primitives = json["meshes"][gltf_mesh]["primitives"];
  for (size_t p = 0; p < primitives.size(); ++p) {
    nlohmann::json& prim = primitives[p];
    nlohmann::json ext = {{"bufferView", stream_view}};
    nlohmann::json attributes = nlohmann::json::object();
    for (const auto& [name, id] : stream.gltf_attributes) {
      if (!prim["attributes"].contains(name)) continue;
      attributes[name] = id;
      if (!fallback) StripData(json["accessors"][prim["attributes"][name].get<int>()]);
    }
    ext["attributes"] = std::move(attributes);
    if (!stream.gltf_targets.empty() && prim.contains("targets") &&
        prim["targets"].size() == stream.gltf_targets.size()) {
      nlohmann::json targets = nlohmann::json::array();
      for (size_t t = 0; t < stream.gltf_targets.size(); ++t) {
        nlohmann::json target = nlohmann::json::object();
        for (const auto& [name, id] : stream.gltf_targets[t]) {
          if (!prim["targets"][t].contains(name)) continue;
          target[name] = id;
          if (!fallback) StripData(json["accessors"][prim["targets"][t][name].get<int>()]);
        }
        targets.push_back(std::move(target));
      }
      ext["targets"] = std::move(targets);
    }
    if (source.grouped && p < layout.primitives.size() && layout.primitives[p].material >= 0) {
      ext["group"] = layout.primitives[p].material;
    }
    if (!fallback && prim.contains("indices"))
      StripData(json["accessors"][prim["indices"].get<int>()]);
    prim["extensions"][kMeshCompressionExtension] = std::move(ext);
  }
}

// A mesh whose plain data was not written (GlbWriteOptions::data_elsewhere) must find every
// attribute in its stream, except the zero-filled texture coordinate sets a material needs.
Status CheckStreamHoldsData(const GltfDocument& doc, int gltf_mesh, const Mesh& mesh) {
  const nlohmann::json& json = doc.json();
  for (const nlohmann::json& prim : json["meshes"][gltf_mesh]["primitives"]) {
    const nlohmann::json& ext = prim["extensions"][kMeshCompressionExtension];
    auto held = [&](const nlohmann::json& accessor, const nlohmann::json& in_stream,
                    const std::string& name) {
      if (in_stream.contains(name) || json["accessors"][accessor.get<int>()].contains("bufferView"))
        return true;
      const std::string uv = "TEXCOORD_";
      if (name.compare(0, uv.size(), uv) != 0) return false;
      char* end = nullptr;
      const unsigned long set = std::strtoul(name.c_str() + uv.size(), &end, 10);
      return end != name.c_str() + uv.size() && *end == '\0' && set >= mesh.uv_sets.size();
    };
    for (const auto& [name, accessor] : prim["attributes"].items()) {
      if (!held(accessor, ext["attributes"], name))
        return Status(StatusCode::kInternal,
                      "mesh '" + mesh.name + "': attribute " + name + " is not in its stream");
    }
    if (!prim.contains("targets")) continue;
    for (size_t t = 0; t < prim["targets"].size(); ++t) {
      const nlohmann::json none = nlohmann::json::object();
      const nlohmann::json& in_stream =
          ext.contains("targets") && t < ext["targets"].size() ? ext["targets"][t] : none;
      for (const auto& [name, accessor] : prim["targets"][t].items()) {
        if (!held(accessor, in_stream, name))
          return Status(StatusCode::kInternal, "mesh '" + mesh.name + "': morph target " +
                                                   std::to_string(t) + " " + name +
                                                   " is not in its stream");
      }
    }
  }
  return Status::Ok();
}

// A hull is a mesh of one POINTS primitive whose only attribute is its quantized POSITION: a
// convex shape is the hull of its points, which every physics engine computes itself, so triangles
// would only add bytes. The grid integers are stored as floats (by default: the hulls then need no
// extension), or, when asked, as VEC3 of unsigned bytes or shorts (padded to 4-byte elements,
// KHR_mesh_quantization, which the file then requires). All hulls share one bufferView per
// component type.
class HullAccessors {
 public:
  explicit HullAccessors(bool floats) : floats_(floats) {}

  // Appends the hull's accessor and mesh; returns the glTF mesh index.
  int Add(GltfDocument& doc, const HullGrid& grid) {
    uint16_t lo[3] = {65535, 65535, 65535}, hi[3] = {0, 0, 0};
    for (size_t i = 0; i < grid.local.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], grid.local[i]);
      hi[i % 3] = std::max(hi[i % 3], grid.local[i]);
    }
    const Kind kind = floats_ ? kFloats : std::max({hi[0], hi[1], hi[2]}) > 255 ? kShorts : kBytes;
    Pending& p = positions_[kind];
    const size_t offset = p.bytes.size();
    const size_t count = grid.local.size() / 3;
    for (size_t v = 0; v < count; ++v) {
      uint8_t element[12] = {};
      for (int k = 0; k < 3; ++k) {
        const uint16_t c = grid.local[v * 3 + k];
        if (kind == kFloats) {
          const float f = c;
          std::memcpy(&element[k * 4], &f, 4);
        } else if (kind == kShorts) {
          element[k * 2] = static_cast<uint8_t>(c & 0xFF);
          element[k * 2 + 1] = static_cast<uint8_t>(c >> 8);
        } else {
          element[k] = static_cast<uint8_t>(c);
        }
      }
      p.bytes.insert(p.bytes.end(), element, element + kStride[kind]);
    }
    nlohmann::json accessor = {{"componentType", kComponentType[kind]},
                               {"count", count},
                               {"type", "VEC3"},
                               {"min", {lo[0], lo[1], lo[2]}},
                               {"max", {hi[0], hi[1], hi[2]}}};
    if (offset != 0) accessor["byteOffset"] = offset;
    const int index = doc.Append("accessors", std::move(accessor));
    p.accessors.push_back(index);
    return doc.Append(
        "meshes",
        {{"primitives", {{{"attributes", {{"POSITION", index}}}, {"mode", gltf::kModePoints}}}}});
  }

  // Writes the shared bufferViews, points the accessors at them, and declares
  // KHR_mesh_quantization when integer positions were written.
  void Finish(GltfDocument& doc) {
    for (int kind = 0; kind < 3; ++kind) {
      if (positions_[kind].accessors.empty()) continue;
      const int view =
          doc.AddBufferView(positions_[kind].bytes, 4, gltf::kArrayBuffer, kStride[kind]);
      for (int a : positions_[kind].accessors) doc.json()["accessors"][a]["bufferView"] = view;
    }
    // The specification and the Khronos validator make it required.
    if (!positions_[kBytes].accessors.empty() || !positions_[kShorts].accessors.empty())
      doc.UseExtension("KHR_mesh_quantization", true);
  }

 private:
  enum Kind { kBytes, kShorts, kFloats };
  static constexpr size_t kStride[3] = {4, 8, 12};
  static constexpr int kComponentType[3] = {gltf::kUnsignedByte, gltf::kUnsignedShort,
                                            gltf::kFloat};
  struct Pending {
    std::vector<uint8_t> bytes;
    std::vector<int> accessors;
  };
  bool floats_;
  Pending positions_[3];
};

void AddColliders(GltfDocument& doc, const PackedStreams& streams, const GltfSceneLayout& layout,
                  const std::vector<int>& hull_meshes, PhysicsForm physics) {
  nlohmann::json& json = doc.json();
  nlohmann::json shapes = nlohmann::json::array();
  for (size_t m = 0; m < streams.hulls_of.size(); ++m) {
    if (streams.hulls_of[m].empty()) continue;
    std::vector<int> hull_refs;  // per hull: OMI shape, or KHR geometry node
    for (int h : streams.hulls_of[m]) {
      const int gltf_hull_mesh = hull_meshes[h];
      if (physics == PhysicsForm::kOmi) {
        hull_refs.push_back(static_cast<int>(shapes.size()));
        shapes.push_back({{"type", "convex"}, {"convex", {{"mesh", gltf_hull_mesh}}}});
      } else {  // a node outside the scene holds the mesh, so that nothing renders it
        hull_refs.push_back(doc.Append("nodes", {{"mesh", gltf_hull_mesh}}));
      }
    }
    for (int node : layout.mesh_nodes[m]) {
      for (size_t k = 0; k < hull_refs.size(); ++k) {
        const HullGrid& grid = streams.sources[streams.hulls_of[m][k]].hull_grid;
        nlohmann::json collider = nlohmann::json::object();
        if (grid.translation[0] != 0 || grid.translation[1] != 0 || grid.translation[2] != 0)
          collider["translation"] = {grid.translation[0], grid.translation[1], grid.translation[2]};
        if (grid.scale != 1) collider["scale"] = {grid.scale, grid.scale, grid.scale};
        if (physics == PhysicsForm::kOmi) {
          collider["extensions"]["OMI_physics_body"] = {{"collider", {{"shape", hull_refs[k]}}}};
        } else {
          collider["extensions"]["KHR_physics_rigid_bodies"] = {
              {"collider", {{"geometry", {{"node", hull_refs[k]}, {"convexHull", true}}}}}};
        }
        const int child = doc.Append("nodes", std::move(collider));
        json["nodes"][node]["children"].push_back(child);
      }
    }
  }
  if (physics == PhysicsForm::kOmi) {
    if (shapes.empty()) return;
    json["extensions"]["OMI_physics_shape"] = {{"shapes", std::move(shapes)}};
    doc.UseExtension("OMI_physics_shape", false);
    doc.UseExtension("OMI_physics_body", false);
  } else if (!streams.hulls_of.empty()) {
    bool any = false;
    for (const auto& h : streams.hulls_of) any |= !h.empty();
    if (any) doc.UseExtension("KHR_physics_rigid_bodies", false);
  }
}

}  // namespace

Result<std::vector<uint8_t>> WritePackedGlb(Scene decoded, const PackedStreams& streams,
                                            const PackedGlbOptions& options,
                                            PackedGlbStats* stats) {
  if (streams.sources.size() != decoded.meshes.size()) {
    return Status(StatusCode::kInternal, "packed GLB: one stream source per mesh expected");
  }
  // The scene's glTF holds the render meshes; the hull meshes (last) get their own accessors.
  size_t render_meshes = 0;
  while (render_meshes < decoded.meshes.size() && !streams.sources[render_meshes].hull)
    ++render_meshes;
  for (size_t m = render_meshes; m < decoded.meshes.size(); ++m) {
    if (!streams.sources[m].hull)
      return Status(StatusCode::kInternal, "packed GLB: hull meshes must follow the render meshes");
  }
  GltfDocument doc;
  GltfSceneLayout layout;
  GlbWriteOptions plain_options;
  plain_options.quantize_rotations = true;
  plain_options.compress_animations = options.compress_animations && !options.fallback;
  // Without fallback, what a stream holds is not written as plain data only to be dropped.
  plain_options.data_elsewhere.assign(render_meshes, false);
  for (size_t m = 0; m < render_meshes && !options.fallback; ++m) {
    const int s = streams.sources[m].stream;
    plain_options.data_elsewhere[m] = s >= 0 && static_cast<size_t>(s) < streams.streams.size();
  }
  // The whole scene but its hull meshes (only their grids are written, from `streams`).
  const size_t all_meshes = decoded.meshes.size();
  decoded.meshes.resize(render_meshes);
  const Status built = BuildGltfDocument(decoded, plain_options, &doc, &layout);
  if (!built.ok()) return built;
  if (stats != nullptr) {
    stats->key_frame_bytes = layout.key_frame_bytes;
    stats->key_frame_stored_bytes = layout.key_frame_stored_bytes;
  }
  std::vector<int> stream_views;
  for (const EncodedMesh& s : streams.streams)
    stream_views.push_back(doc.AddBufferView(s.stream, 4));
  bool any = false;
  for (size_t m = 0; m < render_meshes; ++m) {
    const MeshSource& source = streams.sources[m];
    if (source.stream < 0 || static_cast<size_t>(source.stream) >= streams.streams.size()) continue;
    CompressPrimitives(doc, layout.meshes[m].gltf_mesh, source, streams.streams[source.stream],
                       stream_views[source.stream], layout.meshes[m], options.fallback);
    if (plain_options.data_elsewhere[m]) {
      const Status held = CheckStreamHoldsData(doc, layout.meshes[m].gltf_mesh, decoded.meshes[m]);
      if (!held.ok()) return held;
    }
    any = true;
  }
  if (any) doc.UseExtension(kMeshCompressionExtension, !options.fallback);
  // Fallback files are for readers without extensions: their hulls must not require one.
  HullAccessors hulls(options.fallback || !options.quantized_hulls);
  std::vector<int> hull_meshes(all_meshes, -1);
  for (size_t m = render_meshes; m < all_meshes; ++m)
    hull_meshes[m] = hulls.Add(doc, streams.sources[m].hull_grid);
  hulls.Finish(doc);
  AddColliders(doc, streams, layout, hull_meshes, options.physics);
  Status compacted = CompactBufferViews(doc);
  if (!compacted.ok()) return compacted;
  return doc.Serialize();
}

}  // namespace hullpack
