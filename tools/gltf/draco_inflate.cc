#include "gltf/draco_inflate.h"

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <new>
#include <set>

#include "gltf/buffer_compaction.h"
#include "gltf/component_store.h"
#include "gltf/embedded_buffers.h"
#include "gltf/glb_reader.h"
#include "gltf/json_members.h"

namespace hullpack {
namespace {

class DracoInflater {
 public:
  // Decoded arrays are bounded like any reader allocation: 64 bytes per file byte plus 1 MiB.
  DracoInflater(GltfDocument& doc, const std::string& name)
      : doc_(doc), json_(doc.json()), name_(name), buffers_(doc) {
    const uint64_t input = doc.source_size() != 0 ? doc.source_size() : doc.binary().size();
    budget_ = input * GltfReadOptions().max_expansion + (1u << 20);
  }

  Status Run() {
    Status s = gltf::ForEachPrimitiveWith(
        json_, kDracoExtension, [this](nlohmann::json& prim, const std::string& where) {
          where_ = where;
          uint64_t mode = gltf::kModeTriangles;
          if (!gltf::GetUintMember(prim, "mode", gltf::kModeTriangles, &mode))
            return Error("mode is not a non-negative integer");
          // Points and lines are not kept (the reader drops them); strips and fans decode as lists.
          if (mode < gltf::kModeTriangles) return Status::Ok();
          Status inflated = InflatePrimitive(prim);
          if (inflated.ok()) prim["mode"] = gltf::kModeTriangles;
          return inflated;
        });
    if (!s.ok()) return s;
    return Finish();
  }

 private:
  Status Error(const std::string& what) const {
    return Status(StatusCode::kParseError,
                  name_ + ": " + where_ + ": " + kDracoExtension + ": " + what);
  }

  static int64_t Index(const nlohmann::json& obj, const char* key, size_t limit) {
    return gltf::IndexMember(obj, key, limit);
  }
  size_t ArraySize(const char* key) const { return gltf::ArraySize(json_, key); }

  Result<const draco::Mesh*> Stream(int64_t view) {
    auto it = streams_.find(view);
    if (it != streams_.end()) return static_cast<const draco::Mesh*>(it->second.get());
    const nlohmann::json& v = json_["bufferViews"][static_cast<size_t>(view)];
    const int64_t buffer = Index(v, "buffer", ArraySize("buffers"));
    if (buffer < 0) return Error("stream bufferView has no valid buffer");
    uint64_t offset = 0, length = 0;
    if (!gltf::GetUintMember(v, "byteOffset", 0, &offset) ||
        !gltf::GetUintMember(v, "byteLength", 0, &length)) {
      return Error(
          "stream bufferView has a byteOffset or byteLength that is not a non-negative integer");
    }
    Result<ByteRange> bytes =
        buffers_.Range(buffer, offset, length, name_ + ": " + where_ + ": " + kDracoExtension);
    if (!bytes.ok()) return bytes.status();
    draco::DecoderBuffer input;
    input.Init(reinterpret_cast<const char*>(bytes->data), bytes->size);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&input);
    if (!decoded.ok()) return Error("stream: " + decoded.status().error_msg_string());
    std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (mesh == nullptr) return Error("stream holds no mesh");
    const draco::Mesh* result = mesh.get();
    streams_.emplace(view, std::move(mesh));
    return result;
  }

  // Checks the accessor against `count` elements of `components` each and reserves its bytes.
  Result<nlohmann::json*> Accessor(int64_t index, size_t count, int components, bool* normalized,
                                   int* component_type) {
    nlohmann::json& acc = json_["accessors"][static_cast<size_t>(index)];
    const std::string where = "accessors[" + std::to_string(index) + "]";
    std::string type;
    uint64_t ctype = 0;
    if (!gltf::GetStringMember(acc, "type", &type) ||
        !gltf::GetUintMember(acc, "componentType", 0, &ctype) ||
        !gltf::GetBoolMember(acc, "normalized", normalized)) {
      return Error(where +
                   " has a type, componentType or normalized member of the wrong JSON type");
    }
    const int dims = gltf::ComponentCount(type);
    const size_t size = ctype <= 0xFFFF ? gltf::ComponentSize(static_cast<int>(ctype)) : 0;
    if (dims == 0 || size == 0) return Error(where + " has a bad type or componentType");
    if (dims != components) {
      return Error(where + " is " + type + " but the stream has " + std::to_string(components) +
                   " components");
    }
    if (!acc.contains("count") || !acc["count"].is_number_unsigned() ||
        acc["count"].get<uint64_t>() != count) {
      return Error(where + " count does not match the stream (" + std::to_string(count) + ")");
    }
    const uint64_t bytes = uint64_t(count) * uint64_t(dims) * size;
    if (bytes > budget_) {
      return Status(StatusCode::kUnsupported,
                    name_ + ": " + where_ + ": " + where +
                        ": the decoded streams hold more than the file can justify");
    }
    budget_ -= bytes;
    *component_type = static_cast<int>(ctype);
    return &acc;
  }

  // Gives the accessor a new bufferView holding `values` (count x components, row-major).
  Status Write(int64_t index, nlohmann::json& acc, const std::vector<double>& values,
               int component_type, bool normalized, bool is_indices) {
    const size_t size = gltf::ComponentSize(component_type);
    std::vector<uint8_t> bytes(values.size() * size);
    for (size_t i = 0; i < values.size(); ++i) {
      if (!gltf::StoreComponent(values[i], component_type, normalized, &bytes[i * size])) {
        return Error("accessors[" + std::to_string(index) + "]: value " +
                     std::to_string(values[i]) + " does not fit its component type");
      }
    }
    acc["bufferView"] = doc_.AddBufferView(
        bytes, size < 4 ? 4 : size, is_indices ? gltf::kElementArrayBuffer : gltf::kArrayBuffer);
    acc["byteOffset"] = 0;
    filled_.insert(index);
    return Status::Ok();
  }

