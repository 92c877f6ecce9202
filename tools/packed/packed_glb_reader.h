// Reads the packed GLB (docs/packed-gltf.md) back: every HULLPACK_mesh_compression primitive gets
// its data from its decoded stream, so the document becomes plain glTF that any reader understands
// (and that keeps the collision-hull extensions). Mirror of packed_glb_writer.h; every GLB the
// project reads goes through it.
// Trust model: the file is hostile; every index, count and type is checked, streams are decoded
// with the codec's own limits, and a problem is a Status naming the file and the object.
#ifndef HULLPACK_TOOLS_PACKED_PACKED_GLB_READER_H_
#define HULLPACK_TOOLS_PACKED_PACKED_GLB_READER_H_

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "common/status.h"
#include "gltf/gltf_document.h"
#include "packed/packed_glb_format.h"
#include "scene/scene.h"

namespace hullpack {

// Decodes the compressed primitives of `doc` in place and drops the extension and the streams.
// A document without the extension is left as it is.
Status InflatePackedDocument(GltfDocument& doc, const std::string& name);

// Parses a packed (or plain) GLB or .gltf, inflates it (HULLPACK_mesh_compression, then
// EXT_meshopt_compression and KHR_draco_mesh_compression: gltf/meshopt_inflate.h,
// gltf/draco_inflate.h), and converts it into the scene model.
// `inflated` (may be null) receives the plain document. `base_dir` resolves external buffers
// (empty: external buffers are rejected).
Result<Scene> ReadPackedGltf(const uint8_t* data, size_t size, const std::string& name,
                             const std::string& base_dir, GltfDocument* inflated);

// One collision hull as a physics engine builds it: the convex mesh of a collider node, in the
// space of the collider's parent (the body node: the collider node's own transform applied, which
// is how quantized hulls are dequantized).
struct CollisionHull {
  int body_node = -1;      // glTF node index of the collider's parent (-1: the collider is a root)
  int collider_node = -1;  // glTF node index
  int gltf_mesh = -1;      // the hull's mesh
  Mesh hull;  // positions (body-node space, rounded to float); triangles when the file has them
};

// The extensions whose colliders ReadCollisionHulls reads.
inline constexpr const char* kCollisionExtensions[] = {"OMI_physics_shape", "OMI_physics_body",
                                                       "KHR_physics_rigid_bodies"};

// Every OMI_physics_body / KHR_physics_rigid_bodies collider of an inflated document `doc` (as
// ReadPackedGltf returns it) whose shape is a convex mesh, in node order. Covers the hulls of every
// release: compressed streams (inflated to float triangles) and quantized points (no triangles:
// the hull of the points is the shape). The document is hostile: every index is checked.
Result<std::vector<CollisionHull>> ReadCollisionHulls(const GltfDocument& doc,
                                                      const std::string& name);

// The stream format version ("1.1", "1.3", ...) of each distinct o3dgc stream the compressed
// primitives of a parsed, not inflated, document `doc` reference, with how many streams have it:
// which decoder releases read the file (docs/o3dgc-stream-format.md). A stream whose header cannot
// be read counts as "unreadable" (decoding the file reports why).
std::map<std::string, size_t> StreamVersions(const GltfDocument& doc);

// For a .gltf whose buffers are files beside it (relative URIs resolved in `base_dir`, as
// `hullpack unpack OUT.gltf` and glTF-Transform write): reads buffer 0's file into doc's binary
// chunk and drops its uri, so that ReadCollisionHulls reads the colliders as it reads a GLB's; then
// (unless `first_only`) appends every other buffer file to the binary chunk and moves the views on
// it there, so that the decoders of compressed data read one buffer as in a GLB (glTF-Transform's
// `partition` writes one .bin per mesh). A document with a binary chunk keeps it; data: URIs and
// buffers without a uri stay as they are. Errors name the file.
Status AdoptBufferFiles(GltfDocument& doc, const std::string& base_dir, const std::string& name,
                        bool first_only = false);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PACKED_PACKED_GLB_READER_H_
