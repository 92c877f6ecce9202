// The convex hull of one part: the input surface clipped to the part's box and to its oriented cuts
// (Part::cuts), plus the corners of the part's interior voxels. An axis-aligned cut is a plane
// between voxel slices, so without oriented cuts a part is exactly the voxel set inside its
// bounding box; an oriented cut keeps the voxels whose centres are on its side, and its plane
// bounds the surface the part holds: the hull hugs the input instead of the voxels.
#ifndef VHACD_SRC_PART_HULL_H_
#define VHACD_SRC_PART_HULL_H_

#include <cstdint>
#include <mutex>
#include <vector>

#include "convex_hull.h"
#include "primitive_set.h"
#include "solid_corners.h"
#include "voxelizer.h"

namespace vhacd {
namespace internal {

// Buckets of triangles on a coarse uniform grid, for box queries.
class TriangleIndex {
 public:
  TriangleIndex(const GridMesh& mesh, const int dims[3], int cell);
  // Calls fn(t) once for every triangle whose bounding box meets [lo, hi]: `stamp` (one per
  // triangle) must hold no `mark` on entry; the triangles visited get it.
  template <typename Fn>
  void ForEachInBox(const Vec3& lo, const Vec3& hi, std::vector<uint8_t>* stamp, uint8_t mark,
                    Fn fn) const;

  const GridMesh& mesh() const { return mesh_; }
  // Whether the box [lo, hi] holds every point of the mesh.
  bool HoldsMesh(const Vec3& lo, const Vec3& hi) const {
    return (lo.array() <= mesh_lo_.array()).all() && (hi.array() >= mesh_hi_.array()).all();
  }

 private:
  const GridMesh& mesh_;
  int cell_;
  int dims_[3];
  // The bounding box of triangle t.
  void TriangleBox(size_t t, Vec3* lo, Vec3* hi) const {
    const auto& tr = mesh_.triangles[t];
    // Each point read once: a mesh read in place is mapped on every read.
    const Vec3 a = mesh_.points[tr[0]], b = mesh_.points[tr[1]], c = mesh_.points[tr[2]];
    *lo = a.cwiseMin(b).cwiseMin(c);
    *hi = a.cwiseMax(b).cwiseMax(c);
  }
  std::vector<uint32_t> start_, ids_;
  Vec3 mesh_lo_, mesh_hi_;  // the mesh's bounding box
};

// Appends the vertices of the polygon (triangle abc) intersected with the box [lo, hi].
void ClipTriangleToBox(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& lo, const Vec3& hi,
                       std::vector<Vec3>* out);

// The hull of a part (grid units). Falls back to the hull of the part's voxels when the clipped
// surface is flat (e.g. a single sheet). Empty only when even that fails. With `corners`, the
// inside corners of the part's surface voxels on the faces of its box are added (see
// solid_corners.h: without them a thin wall's hull stops short of the cut).
HullMesh BuildPartHull(const Part& part, const TriangleIndex& index,
                       const SolidCorners* corners = nullptr);

// BuildPartHull for the parts of one decomposition, with the hull of its whole voxel set built
// once: the first clipping level of every attempt and orientation, and a part left whole, all
// ask for that hull, and on a large closed mesh it is the costliest one. Thread-safe.
class PartHulls {
 public:
  PartHulls(const Part& whole, const TriangleIndex& index, const SolidCorners* corners)
      : whole_voxels_(whole.voxels.size()), index_(index), corners_(corners) {}
  HullMesh Of(const Part& part);

 private:
  size_t whole_voxels_;
  const TriangleIndex& index_;
  const SolidCorners* corners_;
  std::mutex mutex_;
  bool built_ = false;
  HullMesh whole_hull_;
};

template <typename Fn>
void TriangleIndex::ForEachInBox(const Vec3& lo, const Vec3& hi, std::vector<uint8_t>* stamp,
                                 uint8_t mark, Fn fn) const {
  int clo[3], chi[3];
  for (int a = 0; a < 3; ++a) {
    clo[a] = std::max(0, std::min(dims_[a] - 1, static_cast<int>(lo[a]) / cell_));
    chi[a] = std::max(0, std::min(dims_[a] - 1, static_cast<int>(hi[a]) / cell_));
  }
  for (int z = clo[2]; z <= chi[2]; ++z)
    for (int y = clo[1]; y <= chi[1]; ++y)
      for (int x = clo[0]; x <= chi[0]; ++x) {
        const size_t c = (static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x;
        for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
          const uint32_t t = ids_[k];
          if ((*stamp)[t] == mark) continue;
          (*stamp)[t] = mark;
          Vec3 tlo, thi;
          TriangleBox(t, &tlo, &thi);
          if ((tlo.array() > hi.array()).any() || (thi.array() < lo.array()).any()) continue;
          fn(t);
        }
      }
}

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_PART_HULL_H_
