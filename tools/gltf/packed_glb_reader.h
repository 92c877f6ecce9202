// Reads the packed GLB (docs/packed-gltf.md) back: every HULLPACK_mesh_compression primitive gets
// its data from its decoded stream, so the document becomes plain glTF that any reader understands
// (and that keeps the collision-hull extensions). Mirror of tools/pipeline/packed_glb_writer.h,
// which needs the pipeline's codec settings; reading needs only the o3dgc decoder, so it lives here
// and every GLB the project reads goes through it.
// Trust model: the file is hostile; every index, count and type is checked, streams are decoded
// with the codec's own limits, and a problem is a Status naming the file and the object.
#ifndef HULLPACK_TOOLS_GLTF_PACKED_GLB_READER_H_
#define HULLPACK_TOOLS_GLTF_PACKED_GLB_READER_H_

#include <cstdint>
#include <string>

#include "common/status.h"
#include "gltf/gltf_document.h"
#include "scene/scene.h"

namespace hullpack {

constexpr const char* kMeshCompressionExtension = "HULLPACK_mesh_compression";

// Decodes the compressed primitives of `doc` in place and drops the extension and the streams.
// A document without the extension is left as it is.
Status InflatePackedDocument(GltfDocument& doc, const std::string& name);

// Parses a packed (or plain) GLB or .gltf, inflates it, and converts it into the scene model.
// `inflated` (may be null) receives the plain document. `base_dir` resolves external buffers
// (empty: external buffers are rejected).
Result<Scene> ReadPackedGltf(const uint8_t* data, size_t size, const std::string& name,
                             const std::string& base_dir, GltfDocument* inflated);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_PACKED_GLB_READER_H_
