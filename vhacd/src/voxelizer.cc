#include "voxelizer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "distance_field.h"
#include "range_halving.h"
#include "thread_pool.h"

namespace vhacd {
namespace internal {

GridPlacement ChooseGrid(const Vec3& bmin, const Vec3& bmax, uint32_t resolution) {
  const Vec3 ext = (bmax - bmin).cwiseMax(0.0);
  const double res = std::max<double>(1.0, resolution);
  double h = std::max(ext.maxCoeff(), 1e-300) / std::cbrt(res);
  for (int it = 0; it < 30; ++it) {
    const double vol = std::max(ext[0], h) * std::max(ext[1], h) * std::max(ext[2], h);
    h = std::cbrt(vol / res);
  }
  // Voxel coordinates are 16-bit (and the exact hull needs them small): at most 30000 per axis.
  h = std::max(h, ext.maxCoeff() / 30000.0);
  GridPlacement g;
  for (int attempt = 0; attempt < 20; ++attempt) {
    g.h = h;
    double total = 1.0;
    for (int a = 0; a < 3; ++a) {
      const int n = std::max(1, static_cast<int>(std::ceil(ext[a] / h - 1e-9)));
      g.dims[a] = n + 2;
      const double center = 0.5 * (bmin[a] + bmax[a]);
      g.origin[a] = center - 0.5 * g.dims[a] * h;
      total *= g.dims[a];
    }
    // Flat or thin boxes: the padding layers would multiply the voxel count; coarsen until the
    // grid, padding included, stays within twice the requested resolution.
    if (total <= 2.0 * res) break;
    h *= std::sqrt(total / (2.0 * res));
  }
  return g;
}

namespace {

// The separating-axis test of triangle abc against the axis-aligned box centre +/- half (per
// axis); radius(axis) is the box's projection radius on any axis. A template so that the voxel
// test keeps its own arithmetic (one half for all axes) exactly.
template <typename Radius>
bool SeparatingAxisOverlap(const Vec3& center, const Vec3& half, Radius radius, const Vec3& a,
                           const Vec3& b, const Vec3& c) {
  const Vec3 v0 = a - center, v1 = b - center, v2 = c - center;
  // Box face normals.
  for (int k = 0; k < 3; ++k) {
    const double mn = std::min({v0[k], v1[k], v2[k]}), mx = std::max({v0[k], v1[k], v2[k]});
    if (mn > half[k] || mx < -half[k]) return false;
  }
  const Vec3 e[3] = {v1 - v0, v2 - v1, v0 - v2};
  // Edge x box-axis cross products.
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      Vec3 axis = Vec3::Zero();
      axis[k] = 1.0;
      axis = axis.cross(e[i]);
      const double p0 = axis.dot(v0), p1 = axis.dot(v1), p2 = axis.dot(v2);
      const double r = radius(axis);
      if (std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r) return false;
    }
  // Triangle plane.
  const Vec3 n = e[0].cross(e[1]);
  return std::fabs(n.dot(v0)) <= radius(n);
}

}  // namespace

bool TriangleBoxOverlap(const Vec3& center, double half, const Vec3& a, const Vec3& b,
                        const Vec3& c) {
  const auto radius = [half](const Vec3& axis) {
    return half * (std::fabs(axis[0]) + std::fabs(axis[1]) + std::fabs(axis[2]));
  };
  return SeparatingAxisOverlap(center, Vec3::Constant(half), radius, a, b, c);
}

bool TriangleMayMeetVoxels(const int lo[3], const int hi[3], const Vec3& a, const Vec3& b,
                           const Vec3& c) {
  // The range's box, widened far beyond the rounding of the tests on its voxels (coordinates are
  // voxel indices).
  constexpr double kMargin = 1e-6;
  Vec3 center, half;
  for (int k = 0; k < 3; ++k) {
    center[k] = 0.5 * (double(lo[k]) + double(hi[k]) + 1.0);
    half[k] = 0.5 * (double(hi[k]) - double(lo[k]) + 1.0) + kMargin;
  }
  const auto radius = [&half](const Vec3& axis) { return half.dot(axis.cwiseAbs()); };
  return SeparatingAxisOverlap(center, half, radius, a, b, c);
}

namespace {

struct Crossing {
  uint32_t line;
  double t;
  bool operator<(const Crossing& o) const { return line != o.line ? line < o.line : t < o.t; }
};

inline double Orient2(double ax, double ay, double bx, double by, double px, double py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// Collects where the lines through voxel centres parallel to `axis` cross the triangles.
void CollectCrossings(const GridMesh& mesh, const int dims[3], int axis, size_t tri_begin,
                      size_t tri_end, std::vector<Crossing>* out) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  for (size_t t = tri_begin; t < tri_end; ++t) {
    const auto tri = mesh.triangles[t];
    const Vec3 corner[3] = {mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]};
    const Vec3* P[3] = {&corner[0], &corner[1], &corner[2]};
    double area = Orient2((*P[0])[u], (*P[0])[v], (*P[1])[u], (*P[1])[v], (*P[2])[u], (*P[2])[v]);
    if (area == 0.0 || !std::isfinite(area)) continue;  // parallel to the rays: never crossed
    if (area < 0) {
      std::swap(P[1], P[2]);
      area = -area;
    }
    // Each edge is evaluated from its lexicographically smaller end, for both of its triangles:
    // same operands, same order, whatever the point numbering.
    bool from_start[3];
    for (int e = 0; e < 3; ++e) {
      const Vec3& a = *P[e];
      const Vec3& b = *P[(e + 1) % 3];
      from_start[e] = std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    }
    const double umin = std::min({(*P[0])[u], (*P[1])[u], (*P[2])[u]});
    const double umax = std::max({(*P[0])[u], (*P[1])[u], (*P[2])[u]});
    const double vmin = std::min({(*P[0])[v], (*P[1])[v], (*P[2])[v]});
    const double vmax = std::max({(*P[0])[v], (*P[1])[v], (*P[2])[v]});
    const int iu0 = std::max(0, static_cast<int>(std::ceil(umin - 0.5)));
    const int iu1 = std::min(dims[u] - 1, static_cast<int>(std::floor(umax - 0.5)));
    const int iv0 = std::max(0, static_cast<int>(std::ceil(vmin - 0.5)));
    const int iv1 = std::min(dims[v] - 1, static_cast<int>(std::floor(vmax - 0.5)));
    // A range of more than kLeafLines lines is halved along its longer side, and a half whose
    // line centres all lie outside one edge, by far more than rounding, is skipped whole: a
    // sliver's range is mostly empty. Every line of the halves kept gets the test below, so the
    // crossings do not change.
    constexpr int kLeafLines = 16;
    constexpr double kMargin = 1e-6;  // grid units
    auto outside_an_edge = [&](int ua, int ub, int va, int vb) {
      for (int e = 0; e < 3; ++e) {
        const Vec3& pi = *P[e];
        const Vec3& pj = *P[(e + 1) % 3];
        const double du = pj[u] - pi[u], dv = pj[v] - pi[v];
        // The largest value of Orient2(pi, pj, q) over the range's line centres q.
        const double qu = (dv > 0 ? ua : ub) + 0.5, qv = (du > 0 ? vb : va) + 0.5;
        if (du * (qv - pi[v]) - dv * (qu - pi[u]) < -kMargin * std::sqrt(du * du + dv * dv))
          return true;
      }
      return false;
    };
    // The line through voxel centres (iu, iv): where it crosses the triangle, if it does.
    auto cross_line = [&](int iu, int iv) {
      const double qu = iu + 0.5, qv = iv + 0.5;
      double w[3];
      for (int e = 0; e < 3; ++e) {
        const int i = e, j = (e + 1) % 3;
        double val;
        if (from_start[e])
          val = Orient2((*P[i])[u], (*P[i])[v], (*P[j])[u], (*P[j])[v], qu, qv);
        else
          val = -Orient2((*P[j])[u], (*P[j])[v], (*P[i])[u], (*P[i])[v], qu, qv);
        if (val < 0) return;
        if (val == 0) {
          const double du = (*P[j])[u] - (*P[i])[u], dv = (*P[j])[v] - (*P[i])[v];
          if (!(dv > 0 || (dv == 0 && du > 0))) return;  // the edge does not own the point
        }
        w[(e + 2) % 3] = val;  // weight of the vertex opposite edge e
      }
      const double s = w[0] + w[1] + w[2];
      if (!(s > 0)) return;
      const double ta = (w[0] * (*P[0])[axis] + w[1] * (*P[1])[axis] + w[2] * (*P[2])[axis]) / s;
      out->push_back({static_cast<uint32_t>(static_cast<size_t>(iv) * dims[u] + iu), ta});
    };
    const int range_lo[2] = {iu0, iv0}, range_hi[2] = {iu1, iv1};
    ForEachLeafRange<2>(
        range_lo, range_hi, kLeafLines,
        [&](const int* rlo, const int* rhi) {
          return !outside_an_edge(rlo[0], rhi[0], rlo[1], rhi[1]);
        },
        [&](const int* rlo, const int* rhi) {
          for (int iv = rlo[1]; iv <= rhi[1]; ++iv)
            for (int iu = rlo[0]; iu <= rhi[0]; ++iu) cross_line(iu, iv);
        });
  }
}

}  // namespace

