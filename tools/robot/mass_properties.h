// Mass, centre of mass and inertia tensor of the union of closed convex hulls at a uniform density.
#ifndef HULLPACK_TOOLS_ROBOT_MASS_PROPERTIES_H_
#define HULLPACK_TOOLS_ROBOT_MASS_PROPERTIES_H_

#include <array>
#include <vector>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

struct MassProperties {
  double volume = 0;               // of the union
  double mass = 0;                 // density * volume
  std::array<double, 3> center{};  // centre of mass
  // Inertia tensor about the centre of mass, axes of the mesh: ixx, iyy, izz, ixy, ixz, iyz
  // (products of inertia with the physics sign convention, ixy = -integral(x y dm)).
  std::array<double, 6> inertia{};
};

// Exact integrals over each hull (closed, outward-facing triangles), minus the parts where hulls
// overlap, which are measured on a grid of about `overlap_cells` cells along the longest side of
// the hulls' bounding box (so hulls that only touch cost nothing and are exact). Errors: no hulls,
// a hull with no volume, a non-finite coordinate, density <= 0.
Result<MassProperties> HullUnionMassProperties(const std::vector<Mesh>& hulls, double density,
                                               int overlap_cells = 96);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_ROBOT_MASS_PROPERTIES_H_
