// Writes EXT_meshopt_compression, the mirror of meshopt_inflate.h: bufferViews whose bytes are
// stored with meshoptimizer's vertex codec (mode ATTRIBUTES), optionally through one of its
// filters, as gltfpack writes them, so that three.js (GLTFLoader.setMeshoptDecoder), Babylon.js
// and every reader of the extension decode them. Encoding is Debian's libmeshoptimizer.
//
// The extension is written as required: each compressed view lies on a fallback buffer (buffer 1,
// no uri, marked `fallback`) and its compressed bytes in the GLB binary chunk (buffer 0).
#ifndef HULLPACK_TOOLS_GLTF_MESHOPT_DEFLATE_H_
#define HULLPACK_TOOLS_GLTF_MESHOPT_DEFLATE_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gltf/gltf_document.h"

namespace hullpack {

// How the decoder turns the stored elements back into the accessor's values.
enum class MeshoptFilter {
  kNone,         // the elements are the values
  kQuaternion,   // unit quaternions, read as 4 normalized shorts (stride 8)
  kExponential,  // floats, a mantissa and an exponent shared by each element's components
};

// Precision of the filters hullpack writes. Quaternions: 16 bits per stored component, within
// 1/32767 of each decoded component (about 0.004 degrees). Exponential: 16 mantissa bits, within
// 2^-15 of the element's largest component.
inline constexpr int kQuaternionFilterBits = 16;
inline constexpr int kExponentialFilterBits = 16;

// The stored form of `count` elements under `filter`: kQuaternion takes 4 floats per element (a
// quaternion, normalized here), kExponential `stride` / 4 floats (stride a multiple of 4). Every
// value must be finite. kNone is not a filter (empty result).
std::vector<uint8_t> ApplyMeshoptFilter(MeshoptFilter filter, const float* values, size_t count,
                                        size_t stride);

// What a reader gets back from ApplyMeshoptFilter's output (the filter undone in place).
void UndoMeshoptFilter(MeshoptFilter filter, std::vector<uint8_t>* elements, size_t stride);

// `elements` (`stride` bytes each, a multiple of 4 up to 256) compressed with the vertex codec.
std::vector<uint8_t> EncodeMeshoptAttributes(const std::vector<uint8_t>& elements, size_t stride);

// About how many more JSON bytes a compressed bufferView takes than a plain one, and what the
// first one adds (the fallback buffer, the extension's name in the two lists): small arrays are
// smaller plain.
inline constexpr size_t kMeshoptViewJsonBytes = 150;
inline constexpr size_t kMeshoptFileJsonBytes = 150;

// Adds a bufferView for `count` elements of `stride` bytes stored as `encoded`
// (EncodeMeshoptAttributes of their stored form: ApplyMeshoptFilter's when `filter` is not
// kNone), and marks the extension used and required. Returns the view's index; its accessors
// address the decoded elements.
int AddMeshoptBufferView(GltfDocument& doc, const std::vector<uint8_t>& encoded, size_t count,
                         size_t stride, MeshoptFilter filter);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_MESHOPT_DEFLATE_H_
