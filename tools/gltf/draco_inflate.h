// Reads KHR_draco_mesh_compression: every primitive compressed with Draco gets its accessors'
// data from its decoded stream, so the document becomes plain glTF. Assets published with Draco
// (glTF-Transform, gltf-pipeline, Blender's exporter) can then be packed, inspected and unpacked
// like any other glTF. Decoding is Debian's libdraco.
//
// Trust model: the file is hostile. Every index, count and type in the JSON is checked against
// the decoded stream before it is used, the decoded data is bounded by the input's size as the
// glTF reader bounds any allocation, and a problem is a Status naming the file and the primitive.
#ifndef HULLPACK_TOOLS_GLTF_DRACO_INFLATE_H_
#define HULLPACK_TOOLS_GLTF_DRACO_INFLATE_H_

#include <string>

#include "common/status.h"
#include "gltf/gltf_document.h"

namespace hullpack {

inline constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

// Decodes the Draco primitives of `doc` in place: each such primitive's attribute and index
// accessors get a new bufferView with the decoded values in their own component type, the
// extension goes from the primitive, extensionsUsed and extensionsRequired, and the streams'
// bufferViews are dropped. The streams must lie in the GLB binary chunk or in a data: URI buffer
// (ReadPackedGltf first reads a .gltf's buffer 0 from its file into the binary chunk; a stream in
// another external buffer is kUnsupported: convert the file to GLB). A document without the
// extension is left as it is.
Status InflateDracoPrimitives(GltfDocument& doc, const std::string& name);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_DRACO_INFLATE_H_
