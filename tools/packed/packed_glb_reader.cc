#include "packed/packed_glb_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <map>
#include <new>
#include <set>

#include "common/file_util.h"
#include "gltf/buffer_compaction.h"
#include "gltf/component_store.h"
#include "gltf/draco_inflate.h"
#include "gltf/glb_reader.h"
#include "gltf/json_members.h"
#include "gltf/meshopt_inflate.h"
#include "o3dgc/o3dgc.h"
#include "packed/packed_glb_format.h"

namespace hullpack {
namespace {

// One attribute of a decoded stream in stream-id order: floats or ints, `dimension` per vertex.
struct StreamAttribute {
  uint32_t dimension = 0;
  const std::vector<float>* floats = nullptr;
  const std::vector<int32_t>* ints = nullptr;
};

struct DecodedStream {
  o3dgc::DecodedMesh mesh;
  std::vector<StreamAttribute> attributes;  // by stream attribute id
};

// Bytes of every array of a decoded stream.
uint64_t DecodedBytes(const o3dgc::DecodedMesh& m) {
  uint64_t n =
      (m.positions.size() + m.normals.size() + m.indices.size() + m.triangle_groups.size()) * 4;
  for (const auto& a : m.float_attributes) n += a.values.size() * 4;
  for (const auto& a : m.int_attributes) n += a.values.size() * 4;
  return n;
}

// The primitive's share of a stream: its vertices (stream indices) and its triangles (indices into
// those vertices).
struct Selection {
  std::vector<uint32_t> vertices;  // empty = all of the stream's vertices, in order
  std::vector<uint32_t> indices;
  size_t vertex_count = 0;
};

class Inflater {
 public:
  // The bytes written into new bufferViews are bounded like any reader allocation: 64 per file byte
  // (GltfReadOptions::max_expansion), plus each decoded stream's own size once (the codec already
  // bounded that by the stream), so a small file cannot inflate one stream many times over.
  Inflater(GltfDocument& doc, const std::string& name) : doc_(doc), json_(doc.json()), name_(name) {
    const uint64_t input = doc.source_size() != 0 ? doc.source_size() : doc.binary().size();
    budget_ = input * GltfReadOptions().max_expansion + (1u << 20);
  }

  Status Run() {
    Status s = gltf::ForEachPrimitiveWith(json_, kMeshCompressionExtension,
                                          [this](nlohmann::json& prim, const std::string& where) {
                                            where_ = where;
                                            return InflatePrimitive(prim);
                                          });
    if (!s.ok()) return s;
    return Finish();
  }

 private:
  Status Error(const std::string& what) const {
    return Status(StatusCode::kParseError,
                  name_ + ": " + where_ + ": " + kMeshCompressionExtension + ": " + what);
  }

  static int64_t Index(const nlohmann::json& obj, const char* key, size_t limit) {
    return gltf::IndexMember(obj, key, limit);
  }
  size_t ArraySize(const char* key) const { return gltf::ArraySize(json_, key); }

  Result<const DecodedStream*> Stream(int64_t view) {
    auto it = streams_.find(view);
    if (it != streams_.end()) return static_cast<const DecodedStream*>(&it->second);
    const nlohmann::json& v = json_["bufferViews"][view];
    if (Index(v, "buffer", 1) != 0)
      return Error("stream bufferView is not on the GLB binary chunk");
    uint64_t offset = 0, length = 0;
    if (!gltf::GetUintMember(v, "byteOffset", 0, &offset) ||
        !gltf::GetUintMember(v, "byteLength", 0, &length)) {
      return Error(
          "stream bufferView has a byteOffset or byteLength that is not a non-negative integer");
    }
    const std::vector<uint8_t>& bin = doc_.binary();
    if (offset > bin.size() || length > bin.size() - offset)
      return Error("stream bufferView lies outside the binary chunk");
    DecodedStream d;
    const o3dgc::Status st = DecodePackedStream(bin.data() + offset, length, &d.mesh);
    if (st != o3dgc::Status::kOk) return Error(std::string("stream: ") + o3dgc::StatusName(st));
    // The attribute table points into the map node, which stays put.
    budget_ += DecodedBytes(d.mesh);
    DecodedStream& s = streams_.emplace(view, std::move(d)).first->second;
    s.attributes.push_back({3, &s.mesh.positions, nullptr});
    if (!s.mesh.normals.empty()) s.attributes.push_back({3, &s.mesh.normals, nullptr});
    for (const auto& a : s.mesh.float_attributes)
      s.attributes.push_back({a.dimension, &a.values, nullptr});
    for (const auto& a : s.mesh.int_attributes)
      s.attributes.push_back({a.dimension, nullptr, &a.values});
    return static_cast<const DecodedStream*>(&s);
  }

