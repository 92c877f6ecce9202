// Local transforms between their two glTF forms: a column-major matrix and translation, rotation,
// scale (TRS). Readers keep TRS where the file has it; writers need TRS for animated nodes, which
// glTF animates component by component.
#ifndef HULLPACK_TOOLS_SCENE_TRANSFORM_H_
#define HULLPACK_TOOLS_SCENE_TRANSFORM_H_

#include "scene/scene.h"

namespace hullpack {

// translation * rotation * scale, as glTF composes them. The quaternion is used as given (glTF
// requires it to be unit length).
Matrix4 TrsMatrix(const Trs& trs);

// The TRS whose matrix is `m`, for a matrix without shear or projection (what TrsMatrix makes).
// A negative determinant (a mirror) becomes a negative x scale. Returns false, with `out`
// unchanged, when `m` has a zero scale, shear or a projective row, which TRS cannot express.
bool DecomposeMatrix(const Matrix4& m, Trs* out);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_SCENE_TRANSFORM_H_
