// A quad mesh with every optional attribute, for the pipeline stage tests. Header-only test helper.
#ifndef HULLPACK_TESTS_TOOLS_PIPELINE_ATTRIBUTED_QUAD_H_
#define HULLPACK_TESTS_TOOLS_PIPELINE_ATTRIBUTED_QUAD_H_

#include "scene/scene.h"

namespace hullpack {
namespace testing {

// Two triangles sharing an edge, with normals, tangents, two UV sets, colours and material 0.
inline Mesh AttributedQuad() {
  Mesh m;
  m.name = "quad";
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  m.tangents = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  m.uv_sets = {{0, 0, 1, 0, 1, 1, 0, 1}, {0, 0, 1, 0, 1, 1, 0, 1}};
  m.colors = {0.5f, 1, 1, 1, 0.5f, 1, 1, 1, 0.5f, 1, 1, 1, 0.5f, 1, 1, 1};
  m.material_ids = {0, 0};
  return m;
}

}  // namespace testing
}  // namespace hullpack

#endif  // HULLPACK_TESTS_TOOLS_PIPELINE_ATTRIBUTED_QUAD_H_
