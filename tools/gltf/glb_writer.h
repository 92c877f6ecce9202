// The plain (uncompressed) glTF 2.0 writer: Scene -> GLB.
//
// Layout: one buffer (the GLB BIN chunk), one tightly packed bufferView per accessor. Per scene
// Mesh one glTF mesh whose primitives share the mesh's vertex accessors (POSITION with min/max,
// NORMAL, TANGENT, TEXCOORD_n, COLOR_0 as float RGBA, JOINTS_0, WEIGHTS_0); one primitive per
// material id present, in ascending id order, each with its own index accessor (UNSIGNED_SHORT
// below 65536 vertices, else UNSIGNED_INT) holding its triangles in their original order. A mesh
// without material ids gets one primitive without a material. Mesh::collides == false is written as
// mesh.extras.hullpack.collides = false.
//
// Images with a uri are referenced by it (their bytes, if any, are not embedded); others are
// embedded as a bufferView with their mime type (sniffed from PNG/JPEG/WebP magic when empty). Each
// image a material uses gets one texture; TextureRef::uv_set becomes texCoord. When a material
// samples a UV set the mesh lacks, zero-filled TEXCOORD accessors (no bufferView) keep the file
// valid and extras.hullpack.uv_sets tells the reader to drop them.
//
// Materials keep alpha mode and cutoff, KHR_materials_unlit and KHR_materials_emissive_strength;
// one texture per image and sampler. Nodes are written as TRS when the scene kept TRS or an
// animation drives them, else as a matrix. Animations share the key-time accessors of equal times.
//
// Nodes keep their scene indices; a node with several meshes gets one extra child node per extra
// mesh (appended after the scene's nodes, marked extras.hullpack.mesh_of_parent so the reader folds
// them back). A scene without nodes gets one root node per mesh.
//
// The packaging stage builds on BuildGltfDocument(): it gets the document plus a layout that maps
// scene meshes/nodes to glTF indices, adds its bufferViews and extensions, then calls Serialize().
#ifndef HULLPACK_TOOLS_GLTF_GLB_WRITER_H_
#define HULLPACK_TOOLS_GLTF_GLB_WRITER_H_

#include <cstdint>
#include <string>
#include <vector>

#include "common/status.h"
#include "gltf/gltf_document.h"
#include "scene/scene.h"

namespace hullpack {

struct GlbWriteOptions {
  std::string generator = "hullpack";  // asset.generator
  // JOINTS_0 as UNSIGNED_BYTE when every joint index is below 256 (else UNSIGNED_SHORT).
  bool compact_joints = true;
  // Rotation key frames (LINEAR and STEP) as normalized shorts, as glTF allows for rotations: half
  // the bytes, within 1/32767 per quaternion component (about 0.004 degrees).
  bool quantize_rotations = false;
  // Key frames stored with EXT_meshopt_compression (required then): times exactly, rotations
  // through its quaternion filter (as precise as quantize_rotations), translations, scales and
  // weights through its exponential filter (16-bit mantissas: within 2^-15 of each key's largest
  // component). See meshopt_deflate.h.
  bool compress_animations = false;
  // Per scene mesh (missing entries: false), whether an extension supplies its vertex data and
  // indices: their accessors keep their count, type and POSITION bounds but get no bufferView,
  // and none of their bytes are written (a packed file's streams).
  std::vector<bool> data_elsewhere;
};

// Where BuildGltfDocument put each scene object.
struct GltfSceneLayout {
  struct Primitive {
    int material = -1;  // scene material id, -1 for none
    int indices_accessor = -1;
    size_t triangle_count = 0;  // triangles in this primitive
  };
  struct MeshLayout {
    int gltf_mesh = -1;
    std::vector<Primitive> primitives;  // the order of mesh.primitives in the JSON
    int position_accessor = -1;
    // Scene triangle index of each triangle, primitive after primitive (the written order).
    std::vector<uint32_t> triangle_order;
  };
  std::vector<MeshLayout> meshes;  // one per Scene::meshes entry
  std::vector<int> nodes;          // scene node -> glTF node (identity when the scene has nodes)
  std::vector<std::vector<int>> mesh_nodes;  // scene mesh -> glTF nodes that reference it
  // Animation key frames: their bytes as plain accessors, and as written (compressed or not).
  size_t key_frame_bytes = 0;
  size_t key_frame_stored_bytes = 0;
};

// Checks what the writer relies on: every mesh has vertices and triangles (glTF has no empty
// meshes), consistent array sizes, finite values, index and material bounds, texture/skin/node
// references, joint indices within the skin of each node that skins the mesh, and a node hierarchy
// that is a forest. kInvalidMesh / kInvalidArgument otherwise, naming the mesh, material, skin or
// node.
Status ValidateSceneForGltf(const Scene& scene);

// The part of ValidateSceneForGltf for scene.animations[index]: channels name existing samplers and
// nodes, at most one channel per node and path, key times finite and ascending, as many finite
// values as the keys need, and animated nodes expressible as TRS.
Status ValidateAnimation(const Scene& scene, size_t index);

// Writes `scene` into `doc` (which should be fresh). `layout` may be null.
Status BuildGltfDocument(const Scene& scene, const GlbWriteOptions& options, GltfDocument* doc,
                         GltfSceneLayout* layout);

// BuildGltfDocument + Serialize.
Result<std::vector<uint8_t>> EncodeGlb(const Scene& scene, const GlbWriteOptions& options = {});

// "image/png", "image/jpeg" or "image/webp" from the first bytes, or "" when unrecognised.
std::string SniffImageMime(const std::vector<uint8_t>& bytes);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_GLB_WRITER_H_
