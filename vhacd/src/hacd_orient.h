// Consistent orientation of a triangle soup, per connected piece (HACD's rays need normals that
// agree across the surface and point outward).
#ifndef VHACD_SRC_HACD_ORIENT_H_
#define VHACD_SRC_HACD_ORIENT_H_

#include <array>
#include <cstdint>
#include <vector>

#include "convex_hull.h"

namespace vhacd {
namespace internal {

// Flips triangles so that every edge shared by exactly two triangles is used in opposite
// directions where the surface allows it (breadth-first from the lowest triangle index of each
// piece), then flips each piece whose signed volume about its centroid is negative.
// Returns the number of triangles flipped.
size_t OrientConsistently(const std::vector<Vec3>& points,
                          std::vector<std::array<uint32_t, 3>>* triangles);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_HACD_ORIENT_H_
