// The torus the pipeline tests share: major radius 1, tube 0.3, in the xy plane centred at
// (cx, 0, 0); rings x sides vertices with unit normals, two triangles per quad, closed, genus 1.
#ifndef HULLPACK_TESTS_TOOLS_PIPELINE_TEST_TORUS_H_
#define HULLPACK_TESTS_TOOLS_PIPELINE_TEST_TORUS_H_

#include <cmath>

#include "scene/scene.h"

namespace hullpack::testing {

inline Mesh TorusMesh(int rings, int sides, float cx = 0) {
  Mesh m;
  m.name = "torus";
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      const double u = 2 * pi * i / rings, v = 2 * pi * j / sides;
      m.positions.insert(m.positions.end(),
                         {float(cx + (1 + 0.3 * std::cos(v)) * std::cos(u)),
                          float((1 + 0.3 * std::cos(v)) * std::sin(u)), float(0.3 * std::sin(v))});
      m.normals.insert(m.normals.end(), {float(std::cos(v) * std::cos(u)),
                                         float(std::cos(v) * std::sin(u)), float(std::sin(v))});
    }
  }
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      const uint32_t a = i * sides + j, b = ((i + 1) % rings) * sides + j,
                     c = ((i + 1) % rings) * sides + (j + 1) % sides,
                     d = i * sides + (j + 1) % sides;
      m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
  }
  return m;
}

}  // namespace hullpack::testing

#endif  // HULLPACK_TESTS_TOOLS_PIPELINE_TEST_TORUS_H_
