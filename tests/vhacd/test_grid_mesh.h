// A generated test mesh as the decomposition's internal grid-unit mesh, for the tests of the
// stages that take one (voxelizer, part hulls, stick-out, error metrics, tetrahedra), and voxels.
#ifndef HULLPACK_TESTS_VHACD_TEST_GRID_MESH_H_
#define HULLPACK_TESTS_VHACD_TEST_GRID_MESH_H_

#include <cstdint>

#include "primitive_set.h"
#include "test_meshes.h"
#include "voxelizer.h"

namespace vhacd_test {

// Every point p of `m` becomes scale * p + offset; the triangles are kept as they are.
inline vhacd::internal::GridMesh ToGridMesh(
    const Mesh& m, double scale = 1.0,
    const vhacd::internal::Vec3& offset = vhacd::internal::Vec3::Zero()) {
  vhacd::internal::GridMesh g;
  std::vector<vhacd::internal::Vec3> points;
  for (size_t i = 0; i < m.point_count(); ++i)
    points.push_back(
        scale * vhacd::internal::Vec3(m.points[3 * i], m.points[3 * i + 1], m.points[3 * i + 2]) +
        offset);
  g.points = vhacd::internal::GridPoints(points);
  for (size_t t = 0; t < m.triangle_count(); ++t)
    g.triangles.push_back({m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]});
  return g;
}

// The voxel at (x, y, z) of a grid.
inline vhacd::internal::Voxel VoxelAt(int x, int y, int z, bool surface = false) {
  vhacd::internal::Voxel v;
  v.c[0] = static_cast<uint16_t>(x);
  v.c[1] = static_cast<uint16_t>(y);
  v.c[2] = static_cast<uint16_t>(z);
  v.surface = surface ? 1 : 0;
  return v;
}

}  // namespace vhacd_test

#endif  // HULLPACK_TESTS_VHACD_TEST_GRID_MESH_H_
