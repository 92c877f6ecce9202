// Drops the bufferViews nothing refers to and repacks the binary chunk, keeping each view's bytes
// at an offset aligned as before (4 bytes, or more when the original offset was more aligned).
// A reference is any JSON member named "bufferView" whose value is an integer, wherever it sits
// (accessors, images, sparse accessors, extensions such as HULLPACK_mesh_compression), so views
// named by extensions stay. A view compressed with EXT_meshopt_compression keeps its place on its
// fallback buffer; its compressed bytes (the extension's range of buffer 0) are what moves.
// buffers[0].byteLength follows the new chunk size.
#ifndef HULLPACK_TOOLS_GLTF_BUFFER_COMPACTION_H_
#define HULLPACK_TOOLS_GLTF_BUFFER_COMPACTION_H_

#include "common/status.h"
#include "gltf/gltf_document.h"

namespace hullpack {

// Precondition: every bufferView (or its compressed bytes) is on buffer 0 (the GLB binary chunk)
// and fits it; otherwise
// kUnsupported / kParseError and the document is unchanged.
Status CompactBufferViews(GltfDocument& doc);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_BUFFER_COMPACTION_H_
