#include "gltf/glb_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <utility>

#include "gltf/json_members.h"
#include "gltf/node_forest.h"

namespace hullpack {
namespace {

using nlohmann::json;

#define HP_RETURN_IF_ERROR(expr)             \
  do {                                       \
    Status hp_status_ = (expr);              \
    if (!hp_status_.ok()) return hp_status_; \
  } while (0)

constexpr uint64_t kMaxIndex = static_cast<uint64_t>(std::numeric_limits<int>::max());

std::string Item(const char* array, uint64_t index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

bool MulAdd(uint64_t a, uint64_t b, uint64_t c, uint64_t* out) {
  uint64_t m;
  if (__builtin_mul_overflow(a, b, &m)) return false;
  return !__builtin_add_overflow(m, c, out);
}

uint32_t LoadU32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
         (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}

uint16_t LoadU16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }

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

struct DataUri {
  std::string mime_type;
  std::vector<uint8_t> bytes;
};

// "data:<mime>;base64,<payload>". Returns false with `error` set when malformed.
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

std::string DirName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// A checked accessor: where its elements are and how to read them.
struct AccessorView {
  const uint8_t* data = nullptr;  // first element; nullptr for a zero-filled accessor
  size_t count = 0;
  int components = 0;
  int component_type = 0;
  size_t stride = 0;
  bool normalized = false;
  std::string type;
};

double ReadComponent(const uint8_t* p, int component_type, bool normalized) {
  switch (component_type) {
    case gltf::kByte: {
      const double v = static_cast<int8_t>(p[0]);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case gltf::kUnsignedByte: {
      const double v = p[0];
      return normalized ? v / 255.0 : v;
    }
    case gltf::kShort: {
      const double v = static_cast<int16_t>(LoadU16(p));
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case gltf::kUnsignedShort: {
      const double v = LoadU16(p);
      return normalized ? v / 65535.0 : v;
    }
    case gltf::kUnsignedInt:
      return static_cast<double>(LoadU32(p));
    case gltf::kFloat: {
      const uint32_t bits = LoadU32(p);
      float f;
      std::memcpy(&f, &bits, sizeof f);
      return f;
    }
    default:
      return 0;
  }
}

uint32_t ReadUnsigned(const uint8_t* p, int component_type) {
  switch (component_type) {
    case gltf::kUnsignedByte:
      return p[0];
    case gltf::kUnsignedShort:
      return LoadU16(p);
    case gltf::kUnsignedInt:
      return LoadU32(p);
    default:
      return 0;
  }
}

struct BufferData {
  bool resolved = false;
  std::vector<uint8_t> storage;  // data URI or external file contents
  const uint8_t* data = nullptr;
  size_t size = 0;  // the declared byteLength (checked against the data)
};

class Decoder {
 public:
  Decoder(const GltfDocument& doc, const std::string& name, const GltfReadOptions& options)
      : doc_(doc), root_(doc.json()), name_(name), options_(options) {
    uint64_t input = doc.source_size() != 0 ? doc.source_size() : doc.binary().size();
    budget_ = input * std::max<size_t>(options.max_expansion, 1) + (1u << 20);
  }

  Result<Scene> Run();

 private:
  Status Error(const std::string& where, const std::string& what) const {
    return Status(StatusCode::kParseError, name_ + ": " + where + ": " + what);
  }
  Status Unsupported(const std::string& where, const std::string& what) const {
    return Status(StatusCode::kUnsupported, name_ + ": " + where + ": " + what);
  }
  Status Charge(uint64_t bytes, const std::string& where) {
    if (bytes > budget_) {
      return Unsupported(where, "decoded data would exceed the limit of " +
                                    std::to_string(options_.max_expansion) +
                                    " bytes per input byte (file too small for what it declares)");
    }
    budget_ -= bytes;
    return Status::Ok();
  }

  // JSON access. Each returns an error naming `where` when the value has the wrong type.
  Status GetArray(const json& obj, const char* key, const std::string& where,
                  const json** out) const;
  Status GetIndex(const json& obj, const char* key, const std::string& where, int64_t* out) const;
  Status GetUint(const json& obj, const char* key, const std::string& where, uint64_t def,
                 uint64_t* out) const;
  Status GetNumbers(const json& obj, const char* key, const std::string& where, size_t n,
                    double* out) const;
  Status GetNumber(const json& obj, const char* key, const std::string& where, double* out) const;
  Status GetString(const json& obj, const char* key, const std::string& where,
                   std::string* out) const;
  Status GetBool(const json& obj, const char* key, const std::string& where, bool* out) const;
  // The top-level array `key` (empty when missing); elements must be objects.
  Status TopLevel(const char* key, const json** out);
  size_t TopCount(const char* key) const {
    auto it = root_.find(key);
    return it != root_.end() && it->is_array() ? it->size() : 0;
  }

  Status CheckExtensions();
  Status GetBuffer(int64_t index, const std::string& where, const BufferData** out);
  Status GetBufferView(int64_t index, const std::string& where, const uint8_t** data, size_t* size,
                       size_t* stride);
  Status GetAccessor(int64_t index, const std::string& where, AccessorView* out);
  // An accessor as floats (normalized integers mapped per the spec); its component count must be
  // one of `allowed_components`.
  Status ReadFloats(int64_t index, const std::string& where,
                    std::initializer_list<int> allowed_components, std::vector<float>* out,
                    int* components);
  Status ReadIndices(int64_t index, const std::string& where, std::vector<uint32_t>* out);

  Status DecodeImages(Scene* scene);
  Status DecodeTextureRef(const json& material, const char* key, const std::string& where,
                          bool inside_pbr, TextureRef* out);
  Status DecodeMaterials(Scene* scene);
  Status DecodeMesh(int64_t index, Scene* scene, Mesh* out);
  Status DecodeSkins(Scene* scene);
  Status DecodeNodes(Scene* scene);
  void Drop(const std::string& what) { dropped_.push_back(what); }

  const GltfDocument& doc_;
  const json& root_;
  std::string name_;
  GltfReadOptions options_;
  uint64_t budget_ = 0;
  std::vector<std::unique_ptr<BufferData>> buffers_;
  std::vector<std::string> dropped_;
  size_t morph_target_primitives_ = 0;
  size_t non_triangle_primitives_ = 0;
  std::set<std::string> dropped_attributes_;
  int default_material_ = -1;
  std::map<std::string, const json*> top_level_;  // checked top-level arrays (nullptr: absent)
};

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
  static const std::set<std::string> kUnderstood = {"KHR_mesh_quantization"};
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

Status Decoder::GetBufferView(int64_t index, const std::string& where, const uint8_t** data,
                              size_t* size, size_t* stride) {
  const json* views = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("bufferViews", &views));
  if (index < 0 || views == nullptr || static_cast<size_t>(index) >= views->size()) {
    return Error(where, "bufferView " + std::to_string(index) + " does not exist");
  }
  const std::string vw = Item("bufferViews", static_cast<uint64_t>(index));
  const json& v = (*views)[static_cast<size_t>(index)];
  int64_t buffer = -1;
  uint64_t offset = 0, length = 0, byte_stride = 0;
  HP_RETURN_IF_ERROR(GetIndex(v, "buffer", vw, &buffer));
  if (buffer < 0) return Error(vw, "has no buffer");
  if (v.find("byteLength") == v.end()) return Error(vw, "has no byteLength");
  HP_RETURN_IF_ERROR(GetUint(v, "byteOffset", vw, 0, &offset));
  HP_RETURN_IF_ERROR(GetUint(v, "byteLength", vw, 0, &length));
  HP_RETURN_IF_ERROR(GetUint(v, "byteStride", vw, 0, &byte_stride));
  if (v.find("byteStride") != v.end() &&
      (byte_stride < 4 || byte_stride > 252 || byte_stride % 4 != 0)) {
    return Error(vw,
                 "byteStride " + std::to_string(byte_stride) + " is not a multiple of 4 in 4..252");
  }
  const BufferData* buf = nullptr;
  HP_RETURN_IF_ERROR(GetBuffer(buffer, vw, &buf));
  uint64_t end = 0;
  if (__builtin_add_overflow(offset, length, &end) || end > buf->size) {
    return Error(vw, "bytes " + std::to_string(offset) + "+" + std::to_string(length) + " exceed " +
                         Item("buffers", static_cast<uint64_t>(buffer)) + " (" +
                         std::to_string(buf->size) + " bytes)");
  }
  *data = buf->data + offset;
  *size = static_cast<size_t>(length);
  *stride = static_cast<size_t>(byte_stride);
  return Status::Ok();
}

Status Decoder::GetAccessor(int64_t index, const std::string& where, AccessorView* out) {
  const json* accessors = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("accessors", &accessors));
  if (index < 0 || accessors == nullptr || static_cast<size_t>(index) >= accessors->size()) {
    return Error(where, "accessor " + std::to_string(index) + " does not exist");
  }
  const std::string aw = Item("accessors", static_cast<uint64_t>(index));
  const json& a = (*accessors)[static_cast<size_t>(index)];
  if (a.contains("sparse")) return Unsupported(aw, "sparse accessors are not supported");
  uint64_t component_type = 0, count = 0, offset = 0;
  if (a.find("componentType") == a.end()) return Error(aw, "has no componentType");
  if (a.find("count") == a.end()) return Error(aw, "has no count");
  HP_RETURN_IF_ERROR(GetUint(a, "componentType", aw, 0, &component_type));
  HP_RETURN_IF_ERROR(GetUint(a, "count", aw, 0, &count));
  HP_RETURN_IF_ERROR(GetUint(a, "byteOffset", aw, 0, &offset));
  const size_t csize =
      component_type > 0xFFFF ? 0 : gltf::ComponentSize(static_cast<int>(component_type));
  if (csize == 0) return Error(aw, "unknown componentType " + std::to_string(component_type));
  std::string type;
  HP_RETURN_IF_ERROR(GetString(a, "type", aw, &type));
  const int components = gltf::ComponentCount(type);
  if (components == 0) return Error(aw, "unknown type '" + type + "'");
  if ((type == "MAT2" || type == "MAT3") && csize < 4) {
    return Unsupported(aw, type + " accessors of 1- or 2-byte components are not supported");
  }
  bool normalized = false;
  HP_RETURN_IF_ERROR(GetBool(a, "normalized", aw, &normalized));
  if (normalized && (component_type == gltf::kFloat || component_type == gltf::kUnsignedInt)) {
    return Error(aw, "normalized is only allowed for byte and short components");
  }
  if (count == 0) return Error(aw, "count is 0");
  out->count = static_cast<size_t>(count);
  out->components = components;
  out->component_type = static_cast<int>(component_type);
  out->normalized = normalized;
  out->type = type;
  const size_t element = csize * static_cast<size_t>(components);
  int64_t view = -1;
  HP_RETURN_IF_ERROR(GetIndex(a, "bufferView", aw, &view));
  if (view < 0) {
    // Zero-filled: no bytes back it, so its size is charged against the budget before any
    // allocation.
    uint64_t bytes = 0;
    if (!MulAdd(count, element, 0, &bytes)) return Error(aw, "count overflows");
    HP_RETURN_IF_ERROR(Charge(bytes, aw));
    out->data = nullptr;
    out->stride = element;
    return Status::Ok();
  }
  const uint8_t* data = nullptr;
  size_t view_size = 0, stride = 0;
  HP_RETURN_IF_ERROR(GetBufferView(view, aw, &data, &view_size, &stride));
  if (stride == 0) stride = element;
  if (stride < element) {
    return Error(aw, "byteStride " + std::to_string(stride) + " is smaller than its element (" +
                         std::to_string(element) + " bytes)");
  }
  uint64_t span = 0;
  if (!MulAdd(count - 1, stride, element, &span) || __builtin_add_overflow(span, offset, &span) ||
      span > view_size) {
    return Error(aw, "byteOffset " + std::to_string(offset) + " + count " + std::to_string(count) +
                         " x stride " + std::to_string(stride) + " exceeds " +
                         Item("bufferViews", static_cast<uint64_t>(view)) + " (" +
                         std::to_string(view_size) + " bytes)");
  }
  out->data = data + offset;
  out->stride = stride;
  return Status::Ok();
}

Status Decoder::ReadFloats(int64_t index, const std::string& where,
                           std::initializer_list<int> allowed_components, std::vector<float>* out,
                           int* components) {
  AccessorView a;
  HP_RETURN_IF_ERROR(GetAccessor(index, where, &a));
  const std::string aw = where + " (" + Item("accessors", static_cast<uint64_t>(index)) + ")";
  if (std::find(allowed_components.begin(), allowed_components.end(), a.components) ==
      allowed_components.end()) {
    return Error(aw, "has type " + a.type + ", which this attribute does not allow");
  }
  const size_t n = a.count * static_cast<size_t>(a.components);
  HP_RETURN_IF_ERROR(Charge(static_cast<uint64_t>(n) * sizeof(float), aw));
  out->assign(n, 0.0f);
  if (a.data != nullptr) {
    const size_t csize = gltf::ComponentSize(a.component_type);
    for (size_t i = 0; i < a.count; ++i) {
      const uint8_t* e = a.data + i * a.stride;
      for (int c = 0; c < a.components; ++c) {
        (*out)[i * static_cast<size_t>(a.components) + static_cast<size_t>(c)] = static_cast<float>(
            ReadComponent(e + static_cast<size_t>(c) * csize, a.component_type, a.normalized));
      }
    }
  }
  *components = a.components;
  return Status::Ok();
}

Status Decoder::ReadIndices(int64_t index, const std::string& where, std::vector<uint32_t>* out) {
  AccessorView a;
  HP_RETURN_IF_ERROR(GetAccessor(index, where, &a));
  const std::string aw = where + " (" + Item("accessors", static_cast<uint64_t>(index)) + ")";
  if (a.components != 1 || a.normalized ||
      (a.component_type != gltf::kUnsignedByte && a.component_type != gltf::kUnsignedShort &&
       a.component_type != gltf::kUnsignedInt)) {
    return Error(aw, "is not an unsigned-integer SCALAR accessor");
  }
  HP_RETURN_IF_ERROR(Charge(static_cast<uint64_t>(a.count) * sizeof(uint32_t), aw));
  out->assign(a.count, 0);
  if (a.data != nullptr) {
    for (size_t i = 0; i < a.count; ++i)
      (*out)[i] = ReadUnsigned(a.data + i * a.stride, a.component_type);
  }
  return Status::Ok();
}

Status Decoder::DecodeImages(Scene* scene) {
  const json* images = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("images", &images));
  if (images == nullptr) return Status::Ok();
  for (size_t i = 0; i < images->size(); ++i) {
    const json& j = (*images)[i];
    const std::string iw = Item("images", i);
    Image img;
    HP_RETURN_IF_ERROR(GetString(j, "name", iw, &img.name));
    HP_RETURN_IF_ERROR(GetString(j, "mimeType", iw, &img.mime_type));
    std::string uri;
    HP_RETURN_IF_ERROR(GetString(j, "uri", iw, &uri));
    int64_t view = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "bufferView", iw, &view));
    if (view >= 0) {
      const uint8_t* data = nullptr;
      size_t size = 0, stride = 0;
      HP_RETURN_IF_ERROR(GetBufferView(view, iw, &data, &size, &stride));
      HP_RETURN_IF_ERROR(Charge(size, iw));
      img.bytes.assign(data, data + size);
    } else if (IsDataUri(uri)) {
      DataUri parsed;
      std::string error;
      if (!ParseDataUri(uri, &parsed, &error)) return Error(iw, error);
      img.bytes = std::move(parsed.bytes);
      if (img.mime_type.empty()) img.mime_type = parsed.mime_type;
    } else if (!uri.empty()) {
      img.uri = uri;
    } else {
      return Error(iw, "has neither a uri nor a bufferView");
    }
    scene->images.push_back(std::move(img));
  }
  return Status::Ok();
}

