#include "primitive_set.h"

#include <algorithm>

namespace vhacd {
namespace internal {

void Part::ComputeBounds() {
  for (int a = 0; a < 3; ++a) {
    bmin[a] = 1 << 30;
    bmax[a] = -1;
  }
  for (const Voxel& v : voxels)
    for (int a = 0; a < 3; ++a) {
      bmin[a] = std::min<int>(bmin[a], v.c[a]);
      bmax[a] = std::max<int>(bmax[a], v.c[a]);
    }
}

namespace {
inline uint64_t LineKey(const Voxel& v, int axis) {
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  return (static_cast<uint64_t>(v.c[w]) << 32) | (static_cast<uint64_t>(v.c[u]) << 16) | v.c[axis];
}

inline Vec3 MakePoint(int axis, double along, double pu, double pv) {
  Vec3 p;
  p[axis] = along;
  p[(axis + 1) % 3] = pu;
  p[(axis + 2) % 3] = pv;
  return p;
}

inline void AddFace(int axis, int along, int u, int v, std::vector<Vec3>* out, int width = 1) {
  out->push_back(MakePoint(axis, along, u, v));
  out->push_back(MakePoint(axis, along, u + width, v));
  out->push_back(MakePoint(axis, along, u, v + width));
  out->push_back(MakePoint(axis, along, u + width, v + width));
}
}  // namespace

AxisLines BuildAxisLines(const Part& part, int axis) {
  AxisLines L;
  L.axis = axis;
  std::vector<uint64_t> keys(part.voxels.size());
  for (size_t i = 0; i < part.voxels.size(); ++i) keys[i] = LineKey(part.voxels[i], axis);
  std::sort(keys.begin(), keys.end());
  L.coords.resize(keys.size());
  uint64_t prev_line = ~uint64_t{0};
  for (size_t i = 0; i < keys.size(); ++i) {
    const uint64_t line = keys[i] >> 16;
    if (line != prev_line) {
      L.start.push_back(static_cast<uint32_t>(i));
      L.lu.push_back(static_cast<uint16_t>(line & 0xffff));
      L.lv.push_back(static_cast<uint16_t>(line >> 16));
      prev_line = line;
    }
    L.coords[i] = static_cast<uint16_t>(keys[i] & 0xffff);
  }
  L.start.push_back(static_cast<uint32_t>(keys.size()));
  const int lo = part.bmin[axis], hi = part.bmax[axis];
  L.slice_count.assign(hi >= lo ? hi - lo + 1 : 0, 0);
  for (const Voxel& v : part.voxels) ++L.slice_count[v.c[axis] - lo];
  return L;
}

void SideHullPoints(const AxisLines& L, int c, bool left, int downsample, std::vector<Vec3>* out,
                    double* volume) {
  out->clear();
  double count = 0.0;
  const int ds = std::max(1, downsample);
  for (size_t l = 0; l < L.line_count(); ++l) {
    if (ds > 1 && (L.lu[l] % ds != 0 || L.lv[l] % ds != 0)) continue;
    const uint16_t* b = L.coords.data() + L.start[l];
    const uint16_t* e = L.coords.data() + L.start[l + 1];
    const uint16_t* split = std::lower_bound(b, e, static_cast<uint16_t>(std::clamp(c, 0, 65535)));
    int lo, hi;
    if (left) {
      if (split == b) continue;
      lo = *b;
      hi = *(split - 1);
    } else {
      if (split == e) continue;
      lo = *split;
      hi = *(e - 1);
    }
    AddFace(L.axis, lo, L.lu[l], L.lv[l], out, ds);
    AddFace(L.axis, hi + 1, L.lu[l], L.lv[l], out, ds);
    count += left ? static_cast<double>(split - b) : static_cast<double>(e - split);
  }
  if (volume != nullptr) *volume = count * ds * ds;
}

void PartHullPoints(const Part& part, bool interior_only, std::vector<Vec3>* out) {
  out->clear();
  std::vector<uint64_t> keys;
  keys.reserve(part.voxels.size());
  for (const Voxel& v : part.voxels)
    if (!interior_only || !v.surface) keys.push_back(LineKey(v, 0));
  std::sort(keys.begin(), keys.end());
  for (size_t i = 0; i < keys.size();) {
    size_t j = i;
    while (j + 1 < keys.size() && (keys[j + 1] >> 16) == (keys[i] >> 16)) ++j;
    const int u = static_cast<int>((keys[i] >> 16) & 0xffff), v = static_cast<int>(keys[i] >> 32);
    AddFace(0, static_cast<int>(keys[i] & 0xffff), u, v, out);
    AddFace(0, static_cast<int>(keys[j] & 0xffff) + 1, u, v, out);
    i = j + 1;
  }
}

double ExactHullVolume(const std::vector<Vec3>& points) {
  HullMesh h;
  if (ComputeConvexHull(points, 0.0, &h) != HullStatus::kOk) return 0.0;
  return h.Volume();
}

}  // namespace internal
}  // namespace vhacd
