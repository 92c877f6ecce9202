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

namespace vhacd {
namespace internal {

struct Voxel {
  uint16_t c[3];
  uint8_t surface;  // 1 when the input surface crosses the voxel
  uint8_t pad = 0;
};

struct Part {
  std::vector<Voxel> voxels;
  int bmin[3] = {0, 0, 0}, bmax[3] = {0, 0, 0};  // inclusive voxel bounds
  double volume() const { return static_cast<double>(voxels.size()); }
  void ComputeBounds();
};

// The voxels of one part sorted into lines parallel to `axis`.
struct AxisLines {
  int axis = 0;
  std::vector<uint32_t> start;     // line l holds coords[start[l] .. start[l+1])
  std::vector<uint16_t> coords;    // sorted coordinates along `axis`
  std::vector<uint16_t> lu, lv;    // the line's coordinates on the two other axes
  std::vector<uint32_t> slice_count;  // voxels per slice, from bmin[axis] to bmax[axis]
  int umin = 0, umax = 0, vmin = 0, vmax = 0;  // bounds of lu and lv

  size_t line_count() const { return lu.size(); }
};

AxisLines BuildAxisLines(const Part& part, int axis);

// Corner points of the hull of the voxels of `lines` whose coordinate along the axis is < c
// (left) or >= c (right). With downsample = d > 1 only the lines whose two other coordinates are
// multiples of d are used, each standing for a d x d bundle of lines (its faces are widened to
// d x d): the hull and *volume (when non-null) then describe the same coarse shape, so their
// difference is a consistent concavity estimate. d = 1 is exact.
void SideHullPoints(const AxisLines& lines, int c, bool left, int downsample, std::vector<Vec3>* out,
                    double* volume = nullptr);

// Exact hull of a part's voxels (of only its non-surface voxels when interior_only).
void PartHullPoints(const Part& part, bool interior_only, std::vector<Vec3>* out);

// Volume of the exact hull of the points (0 when degenerate).
double ExactHullVolume(const std::vector<Vec3>& points);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_PRIMITIVE_SET_H_
