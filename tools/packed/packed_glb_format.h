// The packed GLB's format in one place (docs/packed-gltf.md): the extension name, what a compressed
// stream carries for a glTF primitive, and the decode rule every reader of a packed file applies.
// The reader (packed_glb_reader.h) and the writer (packed_glb_writer.h) sit beside this header; the
// codec stage (pipeline/mesh_codec.h) decodes streams through DecodePackedStream too.
#ifndef HULLPACK_TOOLS_PACKED_PACKED_GLB_FORMAT_H_
#define HULLPACK_TOOLS_PACKED_PACKED_GLB_FORMAT_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace hullpack {

constexpr const char* kMeshCompressionExtension = "HULLPACK_mesh_compression";

// One compressed stream and the glTF attributes it supplies.
struct EncodedMesh {
  std::vector<uint8_t> stream;
  // glTF attribute name -> stream attribute id, in stream order.
  std::vector<std::pair<std::string, int>> gltf_attributes;
  // Per morph target, its glTF attribute names (POSITION, NORMAL) -> stream attribute ids.
  std::vector<std::vector<std::pair<std::string, int>>> gltf_targets;
  o3dgc::StreamInfo info;
};

// A collision hull stored as plain accessors on a grid: unsigned integer coordinates `local` (3 per
// vertex; written as floats, or as bytes/shorts with KHR_mesh_quantization) that its collider
// node's translation and uniform scale map into the body node's space.
struct HullGrid {
  double translation[3] = {0, 0, 0};
  double scale = 1;
  std::vector<uint16_t> local;
};

// The positions an engine computes from `grid`: float(translation + scale * local), in double.
std::vector<float> DequantizeHull(const HullGrid& grid);

// Decodes one HULLPACK_mesh_compression stream and applies the format's decode rule: every
// attribute of semantic weight with 4 components is normalized per vertex (NormalizeSkinWeights),
// so that WEIGHTS_0 sums to 1 as glTF wants. Safe on untrusted bytes.
o3dgc::Status DecodePackedStream(const uint8_t* data, size_t size, o3dgc::DecodedMesh* mesh,
                                 o3dgc::StreamInfo* info = nullptr);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PACKED_PACKED_GLB_FORMAT_H_
