#include "packed/packed_glb_writer.h"

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
    if (source.hull) {
      ext["group"] = source.hull_group;
      ext["compactVertices"] = true;
    } else if (source.grouped && p < layout.primitives.size() &&
               layout.primitives[p].material >= 0) {
      ext["group"] = layout.primitives[p].material;
    }
    if (!fallback && prim.contains("indices"))
      StripData(json["accessors"][prim["indices"].get<int>()]);
    prim["extensions"][kMeshCompressionExtension] = std::move(ext);
  }
}

void AddColliders(GltfDocument& doc, const PackedStreams& streams, const GltfSceneLayout& layout,
                  PhysicsForm physics) {
  nlohmann::json& json = doc.json();
  nlohmann::json shapes = nlohmann::json::array();
  for (size_t m = 0; m < streams.hulls_of.size(); ++m) {
    if (streams.hulls_of[m].empty()) continue;
    std::vector<int> hull_shapes;
    for (int h : streams.hulls_of[m]) {
      hull_shapes.push_back(static_cast<int>(shapes.size()));
      shapes.push_back({{"type", "convex"}, {"convex", {{"mesh", layout.meshes[h].gltf_mesh}}}});
    }
    for (int node : layout.mesh_nodes[m]) {
      for (size_t k = 0; k < hull_shapes.size(); ++k) {
        const int gltf_hull_mesh = layout.meshes[streams.hulls_of[m][k]].gltf_mesh;
        nlohmann::json collider = {{"name", json["nodes"][node].value("name", std::string("node")) +
                                                "_collider_" + std::to_string(k)}};
        if (physics == PhysicsForm::kOmi) {
          collider["extensions"]["OMI_physics_body"] = {{"collider", {{"shape", hull_shapes[k]}}}};
        } else {
          collider["extensions"]["KHR_physics_rigid_bodies"] = {
              {"collider", {{"geometry", {{"mesh", gltf_hull_mesh}, {"convexHull", true}}}}}};
        }
        const int child = doc.Append("nodes", std::move(collider));
        json["nodes"][node]["children"].push_back(child);
      }
    }
  }
  if (shapes.empty()) return;
  if (physics == PhysicsForm::kOmi) {
    json["extensions"]["OMI_physics_shape"] = {{"shapes", std::move(shapes)}};
    doc.UseExtension("OMI_physics_shape", false);
    doc.UseExtension("OMI_physics_body", false);
  } else {
    doc.UseExtension("KHR_physics_rigid_bodies", false);
  }
}

}  // namespace

Result<std::vector<uint8_t>> WritePackedGlb(const Scene& decoded, const PackedStreams& streams,
                                            const PackedGlbOptions& options) {
  if (streams.sources.size() != decoded.meshes.size()) {
    return Status(StatusCode::kInternal, "packed GLB: one stream source per mesh expected");
  }
  GltfDocument doc;
  GltfSceneLayout layout;
  Status built = BuildGltfDocument(decoded, GlbWriteOptions(), &doc, &layout);
  if (!built.ok()) return built;
  std::vector<int> stream_views;
  for (const EncodedMesh& s : streams.streams)
    stream_views.push_back(doc.AddBufferView(s.stream, 4));
  bool any = false;
  for (size_t m = 0; m < decoded.meshes.size(); ++m) {
    const MeshSource& source = streams.sources[m];
    if (source.stream < 0 || static_cast<size_t>(source.stream) >= streams.streams.size()) continue;
    CompressPrimitives(doc, layout.meshes[m].gltf_mesh, source, streams.streams[source.stream],
                       stream_views[source.stream], layout.meshes[m], options.fallback);
    any = true;
  }
  if (any) doc.UseExtension(kMeshCompressionExtension, !options.fallback);
  AddColliders(doc, streams, layout, options.physics);
  Status compacted = CompactBufferViews(doc);
  if (!compacted.ok()) return compacted;
  return doc.Serialize();
}

}  // namespace hullpack
