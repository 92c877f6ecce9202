#ifndef HULLPACK_TOOLS_GLTF_JSON_MEMBERS_H_
#define HULLPACK_TOOLS_GLTF_JSON_MEMBERS_H_

// Optional members of untrusted glTF JSON, read without exceptions (nlohmann's value() and get()
// throw on a member of another type, and a file decides the types). Each returns false when the
// member is present with the wrong type, so the caller can name the file and the member in its
// error. `obj` may be any JSON value: members of a non-object are absent.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/status.h"

namespace hullpack {
namespace gltf {

// A non-negative integer (also written as an integral float below 2^53). Absent: *out = fallback.
bool GetUintMember(const nlohmann::json& obj, const char* key, uint64_t fallback, uint64_t* out);

// A boolean. Absent: *out is left unchanged.
bool GetBoolMember(const nlohmann::json& obj, const char* key, bool* out);

// A string. Absent: *out is left unchanged.
bool GetStringMember(const nlohmann::json& obj, const char* key, std::string* out);

// An integer member in [0, limit), or -1 (absent, of another type, or out of range).
int64_t IndexMember(const nlohmann::json& obj, const char* key, size_t limit);

// The size of the top-level array `key` of `root` (0 when absent or not an array).
size_t ArraySize(const nlohmann::json& root, const char* key);

// Calls `inflate(primitive, where)` for every mesh primitive of `root` that carries the extension
// `extension` ("meshes[m].primitives[p]" as `where`), in order, and removes the extension from the
// primitive once the call succeeds. Stops at the first error.
Status ForEachPrimitiveWith(
    nlohmann::json& root, const char* extension,
    const std::function<Status(nlohmann::json& primitive, const std::string& where)>& inflate);

}  // namespace gltf
}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_JSON_MEMBERS_H_
