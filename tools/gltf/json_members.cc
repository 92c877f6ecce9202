#include "gltf/json_members.h"

#include <cmath>

namespace hullpack {
namespace gltf {

bool GetUintMember(const nlohmann::json& obj, const char* key, uint64_t fallback, uint64_t* out) {
  auto it = obj.find(key);  // end() for a non-object
  if (it == obj.end()) {
    *out = fallback;
    return true;
  }
  if (it->is_number_unsigned()) {
    *out = it->get<uint64_t>();
    return true;
  }
  if (it->is_number_integer() && it->get<int64_t>() >= 0) {
    *out = static_cast<uint64_t>(it->get<int64_t>());
    return true;
  }
  if (it->is_number_float()) {
    const double v = it->get<double>();
    if (v >= 0 && v < 9.0e15 && std::floor(v) == v) {
      *out = static_cast<uint64_t>(v);
      return true;
    }
  }
  return false;
}

bool GetBoolMember(const nlohmann::json& obj, const char* key, bool* out) {
  auto it = obj.find(key);
  if (it == obj.end()) return true;
  if (!it->is_boolean()) return false;
  *out = it->get<bool>();
  return true;
}

bool GetStringMember(const nlohmann::json& obj, const char* key, std::string* out) {
  auto it = obj.find(key);
  if (it == obj.end()) return true;
  if (!it->is_string()) return false;
  *out = it->get<std::string>();
  return true;
}

int64_t IndexMember(const nlohmann::json& obj, const char* key, size_t limit) {
  if (!obj.is_object() || !obj.contains(key) || !obj[key].is_number_integer()) return -1;
  const int64_t v = obj[key].get<int64_t>();
  return v >= 0 && static_cast<uint64_t>(v) < limit ? v : -1;
}

size_t ArraySize(const nlohmann::json& root, const char* key) {
  return root.is_object() && root.contains(key) && root[key].is_array() ? root[key].size() : 0;
}

Status ForEachPrimitiveWith(
    nlohmann::json& root, const char* extension,
    const std::function<Status(nlohmann::json& primitive, const std::string& where)>& inflate) {
  if (!root.is_object() || !root.contains("meshes") || !root["meshes"].is_array())
    return Status::Ok();
  nlohmann::json& meshes = root["meshes"];
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (!meshes[m].is_object() || !meshes[m].contains("primitives") ||
        !meshes[m]["primitives"].is_array())
      continue;
    nlohmann::json& prims = meshes[m]["primitives"];
    for (size_t p = 0; p < prims.size(); ++p) {
      nlohmann::json& prim = prims[p];
      if (!prim.is_object() || !prim.contains("extensions") || !prim["extensions"].is_object() ||
          !prim["extensions"].contains(extension))
        continue;
      Status s =
          inflate(prim, "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]");
      if (!s.ok()) return s;
      prim["extensions"].erase(extension);
      if (prim["extensions"].empty()) prim.erase("extensions");
    }
  }
  return Status::Ok();
}

}  // namespace gltf
}  // namespace hullpack
