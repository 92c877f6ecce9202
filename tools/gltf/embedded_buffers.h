// The bytes of a document's buffers that travel inside it: the GLB binary chunk (buffer 0 without
// a uri) and data: URIs. What a document-level decoder of compressed data
// (KHR_draco_mesh_compression, EXT_meshopt_compression) reads its streams from; external buffer
// files are the reader's concern.
#ifndef HULLPACK_TOOLS_GLTF_EMBEDDED_BUFFERS_H_
#define HULLPACK_TOOLS_GLTF_EMBEDDED_BUFFERS_H_

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "common/status.h"
#include "gltf/gltf_document.h"

namespace hullpack {

struct ByteRange {
  const uint8_t* data = nullptr;
  size_t size = 0;
};

class EmbeddedBuffers {
 public:
  explicit EmbeddedBuffers(const GltfDocument& doc) : doc_(doc) {}

  // Buffer `index`'s bytes. kParseError for a buffer that does not exist or is malformed,
  // kUnsupported for one in an external file. `where` prefixes the message.
  Result<const std::vector<uint8_t>*> Get(int64_t index, const std::string& where);

  // Bytes [offset, offset + length) of buffer `index`, checked against its size.
  Result<ByteRange> Range(int64_t index, uint64_t offset, uint64_t length,
                          const std::string& where);

  // Whether any buffer came from a data: URI (its bytes are not in the binary chunk).
  bool used_data_uris() const { return !data_uris_.empty(); }

 private:
  const GltfDocument& doc_;
  std::map<int64_t, std::vector<uint8_t>> data_uris_;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_EMBEDDED_BUFFERS_H_
