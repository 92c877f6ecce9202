#include "error_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "range_halving.h"
#include "thread_pool.h"

namespace vhacd {
namespace internal {

namespace {

// Each point read once: a mesh read in place is mapped on every read.
double TriangleArea(const GridMesh& mesh, TriangleList::Ref t) {
  const Vec3 a = mesh.points[t[0]];
  return 0.5 * (mesh.points[t[1]] - a).cross(mesh.points[t[2]] - a).norm();
}

}  // namespace

// The Sliver of triangle (a, b, c): every point of the triangle lies in its plane, and within
// its height over its longest edge of that edge.
TriangleLocator::Sliver TriangleLocator::Sliver::Of(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, bc = c - b, ca = a - c;
  const Vec3 n = ab.cross(-ca);
  const double area2 = n.norm();  // twice the area
  Sliver s;
  s.normal = area2 > 0 ? Vec3(n / area2) : Vec3::Zero();
  s.offset = s.normal.dot(a);
  s.start = a;
  s.edge = ab;
  if (bc.squaredNorm() > s.edge.squaredNorm()) s.start = b, s.edge = bc;
  if (ca.squaredNorm() > s.edge.squaredNorm()) s.start = c, s.edge = ca;
  const double len2 = s.edge.squaredNorm();
  s.inv_length2 = len2 > 0 ? 1.0 / len2 : 0.0;
  s.height = len2 > 0 ? area2 / std::sqrt(len2) : 0.0;
  return s;
}

double TriangleLocator::Sliver::Bound(const Vec3& q) const {
  const double plane = std::abs(normal.dot(q) - offset);
  const double t = std::clamp((q - start).dot(edge) * inv_length2, 0.0, 1.0);
  const double to_edge = (q - start - t * edge).norm() - height;
  // Rounding may make either a hair too large: the margin keeps it a lower bound.
  return std::max(plane, to_edge) * (1.0 - 1e-9) - 1e-12;
}

TriangleLocator::TriangleLocator(const GridMesh& mesh, double cell_size)
    : mesh_(mesh), cell_(cell_size) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& t : mesh.triangles)
    for (uint32_t v : t) {
      const Vec3 p = mesh.points[v];
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  if (mesh.triangles.empty()) lo = hi = Vec3::Zero();
  origin_ = lo;
  for (int a = 0; a < 3; ++a)
    dims_[a] = std::max(1, static_cast<int>(std::ceil((hi[a] - lo[a]) / cell_)) + 1);
  const size_t ncell = static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2];
  start_.assign(ncell + 1, 0);
  auto range = [&](TriangleList::Ref t, int* clo, int* chi) {
    // Each point read once: a mesh read in place is mapped on every read.
    const Vec3 p0 = mesh.points[t[0]], p1 = mesh.points[t[1]], p2 = mesh.points[t[2]];
    const Vec3 lo3 = p0.cwiseMin(p1).cwiseMin(p2), hi3 = p0.cwiseMax(p1).cwiseMax(p2);
    for (int a = 0; a < 3; ++a) {
      const double mn = lo3[a], mx = hi3[a];
      clo[a] = std::clamp(static_cast<int>(std::floor((mn - origin_[a]) / cell_)), 0, dims_[a] - 1);
      chi[a] = std::clamp(static_cast<int>(std::floor((mx - origin_[a]) / cell_)), 0, dims_[a] - 1);
    }
  };
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<uint32_t> fill;
    if (pass == 1) {
      for (size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
      ids_.resize(start_[ncell]);
      fill.assign(start_.begin(), start_.end() - 1);
    }
    for (uint32_t ti = 0; ti < mesh.triangles.size(); ++ti) {
      int clo[3], chi[3];
      range(mesh.triangles[ti], clo, chi);
      // A triangle whose box spans more than 2 x 2 x 2 cells (a long sliver, as in the fan of a
      // finely tessellated disc) goes only into the cells it may reach: by its box alone, every
      // cell near the fan's centre held most of the fan, and each query there measured them all.
      const bool large = (chi[0] - clo[0] + 1) * (chi[1] - clo[1] + 1) * (chi[2] - clo[2] + 1) > 8;
      const auto& t = mesh.triangles[ti];
      if (large && pass == 0) {
        if (sliver_of_.empty()) sliver_of_.assign(mesh.triangles.size(), kNone);
        sliver_of_[ti] = static_cast<uint32_t>(slivers_.size());
        slivers_.push_back(Sliver::Of(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]));
      }
      auto add = [&](int x, int y, int z) {
        const size_t c = (static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x;
        if (pass == 0)
          ++start_[c + 1];
        else
          ids_[fill[c]++] = ti;
      };
      if (large) {
        // Only the cells whose centre the sliver may come within a cell's half-diagonal of. A
        // box of cells is dropped when all its centres are farther (Bound is 1-Lipschitz, so at
        // most the box's half-diagonal less than at its centre; the margin covers rounding).
        const Sliver& s = slivers_[sliver_of_[ti]];
        const double reach = 0.5 * std::sqrt(3.0) * cell_;
        auto centre_of = [&](const int* lo3, const int* hi3, Vec3* half) {
          Vec3 centre;
          for (int a = 0; a < 3; ++a) {
            centre[a] = origin_[a] + cell_ * (0.5 * (lo3[a] + hi3[a]) + 0.5);
            (*half)[a] = 0.5 * cell_ * (hi3[a] - lo3[a]);
          }
          return centre;
        };
        ForEachLeafRange<3>(
            clo, chi, 8,
            [&](const int* lo3, const int* hi3) {
              Vec3 half;
              const Vec3 centre = centre_of(lo3, hi3, &half);
              return s.Bound(centre) - half.norm() <= reach + 1e-6 * (1.0 + reach);
            },
            [&](const int* lo3, const int* hi3) {
              for (int z = lo3[2]; z <= hi3[2]; ++z)
                for (int y = lo3[1]; y <= hi3[1]; ++y)
                  for (int x = lo3[0]; x <= hi3[0]; ++x)
                    if (s.Bound(origin_ + cell_ * Vec3(x + 0.5, y + 0.5, z + 0.5)) <= reach)
                      add(x, y, z);
            });
        continue;
      }
      for (int z = clo[2]; z <= chi[2]; ++z)
        for (int y = clo[1]; y <= chi[1]; ++y)
          for (int x = clo[0]; x <= chi[0]; ++x) add(x, y, z);
    }
  }
}