  Result<Selection> Select(const DecodedStream& s, const nlohmann::json& ext) {
    Selection sel;
    const o3dgc::DecodedMesh& m = s.mesh;
    sel.vertex_count = m.num_vertices();
    if (!ext.contains("group")) {
      sel.indices = m.indices;
      return sel;
    }
    if (!ext["group"].is_number_unsigned()) return Error("group must be a non-negative integer");
    const uint64_t group = ext["group"].get<uint64_t>();
    bool compact = false;
    if (!gltf::GetBoolMember(ext, "compactVertices", &compact))
      return Error("compactVertices is not a boolean");
    std::vector<uint32_t> remap;
    if (compact) remap.assign(m.num_vertices(), UINT32_MAX);
    for (size_t t = 0; t < m.num_triangles(); ++t) {
      const uint32_t g = t < m.triangle_groups.size() ? m.triangle_groups[t] : 0;
      if (g != group) continue;
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = m.indices[t * 3 + k];
        if (compact && remap[v] == UINT32_MAX) remap[v] = 0;
        sel.indices.push_back(v);
      }
    }
    if (compact) {
      uint32_t next = 0;
      for (uint32_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == UINT32_MAX) continue;
        remap[v] = next++;
        sel.vertices.push_back(v);
      }
      for (uint32_t& i : sel.indices) i = remap[i];
      sel.vertex_count = sel.vertices.size();
    }
    return sel;
  }

  // Writes `count` x `dims` values, converted to the accessor's component type, into a new
  // bufferView and points the accessor at it.
  Status Fill(int64_t accessor_index, const Selection& sel, const StreamAttribute* attribute,
              bool is_indices) {
    if (filled_.count(accessor_index)) return Status::Ok();  // shared by the mesh's primitives
    nlohmann::json& acc = json_["accessors"][accessor_index];
    std::string type;
    uint64_t ctype = 0;
    bool normalized = false;
    if (!gltf::GetStringMember(acc, "type", &type) ||
        !gltf::GetUintMember(acc, "componentType", 0, &ctype) ||
        !gltf::GetBoolMember(acc, "normalized", &normalized)) {
      return Error("accessors[" + std::to_string(accessor_index) +
                   "] has a type, componentType or normalized member of the wrong JSON type");
    }
    const int dims = gltf::ComponentCount(type);
    const size_t csize = ctype <= 0xFFFF ? gltf::ComponentSize(static_cast<int>(ctype)) : 0;
    const size_t count = is_indices ? sel.indices.size() : sel.vertex_count;
    if (dims == 0 || csize == 0)
      return Error("accessors[" + std::to_string(accessor_index) + "] has a bad type");
    if (!acc.contains("count") || !acc["count"].is_number_unsigned() ||
        acc["count"].get<uint64_t>() != count) {
      return Error("accessors[" + std::to_string(accessor_index) +
                   "] count does not match the stream (" + std::to_string(count) + ")");
    }
    if (!is_indices && static_cast<uint32_t>(dims) != attribute->dimension) {
      return Error("accessors[" + std::to_string(accessor_index) + "] is " + type +
                   " but the stream attribute has " + std::to_string(attribute->dimension) +
                   " components");
    }
    if (is_indices && dims != 1) return Error("index accessor must be SCALAR");
    const uint64_t size = uint64_t(count) * dims * csize;
    if (size > budget_) {
      return Status(
          StatusCode::kUnsupported,
          name_ + ": " + where_ + ": accessors[" + std::to_string(accessor_index) +
              "]: the decoded streams would be copied out more often than the file can justify");
    }
    budget_ -= size;
    std::vector<uint8_t> bytes(size);
    for (size_t i = 0; i < count; ++i) {
      for (int c = 0; c < dims; ++c) {
        double value;
        if (is_indices) {
          value = sel.indices[i];
        } else {
          const size_t v = sel.vertices.empty() ? i : sel.vertices[i];
          const size_t at = v * attribute->dimension + c;
          value = attribute->floats ? (*attribute->floats)[at] : (*attribute->ints)[at];
        }
        uint8_t* out = &bytes[(i * dims + c) * csize];
        if (!gltf::StoreComponent(value, static_cast<int>(ctype), normalized, out)) {
          return Error("accessors[" + std::to_string(accessor_index) + "]: value " +
                       std::to_string(value) + " does not fit its component type");
        }
      }
    }
    const size_t alignment = csize < 4 ? 4 : csize;
    acc["bufferView"] = doc_.AddBufferView(
        bytes, alignment, is_indices ? gltf::kElementArrayBuffer : gltf::kArrayBuffer);
    acc["byteOffset"] = 0;
    filled_.insert(accessor_index);
    return Status::Ok();
  }