Status Decoder::DecodeTextureRef(const json& material, const char* key, const std::string& where,
                                 bool inside_pbr, TextureRef* out) {
  const json* holder = &material;
  if (inside_pbr) {
    auto it = material.find("pbrMetallicRoughness");
    if (it == material.end()) return Status::Ok();
    holder = &*it;
  }
  auto it = holder->find(key);
  if (it == holder->end()) return Status::Ok();
  const std::string tw = where + "." + key;
  if (!it->is_object()) return Error(tw, "is not an object");
  int64_t texture = -1;
  uint64_t tex_coord = 0;
  HP_RETURN_IF_ERROR(GetIndex(*it, "index", tw, &texture));
  HP_RETURN_IF_ERROR(GetUint(*it, "texCoord", tw, 0, &tex_coord));
  if (texture < 0) return Error(tw, "has no texture index");
  if (tex_coord > 255)
    return Error(tw, "texCoord " + std::to_string(tex_coord) + " is out of range");
  const json* textures = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("textures", &textures));
  if (textures == nullptr || static_cast<size_t>(texture) >= textures->size()) {
    return Error(tw, "texture " + std::to_string(texture) + " does not exist");
  }
  const std::string xw = Item("textures", static_cast<uint64_t>(texture));
  const json& t = (*textures)[static_cast<size_t>(texture)];
  int64_t source = -1;
  HP_RETURN_IF_ERROR(GetIndex(t, "source", xw, &source));
  if (source < 0) {
    // An extension (KHR_texture_basisu, EXT_texture_webp, ...) may name the image instead.
    auto ext = t.find("extensions");
    if (ext != t.end() && ext->is_object()) {
      for (const auto& e : ext->items()) {
        if (e.value().is_object() && e.value().contains("source")) {
          HP_RETURN_IF_ERROR(GetIndex(e.value(), "source", xw + ".extensions." + e.key(), &source));
          break;
        }
      }
    }
  }
  if (source < 0) {
    Drop(tw + ": texture without an image");
    return Status::Ok();
  }
  if (static_cast<size_t>(source) >= TopCount("images")) {
    return Error(xw, "source image " + std::to_string(source) + " does not exist");
  }
  out->image = static_cast<int>(source);
  out->uv_set = static_cast<int>(tex_coord);
  return Status::Ok();
}

