// The separate pieces of a voxel set: voxels joined through a face, an edge or a corner (26
// neighbours) belong to one island. A mesh of several objects side by side (a row of crates, a
// scene exported as one mesh) voxelizes to one island per object, or per group of objects closer
// than a voxel.
//
// Why: under a distance target (Parameters::max_concavity) a hull over two objects is within the
// target whenever the gap between them is, so the objects of a scene shared hulls that filled the
// space between them. The decomposition therefore starts from the islands, when they are apart,
// and merges hulls of different islands only to meet a hull budget (vhacd/README.md).
#ifndef VHACD_SRC_VOXEL_ISLANDS_H_
#define VHACD_SRC_VOXEL_ISLANDS_H_

#include <cstdint>
#include <vector>

#include "primitive_set.h"

namespace vhacd {
namespace internal {

class VoxelIslands {
 public:
  // Labels the voxels of `root` on a grid of `dims`, islands numbered in the order of their first
  // voxel in `root`.
  VoxelIslands(const Part& root, const int dims[3]);

  uint32_t count() const { return count_; }
  // The island of a voxel of the labelled set.
  uint32_t Of(const Voxel& v) const { return label_[Cell(v)]; }
  // `root` (the labelled set) as one part per island, in island order; each keeps its voxels (and
  // in tetrahedron mode their cells) in root's order, with bounds and cell volume computed.
  std::vector<Part> Split(Part root) const;
  // The volume of the islands' own hulls together over that of the hull of `root` (the labelled
  // set, its bounds computed), stopping once past `stop`. Small when the pieces are objects apart;
  // near or above 1 for clusters of objects closer than a voxel, whose hulls overlap and fill the
  // same space as one.
  double HullShare(const Part& root, double stop) const;

 private:
  size_t Cell(const Voxel& v) const {
    return (static_cast<size_t>(v.c[2]) * dims_[1] + v.c[1]) * dims_[0] + v.c[0];
  }
  int dims_[3];
  std::vector<uint32_t> label_;  // per grid cell; kNone where no voxel is
  uint32_t count_ = 0;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_VOXEL_ISLANDS_H_
