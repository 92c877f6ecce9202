#ifndef HULLPACK_TOOLS_GLTF_JSON_MEMBERS_H_
#define HULLPACK_TOOLS_GLTF_JSON_MEMBERS_H_

// Optional members of untrusted glTF JSON, read without exceptions (nlohmann's value() and get()
// throw on a member of another type, and a file decides the types). Each returns false when the
// member is present with the wrong type, so the caller can name the file and the member in its
// error. `obj` may be any JSON value: members of a non-object are absent.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace hullpack {
namespace gltf {

// A non-negative integer (also written as an integral float below 2^53). Absent: *out = fallback.
bool GetUintMember(const nlohmann::json& obj, const char* key, uint64_t fallback, uint64_t* out);

// A boolean. Absent: *out is left unchanged.
bool GetBoolMember(const nlohmann::json& obj, const char* key, bool* out);

// A string. Absent: *out is left unchanged.
bool GetStringMember(const nlohmann::json& obj, const char* key, std::string* out);

}  // namespace gltf
}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_JSON_MEMBERS_H_
