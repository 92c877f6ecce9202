#include "gltf/buffer_compaction.h"

#include <cstring>
#include <functional>

#include "gltf/json_members.h"
#include "gltf/meshopt_inflate.h"

namespace hullpack {
namespace {

// Calls `visit` on every integer "bufferView" member of the tree.
void ForEachBufferViewRef(nlohmann::json& node, const std::function<void(nlohmann::json&)>& visit) {
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (it.key() == "bufferView" && it.value().is_number_integer()) {
        visit(it.value());
      } else {
        ForEachBufferViewRef(it.value(), visit);
      }
    }
  } else if (node.is_array()) {
    for (nlohmann::json& child : node) ForEachBufferViewRef(child, visit);
  }
}

// The extension object of a view compressed with EXT_meshopt_compression (its bytes in the binary
// chunk are the extension's; the view itself lies on a fallback buffer), else null.
const nlohmann::json* CompressedBytes(const nlohmann::json& view) {
  if (!view.is_object() || !view.contains("extensions") || !view["extensions"].is_object())
    return nullptr;
  const auto ext = view["extensions"].find(kMeshoptExtension);
  return ext != view["extensions"].end() ? &*ext : nullptr;
}

}  // namespace

Status CompactBufferViews(GltfDocument& doc) {
  nlohmann::json& json = doc.json();
  if (!json.contains("bufferViews") || !json["bufferViews"].is_array()) return Status::Ok();
  nlohmann::json& views = json["bufferViews"];
  const std::vector<uint8_t>& bin = doc.binary();
  std::vector<uint64_t> offsets(views.size()), lengths(views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    const nlohmann::json* bytes = CompressedBytes(views[i]);
    if (bytes == nullptr) bytes = &views[i];
    uint64_t buffer = 1;
    if (!bytes->is_object() || !gltf::GetUintMember(*bytes, "buffer", 1, &buffer) || buffer != 0) {
      return Status(StatusCode::kUnsupported,
                    "bufferViews[" + std::to_string(i) + "] is not on the GLB binary chunk");
    }
    uint64_t& offset = offsets[i];
    uint64_t& length = lengths[i];
    if (!gltf::GetUintMember(*bytes, "byteOffset", 0, &offset) ||
        !gltf::GetUintMember(*bytes, "byteLength", 0, &length)) {
      return Status(StatusCode::kParseError,
                    "bufferViews[" + std::to_string(i) +
                        "] has a byteOffset or byteLength that is not a non-negative integer");
    }
    if (offset > bin.size() || length > bin.size() - offset) {
      return Status(StatusCode::kParseError,
                    "bufferViews[" + std::to_string(i) + "] lies outside the binary chunk");
    }
  }
  std::vector<int64_t> new_index(views.size(), -1);
  ForEachBufferViewRef(json, [&](nlohmann::json& ref) {
    const int64_t i = ref.get<int64_t>();
    if (i >= 0 && static_cast<size_t>(i) < new_index.size()) new_index[i] = 0;
  });
  nlohmann::json kept = nlohmann::json::array();
  std::vector<uint8_t> packed;
  for (size_t i = 0; i < views.size(); ++i) {
    if (new_index[i] < 0) continue;
    nlohmann::json v = views[i];
    const uint64_t offset = offsets[i];
    const uint64_t length = lengths[i];
    size_t alignment = 4;
    while (alignment < 16 && offset % (alignment * 2) == 0) alignment *= 2;
    packed.resize((packed.size() + alignment - 1) / alignment * alignment, 0);
    if (CompressedBytes(v) != nullptr) {
      v["extensions"][kMeshoptExtension]["byteOffset"] = packed.size();
    } else {
      v["byteOffset"] = packed.size();
    }
    packed.insert(packed.end(), bin.begin() + static_cast<ptrdiff_t>(offset),
                  bin.begin() + static_cast<ptrdiff_t>(offset + length));
    new_index[i] = static_cast<int64_t>(kept.size());
    kept.push_back(std::move(v));
  }
  ForEachBufferViewRef(json, [&](nlohmann::json& ref) {
    const int64_t i = ref.get<int64_t>();
    if (i >= 0 && static_cast<size_t>(i) < new_index.size()) ref = new_index[i];
  });
  if (kept.empty()) {
    json.erase("bufferViews");
  } else {
    views = std::move(kept);
  }
  doc.binary() = std::move(packed);
  // Readers check views against the declared length, so it must follow the repacked chunk.
  if (json.contains("buffers") && json["buffers"].is_array() && !json["buffers"].empty() &&
      json["buffers"][0].is_object()) {
    json["buffers"][0]["byteLength"] = doc.binary().size();
  }
  return Status::Ok();
}

}  // namespace hullpack
