// The project's own glTF 2.0 reader: GLB or .gltf JSON -> Scene.
//
// Every byte is treated as hostile: each count, offset, length, stride and index is checked against
// what the file actually holds before it is used, decoded data is capped at a multiple of the input
// size, and failures come back as a Status naming the file and the offending object
// ("model.glb: accessors[4]: count 1000 x stride 12 exceeds bufferViews[2] (96 bytes)").
//
// Kept: meshes (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN primitives; all component types, normalized
// integers for UVs/colours/weights, byteStride, KHR_mesh_quantization), materials
// (metallic-roughness factors, the five texture slots with their samplers, alpha mode and cutoff,
// normal scale, occlusion strength, KHR_materials_unlit, KHR_materials_emissive_strength;
// KHR_texture_transform is baked into the UV set a material's textures sample, noted in
// Scene::dropped where it cannot be), images (bufferView, data: URI or external URI kept as a
// string), skins, the node hierarchy (matrix or TRS, TRS kept as given), animations of node
// translation, rotation and scale (glb_reader_animations.cc), cameras and KHR_lights_punctual
// lights (glb_reader_cameras.cc), and the writer's extras.hullpack markers. One glTF mesh becomes
// one scene Mesh (Scene::meshes[i] is meshes[i]): primitives are concatenated (primitives sharing
// the same attribute accessors share vertices) and the primitive material becomes the triangles'
// material id; primitives without a material get an added "default" material when others in the
// mesh have one. A primitive's missing attributes are filled with defaults (normal/tangent/UV 0,
// colour 1, joints/weights 0) when other primitives of the mesh have them. Nodes keep their glTF
// indices, except that the writer's extra-mesh child nodes (which it appends last) are folded back
// into their parents' Node::meshes. Dropped, with a line in Scene::dropped: morph targets and the
// animation channels of their weights, points/lines primitives, extra attribute
// sets (COLOR_1, JOINTS_1, custom), extra scenes and the extensions it does not interpret; meshes
// left without triangles are noted too. Sparse accessors and required extensions it cannot read
// are kUnsupported.
#ifndef HULLPACK_TOOLS_GLTF_GLB_READER_H_
#define HULLPACK_TOOLS_GLTF_GLB_READER_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/status.h"
#include "gltf/gltf_document.h"
#include "scene/scene.h"

namespace hullpack {

struct GltfReadOptions {
  // Folder that relative buffer URIs resolve against; empty means external buffers are
  // kUnsupported. URIs that are absolute, carry a scheme or climb out with ".." are always
  // rejected.
  std::string base_dir;
  // Names in extensionsRequired that the caller interprets itself (e.g. the unpack command with the
  // project's own extensions); any other required extension except KHR_mesh_quantization fails.
  std::vector<std::string> handled_extensions;
  // Decoded arrays may hold at most this many bytes per input byte (plus 1 MiB).
  size_t max_expansion = 64;
};

// Parses a GLB (or, when it lacks the GLB magic, a .gltf JSON text) without converting it: the
// document's json() and binary() give the raw glTF, e.g. for reading extensions.
Result<GltfDocument> DecodeGlbDocument(const uint8_t* data, size_t size, const std::string& name);

// Converts a parsed document into the scene model with every check described above.
Result<Scene> DecodeGltfDocument(const GltfDocument& doc, const std::string& name,
                                 const GltfReadOptions& options = {});

// DecodeGlbDocument + DecodeGltfDocument for a file in memory (external buffers are kUnsupported).
Result<Scene> DecodeGlb(const uint8_t* data, size_t size, const std::string& name);

// Reads a .glb or .gltf file (detected by content); relative buffer URIs resolve next to it.
Result<Scene> ReadGltfFile(const std::string& path);

// Percent-decodes a relative URI into a path; false (with *error) for anything that could leave
// the folder it is relative to (absolute paths, schemes, "..", backslashes, NUL).
bool RelativePathFromUri(const std::string& uri, std::string* path, std::string* error);

// Reads the file into a document without converting it.
Result<GltfDocument> ReadGltfDocumentFile(const std::string& path);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_GLB_READER_H_
