// Voxel parts: the primitive sets the decomposition clips, and their exact convex hulls.
//
// The hull of a set of voxels equals the hull of, for every line of voxels along one axis, the
// low face of its first voxel and the high face of its last voxel; all functions here use that to
// keep the point counts proportional to an area instead of a volume.
#ifndef VHACD_SRC_PRIMITIVE_SET_H_
#define VHACD_SRC_PRIMITIVE_SET_H_

#include <cstdint>
#include <vector>

#include "convex_hull.h"
#include "tetrahedron_set.h"

namespace vhacd {
namespace internal {

struct Voxel {
  uint16_t c[3];
  uint8_t surface;  // 1 when the input surface crosses the voxel
  uint8_t pad = 0;
};

// A half-space n.x <= d (grid units, n unit length) an oriented cut left a part in.
struct CutPlane {
  Vec3 n = Vec3::UnitX();
  double d = 0.0;
};

struct Part {
  std::vector<Voxel> voxels;
  int bmin[3] = {0, 0, 0}, bmax[3] = {0, 0, 0};  // inclusive voxel bounds
  // Mode 1 (tetrahedra): one cell per surface voxel of `voxels` (same order). The part is then its
  // non-surface voxels (whole cubes, 5 tetrahedra each) plus the cells' trimmed tetrahedra.
  bool tetra = false;
  std::vector<SurfaceCell> cells;
  double cell_volume = 0.0;  // sum of the cells' volumes
  // The oriented cuts that bound the part besides its box (oriented_cuts.h): its surface is the
  // input clipped to the box and to these half-spaces.
  std::vector<CutPlane> cuts;

  double volume() const {
    const double n = static_cast<double>(voxels.size());
    return tetra ? n - static_cast<double>(cells.size()) + cell_volume : n;
  }
  void ComputeBounds();
  void ComputeCellVolume();
};

// The covariance of a part's voxel centres (grid units; zero for fewer than 2 voxels), whose
// eigenvectors are the part's principal axes.
Eigen::Matrix3d VoxelCovariance(const Part& part);

// The voxels of one part sorted into lines parallel to `axis`.
struct AxisLines {
  int axis = 0;
  std::vector<uint32_t> start;                 // line l holds coords[start[l] .. start[l+1])
  std::vector<uint16_t> coords;                // sorted coordinates along `axis`
  std::vector<uint16_t> lu, lv;                // the line's coordinates on the two other axes
  std::vector<uint32_t> slice_count;           // voxels per slice, from bmin[axis] to bmax[axis]
  int umin = 0, umax = 0, vmin = 0, vmax = 0;  // bounds of lu and lv

  size_t line_count() const { return lu.size(); }
};

AxisLines BuildAxisLines(const Part& part, int axis);

// Corner points of the hull of the voxels of `lines` whose coordinate along the axis is < c
// (left) or >= c (right). With downsample = d > 1 only the lines whose two other coordinates are
// multiples of d are used, each standing for a d x d bundle of lines (its faces are widened to
// d x d): the hull and *volume (when non-null) then describe the same coarse shape, so their
// difference is a consistent concavity estimate. d = 1 is exact.
void SideHullPoints(const AxisLines& lines, int c, bool left, int downsample,
                    std::vector<Vec3>* out, double* volume = nullptr);

// The same with a plane per line: line l keeps the voxels below line_split[l] (left) or at/above
// it (right). *count (when non-null) is the exact number of voxels on that side, every line
// counted even when downsampled.
void SideHullPointsPerLine(const AxisLines& lines, const std::vector<int>& line_split, bool left,
                           int downsample, std::vector<Vec3>* out, double* volume,
                           double* count = nullptr);

// Exact hull of a part's voxels (of only its non-surface voxels when interior_only).
void PartHullPoints(const Part& part, bool interior_only, std::vector<Vec3>* out);

// Points whose hull is the hull of the part's primitives: its voxels (mode 0), or its interior
// voxels and its cells' vertices (mode 1).
void PrimitiveHullPoints(const Part& part, std::vector<Vec3>* out);
// Hull of points from PrimitiveHullPoints/SideHullPoints of `part`: exact on voxel coordinates
// (mode 0), tolerant otherwise. False when degenerate.
bool PrimitiveHull(const Part& part, const std::vector<Vec3>& points, HullMesh* out);

// Mode 1, per axis: the part's non-surface voxels as lines, and its cells sorted along the axis.
struct TetraAxis {
  AxisLines interior;
  std::vector<uint32_t> order;        // cell indices sorted by their coordinate along the axis
  std::vector<uint32_t> slice_start;  // order[slice_start[s] ..] are the cells of slice bmin + s
  std::vector<double> prefix_volume;  // primitive volume of the slices below bmin + s
};
TetraAxis BuildTetraAxis(const Part& part, int axis);
// Hull points and volume of the part's primitives below (left) or at/above the plane c.
void TetraSideHullPoints(const Part& part, const TetraAxis& ta, int c, bool left,
                         std::vector<Vec3>* out, double* volume);

// Volume of the exact hull of the points (0 when degenerate).
double ExactHullVolume(const std::vector<Vec3>& points);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_PRIMITIVE_SET_H_