  // The extension's `targets`: per morph target, glTF attribute name -> stream attribute id,
  // filling the primitive's targets[t][name] accessors.
  Status InflateTargets(nlohmann::json& prim, const nlohmann::json& ext,
                        const DecodedStream& stream, const Selection& sel) {
    if (!ext.contains("targets")) return Status::Ok();
    const nlohmann::json& targets = ext["targets"];
    if (!targets.is_array() || !prim.contains("targets") || !prim["targets"].is_array() ||
        prim["targets"].size() != targets.size()) {
      return Error("targets must be an array with one entry per morph target of the primitive");
    }
    const size_t accessors = ArraySize("accessors");
    for (size_t t = 0; t < targets.size(); ++t) {
      const std::string tw = "targets[" + std::to_string(t) + "]";
      if (!targets[t].is_object() || !prim["targets"][t].is_object())
        return Error(tw + " is not an object");
      for (auto it = targets[t].begin(); it != targets[t].end(); ++it) {
        const int64_t id = it.value().is_number_integer() ? it.value().get<int64_t>() : -1;
        if (id < 0 || static_cast<size_t>(id) >= stream.attributes.size()) {
          return Error(tw + " " + it.key() + " names stream attribute " + it.value().dump() +
                       ", which the stream lacks");
        }
        const int64_t accessor = Index(prim["targets"][t], it.key().c_str(), accessors);
        if (accessor < 0) return Error(tw + " " + it.key() + " has no accessor in the primitive");
        Status s = Fill(accessor, sel, &stream.attributes[static_cast<size_t>(id)], false);
        if (!s.ok()) return s;
      }
    }
    return Status::Ok();
  }

  Status InflatePrimitive(nlohmann::json& prim) {
    const nlohmann::json& ext = prim["extensions"][kMeshCompressionExtension];
    if (!ext.is_object()) return Error("not an object");
    const int64_t view = Index(ext, "bufferView", ArraySize("bufferViews"));
    if (view < 0) return Error("bufferView missing or out of range");
    Result<const DecodedStream*> stream = Stream(view);
    if (!stream.ok()) return stream.status();
    Result<Selection> sel = Select(*stream.value(), ext);
    if (!sel.ok()) return sel.status();
    const size_t accessors = ArraySize("accessors");
    if (!ext.contains("attributes") || !ext["attributes"].is_object())
      return Error("attributes missing");
    if (!prim.contains("attributes") || !prim["attributes"].is_object())
      return Error("primitive has no attributes");
    for (auto it = ext["attributes"].begin(); it != ext["attributes"].end(); ++it) {
      const int64_t id = it.value().is_number_integer() ? it.value().get<int64_t>() : -1;
      if (id < 0 || static_cast<size_t>(id) >= stream.value()->attributes.size()) {
        return Error("attribute " + it.key() + " names stream attribute " + it.value().dump() +
                     ", which the stream lacks");
      }
      const int64_t accessor = Index(prim["attributes"], it.key().c_str(), accessors);
      if (accessor < 0) return Error("attribute " + it.key() + " has no accessor in the primitive");
      Status s = Fill(accessor, sel.value(), &stream.value()->attributes[id], false);
      if (!s.ok()) return s;
    }
    Status targets = InflateTargets(prim, ext, *stream.value(), sel.value());
    if (!targets.ok()) return targets;
    if (prim.contains("indices")) {
      const int64_t accessor = Index(prim, "indices", accessors);
      if (accessor < 0) return Error("indices accessor out of range");
      Status s = Fill(accessor, sel.value(), nullptr, true);
      if (!s.ok()) return s;
    } else if (sel->indices.size() != sel->vertex_count || !sel->vertices.empty()) {
      return Error("a non-indexed primitive cannot hold an indexed stream");
    }
    return Status::Ok();
  }

