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

}  // namespace gltf
}  // namespace hullpack