  Status FillAttribute(int64_t index, const draco::Mesh& mesh, const draco::PointAttribute& att) {
    if (filled_.count(index)) return Status::Ok();  // shared by the mesh's primitives
    const size_t count = mesh.num_points();
    const int components = att.num_components();
    bool normalized = false;
    int ctype = 0;
    Result<nlohmann::json*> acc = Accessor(index, count, components, &normalized, &ctype);
    if (!acc.ok()) return acc.status();
    // A normalized accessor over integers the stream does not flag as normalized holds them raw.
    const bool raw_integers = normalized && ctype != gltf::kFloat && !att.normalized() &&
                              att.data_type() != draco::DT_FLOAT32 &&
                              att.data_type() != draco::DT_FLOAT64;
    double raw_scale = 1;
    if (raw_integers) {
      const int bits = int(8 * gltf::ComponentSize(ctype));
      const bool is_signed = ctype == gltf::kByte || ctype == gltf::kShort;
      raw_scale = 1.0 / (std::ldexp(1.0, bits - (is_signed ? 1 : 0)) - 1);
    }
    std::vector<double> values(count * size_t(components));
    for (size_t p = 0; p < count; ++p) {
      const draco::AttributeValueIndex value =
          att.mapped_index(draco::PointIndex(static_cast<uint32_t>(p)));
      double* out = &values[p * components];
      if (value.value() >= att.size() ||
          !att.ConvertValue<double>(value, static_cast<int8_t>(components), out))
        return Error("attribute value " + std::to_string(p) + " cannot be read");
      for (int c = 0; c < components; ++c) out[c] *= raw_scale;
    }
    return Write(index, *acc.value(), values, ctype, normalized, false);
  }

  Status FillIndices(int64_t index, const draco::Mesh& mesh) {
    if (filled_.count(index)) return Status::Ok();
    const size_t count = size_t(mesh.num_faces()) * 3;
    bool normalized = false;
    int ctype = 0;
    Result<nlohmann::json*> acc = Accessor(index, count, 1, &normalized, &ctype);
    if (!acc.ok()) return acc.status();
    std::vector<double> values(count);
    for (uint32_t f = 0; f < mesh.num_faces(); ++f) {
      const draco::Mesh::Face& face = mesh.face(draco::FaceIndex(f));
      for (int k = 0; k < 3; ++k) {
        if (face[k].value() >= mesh.num_points()) return Error("a face names a missing point");
        values[size_t(f) * 3 + k] = face[k].value();
      }
    }
    return Write(index, *acc.value(), values, ctype, normalized, true);
  }

  Status InflatePrimitive(nlohmann::json& prim) {
    const nlohmann::json& ext = prim["extensions"][kDracoExtension];
    if (!ext.is_object()) return Error("not an object");
    const int64_t view = Index(ext, "bufferView", ArraySize("bufferViews"));
    if (view < 0) return Error("bufferView missing or out of range");
    Result<const draco::Mesh*> stream = Stream(view);
    if (!stream.ok()) return stream.status();
    const draco::Mesh& mesh = *stream.value();
    if (!ext.contains("attributes") || !ext["attributes"].is_object())
      return Error("attributes missing");
    if (!prim.contains("attributes") || !prim["attributes"].is_object())
      return Error("primitive has no attributes");
    const size_t accessors = ArraySize("accessors");
    for (auto it = ext["attributes"].begin(); it != ext["attributes"].end(); ++it) {
      const int64_t id = it.value().is_number_integer() ? it.value().get<int64_t>() : -1;
      const draco::PointAttribute* att =
          id >= 0 && id <= INT32_MAX ? mesh.GetAttributeByUniqueId(static_cast<uint32_t>(id))
                                     : nullptr;
      if (att == nullptr) {
        return Error("attribute " + it.key() + " names stream attribute " + it.value().dump() +
                     ", which the stream lacks");
      }
      const int64_t accessor = Index(prim["attributes"], it.key().c_str(), accessors);
      if (accessor < 0) return Error("attribute " + it.key() + " has no accessor in the primitive");
      Status s = FillAttribute(accessor, mesh, *att);
      if (!s.ok()) return s;
    }
    const int64_t indices = Index(prim, "indices", accessors);
    if (indices < 0) return Error("indices accessor missing or out of range");
    return FillIndices(indices, mesh);
  }

  Status Finish() {
    doc_.DropExtension(kDracoExtension);
    if (streams_.empty() || buffers_.used_data_uris()) return Status::Ok();
    // The streams' views are referenced by nothing now; dropping them also frees their bytes.
    Status s = CompactBufferViews(doc_);
    if (!s.ok()) return Status(s.code(), name_ + ": " + s.message());
    return Status::Ok();
  }

  GltfDocument& doc_;
  nlohmann::json& json_;
  const std::string& name_;
  std::string where_;
  std::map<int64_t, std::unique_ptr<draco::Mesh>> streams_;
  EmbeddedBuffers buffers_;
  std::set<int64_t> filled_;
  uint64_t budget_ = 0;  // bytes the remaining accessors may still take
};

}  // namespace

Status InflateDracoPrimitives(GltfDocument& doc, const std::string& name) {
  try {
    return DracoInflater(doc, name).Run();
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kUnsupported,
                  name + ": out of memory while decoding Draco-compressed meshes");
  } catch (const std::exception& e) {
    return Status(StatusCode::kParseError, name + ": malformed glTF: " + e.what());
  }
}

}  // namespace hullpack