  Status Finish() {
    doc_.DropExtension(kMeshCompressionExtension);
    if (streams_.empty()) return Status::Ok();
    Status s = CompactBufferViews(doc_);
    if (!s.ok()) return Status(s.code(), name_ + ": " + s.message());
    return Status::Ok();
  }

  GltfDocument& doc_;
  nlohmann::json& json_;
  const std::string& name_;
  std::string where_;
  std::map<int64_t, DecodedStream> streams_;
  std::set<int64_t> filled_;
  uint64_t budget_ = 0;  // bytes the remaining Fill calls may still allocate
};

}  // namespace

Status InflatePackedDocument(GltfDocument& doc, const std::string& name) {
  try {
    return Inflater(doc, name).Run();
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kUnsupported,
                  name + ": out of memory while inflating compressed meshes");
  } catch (const std::exception& e) {
    // The member checks should make this unreachable; keep malformed input an error, never a crash.
    return Status(StatusCode::kParseError, name + ": malformed glTF: " + e.what());
  }
}

namespace {

// Whether the document uses an extension whose decoder reads its streams from the buffers itself.
bool UsesDocumentCompression(const GltfDocument& doc) {
  const nlohmann::json& json = doc.json();
  if (!json.contains("extensionsUsed") || !json["extensionsUsed"].is_array()) return false;
  for (const nlohmann::json& e : json["extensionsUsed"]) {
    if (e.is_string() &&
        (e == kDracoExtension || e == kMeshoptExtension || e == kMeshCompressionExtension))
      return true;
  }
  return false;
}

}  // namespace

Result<Scene> ReadPackedGltf(const uint8_t* data, size_t size, const std::string& name,
                             const std::string& base_dir, GltfDocument* inflated) {
  Result<GltfDocument> doc = DecodeGlbDocument(data, size, name);
  if (!doc.ok()) return doc.status();
  // A .gltf whose compressed streams sit in the .bin files beside it (glTF-Transform writes Draco
  // and meshopt files so, one .bin per buffer after `partition`): they are read in first, where
  // the inflaters read their streams.
  if (!base_dir.empty() && UsesDocumentCompression(doc.value())) {
    const Status adopted = AdoptBufferFiles(doc.value(), base_dir, name);
    if (!adopted.ok()) return adopted;
  }
  Status s = InflatePackedDocument(doc.value(), name);
  if (!s.ok()) return s;
  s = InflateMeshoptBufferViews(doc.value(), name);
  if (!s.ok()) return s;
  s = InflateDracoPrimitives(doc.value(), name);
  if (!s.ok()) return s;
  GltfReadOptions options;
  options.base_dir = base_dir;
  // The inflated arrays are part of the input now (the inflater bounded them): the file may hold
  // far more than 64 bytes of decoded data per byte when its streams compress that well. Up to 4x
  // for index and attribute types the scene widens to 32 bits.
  const uint64_t file = std::max<uint64_t>(doc->source_size(), 1);
  options.max_expansion +=
      static_cast<size_t>((4 * uint64_t(doc->binary().size()) + file - 1) / file);
  Result<Scene> scene = DecodeGltfDocument(doc.value(), name, options);
  if (scene.ok() && inflated) *inflated = std::move(doc.value());
  return scene;
}

}  // namespace hullpack