bool SweepOpenings(const int dims[3], double opening, Context* ctx, VoxelGrid* grid) {
  // Only voxels that the flood fill reached but the parity vote called inside can change.
  bool any = false;
  for (size_t i = 0; i < grid->size() && !any; ++i)
    any = grid->cell[i] != kCellSurface && !grid->enclosed[i] && grid->votes[i] >= 4;
  if (!any) return true;
  double diag2 = 0.0;
  for (int k = 0; k < 3; ++k) diag2 += static_cast<double>(dims[k] - 2) * (dims[k] - 2);
  const double r = 0.5 * opening * std::sqrt(diag2);
  if (r < 1.0) return true;  // a ball narrower than a voxel passes through any crack
  // The grid padded by pad cells on every side, so that balls also start outside the grid.
  const int pad = static_cast<int>(std::ceil(r)) + 1;
  int pd[3];
  for (int k = 0; k < 3; ++k) pd[k] = dims[k] + 2 * pad;
  const size_t n = static_cast<size_t>(pd[0]) * pd[1] * pd[2];
  auto padded = [&](int x, int y, int z) {
    return (static_cast<size_t>(z) * pd[1] + y) * pd[0] + x;
  };
  const float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> sq(n, kInf);
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x)
        if (grid->cell[grid->Index(x, y, z)] == kCellSurface)
          sq[padded(x + pad, y + pad, z + pad)] = 0.0f;
  if (!SquaredDistanceTransform(pd, ctx, &sq)) return false;
  // Ball centres: cells at least r from every surface voxel centre, connected to the padding.
  const float r2 = static_cast<float>(r * r);
  std::vector<uint8_t> centre(n, 0);
  std::vector<size_t> stack;
  auto push = [&](size_t i) {
    if (!centre[i] && sq[i] >= r2) {
      centre[i] = 1;
      stack.push_back(i);
    }
  };
  for (int z = 0; z < pd[2]; ++z)
    for (int y = 0; y < pd[1]; ++y)
      for (int x = 0; x < pd[0]; ++x)
        if (x == 0 || y == 0 || z == 0 || x == pd[0] - 1 || y == pd[1] - 1 || z == pd[2] - 1)
          push(padded(x, y, z));
  const size_t sy = pd[0], sz = static_cast<size_t>(pd[0]) * pd[1];
  size_t popped = 0;
  while (!stack.empty()) {
    if ((++popped & 0xfffff) == 0 && ctx->Cancelled()) return false;
    const size_t i = stack.back();
    stack.pop_back();
    const int x = static_cast<int>(i % sy), y = static_cast<int>((i / sy) % pd[1]),
              z = static_cast<int>(i / sz);
    if (x > 0) push(i - 1);
    if (x + 1 < pd[0]) push(i + 1);
    if (y > 0) push(i - sy);
    if (y + 1 < pd[1]) push(i + sy);
    if (z > 0) push(i - sz);
    if (z + 1 < pd[2]) push(i + sz);
  }
  // Swept: within r of a ball centre.
  for (size_t i = 0; i < n; ++i) sq[i] = centre[i] ? 0.0f : kInf;
  std::vector<uint8_t>().swap(centre);
  if (!SquaredDistanceTransform(pd, ctx, &sq)) return false;
  const size_t nvox = grid->size();
  std::vector<uint8_t> swept(nvox, 0);
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) {
        const size_t i = grid->Index(x, y, z);
        if (grid->cell[i] != kCellSurface && !grid->enclosed[i] &&
            sq[padded(x + pad, y + pad, z + pad)] <= r2) {
          swept[i] = 1;
          grid->votes[i] = 0;
        }
      }
  std::vector<float>().swap(sq);
  // The ball cannot reach into the concave corners of a cavity (a fillet of its radius stays).
  // Such a left-over region is thin: its volume over its contact with the swept region is below
  // the radius, where the solid behind a hole (the inside of a scan) is far thicker than that.
  const size_t gx = 1, gy = dims[0], gz = static_cast<size_t>(dims[0]) * dims[1];
  auto candidate = [&](size_t i) {
    return grid->cell[i] != kCellSurface && !grid->enclosed[i] && grid->votes[i] >= 4;
  };
  std::vector<uint32_t> label(nvox, 0);
  std::vector<size_t> members;
  uint32_t next_label = 0;
  for (size_t seed = 0; seed < nvox; ++seed) {
    if (label[seed] != 0 || !candidate(seed)) continue;
    if ((++next_label & 0xff) == 0 && ctx->Cancelled()) return false;
    members.clear();
    members.push_back(seed);
    label[seed] = next_label;
    size_t contact = 0;
    for (size_t k = 0; k < members.size(); ++k) {
      const size_t i = members[k];
      const int x = static_cast<int>(i % gy), y = static_cast<int>((i / gy) % dims[1]),
                z = static_cast<int>(i / gz);
      const bool has[6] = {x > 0, x + 1 < dims[0], y > 0, y + 1 < dims[1], z > 0, z + 1 < dims[2]};
      const size_t nb[6] = {i - gx, i + gx, i - gy, i + gy, i - gz, i + gz};
      for (int e = 0; e < 6; ++e) {
        if (!has[e]) continue;
        const size_t j = nb[e];
        if (swept[j]) {
          ++contact;
        } else if (label[j] == 0 && candidate(j)) {
          label[j] = next_label;
          members.push_back(j);
        }
      }
    }
    if (static_cast<double>(members.size()) < r * static_cast<double>(contact))
      for (size_t i : members) grid->votes[i] = 0;
  }
  return true;
}