Status Decoder::DecodeMaterials(Scene* scene) {
  const json* materials = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("materials", &materials));
  if (materials == nullptr) return Status::Ok();
  size_t non_opaque_materials = 0;
  for (size_t i = 0; i < materials->size(); ++i) {
    const json& j = (*materials)[i];
    const std::string mw = Item("materials", i);
    Material m;
    HP_RETURN_IF_ERROR(GetString(j, "name", mw, &m.name));
    auto pbr = j.find("pbrMetallicRoughness");
    if (pbr != j.end()) {
      if (!pbr->is_object()) return Error(mw, "pbrMetallicRoughness is not an object");
      const std::string pw = mw + ".pbrMetallicRoughness";
      double base[4] = {1, 1, 1, 1};
      double metallic = 1, roughness = 1;
      HP_RETURN_IF_ERROR(GetNumbers(*pbr, "baseColorFactor", pw, 4, base));
      HP_RETURN_IF_ERROR(GetNumber(*pbr, "metallicFactor", pw, &metallic));
      HP_RETURN_IF_ERROR(GetNumber(*pbr, "roughnessFactor", pw, &roughness));
      for (int c = 0; c < 4; ++c)
        m.base_color[static_cast<size_t>(c)] = static_cast<float>(base[c]);
      m.metallic = static_cast<float>(metallic);
      m.roughness = static_cast<float>(roughness);
      HP_RETURN_IF_ERROR(DecodeTextureRef(j, "baseColorTexture", mw, true, &m.base_color_texture));
      HP_RETURN_IF_ERROR(
          DecodeTextureRef(j, "metallicRoughnessTexture", mw, true, &m.metallic_roughness_texture));
    }
    double emissive[3] = {0, 0, 0};
    HP_RETURN_IF_ERROR(GetNumbers(j, "emissiveFactor", mw, 3, emissive));
    for (int c = 0; c < 3; ++c)
      m.emissive[static_cast<size_t>(c)] = static_cast<float>(emissive[c]);
    HP_RETURN_IF_ERROR(GetBool(j, "doubleSided", mw, &m.double_sided));
    std::string alpha_mode;
    HP_RETURN_IF_ERROR(GetString(j, "alphaMode", mw, &alpha_mode));
    if (!alpha_mode.empty() && alpha_mode != "OPAQUE") ++non_opaque_materials;
    HP_RETURN_IF_ERROR(DecodeTextureRef(j, "normalTexture", mw, false, &m.normal_texture));
    HP_RETURN_IF_ERROR(DecodeTextureRef(j, "occlusionTexture", mw, false, &m.occlusion_texture));
    HP_RETURN_IF_ERROR(DecodeTextureRef(j, "emissiveTexture", mw, false, &m.emissive_texture));
    scene->materials.push_back(std::move(m));
  }
  if (non_opaque_materials > 0) {
    Drop("dropped alphaMode MASK/BLEND of " + std::to_string(non_opaque_materials) + " materials");
  }
  if (TopCount("samplers") > 0)
    Drop("dropped " + std::to_string(TopCount("samplers")) + " texture samplers");
  return Status::Ok();
}

