#include "voxel_islands.h"

#include <limits>

namespace vhacd {
namespace internal {
namespace {
constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
constexpr uint32_t kUnlabelled = kNone - 1;
}  // namespace

VoxelIslands::VoxelIslands(const Part& root, const int dims[3]) {
  for (int a = 0; a < 3; ++a) dims_[a] = dims[a];
  label_.assign(static_cast<size_t>(dims[0]) * dims[1] * dims[2], kNone);
  for (const Voxel& v : root.voxels) label_[Cell(v)] = kUnlabelled;
  std::vector<Voxel> stack;
  for (const Voxel& seed : root.voxels) {
    if (label_[Cell(seed)] != kUnlabelled) continue;
    const uint32_t island = count_++;
    label_[Cell(seed)] = island;
    stack.push_back(seed);
    while (!stack.empty()) {
      const Voxel v = stack.back();
      stack.pop_back();
      for (int dz = -1; dz <= 1; ++dz) {
        const int z = v.c[2] + dz;
        if (z < 0 || z >= dims_[2]) continue;
        for (int dy = -1; dy <= 1; ++dy) {
          const int y = v.c[1] + dy;
          if (y < 0 || y >= dims_[1]) continue;
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = v.c[0] + dx;
            if (x < 0 || x >= dims_[0]) continue;
            Voxel n;
            n.c[0] = static_cast<uint16_t>(x);
            n.c[1] = static_cast<uint16_t>(y);
            n.c[2] = static_cast<uint16_t>(z);
            n.surface = 0;
            uint32_t& l = label_[Cell(n)];
            if (l != kUnlabelled) continue;
            l = island;
            stack.push_back(n);
          }
        }
      }
    }
  }
}

std::vector<Part> VoxelIslands::Split(Part root) const {
  std::vector<Part> parts(count_);
  size_t cell = 0;  // root.cells follow its surface voxels
  for (const Voxel& v : root.voxels) {
    Part& p = parts[Of(v)];
    p.voxels.push_back(v);
    if (root.tetra && v.surface) p.cells.push_back(root.cells[cell++]);
  }
  for (Part& p : parts) {
    p.tetra = root.tetra;
    p.cuts = root.cuts;
    p.ComputeBounds();
    if (p.tetra) p.ComputeCellVolume();
  }
  return parts;
}

double VoxelIslands::HullShare(const Part& root, double stop) const {
  auto hull_volume = [](const Part& part) {
    std::vector<Vec3> points;
    PrimitiveHullPoints(part, &points);
    HullMesh h;
    return PrimitiveHull(part, points, &h) ? h.Volume() : 0.0;
  };
  const double all = hull_volume(root);
  if (!(all > 0)) return 1.0;
  double sum = 0.0;
  for (const Part& island : Split(root)) {
    sum += hull_volume(island);
    if (sum > stop * all) break;
  }
  return sum / all;
}

}  // namespace internal
}  // namespace vhacd
