// Object File Format (OFF, and COFF with per-vertex colours): one mesh per file.
// The writer merges every mesh of a scene into one vertex and face list.
// Trust model of the parser: any byte sequence is safe; counts are checked against the file size.
#ifndef HULLPACK_TOOLS_IO_OFF_FORMAT_H_
#define HULLPACK_TOOLS_IO_OFF_FORMAT_H_

#include <string>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

Result<Scene> ParseOff(const char* data, size_t size, const std::string& name);
std::string EncodeOff(const Scene& scene);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_OFF_FORMAT_H_