// Pads a per-vertex array to `vertices` entries of `width`, filling with `fill`.
template <typename T>
void PadTo(std::vector<T>& v, size_t vertices, size_t width, T fill) {
  if (v.size() < vertices * width) v.resize(vertices * width, fill);
}

Status Decoder::DecodeMesh(int64_t mesh_index, Scene* scene, Mesh* out) {
  const json* meshes = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("meshes", &meshes));
  const std::string mw = Item("meshes", static_cast<uint64_t>(mesh_index));
  const json& j = (*meshes)[static_cast<size_t>(mesh_index)];
  HP_RETURN_IF_ERROR(GetString(j, "name", mw, &out->name));
  // The writer's zero-filled padding UV sets (see glb_writer.cc) are dropped again.
  constexpr uint64_t kNoUvSetLimit = std::numeric_limits<uint64_t>::max();
  uint64_t uv_set_limit = kNoUvSetLimit;
  auto extras = j.find("extras");
  if (extras != j.end() && extras->is_object()) {
    auto hp = extras->find("hullpack");
    if (hp != extras->end() && hp->is_object()) {
      HP_RETURN_IF_ERROR(GetBool(*hp, "collides", mw + ".extras.hullpack", &out->collides));
      HP_RETURN_IF_ERROR(
          GetUint(*hp, "uv_sets", mw + ".extras.hullpack", kNoUvSetLimit, &uv_set_limit));
    }
  }
  const json* primitives = nullptr;
  HP_RETURN_IF_ERROR(GetArray(j, "primitives", mw, &primitives));
  if (primitives == nullptr) return Error(mw, "has no primitives");

  std::map<std::string, std::pair<size_t, size_t>> vertex_blocks;  // attribute set -> (base, count)
  std::vector<int> triangle_material;
  bool has_normals = false, has_tangents = false, has_colors = false, has_skin = false;
  size_t uv_count = 0;
  const size_t material_count = TopCount("materials");

  for (size_t p = 0; p < primitives->size(); ++p) {
    const std::string pw = mw + ".primitives[" + std::to_string(p) + "]";
    const json& prim = (*primitives)[p];
    if (!prim.is_object()) return Error(pw, "is not an object");
    uint64_t mode = gltf::kModeTriangles;
    HP_RETURN_IF_ERROR(GetUint(prim, "mode", pw, gltf::kModeTriangles, &mode));
    if (mode > gltf::kModeTriangleFan) return Error(pw, "unknown mode " + std::to_string(mode));
    if (prim.contains("targets")) ++morph_target_primitives_;
    if (mode < gltf::kModeTriangles) {
      ++non_triangle_primitives_;
      continue;
    }
    auto attrs_it = prim.find("attributes");
    if (attrs_it == prim.end() || !attrs_it->is_object())
      return Error(pw, "has no attributes object");
    const json& attrs = *attrs_it;
    // The attributes this reader keeps, and their accessors.
    std::map<std::string, int64_t> used;
    for (const auto& kv : attrs.items()) {
      const std::string& sem = kv.key();
      int64_t acc = -1;
      HP_RETURN_IF_ERROR(GetIndex(attrs, sem.c_str(), pw + ".attributes", &acc));
      if (acc < 0) return Error(pw, "attribute " + sem + " has no accessor");
      bool keep = sem == "POSITION" || sem == "NORMAL" || sem == "TANGENT" || sem == "COLOR_0" ||
                  sem == "JOINTS_0" || sem == "WEIGHTS_0";
      if (!keep && sem.compare(0, 9, "TEXCOORD_") == 0 && sem.size() > 9 && sem.size() <= 11 &&
          std::all_of(sem.begin() + 9, sem.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        keep = true;
      }
      if (keep) {
        used[sem] = acc;
      } else {
        dropped_attributes_.insert(sem);
      }
    }
    if (used.count("POSITION") == 0) return Error(pw, "has no POSITION attribute");
    std::string key;
    for (const auto& kv : used) key += kv.first + "=" + std::to_string(kv.second) + ";";

    size_t base = 0, count = 0;
    auto block = vertex_blocks.find(key);
    if (block != vertex_blocks.end()) {
      base = block->second.first;
      count = block->second.second;
    } else {
      int comps = 0;
      std::vector<float> positions;
      HP_RETURN_IF_ERROR(ReadFloats(used["POSITION"], pw + ".POSITION", {3}, &positions, &comps));
      count = positions.size() / 3;
      base = out->vertex_count();
      if (base + count > std::numeric_limits<uint32_t>::max())
        return Unsupported(pw, "more than 2^32-1 vertices");
      auto read_attr = [&](const std::string& sem, std::initializer_list<int> allowed,
                           std::vector<float>* values, int* c) -> Status {
        HP_RETURN_IF_ERROR(ReadFloats(used[sem], pw + "." + sem, allowed, values, c));
        if (values->size() / static_cast<size_t>(*c) != count) {
          return Error(pw, sem + " has " +
                               std::to_string(values->size() / static_cast<size_t>(*c)) +
                               " elements but POSITION has " + std::to_string(count));
        }
        return Status::Ok();
      };
      out->positions.insert(out->positions.end(), positions.begin(), positions.end());
      std::vector<float> values;
      if (used.count("NORMAL") != 0) {
        HP_RETURN_IF_ERROR(read_attr("NORMAL", {3}, &values, &comps));
        PadTo(out->normals, base, 3, 0.0f);
        out->normals.insert(out->normals.end(), values.begin(), values.end());
        has_normals = true;
      }
      if (used.count("TANGENT") != 0) {
        HP_RETURN_IF_ERROR(read_attr("TANGENT", {4}, &values, &comps));
        PadTo(out->tangents, base, 4, 0.0f);
        out->tangents.insert(out->tangents.end(), values.begin(), values.end());
        has_tangents = true;
      }
      for (size_t u = 0;; ++u) {
        const std::string sem = "TEXCOORD_" + std::to_string(u);
        if (used.count(sem) == 0) break;
        HP_RETURN_IF_ERROR(read_attr(sem, {2}, &values, &comps));
        if (out->uv_sets.size() <= u) out->uv_sets.resize(u + 1);
        PadTo(out->uv_sets[u], base, 2, 0.0f);
        out->uv_sets[u].insert(out->uv_sets[u].end(), values.begin(), values.end());
        uv_count = std::max(uv_count, u + 1);
      }
      for (const auto& kv : used) {
        if (kv.first.compare(0, 9, "TEXCOORD_") == 0 &&
            std::stoul(kv.first.substr(9)) >= uv_count) {
          dropped_attributes_.insert(kv.first + " (TEXCOORD sets must be contiguous)");
        }
      }
      if (used.count("COLOR_0") != 0) {
        HP_RETURN_IF_ERROR(read_attr("COLOR_0", {3, 4}, &values, &comps));
        PadTo(out->colors, base, 4, 1.0f);
        for (size_t v = 0; v < count; ++v) {
          for (int c = 0; c < 4; ++c) {
            out->colors.push_back(
                c < comps ? values[v * static_cast<size_t>(comps) + static_cast<size_t>(c)] : 1.0f);
          }
        }
        has_colors = true;
      }
      if (used.count("JOINTS_0") != 0 && used.count("WEIGHTS_0") != 0) {
        AccessorView ja;
        const std::string jw = pw + ".JOINTS_0";
        HP_RETURN_IF_ERROR(GetAccessor(used["JOINTS_0"], jw, &ja));
        if (ja.components != 4 || ja.normalized ||
            (ja.component_type != gltf::kUnsignedByte &&
             ja.component_type != gltf::kUnsignedShort)) {
          return Error(jw, "must be an unnormalized VEC4 of unsigned bytes or shorts");
        }
        if (ja.count != count) return Error(jw, "count differs from POSITION");
        HP_RETURN_IF_ERROR(Charge(static_cast<uint64_t>(count) * 4 * sizeof(uint16_t), jw));
        PadTo(out->joints, base, 4, static_cast<uint16_t>(0));
        const size_t csize = gltf::ComponentSize(ja.component_type);
        for (size_t v = 0; v < count; ++v) {
          for (size_t c = 0; c < 4; ++c) {
            out->joints.push_back(
                ja.data == nullptr ? 0
                                   : static_cast<uint16_t>(ReadUnsigned(
                                         ja.data + v * ja.stride + c * csize, ja.component_type)));
          }
        }
        HP_RETURN_IF_ERROR(read_attr("WEIGHTS_0", {4}, &values, &comps));
        PadTo(out->weights, base, 4, 0.0f);
        out->weights.insert(out->weights.end(), values.begin(), values.end());
        has_skin = true;
      } else if (used.count("JOINTS_0") != 0 || used.count("WEIGHTS_0") != 0) {
        dropped_attributes_.insert("JOINTS_0/WEIGHTS_0 without its partner");
      }
      vertex_blocks.emplace(key, std::make_pair(base, count));
    }

    // Indices, triangulated.
    std::vector<uint32_t> indices;
    int64_t indices_accessor = -1;
    HP_RETURN_IF_ERROR(GetIndex(prim, "indices", pw, &indices_accessor));
    if (indices_accessor >= 0) {
      HP_RETURN_IF_ERROR(ReadIndices(indices_accessor, pw + ".indices", &indices));
      for (size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= count) {
          return Error(pw, "index " + std::to_string(i) + " is " + std::to_string(indices[i]) +
                               " but the primitive has " + std::to_string(count) + " vertices");
        }
      }
    } else {
      HP_RETURN_IF_ERROR(Charge(static_cast<uint64_t>(count) * sizeof(uint32_t), pw));
      indices.resize(count);
      for (size_t i = 0; i < count; ++i) indices[i] = static_cast<uint32_t>(i);
    }
    size_t triangles = 0;
    if (mode == gltf::kModeTriangles) {
      if (indices.size() % 3 != 0) {
        return Error(pw,
                     std::to_string(indices.size()) + " triangle indices is not a multiple of 3");
      }
      triangles = indices.size() / 3;
    } else {
      triangles = indices.size() >= 3 ? indices.size() - 2 : 0;
    }
    HP_RETURN_IF_ERROR(
        Charge(static_cast<uint64_t>(triangles) * (3 * sizeof(uint32_t) + sizeof(int)), pw));
    out->indices.reserve(out->indices.size() + 3 * triangles);
    const uint32_t b = static_cast<uint32_t>(base);
    for (size_t t = 0; t < triangles; ++t) {
      uint32_t v0, v1, v2;
      if (mode == gltf::kModeTriangles) {
        v0 = indices[3 * t];
        v1 = indices[3 * t + 1];
        v2 = indices[3 * t + 2];
      } else if (mode == gltf::kModeTriangleStrip) {
        v0 = indices[t];
        v1 = indices[t + 1 + t % 2];
        v2 = indices[t + 2 - t % 2];
      } else {  // fan
        v0 = indices[t + 1];
        v1 = indices[t + 2];
        v2 = indices[0];
      }
      out->indices.push_back(b + v0);
      out->indices.push_back(b + v1);
      out->indices.push_back(b + v2);
    }
    int64_t material = -1;
    HP_RETURN_IF_ERROR(GetIndex(prim, "material", pw, &material));
    if (material >= 0 && static_cast<size_t>(material) >= material_count) {
      return Error(pw, "material " + std::to_string(material) + " does not exist");
    }
    triangle_material.insert(triangle_material.end(), triangles, static_cast<int>(material));
  }

  const size_t vc = out->vertex_count();
  if (has_normals) PadTo(out->normals, vc, 3, 0.0f);
  if (has_tangents) PadTo(out->tangents, vc, 4, 0.0f);
  if (has_colors) PadTo(out->colors, vc, 4, 1.0f);
  if (has_skin) {
    PadTo(out->joints, vc, 4, static_cast<uint16_t>(0));
    PadTo(out->weights, vc, 4, 0.0f);
  }
  for (size_t u = 0; u < uv_count; ++u) PadTo(out->uv_sets[u], vc, 2, 0.0f);
  if (out->uv_sets.size() > uv_set_limit) out->uv_sets.resize(static_cast<size_t>(uv_set_limit));

  if (out->indices.empty())
    Drop(mw + (out->name.empty() ? "" : " '" + out->name + "'") + " has no triangles");
  const bool any_material =
      std::any_of(triangle_material.begin(), triangle_material.end(), [](int m) { return m >= 0; });
  if (any_material) {
    out->material_ids.resize(triangle_material.size());
    for (size_t t = 0; t < triangle_material.size(); ++t) {
      int m = triangle_material[t];
      if (m < 0) {
        if (default_material_ < 0) {
          Material def;
          def.name = "default";
          scene->materials.push_back(def);
          default_material_ = static_cast<int>(scene->materials.size() - 1);
        }
        m = default_material_;
      }
      out->material_ids[t] = static_cast<uint32_t>(m);
    }
  }
  return Status::Ok();
}