bool Voxelize(const GridMesh& mesh, const int dims[3], Context* ctx, VoxelGrid* grid,
              double* fill_seconds, double opening) {
  for (int a = 0; a < 3; ++a) grid->dims[a] = dims[a];
  const size_t nvox = static_cast<size_t>(dims[0]) * dims[1] * dims[2];
  const size_t ntri = mesh.triangles.size();
  const size_t kChunk = 2048;
  const size_t nchunks = (ntri + kChunk - 1) / kChunk;

  // 1. Surface voxels.
  {
    std::unique_ptr<std::atomic<uint8_t>[]> marks(new std::atomic<uint8_t>[nvox]);
    for (size_t i = 0; i < nvox; ++i) marks[i].store(0, std::memory_order_relaxed);
    const double half = 0.5 + 1e-9;
    // Triangles whose box spans many voxels are done later, in parallel slabs of z.
    const double kBig = 65536.0;
    std::vector<std::vector<uint32_t>> big(nchunks);
    // Marks the voxels of triangle t's box, restricted to [slo, shi] on the box's longest axis
    // (slo = -1: the whole box, deferring big triangles to the slab pass).
    auto mark_range = [&](size_t t, int slo, int shi, size_t chunk) {
      const Vec3 a = mesh.points[mesh.triangles[t][0]];
      const Vec3 b = mesh.points[mesh.triangles[t][1]];
      const Vec3 d = mesh.points[mesh.triangles[t][2]];
      int lo[3], hi[3];
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::clamp(static_cast<int>(std::floor(std::min({a[k], b[k], d[k]}) - 1e-9)), 0,
                           dims[k] - 1);
        hi[k] = std::clamp(static_cast<int>(std::floor(std::max({a[k], b[k], d[k]}) + 1e-9)), 0,
                           dims[k] - 1);
      }
      if (slo < 0) {
        if (static_cast<double>(hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) >
            kBig) {
          big[chunk].push_back(static_cast<uint32_t>(t));
          return;
        }
      } else {
        int axis = 0;
        for (int k = 1; k < 3; ++k)
          if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
        const int base = lo[axis];
        lo[axis] = base + slo;
        hi[axis] = std::min(hi[axis], base + shi);
      }
      // A box of more than 64 voxels is halved, and a half the triangle cannot meet is skipped
      // whole: a sliver's box is mostly empty. Every voxel of the halves kept gets the same test
      // as before, so the marks do not change.
      ForEachLeafRange<3>(
          lo, hi, 64,
          [&](const int* rlo, const int* rhi) { return TriangleMayMeetVoxels(rlo, rhi, a, b, d); },
          [&](const int* rlo, const int* rhi) {
            for (int z = rlo[2]; z <= rhi[2]; ++z)
              for (int y = rlo[1]; y <= rhi[1]; ++y)
                for (int x = rlo[0]; x <= rhi[0]; ++x) {
                  const size_t idx = grid->Index(x, y, z);
                  if (marks[idx].load(std::memory_order_relaxed)) continue;
                  if (TriangleBoxOverlap(Vec3(x + 0.5, y + 0.5, z + 0.5), half, a, b, d))
                    marks[idx].store(1, std::memory_order_relaxed);
                }
          });
    };
    bool ok = ParallelFor(ctx, nchunks, [&](size_t c) {
      const size_t end = std::min(ntri, (c + 1) * kChunk);
      for (size_t t = c * kChunk; t < end; ++t) mark_range(t, -1, -1, c);
    });
    if (!ok) return false;
    std::vector<uint32_t> big_all;
    for (const auto& b : big) big_all.insert(big_all.end(), b.begin(), b.end());
    // Slabs of kSlab layers along each big triangle's longest box axis (offsets from its box).
    const int kSlab = 8;
    const int longest = std::max({dims[0], dims[1], dims[2]});
    const size_t slabs = static_cast<size_t>((longest + kSlab - 1) / kSlab);
    ok = ParallelFor(ctx, big_all.size() * slabs, [&](size_t task) {
      const int s = static_cast<int>(task % slabs);
      mark_range(big_all[task / slabs], s * kSlab, s * kSlab + kSlab - 1, 0);
    });
    if (!ok) return false;
    grid->cell.assign(nvox, kCellOutside);
    for (size_t i = 0; i < nvox; ++i) grid->cell[i] = marks[i].load(std::memory_order_relaxed);
  }
  ctx->Progress(30, "surface voxels");

  const auto fill_start = std::chrono::steady_clock::now();
  // 2. Flood fill from the grid border through non-surface voxels.
  grid->enclosed.assign(nvox, 1);
  {
    std::vector<size_t> stack;
    auto push = [&](int x, int y, int z) {
      const size_t i = grid->Index(x, y, z);
      if (grid->enclosed[i] && grid->cell[i] != kCellSurface) {
        grid->enclosed[i] = 0;
        stack.push_back(i);
      }
    };
    for (int z = 0; z < dims[2]; ++z)
      for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x)
          if (x == 0 || y == 0 || z == 0 || x == dims[0] - 1 || y == dims[1] - 1 ||
              z == dims[2] - 1)
            push(x, y, z);
    const size_t sx = 1, sy = dims[0], sz = static_cast<size_t>(dims[0]) * dims[1];
    size_t popped = 0;
    while (!stack.empty()) {
      if ((++popped & 0xfffff) == 0 && ctx->Cancelled()) return false;
      const size_t i = stack.back();
      stack.pop_back();
      const int x = static_cast<int>(i % sy), y = static_cast<int>((i / sy) % dims[1]),
                z = static_cast<int>(i / sz);
      (void)sx;
      if (x > 0) push(x - 1, y, z);
      if (x + 1 < dims[0]) push(x + 1, y, z);
      if (y > 0) push(x, y - 1, z);
      if (y + 1 < dims[1]) push(x, y + 1, z);
      if (z > 0) push(x, y, z - 1);
      if (z + 1 < dims[2]) push(x, y, z + 1);
    }
    for (size_t i = 0; i < nvox; ++i)
      if (grid->cell[i] == kCellSurface) grid->enclosed[i] = 0;
  }
  if (ctx->Cancelled()) return false;
  ctx->Progress(45, "flood fill");

  // 3. Parity votes along the three axes.
  grid->votes.assign(nvox, 0);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::vector<std::vector<Crossing>> parts(nchunks);
    bool ok = ParallelFor(ctx, nchunks, [&](size_t c) {
      CollectCrossings(mesh, dims, axis, c * kChunk, std::min(ntri, (c + 1) * kChunk), &parts[c]);
    });
    if (!ok) return false;
    // Bucket the crossings by line (counting sort), then sort each line's few crossings.
    const size_t nlines = static_cast<size_t>(dims[u]) * dims[v];
    std::vector<uint32_t> start(nlines + 1,
                                0);  // fewer than 2^32 crossings: one per line and triangle pair
    for (const auto& p : parts)
      for (const Crossing& c : p) ++start[c.line + 1];
    for (size_t l = 0; l < nlines; ++l) start[l + 1] += start[l];
    std::vector<Crossing> all(start[nlines]);
    for (auto& p : parts) {  // start[l] serves as line l's write cursor, then is shifted back
      for (const Crossing& c : p) all[start[c.line]++] = c;
      std::vector<Crossing>().swap(p);
    }
    for (size_t l = nlines; l > 0; --l) start[l] = start[l - 1];
    start[0] = 0;
    const size_t kLineChunk = 256;
    ok = ParallelFor(ctx, (nlines + kLineChunk - 1) / kLineChunk, [&](size_t c) {
      const size_t end = std::min(nlines, (c + 1) * kLineChunk);
      for (size_t l = c * kLineChunk; l < end; ++l) {
        const size_t b = start[l], e = start[l + 1];
        if (b == e) continue;
        std::sort(all.begin() + b, all.begin() + e);
        const size_t count = e - b;
        const int iu = static_cast<int>(l % dims[u]), iv = static_cast<int>(l / dims[u]);
        size_t below = 0;
        int g[3];
        g[u] = iu;
        g[v] = iv;
        for (int k = 0; k < dims[axis]; ++k) {
          const double center = k + 0.5;
          while (b + below < e && all[b + below].t < center) ++below;
          g[axis] = k;
          const size_t idx = grid->Index(g[0], g[1], g[2]);
          grid->votes[idx] += static_cast<uint8_t>((below & 1) + ((count - below) & 1));
        }
      }
    });
    if (!ok) return false;
    ctx->Progress(45 + 18 * (axis + 1), "ray parity");
  }

  // 4. Wide openings: the voxels a ball of the opening's radius sweeps from outside the grid are
  // outside whatever their votes (the cavity of an open container).
  if (opening > 0.0 && !SweepOpenings(dims, opening, ctx, grid)) return false;

  // 5. Classification.
  for (size_t i = 0; i < nvox; ++i)
    if (grid->cell[i] != kCellSurface && (grid->enclosed[i] || grid->votes[i] >= 4))
      grid->cell[i] = kCellInside;
  if (fill_seconds != nullptr)
    *fill_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - fill_start).count();
  return true;
}

}  // namespace internal
}  // namespace vhacd
