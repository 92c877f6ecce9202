#include "distance_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "thread_pool.h"

namespace vhacd {
namespace internal {

namespace {
// 1D squared distance transform of f (lower envelope of parabolas), in place, n samples.
void Edt1D(const double* f, double* out, int n, int* v, double* z) {
  const double kInf = std::numeric_limits<double>::infinity();
  int k = 0;
  int first = -1;
  for (int q = 0; q < n; ++q)
    if (f[q] < kInf) {
      first = q;
      break;
    }
  if (first < 0) {
    for (int q = 0; q < n; ++q) out[q] = kInf;
    return;
  }
  v[0] = first;
  z[0] = -kInf;
  z[1] = kInf;
  for (int q = first + 1; q < n; ++q) {
    if (!(f[q] < kInf)) continue;
    double s;
    for (;;) {
      const int p = v[k];
      s = ((f[q] + static_cast<double>(q) * q) - (f[p] + static_cast<double>(p) * p)) /
          (2.0 * (q - p));
      if (s <= z[k] && k > 0) {
        --k;
        continue;
      }
      break;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    out[q] = dq * dq + f[v[k]];
  }
}
}  // namespace

bool SquaredDistanceTransform(const int dims[3], Context* ctx, std::vector<float>* sq_io) {
  std::vector<float>& sq = *sq_io;
  const size_t stride[3] = {1, static_cast<size_t>(dims[0]),
                            static_cast<size_t>(dims[0]) * dims[1]};
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    const size_t nlines = static_cast<size_t>(dims[u]) * dims[w];
    const int len = dims[axis];
    const size_t kChunk = 64;
    if (!ParallelFor(ctx, (nlines + kChunk - 1) / kChunk, [&](size_t c) {
          std::vector<double> f(len), out(len), z(len + 1);
          std::vector<int> v(len);
          for (size_t l = c * kChunk; l < std::min(nlines, (c + 1) * kChunk); ++l) {
            const size_t iu = l % dims[u], iw = l / dims[u];
            const size_t base = iu * stride[u] + iw * stride[w];
            for (int q = 0; q < len; ++q) f[q] = sq[base + q * stride[axis]];
            Edt1D(f.data(), out.data(), len, v.data(), z.data());
            for (int q = 0; q < len; ++q) sq[base + q * stride[axis]] = static_cast<float>(out[q]);
          }
        }))
      return false;
  }
  return true;
}

bool DistanceField::Build(const VoxelGrid& grid, Context* ctx) {
  for (int a = 0; a < 3; ++a) dims_[a] = grid.dims[a];
  const size_t n = grid.size();
  // Squared distances in float: ample precision here, half the memory of double.
  std::vector<float> sq(n);
  for (size_t i = 0; i < n; ++i)
    sq[i] = grid.cell[i] == kCellOutside ? std::numeric_limits<float>::infinity() : 0.0f;
  if (!SquaredDistanceTransform(dims_, ctx, &sq)) return false;
  for (float& s : sq) s = std::isfinite(s) ? std::sqrt(s) : 1e6f;  // in place: no second array
  d_ = std::move(sq);
  return true;
}

double DistanceField::HullDepth(const HullPlanes& hull, double limit) const {
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::clamp(static_cast<int>(std::floor(hull.bmin[a] - 0.5)), 0, dims_[a] - 1);
    hi[a] = std::clamp(static_cast<int>(std::ceil(hull.bmax[a] - 0.5)), 0, dims_[a] - 1);
  }
  double best = 0.0;
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y) {
      const size_t row = (static_cast<size_t>(z) * dims_[1] + y) * dims_[0];
      for (int x = lo[0]; x <= hi[0]; ++x) {
        const double d = d_[row + x];
        if (d <= best) continue;
        if (hull.Contains(Vec3(x + 0.5, y + 0.5, z + 0.5))) {
          best = d;
          if (best > limit) return best;
        }
      }
    }
  return best;
}

double DistanceField::HullDepth(const HullMesh& hull, double limit) const {
  if (hull.empty()) return 0.0;
  return HullDepth(HullPlanes(hull), limit);
}

double DistanceField::Interpolate(const Vec3& p) const {
  int i0[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double x = std::clamp(p[a] - 0.5, 0.0, static_cast<double>(dims_[a] - 1));
    i0[a] = std::min(static_cast<int>(x), std::max(0, dims_[a] - 2));
    f[a] = dims_[a] > 1 ? x - i0[a] : 0.0;
  }
  double acc = 0.0;
  for (int k = 0; k < 8; ++k) {
    const int x = std::min(i0[0] + (k & 1), dims_[0] - 1),
              y = std::min(i0[1] + ((k >> 1) & 1), dims_[1] - 1),
              z = std::min(i0[2] + ((k >> 2) & 1), dims_[2] - 1);
    const double w = ((k & 1) ? f[0] : 1 - f[0]) * (((k >> 1) & 1) ? f[1] : 1 - f[1]) *
                     (((k >> 2) & 1) ? f[2] : 1 - f[2]);
    acc += w * d_[(static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x];
  }
  return acc;
}

double DistanceField::SurfaceDepth(const HullMesh& hull, double limit) const {
  double best = 0.0;
  for (const auto& t : hull.triangles) {
    const Vec3 &a = hull.vertices[t[0]], &b = hull.vertices[t[1]], &c = hull.vertices[t[2]];
    const double len = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int n = std::clamp(static_cast<int>(std::ceil(len)), 1, 64);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
        best = std::max(best, Interpolate(a + u * (b - a) + v * (c - a)));
        if (best > limit) return best;
      }
  }
  return best;
}

}  // namespace internal
}  // namespace vhacd