Status Decoder::DecodeSkins(Scene* scene) {
  const json* skins = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("skins", &skins));
  if (skins == nullptr) return Status::Ok();
  const size_t node_count = TopCount("nodes");
  for (size_t i = 0; i < skins->size(); ++i) {
    const json& j = (*skins)[i];
    const std::string sw = Item("skins", i);
    Skin skin;
    HP_RETURN_IF_ERROR(GetString(j, "name", sw, &skin.name));
    const json* joints = nullptr;
    HP_RETURN_IF_ERROR(GetArray(j, "joints", sw, &joints));
    if (joints == nullptr || joints->empty()) return Error(sw, "has no joints");
    std::set<int64_t> seen;
    for (size_t k = 0; k < joints->size(); ++k) {
      const json& e = (*joints)[k];
      if (!e.is_number_integer() || e.get<int64_t>() < 0 ||
          static_cast<uint64_t>(e.get<int64_t>()) >= node_count) {
        return Error(sw, "joint " + std::to_string(k) + " is not a node index");
      }
      if (!seen.insert(e.get<int64_t>()).second) return Error(sw, "lists a joint node twice");
      skin.joints.push_back(static_cast<int>(e.get<int64_t>()));
    }
    int64_t skeleton = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "skeleton", sw, &skeleton));
    if (skeleton >= 0 && static_cast<size_t>(skeleton) >= node_count) {
      return Error(sw, "skeleton " + std::to_string(skeleton) + " is not a node");
    }
    skin.skeleton = static_cast<int>(skeleton);
    int64_t ibm = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "inverseBindMatrices", sw, &ibm));
    if (ibm >= 0) {
      int comps = 0;
      HP_RETURN_IF_ERROR(
          ReadFloats(ibm, sw + ".inverseBindMatrices", {16}, &skin.inverse_bind_matrices, &comps));
      if (skin.inverse_bind_matrices.size() != 16 * skin.joints.size()) {
        return Error(sw, "inverseBindMatrices has " +
                             std::to_string(skin.inverse_bind_matrices.size() / 16) +
                             " matrices for " + std::to_string(skin.joints.size()) + " joints");
      }
    }
    scene->skins.push_back(std::move(skin));
  }
  return Status::Ok();
}

