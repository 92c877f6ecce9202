// Stanford PLY, read by the project's own parser: ASCII, binary_little_endian and
// binary_big_endian 1.0. One mesh per file: the `vertex` element's positions (x y z), normals
// (nx ny nz), texture coordinates (s t, u v, texture_u texture_v or texture_s texture_t; t is up,
// as in OBJ) and colours (red green blue [alpha], integers of 0..255 or floats of 0..1), and the
// `face` element's polygons (`vertex_indices` or `vertex_index`), triangulated as fans. Other
// elements and properties are read past and listed in Scene::dropped.
// Trust model: any byte sequence is safe. Every count is checked against the bytes left before
// anything is allocated, every index against the vertex count.
#ifndef HULLPACK_TOOLS_IO_PLY_READER_H_
#define HULLPACK_TOOLS_IO_PLY_READER_H_

#include <cstddef>
#include <cstdint>
#include <string>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

// `name` starts every error message.
Result<Scene> ParsePly(const uint8_t* data, size_t size, const std::string& name);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_PLY_READER_H_
