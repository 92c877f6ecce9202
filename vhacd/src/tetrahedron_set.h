// Mode 1 (tetrahedra): the voxel set as tetrahedra trimmed to the input surface.
//
// Every solid voxel is split into 5 tetrahedra (a central one and four corner ones). An interior
// voxel keeps them whole: together they are its cube, so it stays an ordinary voxel of the part.
// The tetrahedra of a surface voxel are trimmed to the local surface. The input triangles inside
// the voxel are grouped into sheets of similar normals (up to 3); each sheet gives a plane,
// oriented away from the solid by the neighbouring inside/outside voxels and pushed out to the
// sheet's outermost point, so that only empty space is cut away. One sheet: the tetrahedra are
// clipped by its half-space; sheets meeting at a convex edge or corner: by the intersection of the
// half-spaces; two sheets at a concave edge: by their union. A clipped tetrahedron is split into
// tetrahedra again. Voxels whose surface is anything else (folds, thin sheets with outside on both
// sides, more than 3 sheets) keep their 5 tetrahedra whole.
//
// Cut planes lie between voxel slices (as in mode 0), so no tetrahedron is ever cut by one: a
// surface voxel's tetrahedra are kept as a SurfaceCell, their total volume and the distinct
// vertices of their union, which is everything the clipping stage needs (volumes and hulls).
#ifndef VHACD_SRC_TETRAHEDRON_SET_H_
#define VHACD_SRC_TETRAHEDRON_SET_H_

#include <array>
#include <cstdint>
#include <vector>

#include "context.h"
#include "convex_hull.h"
#include "voxelizer.h"

namespace vhacd {
namespace internal {

struct SurfaceCell {
  static constexpr int kMaxPoints = 16;
  uint16_t c[3] = {0, 0, 0};  // the voxel
  uint8_t point_count = 0;
  uint8_t tetrahedra = 0;  // number of (trimmed) tetrahedra
  float volume = 0.0f;     // their total volume, in voxels (<= 1)
  float p[kMaxPoints][3];  // distinct vertices, grid coordinates
};

// Volume of tetrahedron (a, b, c, d) clipped to the half-space n.x <= d0, and the number of
// tetrahedra the clipped solid is split into (0 when nothing is left). When `pieces` is non-null
// the pieces are appended (4 points each).
double ClipTetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& n,
                       double d0, int* count, std::vector<std::array<Vec3, 4>>* pieces = nullptr);

// The 5 tetrahedra of the unit cube [0,1]^3 (corner k at (k & 1, (k >> 1) & 1, (k >> 2) & 1)).
extern const int kCubeTetrahedra[5][4];

// n.x <= d, n of unit length, grid coordinates.
struct HalfSpace {
  Vec3 n = Vec3::UnitZ();
  double d = 0.0;
};

// The cell of voxel (x, y, z) trimmed to the intersection of the half-spaces, or, when
// union_of_two, to the union of two of them (a concave edge). Whole when nothing is cut away (or
// the trimmed cell would need more than kMaxPoints vertices).
SurfaceCell TrimmedCell(int x, int y, int z, const HalfSpace* planes, int count, bool union_of_two);
SurfaceCell TrimmedCell(int x, int y, int z, const Vec3& n, double d0);
// The untrimmed cell (its 8 corners, volume 1, 5 tetrahedra).
SurfaceCell FullCell(int x, int y, int z);

// One cell per surface voxel of `grid`, in grid order (z, then y, then x). False when cancelled.
bool BuildSurfaceCells(const GridMesh& mesh, const VoxelGrid& grid, Context* ctx,
                       std::vector<SurfaceCell>* cells);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_TETRAHEDRON_SET_H_