Matrix4 ComposeTrs(const double t[3], const double q[4], const double s[3]) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                       2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                       2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
  // r is column-major: column c = r[3c..3c+2].
  Matrix4 m = kIdentity;
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) m[static_cast<size_t>(4 * c + row)] = r[3 * c + row] * s[c];
  }
  m[12] = t[0];
  m[13] = t[1];
  m[14] = t[2];
  return m;
}

Status Decoder::DecodeNodes(Scene* scene) {
  const json* nodes = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("nodes", &nodes));
  if (nodes == nullptr) return Status::Ok();
  const size_t n = nodes->size();
  scene->nodes.resize(n);
  std::vector<bool> mesh_of_parent(n, false);
  size_t cameras = 0, lights = 0;
  for (size_t i = 0; i < n; ++i) {
    const json& j = (*nodes)[i];
    const std::string nw = Item("nodes", i);
    Node& node = scene->nodes[i];
    HP_RETURN_IF_ERROR(GetString(j, "name", nw, &node.name));
    const json* children = nullptr;
    HP_RETURN_IF_ERROR(GetArray(j, "children", nw, &children));
    if (children != nullptr) {
      for (size_t k = 0; k < children->size(); ++k) {
        const json& c = (*children)[k];
        if (!c.is_number_integer() || c.get<int64_t>() < 0 ||
            static_cast<uint64_t>(c.get<int64_t>()) >= n) {
          return Error(nw, "child " + std::to_string(k) + " is not a node index");
        }
        const size_t child = static_cast<size_t>(c.get<int64_t>());
        if (child == i) return Error(nw, "lists itself as a child");
        if (scene->nodes[child].parent != -1) {
          return Error(nw, "child node " + std::to_string(child) + " already has parent " +
                               std::to_string(scene->nodes[child].parent));
        }
        scene->nodes[child].parent = static_cast<int>(i);
        node.children.push_back(static_cast<int>(child));
      }
    }
    if (j.contains("matrix")) {
      double m[16];
      HP_RETURN_IF_ERROR(GetNumbers(j, "matrix", nw, 16, m));
      std::copy(m, m + 16, node.local_transform.begin());
    } else if (j.contains("translation") || j.contains("rotation") || j.contains("scale")) {
      double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
      HP_RETURN_IF_ERROR(GetNumbers(j, "translation", nw, 3, t));
      HP_RETURN_IF_ERROR(GetNumbers(j, "rotation", nw, 4, q));
      HP_RETURN_IF_ERROR(GetNumbers(j, "scale", nw, 3, s));
      node.local_transform = ComposeTrs(t, q, s);
    }
    int64_t mesh = -1, skin = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "mesh", nw, &mesh));
    HP_RETURN_IF_ERROR(GetIndex(j, "skin", nw, &skin));
    if (mesh >= 0) {
      if (static_cast<size_t>(mesh) >= scene->meshes.size())
        return Error(nw, "mesh " + std::to_string(mesh) + " does not exist");
      node.meshes.push_back(static_cast<int>(mesh));
    }
    if (skin >= 0) {
      if (static_cast<size_t>(skin) >= scene->skins.size())
        return Error(nw, "skin " + std::to_string(skin) + " does not exist");
      node.skin = static_cast<int>(skin);
    }
    if (j.contains("camera")) ++cameras;
    auto ext = j.find("extensions");
    if (ext != j.end() && ext->is_object() && ext->contains("KHR_lights_punctual")) ++lights;
    auto extras = j.find("extras");
    if (extras != j.end() && extras->is_object()) {
      auto hp = extras->find("hullpack");
      if (hp != extras->end() && hp->is_object()) {
        bool marker = false;
        HP_RETURN_IF_ERROR(GetBool(*hp, "mesh_of_parent", nw + ".extras.hullpack", &marker));
        mesh_of_parent[i] = marker;
      }
    }
  }
  const int on_cycle = gltf_internal::FirstNodeOnCycle(scene->nodes);
  if (on_cycle >= 0) {
    return Error(Item("nodes", static_cast<uint64_t>(on_cycle)),
                 "is part of a cycle in the node hierarchy");
  }
  if (cameras > 0) Drop("dropped " + std::to_string(cameras) + " node cameras");
  if (lights > 0) Drop("dropped " + std::to_string(lights) + " KHR_lights_punctual node lights");

  // Fold the writer's extra-mesh children back into their parents.
  std::vector<bool> referenced(n, false);
  for (const Skin& s : scene->skins) {
    for (int jn : s.joints) referenced[static_cast<size_t>(jn)] = true;
    if (s.skeleton >= 0) referenced[static_cast<size_t>(s.skeleton)] = true;
  }
  std::vector<int> remap(n, -1);
  std::vector<bool> remove(n, false);
  for (size_t i = 0; i < n; ++i) {
    const Node& node = scene->nodes[i];
    const bool fold = mesh_of_parent[i] && node.parent >= 0 && node.children.empty() &&
                      node.meshes.size() == 1 && !referenced[i] &&
                      node.local_transform == kIdentity &&
                      node.skin == scene->nodes[static_cast<size_t>(node.parent)].skin;
    remove[i] = fold;
  }
  if (std::find(remove.begin(), remove.end(), true) == remove.end()) return Status::Ok();
  for (size_t i = 0; i < n; ++i) {
    if (!remove[i]) continue;
    Node& parent = scene->nodes[static_cast<size_t>(scene->nodes[i].parent)];
    parent.meshes.push_back(scene->nodes[i].meshes[0]);
  }
  std::vector<Node> kept;
  for (size_t i = 0; i < n; ++i) {
    if (remove[i]) continue;
    remap[i] = static_cast<int>(kept.size());
    kept.push_back(std::move(scene->nodes[i]));
  }
  for (Node& node : kept) {
    if (node.parent >= 0) node.parent = remap[static_cast<size_t>(node.parent)];
    std::vector<int> children;
    for (int c : node.children) {
      if (remap[static_cast<size_t>(c)] >= 0) children.push_back(remap[static_cast<size_t>(c)]);
    }
    node.children = std::move(children);
  }
  for (Skin& s : scene->skins) {
    for (int& jn : s.joints) jn = remap[static_cast<size_t>(jn)];
    if (s.skeleton >= 0) s.skeleton = remap[static_cast<size_t>(s.skeleton)];
  }
  scene->nodes = std::move(kept);
  return Status::Ok();
}