double TriangleLocator::Distance(const Vec3& p) const {
  uint32_t nearest;
  return Distance(p, &nearest);
}

double TriangleLocator::Distance(const Vec3& p, uint32_t* nearest) const {
  return DistanceUnlessWithin(p, -1.0, nearest);
}

double TriangleLocator::DistanceUnlessWithin(const Vec3& p, double enough,
                                             uint32_t* nearest) const {
  *nearest = static_cast<uint32_t>(mesh_.triangles.size());
  int c0[3];
  for (int a = 0; a < 3; ++a)
    c0[a] = std::clamp(static_cast<int>(std::floor((p[a] - origin_[a]) / cell_)), 0, dims_[a] - 1);
  double best = std::numeric_limits<double>::infinity();
  const int rmax = std::max({dims_[0], dims_[1], dims_[2]});
  for (int r = 0; r <= rmax; ++r) {
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::max(0, c0[a] - r);
      hi[a] = std::min(dims_[a] - 1, c0[a] + r);
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          // Only the shell of the block is new.
          if (r > 0 && std::abs(x - c0[0]) < r && std::abs(y - c0[1]) < r &&
              std::abs(z - c0[2]) < r)
            continue;
          const size_t c = (static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x;
          for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
            const uint32_t ti = ids_[k];
            const auto& t = mesh_.triangles[ti];
            const Vec3 a = mesh_.points[t[0]], b = mesh_.points[t[1]], e = mesh_.points[t[2]];
            // The triangle's box first: a cheap lower bound (computed here, not stored: 48 bytes
            // per triangle of a large mesh). Skipping it would give the same result, slower.
            const Vec3 tlo = a.cwiseMin(b).cwiseMin(e), thi = a.cwiseMax(b).cwiseMax(e);
            if ((tlo - p).cwiseMax(p - thi).cwiseMax(0.0).squaredNorm() >= best * best) continue;
            // A long triangle's box is a loose bound (a sliver crossing the cell passes it); its
            // Sliver bound is a tight one.
            if (!sliver_of_.empty() && sliver_of_[ti] != kNone &&
                slivers_[sliver_of_[ti]].Bound(p) >= best)
              continue;
            const double d = PointTriangleDistance(p, a, b, e);
            if (d < best) {
              best = d;
              *nearest = ids_[k];
              if (best <= enough) return best;
            }
          }
        }
    // Distance from p to the space outside the visited block (infinite beyond the grid).
    double bound = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (lo[a] > 0) bound = std::min(bound, p[a] - (origin_[a] + lo[a] * cell_));
      if (hi[a] < dims_[a] - 1) bound = std::min(bound, origin_[a] + (hi[a] + 1) * cell_ - p[a]);
    }
    if (best <= std::max(0.0, bound)) break;
  }
  return best;
}

