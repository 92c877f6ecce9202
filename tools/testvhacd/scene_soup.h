// Every mesh instance of a scene in world space, as one triangle soup in double precision (what
// testVHACD and vhacd_bench decompose). The flattening itself is mesh/flatten.h's.
#ifndef HULLPACK_TOOLS_TESTVHACD_SCENE_SOUP_H_
#define HULLPACK_TOOLS_TESTVHACD_SCENE_SOUP_H_

#include <cstdint>
#include <vector>

#include "mesh/flatten.h"
#include "scene/scene.h"

namespace hullpack {

// Appends FlattenScene(scene)'s positions (xyz) to `points` and its triangles to `indices`.
inline void SceneSoup(const Scene& scene, std::vector<double>* points,
                      std::vector<uint32_t>* indices) {
  const Mesh all = FlattenScene(scene);
  const uint32_t base = static_cast<uint32_t>(points->size() / 3);
  points->insert(points->end(), all.positions.begin(), all.positions.end());
  for (uint32_t i : all.indices) indices->push_back(base + i);
}

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_TESTVHACD_SCENE_SOUP_H_
