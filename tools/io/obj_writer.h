// Wavefront OBJ writer: `o` per mesh, `v` (with `r g b` when the mesh has colours), `vt` from the
// first UV set (flipped back to the OBJ convention), `vn`, and `usemtl` runs per material id.
// Joints, weights, tangents and extra UV sets have no OBJ form and are left out.
#ifndef HULLPACK_TOOLS_IO_OBJ_WRITER_H_
#define HULLPACK_TOOLS_IO_OBJ_WRITER_H_

#include <functional>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace hullpack {

// Receives a text in consecutive pieces.
using TextSink = std::function<void(std::string_view)>;

std::string EncodeObj(const Scene& scene);
// The same text in pieces of about a megabyte: for files too large to hold whole.
void EncodeObj(const Scene& scene, const TextSink& sink);
// One mesh alone, as EncodeObj would write a scene of it without materials (no `usemtl`).
void EncodeObjMesh(const Mesh& mesh, const TextSink& sink);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_OBJ_WRITER_H_
