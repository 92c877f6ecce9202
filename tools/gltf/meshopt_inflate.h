// Reads EXT_meshopt_compression: every bufferView compressed with meshoptimizer's codecs (as
// gltfpack and glTF-Transform write them) gets its decoded bytes in the GLB binary chunk, so the
// document becomes plain glTF (its KHR_mesh_quantization accessors stay, the reader takes them).
// Decoding is Debian's libmeshoptimizer, whose decoders check every stream against its size.
//
// Trust model: the file is hostile. Counts, strides, modes and filters are checked against the
// extension's rules before decoding, the decoded bytes are bounded by the input's size as the glTF
// reader bounds any allocation, and a problem is a Status naming the file and the bufferView.
#ifndef HULLPACK_TOOLS_GLTF_MESHOPT_INFLATE_H_
#define HULLPACK_TOOLS_GLTF_MESHOPT_INFLATE_H_

#include <string>

#include "common/status.h"
#include "gltf/gltf_document.h"

namespace hullpack {

inline constexpr const char* kMeshoptExtension = "EXT_meshopt_compression";

// Decodes the compressed bufferViews of `doc` in place: each gets buffer 0 (the binary chunk),
// a new byteOffset and its decoded length, the extension goes from the views, extensionsUsed and
// extensionsRequired, and the fallback buffers nothing refers to any more are removed. The
// compressed data must lie in the GLB binary chunk or in data: URI buffers (ReadPackedGltf first
// reads a .gltf's buffer 0 from its file into the binary chunk; data in another external buffer is
// kUnsupported). A document without the extension is left as it is.
Status InflateMeshoptBufferViews(GltfDocument& doc, const std::string& name);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_MESHOPT_INFLATE_H_
