// Binary little-endian PLY writer: x y z float, optional nx ny nz, s t (first UV set, OBJ-style v),
// red green blue alpha uchar; faces as uchar-counted int lists. Meshes are merged into one.
// PLY is read back through assimp.
#ifndef HULLPACK_TOOLS_IO_PLY_WRITER_H_
#define HULLPACK_TOOLS_IO_PLY_WRITER_H_

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace hullpack {

std::vector<uint8_t> EncodePly(const Scene& scene);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_PLY_WRITER_H_
