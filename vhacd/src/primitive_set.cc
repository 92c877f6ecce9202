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

void Part::ComputeCellVolume() {
  cell_volume = 0.0;
  for (const SurfaceCell& c : cells) cell_volume += c.volume;
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

// The corners of the line faces, keyed by their (u, v) grid position: only the lowest and the
// highest face along the axis at each position can be a hull vertex, so each position yields at
// most two points (instead of up to eight from the four lines sharing it).
class CornerSet {
 public:
  // `lines` bounds the number of Add() calls: when the (u, v) grid would be much larger than the
  // lines it holds (a sparse, wide part), faces are emitted directly instead.
  CornerSet(int axis, int umin, int umax, int vmin, int vmax, int step, size_t lines,
            std::vector<Vec3>* out)
      : axis_(axis), step_(step), out_(out) {
    u0_ = umin - ((umin % step) + step) % step;
    v0_ = vmin - ((vmin % step) + step) % step;
    nu_ = (umax - u0_) / step + 2;
    nv_ = (vmax - v0_) / step + 2;
    const size_t n = static_cast<size_t>(nu_) * nv_;
    direct_ = n > 16 * lines + 4096;
    if (direct_) return;
    thread_local std::vector<int> lo_buf, hi_buf;
    lo_buf.assign(n, kNone);
    hi_buf.assign(n, -kNone);
    lo_ = lo_buf.data();
    hi_ = hi_buf.data();
  }
  // A line at (u, v) whose faces are at `lo` and `hi` along the axis.
  void Add(int u, int v, int lo, int hi) {
    if (direct_) {
      for (int along : {lo, hi})
        for (int dv = 0; dv <= step_; dv += step_)
          for (int du = 0; du <= step_; du += step_)
            out_->push_back(MakePoint(axis_, along, u + du, v + dv));
      return;
    }
    const int iu = (u - u0_) / step_, iv = (v - v0_) / step_;
    for (int dv = 0; dv < 2; ++dv)
      for (int du = 0; du < 2; ++du) {
        const size_t k = static_cast<size_t>(iv + dv) * nu_ + iu + du;
        lo_[k] = std::min(lo_[k], lo);
        hi_[k] = std::max(hi_[k], hi);
      }
  }
  void Emit() const {
    if (direct_) return;
    std::vector<Vec3>* out = out_;
    for (int iv = 0; iv < nv_; ++iv)
      for (int iu = 0; iu < nu_; ++iu) {
        const size_t k = static_cast<size_t>(iv) * nu_ + iu;
        if (lo_[k] == kNone) continue;
        const double u = u0_ + iu * step_, v = v0_ + iv * step_;
        out->push_back(MakePoint(axis_, lo_[k], u, v));
        if (hi_[k] != lo_[k]) out->push_back(MakePoint(axis_, hi_[k], u, v));
      }
  }

 private:
  static constexpr int kNone = 1 << 30;
  int axis_, step_, u0_, v0_, nu_, nv_;
  std::vector<Vec3>* out_;
  bool direct_ = false;
  int* lo_ = nullptr;
  int* hi_ = nullptr;
};

}  // namespace

namespace {
AxisLines BuildLines(const Part& part, int axis, bool interior_only) {
  AxisLines L;
  L.axis = axis;
  std::vector<uint64_t> keys;
  keys.reserve(part.voxels.size());
  for (const Voxel& v : part.voxels)
    if (!interior_only || !v.surface) keys.push_back(LineKey(v, axis));
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
  L.umin = part.bmin[(axis + 1) % 3];
  L.umax = part.bmax[(axis + 1) % 3];
  L.vmin = part.bmin[(axis + 2) % 3];
  L.vmax = part.bmax[(axis + 2) % 3];
  const int lo = part.bmin[axis], hi = part.bmax[axis];
  L.slice_count.assign(hi >= lo ? hi - lo + 1 : 0, 0);
  for (const Voxel& v : part.voxels)
    if (!interior_only || !v.surface) ++L.slice_count[v.c[axis] - lo];
  return L;
}
}  // namespace

AxisLines BuildAxisLines(const Part& part, int axis) { return BuildLines(part, axis, false); }

TetraAxis BuildTetraAxis(const Part& part, int axis) {
  TetraAxis T;
  T.interior = BuildLines(part, axis, true);
  const int lo = part.bmin[axis], hi = part.bmax[axis];
  const size_t slices = hi >= lo ? static_cast<size_t>(hi - lo + 1) : 0;
  T.order.resize(part.cells.size());
  for (size_t i = 0; i < T.order.size(); ++i) T.order[i] = static_cast<uint32_t>(i);
  std::stable_sort(T.order.begin(), T.order.end(), [&](uint32_t a, uint32_t b) {
    return part.cells[a].c[axis] < part.cells[b].c[axis];
  });
  T.slice_start.assign(slices + 1, 0);
  std::vector<double> volume(slices, 0.0);
  for (const SurfaceCell& c : part.cells) {
    ++T.slice_start[c.c[axis] - lo + 1];
    volume[c.c[axis] - lo] += c.volume;
  }
  for (size_t s = 0; s < slices; ++s) T.slice_start[s + 1] += T.slice_start[s];
  T.prefix_volume.assign(slices + 1, 0.0);
  for (size_t s = 0; s < slices; ++s)
    T.prefix_volume[s + 1] = T.prefix_volume[s] + volume[s] + T.interior.slice_count[s];
  return T;
}

