#include "gltf/meshopt_inflate.h"

#include <meshoptimizer.h>

#include <exception>
#include <new>

#include "gltf/buffer_compaction.h"
#include "gltf/embedded_buffers.h"
#include "gltf/glb_reader.h"
#include "gltf/json_members.h"

namespace hullpack {
namespace {

class MeshoptInflater {
 public:
  // Decoded bytes are bounded like any reader allocation: 64 per file byte plus 1 MiB.
  MeshoptInflater(GltfDocument& doc, const std::string& name)
      : doc_(doc), json_(doc.json()), name_(name), buffers_(doc) {
    const uint64_t input = doc.source_size() != 0 ? doc.source_size() : doc.binary().size();
    budget_ = input * GltfReadOptions().max_expansion + (1u << 20);
  }

  Status Run() {
    if (!json_.contains("bufferViews") || !json_["bufferViews"].is_array()) return Finish();
    nlohmann::json& views = json_["bufferViews"];
    for (size_t v = 0; v < views.size(); ++v) {
      if (!views[v].is_object() || !views[v].contains("extensions") ||
          !views[v]["extensions"].is_object() ||
          !views[v]["extensions"].contains(kMeshoptExtension))
        continue;
      where_ = "bufferViews[" + std::to_string(v) + "]";
      // The decoded bytes go to the binary chunk, so the document must have one as buffer 0.
      if (inflated_ == 0 && !HasBinaryChunk()) {
        return Status(StatusCode::kUnsupported,
                      name_ + ": " + kMeshoptExtension +
                          " is read from GLB files only (convert the .gltf to .glb first)");
      }
      Status s = InflateView(views[v]);
      if (!s.ok()) return s;
      ++inflated_;
    }
    return Finish();
  }

 private:
  Status Error(const std::string& what) const {
    return Status(StatusCode::kParseError,
                  name_ + ": " + where_ + ": " + kMeshoptExtension + ": " + what);
  }

  bool HasBinaryChunk() const {
    return doc_.has_binary_chunk() && json_.contains("buffers") && json_["buffers"].is_array() &&
           !json_["buffers"].empty() && json_["buffers"][0].is_object() &&
           !json_["buffers"][0].contains("uri");
  }

  Status InflateView(nlohmann::json& view) {
    const nlohmann::json& ext = view["extensions"][kMeshoptExtension];
    if (!ext.is_object()) return Error("not an object");
    uint64_t buffer = 0, offset = 0, length = 0, stride = 0, count = 0;
    std::string mode, filter = "NONE";
    if (!ext.contains("buffer") || !ext.contains("byteLength") || !ext.contains("byteStride") ||
        !ext.contains("count") || !ext.contains("mode"))
      return Error("buffer, byteLength, byteStride, count or mode missing");
    if (!gltf::GetUintMember(ext, "buffer", 0, &buffer) ||
        !gltf::GetUintMember(ext, "byteOffset", 0, &offset) ||
        !gltf::GetUintMember(ext, "byteLength", 0, &length) ||
        !gltf::GetUintMember(ext, "byteStride", 0, &stride) ||
        !gltf::GetUintMember(ext, "count", 0, &count) ||
        !gltf::GetStringMember(ext, "mode", &mode) ||
        !gltf::GetStringMember(ext, "filter", &filter))
      return Error("a member has the wrong JSON type");
    // The extension's rules for each mode and filter.
    if (mode == "ATTRIBUTES") {
      if (stride == 0 || stride > 256 || stride % 4 != 0)
        return Error("ATTRIBUTES need a byteStride that is a multiple of 4 up to 256");
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
      if (stride != 2 && stride != 4) return Error(mode + " need a byteStride of 2 or 4");
      if (mode == "TRIANGLES" && count % 3 != 0) return Error("TRIANGLES need a count of 3n");
      if (filter != "NONE") return Error("filters apply to ATTRIBUTES only");
    } else {
      return Error("unknown mode " + mode);
    }
    if (filter == "OCTAHEDRAL"    ? (stride != 4 && stride != 8)
        : filter == "QUATERNION"  ? stride != 8
        : filter == "EXPONENTIAL" ? stride % 4 != 0
                                  : filter != "NONE")
      return Error("filter " + filter + " does not fit byteStride " + std::to_string(stride));
    uint64_t size = 0;
    if (__builtin_mul_overflow(count, stride, &size) || size > budget_) {
      return Status(StatusCode::kUnsupported,
                    name_ + ": " + where_ + ": " + kMeshoptExtension + ": " +
                        std::to_string(count) + " x " + std::to_string(stride) +
                        " decoded bytes are more than the file can justify");
    }
    uint64_t view_length = 0;
    if (!gltf::GetUintMember(view, "byteLength", 0, &view_length) || view_length < size)
      return Error("the bufferView's byteLength is smaller than count x byteStride");
    if (buffer > uint64_t(INT64_MAX)) return Error("buffer out of range");
    Result<ByteRange> source = buffers_.Range(int64_t(buffer), offset, length,
                                              name_ + ": " + where_ + ": " + kMeshoptExtension);
    if (!source.ok()) return source.status();
    budget_ -= size;

    std::vector<uint8_t> decoded(size);
    int rc = 0;
    if (mode == "ATTRIBUTES") {
      rc = meshopt_decodeVertexBuffer(decoded.data(), count, stride, source->data, source->size);
    } else if (mode == "TRIANGLES") {
      rc = meshopt_decodeIndexBuffer(decoded.data(), count, stride, source->data, source->size);
    } else {
      rc = meshopt_decodeIndexSequence(decoded.data(), count, stride, source->data, source->size);
    }
    if (rc != 0)
      return Error("the compressed data is malformed (decoder error " + std::to_string(rc) + ")");
    if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(decoded.data(), count, stride);
    if (filter == "QUATERNION") meshopt_decodeFilterQuat(decoded.data(), count, stride);
    if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(decoded.data(), count, stride);

    std::vector<uint8_t>& bin = doc_.binary();
    while (bin.size() % 16 != 0) bin.push_back(0);  // as aligned as any attribute needs
    view["buffer"] = 0;
    view["byteOffset"] = bin.size();
    view["byteLength"] = size;
    bin.insert(bin.end(), decoded.begin(), decoded.end());
    view["extensions"].erase(kMeshoptExtension);
    if (view["extensions"].empty()) view.erase("extensions");
    return Status::Ok();
  }

