#include "gltf/gltf_document.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <utility>

namespace hullpack {
namespace gltf {

size_t ComponentSize(int component_type) {
  switch (component_type) {
    case kByte:
    case kUnsignedByte:
      return 1;
    case kShort:
    case kUnsignedShort:
      return 2;
    case kUnsignedInt:
    case kFloat:
      return 4;
    default:
      return 0;
  }
}

int ComponentCount(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  if (type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

}  // namespace gltf

namespace {

uint32_t ReadU32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
         (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}

void AppendU32(std::vector<uint8_t>& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

constexpr int kMaxJsonDepth = 256;

Status ParseError(const std::string& name, const std::string& what) {
  return Status(StatusCode::kParseError, name + ": " + what);
}

// True when brackets outside strings nest deeper than `limit` (exact for valid JSON).
bool NestsDeeperThan(const uint8_t* data, size_t size, int limit) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < size; ++i) {
    const uint8_t c = data[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

Result<nlohmann::json> ParseJsonText(const uint8_t* data, size_t size, const std::string& name) {
  try {
    // Deeply nested values are refused before parsing: copying or dumping a json value recurses
    // per level. (nlohmann's parser callback could count depth too, but it is quadratic on large
    // arrays, so the text is scanned instead.)
    if (NestsDeeperThan(data, size, kMaxJsonDepth)) {
      return ParseError(
          name, "the glTF JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    nlohmann::json j = nlohmann::json::parse(data, data + size);
    if (!j.is_object()) return ParseError(name, "the glTF JSON is not an object");
    return j;
  } catch (const nlohmann::json::parse_error& e) {
    return ParseError(name, std::string("invalid glTF JSON: ") + e.what());
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kUnsupported, name + ": the glTF JSON is too large to parse");
  } catch (const std::exception& e) {
    return ParseError(name, std::string("invalid glTF JSON: ") + e.what());
  }
}

}  // namespace

GltfDocument::GltfDocument() : json_({{"asset", {{"version", "2.0"}}}}) {}

GltfDocument::GltfDocument(nlohmann::json json, std::vector<uint8_t> binary, bool has_binary_chunk,
                           size_t source_size)
    : json_(std::move(json)),
      binary_(std::move(binary)),
      has_binary_chunk_(has_binary_chunk),
      source_size_(source_size) {}

int GltfDocument::AddBufferView(const void* data, size_t size, size_t alignment, int target,
                                size_t byte_stride) {
  if (alignment == 0) alignment = 1;
  while (binary_.size() % alignment != 0) binary_.push_back(0);
  const size_t offset = binary_.size();
  if (size > 0) {
    const uint8_t* bytes = static_cast<const uint8_t*>(data);
    binary_.insert(binary_.end(), bytes, bytes + size);
  }
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
  if (byte_stride != 0) view["byteStride"] = byte_stride;
  if (target != gltf::kNoTarget) view["target"] = target;
  return Append("bufferViews", std::move(view));
}

namespace {

// The shortest decimal that reads back as the same float. Bounds of float accessors need no more
// digits: the 17 of a double would double their share of the JSON (a collision hull's accessors
// are most of its JSON). Values that are not floats are left alone.
double ShortestFloatDecimal(double v) {
  const float f = static_cast<float>(v);
  if (!std::isfinite(f) || static_cast<double>(f) != v) return v;
  char text[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, static_cast<double>(f));
    if (std::strtof(text, nullptr) == f) return std::strtod(text, nullptr);
  }
  return v;
}

nlohmann::json Bounds(const std::vector<double>& values, int component_type) {
  nlohmann::json out = nlohmann::json::array();
  for (double v : values)
    out.push_back(component_type == gltf::kFloat ? ShortestFloatDecimal(v) : v);
  return out;
}

}  // namespace

int GltfDocument::AddAccessor(const AccessorDesc& desc) {
  nlohmann::json a = nlohmann::json::object();
  if (desc.buffer_view >= 0) {
    a["bufferView"] = desc.buffer_view;
    if (desc.byte_offset != 0) a["byteOffset"] = desc.byte_offset;
  }
  a["componentType"] = desc.component_type;
  if (desc.normalized) a["normalized"] = true;
  a["count"] = desc.count;
  a["type"] = desc.type;
  if (!desc.min.empty()) a["min"] = Bounds(desc.min, desc.component_type);
  if (!desc.max.empty()) a["max"] = Bounds(desc.max, desc.component_type);
  return Append("accessors", std::move(a));
}

int GltfDocument::Append(const std::string& array_name, nlohmann::json value) {
  nlohmann::json& arr = json_[array_name];
  if (!arr.is_array()) arr = nlohmann::json::array();
  arr.push_back(std::move(value));
  return static_cast<int>(arr.size() - 1);
}

void GltfDocument::UseExtension(const std::string& name, bool required) {
  auto add_once = [this, &name](const char* key) {
    nlohmann::json& arr = json_[key];
    if (!arr.is_array()) arr = nlohmann::json::array();
    for (const auto& e : arr) {
      if (e.is_string() && e.get<std::string>() == name) return;
    }
    arr.push_back(name);
  };
  add_once("extensionsUsed");
  if (required) add_once("extensionsRequired");
}

void GltfDocument::DropExtension(const std::string& name) {
  for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
    if (!json_.contains(list) || !json_[list].is_array()) continue;
    nlohmann::json kept = nlohmann::json::array();
    for (const auto& e : json_[list]) {
      if (!(e.is_string() && e.get<std::string>() == name)) kept.push_back(e);
    }
    if (kept.empty()) {
      json_.erase(list);
    } else {
      json_[list] = std::move(kept);
    }
  }
}

namespace {

// buffers[0] of `j`, made an object (and the list made) when it is not one.
nlohmann::json& BufferZero(nlohmann::json& j) {
  nlohmann::json& buffers = j["buffers"];
  if (!buffers.is_array()) buffers = nlohmann::json::array();
  if (buffers.empty()) buffers.push_back(nlohmann::json::object());
  if (!buffers[0].is_object()) buffers[0] = nlohmann::json::object();
  return buffers[0];
}

// Invalid UTF-8 in names is replaced rather than failing the whole write.
Result<std::string> DumpJson(const nlohmann::json& j) {
  try {
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  } catch (const std::exception& e) {
    return Status(StatusCode::kInternal, std::string("cannot serialize glTF JSON: ") + e.what());
  }
}

}  // namespace

Result<std::string> GltfDocument::SerializeJson(const std::string& buffer_uri) const {
  nlohmann::json j = json_;
  if (!binary_.empty()) {
    nlohmann::json& buffer = BufferZero(j);
    buffer["uri"] = buffer_uri;
    buffer["byteLength"] = binary_.size();
  }
  const nlohmann::json* buffers = j.contains("buffers") ? &j["buffers"] : nullptr;
  for (size_t b = binary_.empty() ? 0 : 1; buffers && buffers->is_array() && b < buffers->size();
       ++b) {
    if (!(*buffers)[b].is_object() || !(*buffers)[b].contains("uri")) {
      return Status(StatusCode::kUnsupported,
                    "buffer " + std::to_string(b) + " has no uri: it can only live in a GLB");
    }
  }
  return DumpJson(j);
}

Result<std::vector<uint8_t>> GltfDocument::Serialize() const {
  nlohmann::json j = json_;
  if (!binary_.empty()) {
    nlohmann::json& buffer = BufferZero(j);
    if (buffer.contains("uri")) {
      return Status(StatusCode::kInvalidArgument,
                    "buffer 0 has a uri, so it cannot be the GLB binary chunk");
    }
    buffer["byteLength"] = binary_.size();
  }
  Result<std::string> dumped = DumpJson(j);
  if (!dumped.ok()) return dumped.status();
  const std::string& text = dumped.value();
  const size_t json_padded = (text.size() + 3) & ~static_cast<size_t>(3);
  const size_t bin_padded = (binary_.size() + 3) & ~static_cast<size_t>(3);
  uint64_t total =
      gltf::kGlbHeaderSize + gltf::kChunkHeaderSize + static_cast<uint64_t>(json_padded);
  if (!binary_.empty()) total += gltf::kChunkHeaderSize + static_cast<uint64_t>(bin_padded);
  if (total > std::numeric_limits<uint32_t>::max()) {
    return Status(StatusCode::kUnsupported, "the GLB would be " + std::to_string(total) +
                                                " bytes; GLB files are limited to 4 GiB");
  }
  std::vector<uint8_t> out;
  out.reserve(static_cast<size_t>(total));
  AppendU32(out, gltf::kGlbMagic);
  AppendU32(out, gltf::kGlbVersion);
  AppendU32(out, static_cast<uint32_t>(total));
  AppendU32(out, static_cast<uint32_t>(json_padded));
  AppendU32(out, gltf::kChunkJson);
  out.insert(out.end(), text.begin(), text.end());
  out.resize(out.size() + (json_padded - text.size()), ' ');
  if (!binary_.empty()) {
    AppendU32(out, static_cast<uint32_t>(bin_padded));
    AppendU32(out, gltf::kChunkBin);
    out.insert(out.end(), binary_.begin(), binary_.end());
    out.resize(out.size() + (bin_padded - binary_.size()), 0);
  }
  return out;
}

Result<GltfDocument> ParseGlb(const uint8_t* data, size_t size, const std::string& name) {
  if (data == nullptr || size < gltf::kGlbHeaderSize) {
    return ParseError(name,
                      "truncated GLB: " + std::to_string(size) + " bytes, the header needs 12");
  }
  if (ReadU32(data) != gltf::kGlbMagic) return ParseError(name, "not a GLB file (wrong magic)");
  const uint32_t version = ReadU32(data + 4);
  if (version != gltf::kGlbVersion) {
    return Status(StatusCode::kUnsupported, name + ": GLB version " + std::to_string(version) +
                                                " (only version 2 is supported)");
  }
  const uint32_t length = ReadU32(data + 8);
  if (length > size) {
    return ParseError(name, "truncated GLB: the header declares " + std::to_string(length) +
                                " bytes but the file has " + std::to_string(size));
  }
  if (length < gltf::kGlbHeaderSize + gltf::kChunkHeaderSize) {
    return ParseError(
        name, "GLB length " + std::to_string(length) + " leaves no room for the JSON chunk");
  }
  size_t pos = gltf::kGlbHeaderSize;
  bool have_json = false;
  bool have_bin = false;
  nlohmann::json json;
  std::vector<uint8_t> bin;
  int chunk_index = 0;
  while (pos < length) {
    if (length - pos < gltf::kChunkHeaderSize) {
      return ParseError(name, "truncated GLB: chunk " + std::to_string(chunk_index) +
                                  " header at byte " + std::to_string(pos) + " is cut off");
    }
    const uint32_t chunk_length = ReadU32(data + pos);
    const uint32_t chunk_type = ReadU32(data + pos + 4);
    pos += gltf::kChunkHeaderSize;
    if (chunk_length > length - pos) {
      return ParseError(name, "GLB chunk " + std::to_string(chunk_index) + " declares " +
                                  std::to_string(chunk_length) + " bytes but only " +
                                  std::to_string(length - pos) + " remain");
    }
    const uint8_t* chunk = data + pos;
    if (chunk_index == 0) {
      if (chunk_type != gltf::kChunkJson)
        return ParseError(name, "the first GLB chunk is not JSON");
      Result<nlohmann::json> parsed = ParseJsonText(chunk, chunk_length, name);
      if (!parsed.ok()) return parsed.status();
      json = std::move(parsed).value();
      have_json = true;
    } else if (chunk_type == gltf::kChunkJson) {
      return ParseError(name, "the GLB has a second JSON chunk");
    } else if (chunk_type == gltf::kChunkBin) {
      if (have_bin) return ParseError(name, "the GLB has more than one BIN chunk");
      bin.assign(chunk, chunk + chunk_length);
      have_bin = true;
    }
    // Other chunk types are skipped, as the specification asks.
    pos += chunk_length;
    ++chunk_index;
  }
  if (!have_json) return ParseError(name, "the GLB has no JSON chunk");
  return GltfDocument(std::move(json), std::move(bin), have_bin, size);
}

Result<GltfDocument> ParseGltfJson(const uint8_t* data, size_t size, const std::string& name) {
  if (data == nullptr || size == 0) return ParseError(name, "empty glTF file");
  Result<nlohmann::json> parsed = ParseJsonText(data, size, name);
  if (!parsed.ok()) return parsed.status();
  return GltfDocument(std::move(parsed).value(), {}, false, size);
}

Result<GltfDocument> ParseGltfBytes(const uint8_t* data, size_t size, const std::string& name) {
  if (data != nullptr && size >= 4 && ReadU32(data) == gltf::kGlbMagic)
    return ParseGlb(data, size, name);
  return ParseGltfJson(data, size, name);
}

}  // namespace hullpack
