// VRML 2.0 (.wrl): the writer emits one Shape with an IndexedFaceSet per mesh, each with its own
// diffuse colour, as the original testVHACD wrote hull sets. The parser reads back the
// IndexedFaceSet `coord Coordinate { point [...] }` and `coordIndex [...]` of every Shape
// (other VRML nodes are skipped) so that hull files can be checked and round-tripped.
// Trust model of the parser: any byte sequence is safe; malformed input gives a kParseError.
#ifndef HULLPACK_TOOLS_IO_WRL_FORMAT_H_
#define HULLPACK_TOOLS_IO_WRL_FORMAT_H_

#include <string>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

Result<Scene> ParseWrl(const char* data, size_t size, const std::string& name);
std::string EncodeWrl(const Scene& scene);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_WRL_FORMAT_H_
