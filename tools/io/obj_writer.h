// Wavefront OBJ writer: `o` per mesh, `v` (with `r g b` when the mesh has colours), `vt` from the
// first UV set (flipped back to the OBJ convention), `vn`, and `usemtl` runs per material id.
// Joints, weights, tangents and extra UV sets have no OBJ form and are left out.
#ifndef HULLPACK_TOOLS_IO_OBJ_WRITER_H_
#define HULLPACK_TOOLS_IO_OBJ_WRITER_H_

#include <string>

#include "scene/scene.h"

namespace hullpack {

std::string EncodeObj(const Scene& scene);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_OBJ_WRITER_H_