Result<Scene> Decoder::Run() {
  Scene scene;
  auto asset = root_.find("asset");
  if (asset == root_.end() || !asset->is_object()) return Error("asset", "is missing");
  std::string version, min_version;
  HP_RETURN_IF_ERROR(GetString(*asset, "version", "asset", &version));
  HP_RETURN_IF_ERROR(GetString(*asset, "minVersion", "asset", &min_version));
  if (version.compare(0, 2, "2.") != 0)
    return Unsupported("asset", "glTF version '" + version + "' (need 2.x)");
  if (!min_version.empty() && min_version != "2.0") {
    return Unsupported("asset", "minVersion '" + min_version + "' is newer than 2.0");
  }
  HP_RETURN_IF_ERROR(CheckExtensions());
  HP_RETURN_IF_ERROR(DecodeImages(&scene));
  HP_RETURN_IF_ERROR(DecodeMaterials(&scene));
  const json* meshes = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("meshes", &meshes));
  if (meshes != nullptr) {
    scene.meshes.resize(meshes->size());
    for (size_t i = 0; i < meshes->size(); ++i) {
      HP_RETURN_IF_ERROR(DecodeMesh(static_cast<int64_t>(i), &scene, &scene.meshes[i]));
    }
  }
  HP_RETURN_IF_ERROR(DecodeSkins(&scene));
  HP_RETURN_IF_ERROR(DecodeNodes(&scene));

  // Skinned meshes: every joint index must name one of the skin's joints.
  for (size_t i = 0; i < scene.nodes.size(); ++i) {
    const Node& node = scene.nodes[i];
    if (node.skin < 0) continue;
    const size_t joint_count = scene.skins[static_cast<size_t>(node.skin)].joints.size();
    for (int m : node.meshes) {
      for (uint16_t jn : scene.meshes[static_cast<size_t>(m)].joints) {
        if (jn >= joint_count) {
          return Error(Item("nodes", i), "mesh " + std::to_string(m) + " uses joint " +
                                             std::to_string(jn) + " but skin " +
                                             std::to_string(node.skin) + " has " +
                                             std::to_string(joint_count));
        }
      }
    }
  }

  if (TopCount("animations") > 0)
    Drop("dropped " + std::to_string(TopCount("animations")) + " animations");
  if (TopCount("cameras") > 0) Drop("dropped " + std::to_string(TopCount("cameras")) + " cameras");
  if (TopCount("scenes") > 1) {
    Drop("dropped " + std::to_string(TopCount("scenes") - 1) +
         " extra scenes (all nodes are kept)");
  }
  if (morph_target_primitives_ > 0) {
    Drop("dropped morph targets of " + std::to_string(morph_target_primitives_) + " primitives");
  }
  if (non_triangle_primitives_ > 0) {
    Drop("dropped " + std::to_string(non_triangle_primitives_) + " point/line primitives");
  }
  if (!dropped_attributes_.empty()) {
    std::string list;
    for (const std::string& a : dropped_attributes_) list += (list.empty() ? "" : ", ") + a;
    Drop("dropped vertex attributes: " + list);
  }
  scene.dropped = std::move(dropped_);
  return scene;
}

}  // namespace

