// The container of a glTF: base64, data URIs and files, JSON access, required extensions and
// buffers.
#include "gltf/glb_reader_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <set>
#include <utility>
#include "gltf/json_members.h"

namespace hullpack {
namespace glb_reader_internal {

int Base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;
  if (c == '/' || c == '_') return 63;
  return -1;
}

// Decodes standard or URL-safe base64 (padding optional). False on any other character.
bool DecodeBase64(const std::string& text, size_t begin, std::vector<uint8_t>* out) {
  out->clear();
  out->reserve((text.size() - begin) / 4 * 3 + 3);
  uint32_t acc = 0;
  int bits = 0;
  size_t i = begin;
  for (; i < text.size() && text[i] != '='; ++i) {
    const int v = Base64Value(text[i]);
    if (v < 0) return false;
    acc = (acc << 6) | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out->push_back(static_cast<uint8_t>(acc >> bits));
    }
  }
  for (; i < text.size(); ++i) {
    if (text[i] != '=') return false;
  }
  return true;
}

bool ParseDataUri(const std::string& uri, DataUri* out, std::string* error) {
  const size_t comma = uri.find(',');
  if (comma == std::string::npos) {
    *error = "data URI without ','";
    return false;
  }
  const std::string header = uri.substr(5, comma - 5);
  out->mime_type = header.substr(0, header.find(';'));
  static const std::string kBase64 = ";base64";
  if (header.size() < kBase64.size() ||
      header.compare(header.size() - kBase64.size(), kBase64.size(), kBase64) != 0) {
    *error = "only base64 data URIs are supported";
    return false;
  }
  if (!DecodeBase64(uri, comma + 1, &out->bytes)) {
    *error = "invalid base64 in data URI";
    return false;
  }
  return true;
}

bool IsDataUri(const std::string& uri) { return uri.compare(0, 5, "data:") == 0; }

Status ReadWholeFile(const std::string& path, std::vector<uint8_t>* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status(StatusCode::kIoError, path + ": cannot open");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) return Status(StatusCode::kIoError, path + ": cannot determine the size");
  in.seekg(0, std::ios::beg);
  out->resize(static_cast<size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), size)) {
    return Status(StatusCode::kIoError, path + ": read failed");
  }
  return Status::Ok();
}

Status Decoder::GetArray(const json& obj, const char* key, const std::string& where,
                         const json** out) const {
  *out = nullptr;
  auto it = obj.find(key);
  if (it == obj.end()) return Status::Ok();
  if (!it->is_array()) return Error(where, std::string("'") + key + "' is not an array");
  *out = &*it;
  return Status::Ok();
}

Status Decoder::GetUint(const json& obj, const char* key, const std::string& where, uint64_t def,
                        uint64_t* out) const {
  if (!gltf::GetUintMember(obj, key, def, out)) {
    return Error(where, std::string("'") + key + "' is not a non-negative integer");
  }
  return Status::Ok();
}

Status Decoder::GetIndex(const json& obj, const char* key, const std::string& where,
                         int64_t* out) const {
  uint64_t v = 0;
  if (obj.find(key) == obj.end()) {
    *out = -1;
    return Status::Ok();
  }
  HP_RETURN_IF_ERROR(GetUint(obj, key, where, 0, &v));
  if (v > kMaxIndex)
    return Error(where, std::string("'") + key + "' index " + std::to_string(v) + " is too large");
  *out = static_cast<int64_t>(v);
  return Status::Ok();
}

Status Decoder::GetNumber(const json& obj, const char* key, const std::string& where,
                          double* out) const {
  auto it = obj.find(key);
  if (it == obj.end()) return Status::Ok();
  if (!it->is_number()) return Error(where, std::string("'") + key + "' is not a number");
  const double v = it->get<double>();
  if (!std::isfinite(v)) return Error(where, std::string("'") + key + "' is not finite");
  *out = v;
  return Status::Ok();
}

Status Decoder::GetNumbers(const json& obj, const char* key, const std::string& where, size_t n,
                           double* out) const {
  auto it = obj.find(key);
  if (it == obj.end()) return Status::Ok();
  if (!it->is_array() || it->size() != n) {
    return Error(where,
                 std::string("'") + key + "' is not an array of " + std::to_string(n) + " numbers");
  }
  for (size_t i = 0; i < n; ++i) {
    const json& v = (*it)[i];
    if (!v.is_number() || !std::isfinite(v.get<double>())) {
      return Error(where, std::string("'") + key + "' element " + std::to_string(i) +
                              " is not a finite number");
    }
    out[i] = v.get<double>();
  }
  return Status::Ok();
}

Status Decoder::GetString(const json& obj, const char* key, const std::string& where,
                          std::string* out) const {
  if (!gltf::GetStringMember(obj, key, out))
    return Error(where, std::string("'") + key + "' is not a string");
  return Status::Ok();
}

Status Decoder::GetBool(const json& obj, const char* key, const std::string& where,
                        bool* out) const {
  if (!gltf::GetBoolMember(obj, key, out))
    return Error(where, std::string("'") + key + "' is not a boolean");
  return Status::Ok();
}

Status Decoder::TopLevel(const char* key, const json** out) {
  // Each array is checked once; lookups after that are O(1), so per-accessor calls stay linear.
  auto cached = top_level_.find(key);
  if (cached != top_level_.end()) {
    *out = cached->second;
    return Status::Ok();
  }
  HP_RETURN_IF_ERROR(GetArray(root_, key, "glTF", out));
  if (*out != nullptr) {
    for (size_t i = 0; i < (*out)->size(); ++i) {
      if (!(**out)[i].is_object()) return Error(Item(key, i), "is not an object");
    }
  }
  top_level_.emplace(key, *out);
  return Status::Ok();
}

