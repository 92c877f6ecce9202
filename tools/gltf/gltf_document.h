// A glTF 2.0 document in memory: the JSON tree plus the GLB binary chunk (buffer 0).
//
// Both directions use it. Writers build one with the Add* helpers (aligned appends to the binary
// chunk, bufferViews, accessors, extension bookkeeping) and call Serialize() for GLB bytes; the
// plain writer (glb_writer.h) and the packaging stage share it, so the packer can add compressed
// streams as extra bufferViews and any `extensions` object on top of what the plain writer
// produced. Readers get one from ParseGlb()/ParseGltfJson(): the JSON is parsed, but nothing in it
// is trusted yet — glb_reader.h does the checked conversion into the scene model.
#ifndef HULLPACK_TOOLS_GLTF_GLTF_DOCUMENT_H_
#define HULLPACK_TOOLS_GLTF_GLTF_DOCUMENT_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/status.h"

namespace hullpack {
namespace gltf {

// GLB container constants (glTF 2.0, section "Binary glTF Layout").
constexpr uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr uint32_t kGlbVersion = 2;
constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr size_t kGlbHeaderSize = 12;
constexpr size_t kChunkHeaderSize = 8;

// accessor.componentType
constexpr int kByte = 5120;
constexpr int kUnsignedByte = 5121;
constexpr int kShort = 5122;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

// bufferView.target
constexpr int kNoTarget = 0;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// mesh.primitive.mode
constexpr int kModePoints = 0;
constexpr int kModeTriangles = 4;
constexpr int kModeTriangleStrip = 5;
constexpr int kModeTriangleFan = 6;

// Bytes per component of `component_type`, or 0 when it is not a glTF component type.
size_t ComponentSize(int component_type);
// Components of an accessor.type ("SCALAR" 1, "VEC2" 2, ..., "MAT4" 16), or 0 when unknown.
int ComponentCount(const std::string& type);

}  // namespace gltf

// What AddAccessor writes. min/max are omitted when empty.
struct AccessorDesc {
  int buffer_view = -1;  // -1: no bufferView (zero-filled, or an extension supplies the data)
  size_t byte_offset = 0;
  int component_type = gltf::kFloat;
  size_t count = 0;
  std::string type = "SCALAR";
  bool normalized = false;
  std::vector<double> min;
  std::vector<double> max;
};

class GltfDocument {
 public:
  // An empty document: {"asset": {"version": "2.0"}}.
  GltfDocument();
  GltfDocument(nlohmann::json json, std::vector<uint8_t> binary, bool has_binary_chunk,
               size_t source_size);

  nlohmann::json& json() { return json_; }
  const nlohmann::json& json() const { return json_; }

  // The GLB BIN chunk, which is buffer 0 of a GLB (without its trailing padding when written here).
  std::vector<uint8_t>& binary() { return binary_; }
  const std::vector<uint8_t>& binary() const { return binary_; }
  // True for a parsed GLB that carried a BIN chunk, and for a built document once bytes were added.
  bool has_binary_chunk() const { return has_binary_chunk_ || !binary_.empty(); }
  // Bytes of the file this document was parsed from (0 for a built one); bounds reader allocations.
  size_t source_size() const { return source_size_; }

  // Appends `size` bytes to the binary chunk at the next multiple of `alignment` (a power of two,
  // at least 1; the gap is zero-filled) and adds a bufferView on buffer 0 for them. `target` is
  // gltf::kArrayBuffer / kElementArrayBuffer or kNoTarget; `byte_stride` 0 is omitted.
  // Returns the new bufferView's index.
  int AddBufferView(const void* data, size_t size, size_t alignment, int target = gltf::kNoTarget,
                    size_t byte_stride = 0);
  int AddBufferView(const std::vector<uint8_t>& bytes, size_t alignment,
                    int target = gltf::kNoTarget, size_t byte_stride = 0) {
    return AddBufferView(bytes.data(), bytes.size(), alignment, target, byte_stride);
  }

  // Adds an accessor; returns its index.
  int AddAccessor(const AccessorDesc& desc);

  // Appends `value` to the top-level array `array_name` ("meshes", "nodes", ...), creating it when
  // missing; returns the new element's index.
  int Append(const std::string& array_name, nlohmann::json value);

  // Lists `name` in extensionsUsed (once) and, when `required`, in extensionsRequired.
  void UseExtension(const std::string& name, bool required);
  // Removes `name` from extensionsUsed and extensionsRequired (a list left empty goes too): what a
  // reader does once it has decoded an extension's data into plain glTF.
  void DropExtension(const std::string& name);

  // The GLB file: header, JSON chunk (space-padded), BIN chunk (zero-padded; omitted when the
  // binary chunk is empty). Sets buffers[0].byteLength. Fails when the file would exceed 4 GiB.
  Result<std::vector<uint8_t>> Serialize() const;
  // The .gltf form of the same document: the JSON text, with buffer 0 (the binary chunk, which the
  // caller writes as its own file) at `buffer_uri`, a URI relative to the .gltf. Fails when another
  // buffer has no uri (it would only exist inside a GLB).
  Result<std::string> SerializeJson(const std::string& buffer_uri) const;

 private:
  nlohmann::json json_;
  std::vector<uint8_t> binary_;
  bool has_binary_chunk_ = false;
  size_t source_size_ = 0;
};

// Splits a GLB file into its JSON and BIN chunks and parses the JSON. Every header field is checked
// against `size`; errors are kParseError/kUnsupported with `name` in the message.
Result<GltfDocument> ParseGlb(const uint8_t* data, size_t size, const std::string& name);

// Parses a .gltf JSON text (no binary chunk).
Result<GltfDocument> ParseGltfJson(const uint8_t* data, size_t size, const std::string& name);

// ParseGlb when `data` starts with the GLB magic, ParseGltfJson otherwise.
Result<GltfDocument> ParseGltfBytes(const uint8_t* data, size_t size, const std::string& name);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_GLTF_DOCUMENT_H_