void TetraSideHullPoints(const Part& part, const TetraAxis& ta, int c, bool left,
                         std::vector<Vec3>* out, double* volume) {
  SideHullPoints(ta.interior, c, left, 1, out);
  const int axis = ta.interior.axis;
  const int lo = part.bmin[axis];
  const int slices = static_cast<int>(ta.prefix_volume.size()) - 1;
  const int split = std::clamp(c - lo, 0, slices);  // first slice on the right
  const uint32_t b = left ? 0 : ta.slice_start[split];
  const uint32_t e = left ? ta.slice_start[split] : ta.slice_start[slices];
  for (uint32_t k = b; k < e; ++k) {
    const SurfaceCell& cell = part.cells[ta.order[k]];
    for (int i = 0; i < cell.point_count; ++i)
      out->emplace_back(cell.p[i][0], cell.p[i][1], cell.p[i][2]);
  }
  if (volume != nullptr)
    *volume = left ? ta.prefix_volume[split] : ta.prefix_volume[slices] - ta.prefix_volume[split];
}

namespace {
// SideHullPoints with the plane of line l at split(l).
template <typename SplitOfLine>
void SideHullPointsImpl(const AxisLines& L, SplitOfLine split_of_line, bool left, int downsample,
                        std::vector<Vec3>* out, double* volume, double* exact_count) {
  out->clear();
  double count = 0.0, all = 0.0;
  const int ds = std::max(1, downsample);
  CornerSet corners(L.axis, L.umin, L.umax, L.vmin, L.vmax, ds, L.line_count(), out);
  for (size_t l = 0; l < L.line_count(); ++l) {
    const bool sampled = ds == 1 || (L.lu[l] % ds == 0 && L.lv[l] % ds == 0);
    if (!sampled && exact_count == nullptr) continue;
    const uint16_t* b = L.coords.data() + L.start[l];
    const uint16_t* e = L.coords.data() + L.start[l + 1];
    const int c = std::clamp(split_of_line(l), 0, 65535);
    const uint16_t* split = std::lower_bound(b, e, static_cast<uint16_t>(c));
    const double side = left ? static_cast<double>(split - b) : static_cast<double>(e - split);
    all += side;
    if (!sampled || side == 0) continue;
    const int lo = left ? *b : *split;
    const int hi = left ? *(split - 1) : *(e - 1);
    corners.Add(L.lu[l], L.lv[l], lo, hi + 1);
    count += side;
  }
  corners.Emit();
  if (volume != nullptr) *volume = count * ds * ds;
  if (exact_count != nullptr) *exact_count = all;
}
}  // namespace

void SideHullPoints(const AxisLines& L, int c, bool left, int downsample, std::vector<Vec3>* out,
                    double* volume) {
  SideHullPointsImpl(
      L, [c](size_t) { return c; }, left, downsample, out, volume, nullptr);
}

void SideHullPointsPerLine(const AxisLines& L, const std::vector<int>& line_split, bool left,
                           int downsample, std::vector<Vec3>* out, double* volume, double* count) {
  SideHullPointsImpl(
      L, [&line_split](size_t l) { return line_split[l]; }, left, downsample, out, volume, count);
}

void PartHullPoints(const Part& part, bool interior_only, std::vector<Vec3>* out) {
  out->clear();
  std::vector<uint64_t> keys;
  keys.reserve(part.voxels.size());
  for (const Voxel& v : part.voxels)
    if (!interior_only || !v.surface) keys.push_back(LineKey(v, 0));
  if (keys.empty()) return;
  std::sort(keys.begin(), keys.end());
  CornerSet corners(0, part.bmin[1], part.bmax[1], part.bmin[2], part.bmax[2], 1, keys.size(), out);
  for (size_t i = 0; i < keys.size();) {
    size_t j = i;
    while (j + 1 < keys.size() && (keys[j + 1] >> 16) == (keys[i] >> 16)) ++j;
    const int u = static_cast<int>((keys[i] >> 16) & 0xffff), v = static_cast<int>(keys[i] >> 32);
    corners.Add(u, v, static_cast<int>(keys[i] & 0xffff), static_cast<int>(keys[j] & 0xffff) + 1);
    i = j + 1;
  }
  corners.Emit();
}

void PrimitiveHullPoints(const Part& part, std::vector<Vec3>* out) {
  if (!part.tetra) {
    PartHullPoints(part, false, out);
    return;
  }
  PartHullPoints(part, true, out);
  for (const SurfaceCell& cell : part.cells)
    for (int i = 0; i < cell.point_count; ++i)
      out->emplace_back(cell.p[i][0], cell.p[i][1], cell.p[i][2]);
}

bool PrimitiveHull(const Part& part, const std::vector<Vec3>& points, HullMesh* out) {
  return ComputeConvexHull(points, part.tetra ? -1.0 : 0.0, out) == HullStatus::kOk;
}

double ExactHullVolume(const std::vector<Vec3>& points) {
  HullMesh h;
  if (ComputeConvexHull(points, 0.0, &h) != HullStatus::kOk) return 0.0;
  return h.Volume();
}

Eigen::Matrix3d VoxelCovariance(const Part& part) {
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  if (part.voxels.size() < 2) return cov;
  Vec3 mean = Vec3::Zero();
  for (const Voxel& v : part.voxels) mean += Vec3(v.c[0], v.c[1], v.c[2]);
  mean /= static_cast<double>(part.voxels.size());
  for (const Voxel& v : part.voxels) {
    const Vec3 d = Vec3(v.c[0], v.c[1], v.c[2]) - mean;
    cov += d * d.transpose();
  }
  return cov / static_cast<double>(part.voxels.size());
}

}  // namespace internal
}  // namespace vhacd
