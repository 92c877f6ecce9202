#include "gltf/embedded_buffers.h"

#include "gltf/glb_reader_decoder.h"
#include "gltf/json_members.h"

namespace hullpack {

Result<const std::vector<uint8_t>*> EmbeddedBuffers::Get(int64_t index, const std::string& where) {
  const nlohmann::json& json = doc_.json();
  const std::string item = "buffers[" + std::to_string(index) + "]";
  if (index < 0 || !json.contains("buffers") || !json["buffers"].is_array() ||
      static_cast<uint64_t>(index) >= json["buffers"].size())
    return Status(StatusCode::kParseError, where + ": " + item + " does not exist");
  const nlohmann::json& b = json["buffers"][static_cast<size_t>(index)];
  if (!b.is_object())
    return Status(StatusCode::kParseError, where + ": " + item + " is not an object");
  if (!b.contains("uri")) {
    if (index != 0 || !doc_.has_binary_chunk()) {
      return Status(StatusCode::kParseError,
                    where + ": " + item + " has no uri and is not the GLB binary chunk");
    }
    return &doc_.binary();
  }
  std::string uri;
  if (!gltf::GetStringMember(b, "uri", &uri))
    return Status(StatusCode::kParseError, where + ": " + item + ": uri is not a string");
  if (!glb_reader_internal::IsDataUri(uri)) {
    return Status(StatusCode::kUnsupported,
                  where + ": " + item +
                      " is an external file; compressed data is read from a GLB or data: URIs "
                      "only (convert the .gltf to .glb first)");
  }
  auto cached = data_uris_.find(index);
  if (cached != data_uris_.end()) return &cached->second;
  glb_reader_internal::DataUri parsed;
  std::string error;
  if (!glb_reader_internal::ParseDataUri(uri, &parsed, &error))
    return Status(StatusCode::kParseError, where + ": " + item + ": " + error);
  return &data_uris_.emplace(index, std::move(parsed.bytes)).first->second;
}

Result<ByteRange> EmbeddedBuffers::Range(int64_t index, uint64_t offset, uint64_t length,
                                         const std::string& where) {
  Result<const std::vector<uint8_t>*> buffer = Get(index, where);
  if (!buffer.ok()) return buffer.status();
  const std::vector<uint8_t>& bytes = *buffer.value();
  if (offset > bytes.size() || length > bytes.size() - offset) {
    return Status(StatusCode::kParseError, where + ": bytes " + std::to_string(offset) + " + " +
                                               std::to_string(length) + " lie outside buffers[" +
                                               std::to_string(index) + "] (" +
                                               std::to_string(bytes.size()) + " bytes)");
  }
  return ByteRange{bytes.data() + offset, static_cast<size_t>(length)};
}

}  // namespace hullpack