namespace hullpack {
namespace {

// The mesh a collider node's convex shape uses, or -1 when the node has no convex collider.
Result<int64_t> ColliderMesh(const nlohmann::json& json, const nlohmann::json& node,
                             const std::string& where) {
  if (!node.is_object() || !node.contains("extensions") || !node["extensions"].is_object())
    return int64_t(-1);
  const nlohmann::json& ext = node["extensions"];
  auto integer = [](const nlohmann::json& obj, const char* key) -> int64_t {
    if (!obj.is_object() || !obj.contains(key) || !obj[key].is_number_integer()) return -1;
    return obj[key].get<int64_t>();
  };
  auto array_item = [](const nlohmann::json& obj, const char* key,
                       int64_t i) -> const nlohmann::json* {
    if (i < 0 || !obj.is_object() || !obj.contains(key) || !obj[key].is_array() ||
        static_cast<uint64_t>(i) >= obj[key].size())
      return nullptr;
    return &obj[key][static_cast<size_t>(i)];
  };
  if (ext.contains("OMI_physics_body")) {
    const nlohmann::json& body = ext["OMI_physics_body"];
    if (!body.is_object() || !body.contains("collider")) return int64_t(-1);
    const int64_t shape = integer(body["collider"], "shape");
    const nlohmann::json* shapes = json.contains("extensions") && json["extensions"].is_object() &&
                                           json["extensions"].contains("OMI_physics_shape")
                                       ? &json["extensions"]["OMI_physics_shape"]
                                       : nullptr;
    const nlohmann::json* s = shapes ? array_item(*shapes, "shapes", shape) : nullptr;
    if (!s) return Status(StatusCode::kParseError, where + ": collider shape does not exist");
    if (!s->is_object() || s->value("type", std::string()) != "convex") return int64_t(-1);
    const int64_t mesh = s->contains("convex") ? integer((*s)["convex"], "mesh") : -1;
    if (mesh < 0) return Status(StatusCode::kParseError, where + ": convex shape has no mesh");
    return mesh;
  }
  if (ext.contains("KHR_physics_rigid_bodies")) {
    const nlohmann::json& body = ext["KHR_physics_rigid_bodies"];
    if (!body.is_object() || !body.contains("collider") || !body["collider"].is_object() ||
        !body["collider"].contains("geometry"))
      return int64_t(-1);
    const nlohmann::json& geometry = body["collider"]["geometry"];
    const int64_t mesh = integer(geometry, "mesh");  // earlier draft: the mesh itself
    if (mesh >= 0) return mesh;
    const nlohmann::json* holder = array_item(json, "nodes", integer(geometry, "node"));
    if (!holder) return int64_t(-1);
    const int64_t held = integer(*holder, "mesh");
    if (held < 0)
      return Status(StatusCode::kParseError, where + ": collider geometry node has no mesh");
    return held;
  }
  return int64_t(-1);
}

// The node's local transform applied to `p`, in double precision.
void Transform(const nlohmann::json& node, const double p[3], double out[3]) {
  auto numbers = [&](const char* key, double* v, size_t n) {
    if (!node.contains(key) || !node[key].is_array() || node[key].size() != n) return;
    for (size_t i = 0; i < n; ++i)
      if (node[key][i].is_number()) v[i] = node[key][i].get<double>();
  };
  if (node.contains("matrix")) {
    double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    numbers("matrix", m, 16);
    for (int r = 0; r < 3; ++r)
      out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
    return;
  }
  double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
  numbers("translation", t, 3);
  numbers("rotation", q, 4);
  numbers("scale", s, 3);
  const double v[3] = {p[0] * s[0], p[1] * s[1], p[2] * s[2]};
  // v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z), w the quaternion's scalar part.
  const double u[3] = {q[0], q[1], q[2]}, w = q[3];
  const double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
  const double cc[3] = {u[1] * c[2] - u[2] * c[1], u[2] * c[0] - u[0] * c[2],
                        u[0] * c[1] - u[1] * c[0]};
  for (int k = 0; k < 3; ++k) out[k] = v[k] + 2 * (w * c[k] + cc[k]) + t[k];
}

// Reads accessor `index` of `doc` as doubles (components per element in *components), normalized
// integers mapped as glTF says. Every offset and length is checked against the binary chunk.
Status ReadAccessor(const GltfDocument& doc, int64_t index, const std::string& where,
                    std::vector<double>* out, int* components) {
  const nlohmann::json& json = doc.json();
  auto bad = [&](const std::string& what) {
    return Status(StatusCode::kParseError,
                  where + ": accessors[" + std::to_string(index) + "]: " + what);
  };
  if (!json.contains("accessors") || !json["accessors"].is_array() || index < 0 ||
      static_cast<uint64_t>(index) >= json["accessors"].size())
    return bad("does not exist");
  const nlohmann::json& a = json["accessors"][static_cast<size_t>(index)];
  std::string type;
  uint64_t ctype = 0, count = 0, offset = 0, view_index = 0;
  bool normalized = false;
  if (!gltf::GetStringMember(a, "type", &type) ||
      !gltf::GetUintMember(a, "componentType", 0, &ctype) ||
      !gltf::GetUintMember(a, "count", 0, &count) ||
      !gltf::GetUintMember(a, "byteOffset", 0, &offset) ||
      !gltf::GetBoolMember(a, "normalized", &normalized) ||
      !gltf::GetUintMember(a, "bufferView", UINT64_MAX, &view_index))
    return bad("a member has the wrong JSON type");
  const int dims = gltf::ComponentCount(type);
  const size_t csize = ctype <= 0xFFFF ? gltf::ComponentSize(static_cast<int>(ctype)) : 0;
  if (dims == 0 || csize == 0) return bad("bad type or componentType");
  if (view_index == UINT64_MAX || !json.contains("bufferViews") ||
      view_index >= json["bufferViews"].size())
    return bad("has no bufferView");
  const nlohmann::json& v = json["bufferViews"][static_cast<size_t>(view_index)];
  uint64_t view_offset = 0, view_length = 0, stride = 0, buffer = 0;
  if (!gltf::GetUintMember(v, "byteOffset", 0, &view_offset) ||
      !gltf::GetUintMember(v, "byteLength", 0, &view_length) ||
      !gltf::GetUintMember(v, "byteStride", 0, &stride) ||
      !gltf::GetUintMember(v, "buffer", 0, &buffer) || buffer != 0)
    return bad("its bufferView is malformed or not on the binary chunk");
  const uint64_t element = uint64_t(dims) * csize;
  if (stride == 0) stride = element;
  const std::vector<uint8_t>& bin = doc.binary();
  if (view_offset > bin.size() || view_length > bin.size() - view_offset ||
      (count > 0 &&
       (offset > view_length || stride < element ||
        (count - 1) > (view_length - offset - element) / stride || element > view_length - offset)))
    return bad("lies outside its bufferView");
  out->resize(count * dims);
  *components = dims;
  for (uint64_t i = 0; i < count; ++i) {
    const uint8_t* e = bin.data() + view_offset + offset + i * stride;
    for (int c = 0; c < dims; ++c) {
      const uint8_t* p = e + c * csize;
      double value = 0;
      switch (ctype) {
        case gltf::kFloat: {
          float f;
          std::memcpy(&f, p, 4);
          value = f;
          break;
        }
        case gltf::kUnsignedByte:
          value = normalized ? p[0] / 255.0 : p[0];
          break;
        case gltf::kByte:
          value = normalized ? std::max(int8_t(p[0]) / 127.0, -1.0) : int8_t(p[0]);
          break;
        case gltf::kUnsignedShort: {
          uint16_t u;
          std::memcpy(&u, p, 2);
          value = normalized ? u / 65535.0 : u;
          break;
        }
        case gltf::kShort: {
          int16_t u;
          std::memcpy(&u, p, 2);
          value = normalized ? std::max(u / 32767.0, -1.0) : u;
          break;
        }
        case gltf::kUnsignedInt: {
          uint32_t u;
          std::memcpy(&u, p, 4);
          value = u;
          break;
        }
        default:
          return bad("unknown componentType");
      }
      (*out)[i * dims + c] = value;
    }
  }
  return Status::Ok();
}

}  // namespace

std::map<std::string, size_t> StreamVersions(const GltfDocument& doc) {
  std::map<std::string, size_t> versions;
  nlohmann::json json = doc.json();  // ForEachPrimitiveWith takes the extension off its copy
  const size_t views = gltf::ArraySize(json, "bufferViews");
  std::set<int64_t> seen;
  const std::vector<uint8_t>& bin = doc.binary();
  gltf::ForEachPrimitiveWith(
      json, kMeshCompressionExtension, [&](nlohmann::json& prim, const std::string&) {
        const nlohmann::json& ext = prim["extensions"][kMeshCompressionExtension];
        const int64_t view = ext.is_object() ? gltf::IndexMember(ext, "bufferView", views) : -1;
        if (view < 0 || !seen.insert(view).second) return Status::Ok();
        const nlohmann::json& v = json["bufferViews"][size_t(view)];
        uint64_t offset = 0, length = 0, buffer = 0;
        o3dgc::StreamInfo info;
        const bool inside = gltf::GetUintMember(v, "byteOffset", 0, &offset) &&
                            gltf::GetUintMember(v, "byteLength", 0, &length) &&
                            gltf::GetUintMember(v, "buffer", 0, &buffer) && buffer == 0 &&
                            offset <= bin.size() && length <= bin.size() - offset;
        if (!inside ||
            o3dgc::ReadStreamInfo(bin.data() + offset, length, &info) != o3dgc::Status::kOk) {
          ++versions["unreadable"];
        } else if (info.format != o3dgc::StreamFormat::kNative) {
          ++versions["Open3DGC 2013"];
        } else {
          ++versions[std::to_string(info.version_major) + "." + std::to_string(info.version_minor)];
        }
        return Status::Ok();
      });
  return versions;
}

namespace {

// The bytes of buffer `index`'s file, when it is one beside the .gltf (a relative URI, not data:);
// else *found stays false.
Result<std::vector<uint8_t>> ReadBufferFile(const nlohmann::json& buffer, size_t index,
                                            const std::string& base_dir, const std::string& name,
                                            bool* found) {
  *found = false;
  const std::string item = "buffers[" + std::to_string(index) + "]";
  if (!buffer.is_object() || !buffer.contains("uri") || !buffer["uri"].is_string())
    return std::vector<uint8_t>();
  const std::string uri = buffer["uri"].get<std::string>();
  std::string relative, error;
  if (uri.compare(0, 5, "data:") == 0 || !RelativePathFromUri(uri, &relative, &error))
    return std::vector<uint8_t>();
  uint64_t length = 0;
  if (!gltf::GetUintMember(buffer, "byteLength", 0, &length))
    return Status(StatusCode::kParseError, name + ": " + item + ": byteLength is malformed");
  const std::string path = (base_dir.empty() ? std::string(".") : base_dir) + "/" + relative;
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(path);
  if (!bytes.ok()) return bytes.status();
  if (bytes->size() < length) {
    return Status(StatusCode::kParseError, name + ": " + item + ": byteLength " +
                                               std::to_string(length) + " exceeds " + path);
  }
  bytes->resize(static_cast<size_t>(length));
  *found = true;
  return bytes;
}

}  // namespace

// Every object that refers to a buffer by its "buffer" member (an unsigned integer): each
// bufferView and, for EXT_meshopt_compression, the view's extension.
void ForEachBufferHolder(nlohmann::json& json, const std::function<void(nlohmann::json&)>& visit) {
  if (!json.contains("bufferViews") || !json["bufferViews"].is_array()) return;
  auto holds = [](const nlohmann::json& h) {
    return h.is_object() && h.contains("buffer") && h["buffer"].is_number_unsigned();
  };
  for (nlohmann::json& view : json["bufferViews"]) {
    if (!view.is_object()) continue;
    if (holds(view)) visit(view);
    if (view.contains("extensions") && view["extensions"].is_object() &&
        view["extensions"].contains(kMeshoptExtension) &&
        holds(view["extensions"][kMeshoptExtension]))
      visit(view["extensions"][kMeshoptExtension]);
  }
}

bool MoveOffset(nlohmann::json& holder, uint64_t by) {
  uint64_t offset = 0;
  if (!gltf::GetUintMember(holder, "byteOffset", 0, &offset) || offset > UINT64_MAX - by)
    return false;
  holder["byteOffset"] = offset + by;
  return true;
}

Status AdoptBufferFiles(GltfDocument& doc, const std::string& base_dir, const std::string& name,
                        bool first_only) {
  nlohmann::json& json = doc.json();
  if (!json.contains("buffers") || !json["buffers"].is_array() || json["buffers"].empty())
    return Status::Ok();
  nlohmann::json& buffers = json["buffers"];
  if (!doc.has_binary_chunk()) {
    bool found = false;
    Result<std::vector<uint8_t>> bytes = ReadBufferFile(buffers[0], 0, base_dir, name, &found);
    if (!bytes.ok()) return bytes.status();
    if (!found) return Status::Ok();
    doc.binary() = std::move(bytes.value());
    buffers[0].erase("uri");
  }
  if (first_only) return Status::Ok();
  // The other buffer files are appended to the binary chunk (16-byte aligned) and their views
  // rebased onto it, so that the decoders read one buffer, as in a GLB.
  std::vector<int64_t> new_index(buffers.size());
  std::vector<uint64_t> base(buffers.size(), 0);
  std::vector<bool> merged(buffers.size(), false);
  nlohmann::json kept = nlohmann::json::array();
  kept.push_back(buffers[0]);
  new_index[0] = 0;
  for (size_t i = 1; i < buffers.size(); ++i) {
    bool found = false;
    Result<std::vector<uint8_t>> bytes = ReadBufferFile(buffers[i], i, base_dir, name, &found);
    if (!bytes.ok()) return bytes.status();
    if (!found) {
      new_index[i] = static_cast<int64_t>(kept.size());
      kept.push_back(buffers[i]);
      continue;
    }
    std::vector<uint8_t>& bin = doc.binary();
    bin.resize((bin.size() + 15) / 16 * 16, 0);
    base[i] = bin.size();
    bin.insert(bin.end(), bytes->begin(), bytes->end());
    merged[i] = true;
    new_index[i] = 0;
  }
  if (kept.size() == buffers.size()) return Status::Ok();
  bool well_formed = true;
  ForEachBufferHolder(json, [&](nlohmann::json& holder) {
    const uint64_t i = holder["buffer"].get<uint64_t>();
    if (i >= new_index.size()) return;
    if (merged[i]) well_formed = well_formed && MoveOffset(holder, base[i]);
    holder["buffer"] = new_index[i];
  });
  if (!well_formed)
    return Status(StatusCode::kParseError, name + ": a bufferView's byteOffset is malformed");
  buffers = std::move(kept);
  buffers[0]["byteLength"] = doc.binary().size();
  return Status::Ok();
}

Result<std::vector<CollisionHull>> ReadCollisionHulls(const GltfDocument& doc,
                                                      const std::string& name) {
  std::vector<CollisionHull> out;
  const nlohmann::json& json = doc.json();
  if (!json.contains("nodes") || !json["nodes"].is_array()) return out;
  const nlohmann::json& nodes = json["nodes"];
  std::vector<int> parent(nodes.size(), -1);
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i].is_object() || !nodes[i].contains("children") || !nodes[i]["children"].is_array())
      continue;
    for (const nlohmann::json& c : nodes[i]["children"]) {
      if (c.is_number_integer() && c.get<int64_t>() >= 0 &&
          static_cast<uint64_t>(c.get<int64_t>()) < nodes.size())
        parent[static_cast<size_t>(c.get<int64_t>())] = static_cast<int>(i);
    }
  }
  const size_t meshes =
      json.contains("meshes") && json["meshes"].is_array() ? json["meshes"].size() : 0;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const std::string where = name + ": nodes[" + std::to_string(i) + "]";
    Result<int64_t> mesh = ColliderMesh(json, nodes[i], where);
    if (!mesh.ok()) return mesh.status();
    if (mesh.value() < 0) continue;
    if (static_cast<uint64_t>(mesh.value()) >= meshes)
      return Status(StatusCode::kParseError, where + ": collider mesh does not exist");
    CollisionHull h;
    h.body_node = parent[i];
    h.collider_node = static_cast<int>(i);
    h.gltf_mesh = static_cast<int>(mesh.value());
    const nlohmann::json& m = json["meshes"][static_cast<size_t>(mesh.value())];
    if (!m.is_object() || !m.contains("primitives") || !m["primitives"].is_array())
      return Status(StatusCode::kParseError, where + ": collider mesh has no primitives");
    for (const nlohmann::json& prim : m["primitives"]) {
      int64_t position = -1, indices = -1;
      uint64_t mode = gltf::kModeTriangles;
      if (prim.is_object() && prim.contains("attributes") && prim["attributes"].is_object() &&
          prim["attributes"].contains("POSITION") &&
          prim["attributes"]["POSITION"].is_number_integer())
        position = prim["attributes"]["POSITION"].get<int64_t>();
      if (prim.is_object() && prim.contains("indices") && prim["indices"].is_number_integer())
        indices = prim["indices"].get<int64_t>();
      if (!gltf::GetUintMember(prim, "mode", gltf::kModeTriangles, &mode))
        return Status(StatusCode::kParseError, where + ": collider primitive mode is malformed");
      std::vector<double> p;
      int dims = 0;
      Status s = ReadAccessor(doc, position, where, &p, &dims);
      if (!s.ok()) return s;
      if (dims != 3) return Status(StatusCode::kParseError, where + ": POSITION is not VEC3");
      const uint32_t base = static_cast<uint32_t>(h.hull.vertex_count());
      for (size_t v = 0; v * 3 < p.size(); ++v) {
        double q[3];
        Transform(nodes[i], &p[v * 3], q);
        for (int k = 0; k < 3; ++k) h.hull.positions.push_back(static_cast<float>(q[k]));
      }
      if (mode != gltf::kModeTriangles) continue;  // points: the engine builds the hull
      std::vector<double> idx;
      if (indices >= 0) {
        s = ReadAccessor(doc, indices, where, &idx, &dims);
        if (!s.ok()) return s;
      } else {
        for (size_t v = 0; v < p.size() / 3; ++v) idx.push_back(double(v));
      }
      for (double x : idx) {
        if (!(x >= 0 && x < double(p.size() / 3)))
          return Status(StatusCode::kParseError, where + ": collider index out of range");
        h.hull.indices.push_back(base + static_cast<uint32_t>(x));
      }
    }
    out.push_back(std::move(h));
  }
  return out;
}

}  // namespace hullpack