bool RelativePathFromUri(const std::string& uri, std::string* path, std::string* error) {
  std::string decoded;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%') {
      if (i + 2 >= uri.size()) {
        *error = "truncated percent escape";
        return false;
      }
      auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
      };
      const int hi = hex(uri[i + 1]);
      const int lo = hex(uri[i + 2]);
      if (hi < 0 || lo < 0) {
        *error = "bad percent escape";
        return false;
      }
      decoded.push_back(static_cast<char>(hi * 16 + lo));
      i += 2;
    } else {
      decoded.push_back(uri[i]);
    }
  }
  if (decoded.empty()) {
    *error = "empty URI";
    return false;
  }
  if (decoded.find('\0') != std::string::npos || decoded.find('\\') != std::string::npos) {
    *error = "URI contains a NUL or backslash";
    return false;
  }
  if (decoded[0] == '/') {
    *error = "absolute URIs are not followed";
    return false;
  }
  const size_t colon = decoded.find(':');
  if (colon != std::string::npos && decoded.find('/') > colon) {
    *error = "URIs with a scheme are not followed";
    return false;
  }
  size_t start = 0;
  while (start <= decoded.size()) {
    size_t end = decoded.find('/', start);
    if (end == std::string::npos) end = decoded.size();
    if (decoded.compare(start, end - start, "..") == 0 && end - start == 2) {
      *error = "URIs containing '..' are not followed";
      return false;
    }
    start = end + 1;
  }
  *path = decoded;
  return true;
}

Result<GltfDocument> DecodeGlbDocument(const uint8_t* data, size_t size, const std::string& name) {
  return ParseGltfBytes(data, size, name);
}

Result<Scene> DecodeGltfDocument(const GltfDocument& doc, const std::string& name,
                                 const GltfReadOptions& options) {
  try {
    Decoder decoder(doc, name, options);
    return decoder.Run();
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kUnsupported, name + ": out of memory while decoding");
  } catch (const std::exception& e) {
    // The checks above should make this unreachable; keep malformed input an error, never a crash.
    return Status(StatusCode::kParseError, name + ": malformed glTF: " + e.what());
  }
}

Result<Scene> DecodeGlb(const uint8_t* data, size_t size, const std::string& name) {
  Result<GltfDocument> doc = DecodeGlbDocument(data, size, name);
  if (!doc.ok()) return doc.status();
  return DecodeGltfDocument(doc.value(), name);
}

Result<GltfDocument> ReadGltfDocumentFile(const std::string& path) {
  std::vector<uint8_t> bytes;
  Status s = ReadWholeFile(path, &bytes);
  if (!s.ok()) return s;
  return ParseGltfBytes(bytes.data(), bytes.size(), path);
}

Result<Scene> ReadGltfFile(const std::string& path) {
  Result<GltfDocument> doc = ReadGltfDocumentFile(path);
  if (!doc.ok()) return doc.status();
  GltfReadOptions options;
  options.base_dir = DirName(path);
  return DecodeGltfDocument(doc.value(), path, options);
}

}  // namespace hullpack
