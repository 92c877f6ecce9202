#include "part_hull.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "oriented_cuts.h"

namespace vhacd {
namespace internal {

TriangleIndex::TriangleIndex(const GridMesh& mesh, const int dims[3], int cell)
    : mesh_(mesh), cell_(cell) {
  for (int a = 0; a < 3; ++a) dims_[a] = std::max(1, (dims[a] + cell - 1) / cell);
  const size_t ncell = static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2];
  const size_t nt = mesh.triangles.size();
  // The cells a triangle's box covers, found again in each pass: stored, they and the boxes took
  // 72 bytes per triangle, three times the mesh's own points and triangles.
  auto cells = [&](size_t t, int range[6]) {
    Vec3 lo, hi;
    TriangleBox(t, &lo, &hi);
    for (int a = 0; a < 3; ++a) {
      range[a] = std::clamp(static_cast<int>(std::floor(lo[a])) / cell, 0, dims_[a] - 1);
      range[a + 3] = std::clamp(static_cast<int>(std::floor(hi[a])) / cell, 0, dims_[a] - 1);
    }
  };
  mesh_lo_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  mesh_hi_ = -mesh_lo_;
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    const Vec3 p = mesh.points[i];
    mesh_lo_ = mesh_lo_.cwiseMin(p);
    mesh_hi_ = mesh_hi_.cwiseMax(p);
  }
  start_.assign(ncell + 1, 0);
  int range[6];
  for (size_t t = 0; t < nt; ++t) {
    cells(t, range);
    for (int z = range[2]; z <= range[5]; ++z)
      for (int y = range[1]; y <= range[4]; ++y)
        for (int x = range[0]; x <= range[3]; ++x)
          ++start_[(static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x + 1];
  }
  for (size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  ids_.resize(start_[ncell]);
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  for (size_t t = 0; t < nt; ++t) {
    cells(t, range);
    for (int z = range[2]; z <= range[5]; ++z)
      for (int y = range[1]; y <= range[4]; ++y)
        for (int x = range[0]; x <= range[3]; ++x)
          ids_[fill[(static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x]++] =
              static_cast<uint32_t>(t);
  }
}

void ClipTriangleToBox(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& lo, const Vec3& hi,
                       std::vector<Vec3>* out) {
  Vec3 buf0[12], buf1[12];
  Vec3* poly = buf0;
  Vec3* next = buf1;
  int n = 3;
  poly[0] = a;
  poly[1] = b;
  poly[2] = c;
  for (int plane = 0; plane < 6 && n > 0; ++plane) {
    const int axis = plane / 2;
    const bool upper = plane % 2 == 1;
    const double bound = upper ? hi[axis] : lo[axis];
    auto inside = [&](const Vec3& p) { return upper ? p[axis] <= bound : p[axis] >= bound; };
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3& p = poly[i];
      const Vec3& q = poly[(i + 1) % n];
      const bool pin = inside(p), qin = inside(q);
      if (pin) next[m++] = p;
      if (pin != qin) {
        const double t = (bound - p[axis]) / (q[axis] - p[axis]);
        Vec3 x = p + t * (q - p);
        x[axis] = bound;
        next[m++] = x;
      }
    }
    std::swap(poly, next);
    n = m;
  }
  for (int i = 0; i < n; ++i) out->push_back(poly[i]);
}

namespace {
// From this many mesh points on, part hulls read the mesh's points by index.
constexpr size_t kPartRefsFrom = size_t{1} << 18;

bool CutsContain(const std::vector<CutPlane>& cuts, const Vec3& p) {
  for (const CutPlane& cut : cuts)
    if (cut.n.dot(p) > cut.d) return false;
  return true;
}
}  // namespace

HullMesh BuildPartHull(const Part& part, const TriangleIndex& index, const SolidCorners* corners) {
  std::vector<Vec3> pts;
  PartHullPoints(part, true, &pts);
  const Vec3 lo(part.bmin[0], part.bmin[1], part.bmin[2]);
  const Vec3 hi(part.bmax[0] + 1, part.bmax[1] + 1, part.bmax[2] + 1);
  if (corners != nullptr) {
    for (const Voxel& v : part.voxels) {
      if (!v.surface) continue;
      const uint8_t mask = corners->Mask(v.c[0], v.c[1], v.c[2]);
      for (int k = 0; k < 8; ++k) {
        if (!(mask & (1u << k))) continue;
        const Vec3 c(v.c[0] + (k & 1), v.c[1] + ((k >> 1) & 1), v.c[2] + ((k >> 2) & 1));
        if (((c.array() == lo.array()) || (c.array() == hi.array())).any()) {
          pts.push_back(c);
          continue;
        }
        // The same at an oriented cut: the corners within a voxel of its plane, on this side.
        for (const CutPlane& cut : part.cuts) {
          const double s = cut.n.dot(c) - cut.d;
          if (s <= 0 && s > -1 && CutsContain(part.cuts, c)) {
            pts.push_back(c);
            break;
          }
        }
      }
    }
  }
  const GridMesh& mesh = index.mesh();
  // Per triangle and per vertex, the part that last saw it: a byte each (these are a mesh's worth
  // per thread), cleared when the marks wrap.
  thread_local std::vector<uint8_t> stamp, vstamp;
  thread_local uint8_t mark = 0;
  if (stamp.size() != mesh.triangles.size() || vstamp.size() != mesh.points.size()) {
    stamp.assign(mesh.triangles.size(), 0);
    vstamp.assign(mesh.points.size(), 0);
    mark = 0;
  }
  if (++mark == 0) {
    std::fill(stamp.begin(), stamp.end(), 0);
    std::fill(vstamp.begin(), vstamp.end(), 0);
    mark = 1;
  }
  // The mesh's own vertices are read by index (`refs`, in the order they come, with the voxel
  // corners above and the clipped points kept in `pts`) for the root, and for every part of a
  // large mesh or of one mapped on every read: copied they were the largest array of a large part
  // (24 bytes per point, against 4), one per thread. A smaller mesh holding its points copies a
  // part's own (the hull's passes then read them in order, which is faster).
  const bool root = part.cuts.empty() && index.HoldsMesh(lo, hi);
  const bool by_index = root || mesh.points.mapped() || mesh.points.size() >= kPartRefsFrom;
  const size_t before_surface = pts.size();
  std::vector<uint32_t> refs;
  auto add_own = [&](size_t from) {
    if (!by_index) return;
    for (size_t i = from; i < pts.size(); ++i) refs.push_back(kHeadRef + static_cast<uint32_t>(i));
  };
  auto add_vertex = [&](uint32_t v, const Vec3& p) {
    if (by_index)
      refs.push_back(v);
    else
      pts.push_back(p);
  };
  add_own(0);
  if (root) {
    // Every triangle lies in the box and gives its vertices, in the order the triangles give them.
    refs.reserve(before_surface + mesh.points.size());
    index.ForEachInBox(lo, hi, &stamp, mark, [&](uint32_t t) {
      for (uint32_t v : mesh.triangles[t])
        if (vstamp[v] != mark) {
          vstamp[v] = mark;
          refs.push_back(v);
        }
    });
  } else {
    auto inside = [&](const Vec3& q) {
      return (q.array() >= lo.array()).all() && (q.array() <= hi.array()).all();
    };
    // Triangles inside the box and every cut contribute their vertices (each once), the others
    // their clipped polygon. (Clipped too, an inside triangle gave its corners again: a copy of a
    // vertex per triangle around it, most of a large part's points.)
    std::vector<Vec3> poly;
    index.ForEachInBox(lo, hi, &stamp, mark, [&](uint32_t t) {
      const auto& tr = mesh.triangles[t];
      // Each point read once: a mesh read in place is mapped on every read.
      const Vec3 corner[3] = {mesh.points[tr[0]], mesh.points[tr[1]], mesh.points[tr[2]]};
      const bool in_box = inside(corner[0]) && inside(corner[1]) && inside(corner[2]);
      const size_t own = pts.size();
      if (!part.cuts.empty() &&
          !(in_box && CutsContain(part.cuts, corner[0]) && CutsContain(part.cuts, corner[1]) &&
            CutsContain(part.cuts, corner[2]))) {
        poly.clear();
        ClipTriangleToBox(corner[0], corner[1], corner[2], lo, hi, &poly);
        if (!poly.empty()) ClipPolygonToCuts(poly, part.cuts, &pts);
        add_own(own);
        return;
      }
      if (in_box) {
        for (int k = 0; k < 3; ++k)
          if (vstamp[tr[k]] != mark) {
            vstamp[tr[k]] = mark;
            add_vertex(tr[k], corner[k]);
          }
        return;
      }
      ClipTriangleToBox(corner[0], corner[1], corner[2], lo, hi, &pts);
      add_own(own);
    });
  }
  const bool has_surface = (by_index ? refs.size() : pts.size()) > before_surface;
  HullMesh h;
  HullStatus status = by_index ? ComputeConvexHull(pts, mesh.points, refs, -1.0, &h)
                               : ComputeConvexHull(pts, -1.0, &h);
  std::vector<uint32_t>().swap(refs);
  if (status == HullStatus::kOk && h.Volume() > 1e-3) return h;
  // A sliver along an oriented cut can hold surface voxels whose surface lies across the plane:
  // its voxels' hull would stick out of the solid by up to a voxel, and the surface is held by the
  // part across the cut. It gets no hull.
  if (!part.cuts.empty() && !has_surface) return HullMesh();
  PartHullPoints(part, false, &pts);
  if (ComputeConvexHull(pts, 0.0, &h) != HullStatus::kOk) return HullMesh();
  // A flat piece of surface (a sheet) gets the slab of its voxels, within its cuts.
  if (!part.cuts.empty()) h = ClipHullToCuts(h, part.cuts);
  return h;
}

HullMesh PartHulls::Of(const Part& part) {
  // Parts are subsets of the whole set: one without cuts holding all its voxels is the whole set
  // (same voxels, in the same order, so the same points for the hull).
  if (!part.cuts.empty() || part.voxels.size() != whole_voxels_)
    return BuildPartHull(part, index_, corners_);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!built_) {
    whole_hull_ = BuildPartHull(part, index_, corners_);
    built_ = true;
  }
  return whole_hull_;
}

}  // namespace internal
}  // namespace vhacd