Status Decoder::CheckExtensions() {
  static const std::set<std::string> kUnderstood = {
      "KHR_mesh_quantization", "KHR_texture_transform", "KHR_materials_unlit",
      "KHR_materials_emissive_strength", "KHR_lights_punctual"};
  const json* required = nullptr;
  HP_RETURN_IF_ERROR(GetArray(root_, "extensionsRequired", "glTF", &required));
  if (required != nullptr) {
    for (const json& e : *required) {
      if (!e.is_string()) return Error("extensionsRequired", "holds a non-string");
      const std::string ext = e.get<std::string>();
      if (kUnderstood.count(ext) != 0) continue;
      if (std::find(options_.handled_extensions.begin(), options_.handled_extensions.end(), ext) !=
          options_.handled_extensions.end()) {
        continue;
      }
      return Unsupported("extensionsRequired",
                         "requires " + ext + ", which this reader cannot decode");
    }
  }
  const json* used = nullptr;
  HP_RETURN_IF_ERROR(GetArray(root_, "extensionsUsed", "glTF", &used));
  if (used != nullptr) {
    std::string ignored;
    for (const json& e : *used) {
      if (!e.is_string()) return Error("extensionsUsed", "holds a non-string");
      const std::string ext = e.get<std::string>();
      if (kUnderstood.count(ext) != 0) continue;
      if (std::find(options_.handled_extensions.begin(), options_.handled_extensions.end(), ext) !=
          options_.handled_extensions.end()) {
        continue;
      }
      ignored += (ignored.empty() ? "" : ", ") + ext;
    }
    if (!ignored.empty()) Drop("ignored extensions: " + ignored);
  }
  return Status::Ok();
}

Status Decoder::GetBuffer(int64_t index, const std::string& where, const BufferData** out) {
  const json* buffers = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("buffers", &buffers));
  if (index < 0 || buffers == nullptr || static_cast<size_t>(index) >= buffers->size()) {
    return Error(where, "buffer " + std::to_string(index) + " does not exist");
  }
  if (buffers_.size() < buffers->size()) buffers_.resize(buffers->size());
  std::unique_ptr<BufferData>& slot = buffers_[static_cast<size_t>(index)];
  if (slot != nullptr) {
    *out = slot.get();
    return Status::Ok();
  }
  const std::string bw = Item("buffers", static_cast<uint64_t>(index));
  const json& b = (*buffers)[static_cast<size_t>(index)];
  uint64_t length = 0;
  if (b.find("byteLength") == b.end()) return Error(bw, "has no byteLength");
  HP_RETURN_IF_ERROR(GetUint(b, "byteLength", bw, 0, &length));
  std::string uri;
  HP_RETURN_IF_ERROR(GetString(b, "uri", bw, &uri));
  auto data = std::make_unique<BufferData>();
  if (b.find("uri") == b.end()) {
    if (index != 0 || !doc_.has_binary_chunk()) {
      return Error(bw, "has no uri and is not the GLB binary chunk");
    }
    if (length > doc_.binary().size()) {
      return Error(bw, "byteLength " + std::to_string(length) + " exceeds the GLB binary chunk (" +
                           std::to_string(doc_.binary().size()) + " bytes)");
    }
    data->data = doc_.binary().data();
  } else if (IsDataUri(uri)) {
    DataUri parsed;
    std::string error;
    if (!ParseDataUri(uri, &parsed, &error)) return Error(bw, error);
    if (length > parsed.bytes.size()) {
      return Error(bw, "byteLength " + std::to_string(length) + " exceeds its data URI (" +
                           std::to_string(parsed.bytes.size()) + " bytes)");
    }
    data->storage = std::move(parsed.bytes);
    data->data = data->storage.data();
  } else {
    if (options_.base_dir.empty()) {
      return Unsupported(
          bw, "external buffer '" + uri + "' cannot be resolved when reading from memory");
    }
    std::string rel, error;
    if (!RelativePathFromUri(uri, &rel, &error))
      return Unsupported(bw, "buffer uri '" + uri + "': " + error);
    const std::string path = options_.base_dir + "/" + rel;
    std::ifstream in(path, std::ios::binary);
    if (!in)
      return Status(StatusCode::kIoError,
                    name_ + ": " + bw + ": cannot open external buffer " + path);
    in.seekg(0, std::ios::end);
    const std::streamoff file_size = in.tellg();
    if (file_size < 0 || static_cast<uint64_t>(file_size) < length) {
      return Error(bw, "byteLength " + std::to_string(length) + " exceeds " + path + " (" +
                           std::to_string(file_size) + " bytes)");
    }
    in.seekg(0, std::ios::beg);
    data->storage.resize(static_cast<size_t>(length));
    if (length > 0 && !in.read(reinterpret_cast<char*>(data->storage.data()),
                               static_cast<std::streamsize>(length))) {
      return Status(StatusCode::kIoError, name_ + ": " + bw + ": cannot read " + path);
    }
    data->data = data->storage.data();
    budget_ +=
        length * std::max<size_t>(options_.max_expansion, 1);  // external input earns budget too
  }
  data->size = static_cast<size_t>(length);
  data->resolved = true;
  slot = std::move(data);
  *out = slot.get();
  return Status::Ok();
}

}  // namespace glb_reader_internal
}  // namespace hullpack
