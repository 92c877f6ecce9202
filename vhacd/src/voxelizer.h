// Voxelization of a triangle soup: surface voxels by exact triangle/box overlap, then the interior
// fill rule documented in include/vhacd/vhacd.h (flood fill from outside + 6-ray parity vote).
#ifndef VHACD_SRC_VOXELIZER_H_
#define VHACD_SRC_VOXELIZER_H_

#include <array>
#include <cstdint>
#include <vector>

#include "context.h"
#include "convex_hull.h"
#include "grid_points.h"
#include "triangle_list.h"

namespace vhacd {
namespace internal {

// A triangle soup in grid units: voxel (x, y, z) is the box [x, x+1] x [y, y+1] x [z, z+1].
struct GridMesh {
  GridPoints points;
  TriangleList triangles;  // no degenerate or duplicate triangles
  // The error report's vertex samples (see SampleSurface); empty when `points` are in
  // lexicographic order.
  std::vector<uint32_t> vertex_samples;
};

// Where the grid sits in the (normalized) input space: p = origin + h * g.
struct GridPlacement {
  Vec3 origin = Vec3::Zero();
  double h = 1.0;
  int dims[3] = {0, 0, 0};
};

// Chooses a voxel size giving about `resolution` voxels over the box [bmin, bmax], plus one
// empty voxel of padding on every side. Works for flat and linear boxes too.
GridPlacement ChooseGrid(const Vec3& bmin, const Vec3& bmax, uint32_t resolution);

enum : uint8_t { kCellOutside = 0, kCellSurface = 1, kCellInside = 2 };

struct VoxelGrid {
  int dims[3] = {0, 0, 0};
  std::vector<uint8_t> cell;      // kCellOutside / kCellSurface / kCellInside
  std::vector<uint8_t> votes;     // number of the 6 axis rays from the centre with odd crossings
  std::vector<uint8_t> enclosed;  // 1 when not reachable from outside through non-surface cells

  size_t Index(int x, int y, int z) const {
    return (static_cast<size_t>(z) * dims[1] + y) * dims[0] + x;
  }
  size_t size() const { return cell.size(); }
  // Whether the centre of voxel i is inside the solid (used by the error report).
  bool CenterInside(size_t i) const { return votes[i] >= 4 || (cell[i] == kCellInside); }
};

// Exact separating-axis test between a triangle and the axis-aligned box centre +/- half.
bool TriangleBoxOverlap(const Vec3& center, double half, const Vec3& a, const Vec3& b,
                        const Vec3& c);

// Conservative test for the voxels lo..hi (inclusive index ranges): false only when no voxel of the
// range can pass TriangleBoxOverlap (with a half of 0.5 plus rounding) for the triangle. Lets the
// voxelizer skip the empty parts of a long triangle's box, which are most of it.
bool TriangleMayMeetVoxels(const int lo[3], const int hi[3], const Vec3& a, const Vec3& b,
                           const Vec3& c);

// Marks surface voxels and fills the interior. Returns false when cancelled. *fill_seconds (when
// non-null) receives the time spent on the interior fill. `opening` (a fraction of the grid's
// diagonal, 0 = off): voxels that a ball of that diameter reaches from outside the grid through
// the gaps between surface voxels are outside even when the parity vote says inside.
bool Voxelize(const GridMesh& mesh, const int dims[3], Context* ctx, VoxelGrid* grid,
              double* fill_seconds = nullptr, double opening = 0.0);

// Step 4 of Voxelize: clears the votes of the voxels swept by a ball of diameter `opening` times
// the diagonal coming from outside the grid. False when cancelled.
bool SweepOpenings(const int dims[3], double opening, Context* ctx, VoxelGrid* grid);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_VOXELIZER_H_