namespace {

// Distance from p to the union of hulls (0 inside one).
double DistanceToHulls(const Vec3& p, const std::vector<HullMesh>& hulls,
                       const std::vector<HullPlanes>& planes) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t h = 0; h < hulls.size(); ++h) {
    const HullPlanes& hp = planes[h];
    const Vec3 d = (hp.bmin - p).cwiseMax(p - hp.bmax).cwiseMax(0.0);
    if (d.norm() >= best) continue;
    const double s = hp.SignedDistanceBound(p);
    if (s <= 1e-9) return 0.0;
    if (s >= best) continue;
    for (const auto& t : hulls[h].triangles)
      best =
          std::min(best, PointTriangleDistance(p, hulls[h].vertices[t[0]], hulls[h].vertices[t[1]],
                                               hulls[h].vertices[t[2]]));
  }
  return best;
}

// Distance from p to the surface of `hull`, or any value >= limit once known to be at least limit.
double HullSurfaceDistance(const Vec3& p, const HullMesh& hull, double limit) {
  double best = limit;
  for (const auto& t : hull.triangles)
    best = std::min(best, PointTriangleDistance(p, hull.vertices[t[0]], hull.vertices[t[1]],
                                                hull.vertices[t[2]]));
  return best;
}

// Cracks between hulls narrower than this fraction of the diagonal do not count as boundary.
constexpr double kGap = 0.002;

}  // namespace

void SampleTriangle(Vec3 a, Vec3 b, Vec3 c, double spacing, std::vector<Vec3>* out) {
  if ((c - b).norm() > (b - a).norm() && (c - b).norm() >= (a - c).norm())
    std::swap(a, c);
  else if ((a - c).norm() > (b - a).norm())
    std::swap(b, c);
  const double ab = (b - a).norm();
  if (!(ab > 0)) return;
  const double height = (c - a).cross(b - a).norm() / ab;
  const int rows = static_cast<int>(std::floor(height / spacing));
  for (int r = 1; r <= rows; ++r) {
    const double s = (r - 0.5) / rows;
    const Vec3 p = a + s * (c - a), q = b + s * (c - b);
    const int cols = static_cast<int>(std::floor((q - p).norm() / spacing));
    for (int k = 0; k < cols; ++k) out->push_back(p + ((k + 0.5) / cols) * (q - p));
  }
}

