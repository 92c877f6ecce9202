// The torus the pipeline tests share: major radius 1, tube 0.3, in the xy plane centred at
// (cx, 0, 0); rings x sides vertices with unit normals, two triangles per quad, closed, genus 1
// (test_shapes::Torus, whose vertex order it keeps).
#ifndef HULLPACK_TESTS_TOOLS_PIPELINE_TEST_TORUS_H_
#define HULLPACK_TESTS_TOOLS_PIPELINE_TEST_TORUS_H_

#include "common/test_shapes.h"
#include "scene/scene.h"

namespace hullpack::testing {

inline Mesh TorusMesh(int rings, int sides, float cx = 0) {
  Mesh m;
  m.name = "torus";
  test_shapes::AppendTo(test_shapes::Torus(1, 0.3, rings, sides, cx), &m);
  return m;
}

}  // namespace hullpack::testing

#endif  // HULLPACK_TESTS_TOOLS_PIPELINE_TEST_TORUS_H_