  // Drops the buffers no bufferView refers to any more (the fallbacks) and renumbers the rest.
  Status DropUnreferencedBuffers() {
    if (!json_.contains("buffers") || !json_["buffers"].is_array()) return Status::Ok();
    nlohmann::json& buffers = json_["buffers"];
    std::vector<int64_t> new_index(buffers.size(), -1);
    new_index[0] = 0;  // the binary chunk, which now holds the decoded bytes
    nlohmann::json& views = json_["bufferViews"];
    for (const nlohmann::json& v : views) {
      uint64_t b = 0;
      if (v.is_object() && gltf::GetUintMember(v, "buffer", 0, &b) && b < buffers.size())
        new_index[b] = 0;
    }
    nlohmann::json kept = nlohmann::json::array();
    for (size_t b = 0; b < buffers.size(); ++b) {
      if (new_index[b] < 0) continue;
      new_index[b] = int64_t(kept.size());
      kept.push_back(std::move(buffers[b]));
    }
    for (nlohmann::json& v : views) {
      uint64_t b = 0;
      if (v.is_object() && gltf::GetUintMember(v, "buffer", 0, &b) && b < new_index.size())
        v["buffer"] = new_index[b];
    }
    if (kept.empty() || !kept[0].is_object()) return Error("buffers[0] is not an object");
    kept[0]["byteLength"] = doc_.binary().size();
    buffers = std::move(kept);
    return Status::Ok();
  }

  Status Finish() {
    doc_.DropExtension(kMeshoptExtension);
    if (inflated_ == 0) return Status::Ok();
    where_ = "buffers";
    Status s = DropUnreferencedBuffers();
    if (!s.ok()) return s;
    if (buffers_.used_data_uris()) return Status::Ok();
    // The compressed bytes are referenced by nothing now; repacking drops them.
    s = CompactBufferViews(doc_);
    if (!s.ok()) return Status(s.code(), name_ + ": " + s.message());
    return Status::Ok();
  }

  GltfDocument& doc_;
  nlohmann::json& json_;
  const std::string& name_;
  EmbeddedBuffers buffers_;
  std::string where_;
  size_t inflated_ = 0;
  uint64_t budget_ = 0;  // bytes the remaining views may still take
};

}  // namespace

Status InflateMeshoptBufferViews(GltfDocument& doc, const std::string& name) {
  try {
    return MeshoptInflater(doc, name).Run();
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kUnsupported,
                  name + ": out of memory while decoding meshopt-compressed buffers");
  } catch (const std::exception& e) {
    return Status(StatusCode::kParseError, name + ": malformed glTF: " + e.what());
  }
}

}  // namespace hullpack
