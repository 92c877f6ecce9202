// Whole-file reads and atomic writes: outputs go to a temporary file beside the target, then
// rename, so an interrupted run never leaves a half-written file and never destroys the previous
// one.
#ifndef HULLPACK_TOOLS_COMMON_FILE_UTIL_H_
#define HULLPACK_TOOLS_COMMON_FILE_UTIL_H_

#include <cstdint>
#include <string>
#include <vector>

#include "common/status.h"

namespace hullpack {

// Reads all of `path`. Errors name the path.
Result<std::vector<uint8_t>> ReadFileBytes(const std::string& path);

// Writes `size` bytes to `path` through a temporary file in the same folder and a rename.
Status WriteFileAtomically(const std::string& path, const void* data, size_t size);
inline Status WriteFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes) {
  return WriteFileAtomically(path, bytes.data(), bytes.size());
}

// Creates `path` and its missing parents (like mkdir -p). Errors name the folder.
Status MakeDirectories(const std::string& path);

// True when both paths name the same existing file (hard links and symlinks included).
bool SameFile(const std::string& a, const std::string& b);

// Lower-case extension without the dot ("obj" for "a/b.OBJ"), or "".
std::string LowerExtension(const std::string& path);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_FILE_UTIL_H_