std::vector<Vec3> SampleSurface(const GridMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) area += TriangleArea(mesh, t);
  std::vector<Vec3> out;
  // Vertices (a deterministic stride of them), then rows across each triangle.
  if (!mesh.vertex_samples.empty()) {
    for (uint32_t i : mesh.vertex_samples) out.push_back(mesh.points[i]);
  } else {
    const size_t vstride = VertexSampleStride(mesh.points.size());
    for (size_t i = 0; i < mesh.points.size(); i += vstride) out.push_back(mesh.points[i]);
  }
  const double spacing =
      std::max(1e-9, std::sqrt(2.0 * area / std::max<size_t>(1, kSurfaceSamples / 2)));
  for (const auto& t : mesh.triangles)
    SampleTriangle(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], spacing, &out);
  return out;
}

bool ComputeErrorReport(const MetricsInput& in, Context* ctx, Report* report) {
  const std::vector<HullMesh>& hulls = *in.hulls;
  const VoxelGrid& grid = *in.grid;
  std::vector<HullPlanes> planes;
  planes.reserve(hulls.size());
  for (const HullMesh& h : hulls) planes.emplace_back(h);

  // Voxel centres inside each hull.
  const size_t nvox = grid.size();
  std::vector<uint8_t> in_hull(nvox, 0);
  report->hulls.assign(hulls.size(), HullReport());
  std::vector<uint64_t> empty_inside(hulls.size(), 0);
  for (size_t h = 0; h < hulls.size(); ++h) {
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] =
          std::clamp(static_cast<int>(std::floor(planes[h].bmin[a] - 0.5)), 0, grid.dims[a] - 1);
      hi[a] = std::clamp(static_cast<int>(std::ceil(planes[h].bmax[a] - 0.5)), 0, grid.dims[a] - 1);
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x)
          if (planes[h].Contains(Vec3(x + 0.5, y + 0.5, z + 0.5), 1e-12)) {
            const size_t i = grid.Index(x, y, z);
            in_hull[i] = 1;
            if (!grid.CenterInside(i)) ++empty_inside[h];
          }
    report->hulls[h].vertex_count = static_cast<uint32_t>(hulls[h].vertices.size());
    report->hulls[h].concavity = static_cast<double>(empty_inside[h]) / in.volume0;
  }
  {
    uint64_t inter = 0, uni = 0, solid = 0;
    for (size_t i = 0; i < nvox; ++i) {
      const bool s = grid.CenterInside(i), h = in_hull[i] != 0;
      inter += (s && h);
      uni += (s || h);
      solid += s;
    }
    if (in.closed) report->volume_iou = uni > 0 ? static_cast<double>(inter) / uni : 1.0;
    report->solid_coverage = solid > 0 ? static_cast<double>(inter) / solid : 1.0;
  }
  if (ctx->Cancelled()) return false;

  // mesh -> hulls.
  const std::vector<Vec3> ms = SampleSurface(*in.mesh);
  const size_t stride = 1;
  const size_t nms = ms.size();
  const size_t kChunk = 256;
  std::vector<double> chunk_max((nms + kChunk - 1) / kChunk, 0.0);
  if (!ParallelFor(ctx, chunk_max.size(), [&](size_t c) {
        double m = 0.0;
        for (size_t k = c * kChunk; k < std::min(nms, (c + 1) * kChunk); ++k)
          m = std::max(m, DistanceToHulls(ms[k * stride], hulls, planes));
        chunk_max[c] = m;
      }))
    return false;
  double d_mh = 0.0;
  for (double m : chunk_max) d_mh = std::max(d_mh, m);

  // hulls -> mesh, on the boundary of the union.
  double total_area = 0.0;
  for (const HullMesh& h : hulls)
    for (const auto& t : h.triangles)
      total_area +=
          0.5 *
          (h.vertices[t[1]] - h.vertices[t[0]]).cross(h.vertices[t[2]] - h.vertices[t[0]]).norm();
  const double spacing = std::max(0.25, std::sqrt(2.0 * total_area / 30000.0));
  std::vector<std::pair<uint32_t, Vec3>> hs;  // (hull, point)
  std::vector<Vec3> tmp;
  for (uint32_t hi = 0; hi < hulls.size(); ++hi) {
    const HullMesh& h = hulls[hi];
    tmp.assign(h.vertices.begin(), h.vertices.end());
    for (const auto& t : h.triangles)
      SampleTriangle(h.vertices[t[0]], h.vertices[t[1]], h.vertices[t[2]], spacing, &tmp);
    for (const Vec3& p : tmp) hs.emplace_back(hi, p);
  }
  std::unique_ptr<TriangleLocator> own;
  if (in.locator == nullptr) {
    // Buckets of a few triangles each: about 3 mean triangle sizes, at most 4 voxels.
    double mesh_area = 0.0;
    for (const auto& t : in.mesh->triangles) mesh_area += TriangleArea(*in.mesh, t);
    double cell = 3.0 * std::sqrt(2.0 * mesh_area / std::max<size_t>(1, in.mesh->triangles.size()));
    const double cells_at_one = static_cast<double>(grid.dims[0]) * grid.dims[1] * grid.dims[2];
    cell = std::clamp(cell, std::max(0.5, std::cbrt(cells_at_one / 8e6)), 4.0);
    own.reset(new TriangleLocator(*in.mesh, cell));
  }
  const TriangleLocator& locator = in.locator != nullptr ? *in.locator : *own;
  const double gap = kGap * in.diagonal;
  chunk_max.assign((hs.size() + kChunk - 1) / kChunk, 0.0);
  std::vector<float> point_distance(hs.size(), 0.0f);
  if (!ParallelFor(ctx, chunk_max.size(), [&](size_t c) {
        double m = 0.0;
        // Only maxima are reported (per hull and overall): a sample that cannot raise its hull's
        // largest distance so far (the samples come hull by hull) needs no exact value.
        size_t hull = hulls.size();
        double hull_max = 0.0;
        for (size_t k = c * kChunk; k < std::min(hs.size(), (c + 1) * kChunk); ++k) {
          const Vec3& p = hs[k].second;
          // On the union's boundary unless inside another hull or across a crack narrower than
          // kGap (exact distance: the plane bound alone reaches much farther near sharp edges).
          bool interior = false;
          for (size_t h = 0; h < hulls.size() && !interior; ++h) {
            if (h == hs[k].first) continue;
            const double s = planes[h].SignedDistanceBound(p);
            if (s <= 0)
              interior = true;
            else if (s < gap)
              interior = HullSurfaceDistance(p, hulls[h], gap) < gap;
          }
          if (!interior) {
            if (hs[k].first != hull) {
              hull = hs[k].first;
              hull_max = 0.0;
            }
            uint32_t nearest = 0;
            const double dd = locator.DistanceUnlessWithin(p, hull_max, &nearest);
            hull_max = std::max(hull_max, dd);
            m = std::max(m, dd);
            point_distance[k] = static_cast<float>(dd);
          }
        }
        chunk_max[c] = m;
      }))
    return false;
  double d_hm = 0.0;
  for (double m : chunk_max) d_hm = std::max(d_hm, m);
  const double diag = in.diagonal > 0 ? in.diagonal : 1.0;
  report->hausdorff_mesh_to_hulls = std::isfinite(d_mh) ? d_mh / diag : 1.0;
  report->hausdorff_hulls_to_mesh = std::isfinite(d_hm) ? d_hm / diag : 1.0;
  report->concavity = std::max(report->hausdorff_mesh_to_hulls, report->hausdorff_hulls_to_mesh);
  for (HullReport& h : report->hulls) h.distance = 0.0;
  for (size_t k = 0; k < hs.size(); ++k) {
    double& d = report->hulls[hs[k].first].distance;
    d = std::max(d, point_distance[k] / diag);
  }
  return true;
}

void ClearMeasures(Report* report) {
  const Report none;
  report->hulls.clear();
  report->volume_iou = none.volume_iou;
  report->solid_coverage = none.solid_coverage;
  report->hausdorff_mesh_to_hulls = none.hausdorff_mesh_to_hulls;
  report->hausdorff_hulls_to_mesh = none.hausdorff_hulls_to_mesh;
  report->concavity = none.concavity;
}

}  // namespace internal
}  // namespace vhacd
