#include "tetrahedron_set.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "part_hull.h"
#include "thread_pool.h"

namespace vhacd {
namespace internal {

// Corner k of the unit cube is (k & 1, (k >> 1) & 1, (k >> 2) & 1). The central tetrahedron uses
// the corners 1, 2, 4, 7; the four others cut off the corners 0, 3, 5, 6.
const int kCubeTetrahedra[5][4] = {
    {1, 2, 7, 4}, {0, 1, 2, 4}, {3, 2, 1, 7}, {5, 1, 4, 7}, {6, 4, 2, 7}};

namespace {

double TetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return std::fabs((b - a).dot((c - a).cross(d - a))) / 6.0;
}

// Where segment pq meets n.x = d0, evaluated with the endpoints in a canonical order so that the
// two tetrahedra sharing an edge get bitwise the same point.
Vec3 Crossing(const Vec3& p, double sp, const Vec3& q, double sq) {
  const bool swap = std::lexicographical_compare(q.data(), q.data() + 3, p.data(), p.data() + 3);
  const Vec3& a = swap ? q : p;
  const Vec3& b = swap ? p : q;
  const double sa = swap ? sq : sp, sb = swap ? sp : sq;
  const double t = sa / (sa - sb);
  return a + t * (b - a);
}

// Prism with end triangles (a0, a1, a2) and (b0, b1, b2), ai joined to bi: three tetrahedra.
void SplitPrism(const Vec3 (&a)[3], const Vec3 (&b)[3], double* volume, int* count,
                std::vector<std::array<Vec3, 4>>* pieces) {
  const std::array<Vec3, 4> t[3] = {
      {a[0], a[1], a[2], b[0]}, {a[1], a[2], b[0], b[1]}, {a[2], b[0], b[1], b[2]}};
  for (const auto& q : t) {
    const double v = TetVolume(q[0], q[1], q[2], q[3]);
    if (!(v > 0)) continue;
    *volume += v;
    ++*count;
    if (pieces != nullptr) pieces->push_back(q);
  }
}

}  // namespace

double ClipTetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& n,
                       double d0, int* count, std::vector<std::array<Vec3, 4>>* pieces) {
  const Vec3 P[4] = {a, b, c, d};
  double s[4];
  int in[4], out[4], ni = 0, no = 0;
  for (int k = 0; k < 4; ++k) {
    s[k] = n.dot(P[k]) - d0;
    if (s[k] <= 0)
      in[ni++] = k;
    else
      out[no++] = k;
  }
  *count = 0;
  double volume = 0.0;
  auto add = [&](const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    const double v = TetVolume(p0, p1, p2, p3);
    if (!(v > 0)) return;
    volume += v;
    ++*count;
    if (pieces != nullptr) pieces->push_back({p0, p1, p2, p3});
  };
  if (no == 0) {
    add(a, b, c, d);
  } else if (ni == 1) {
    const int k = in[0];
    Vec3 x[3];
    for (int j = 0; j < 3; ++j) x[j] = Crossing(P[k], s[k], P[out[j]], s[out[j]]);
    add(P[k], x[0], x[1], x[2]);
  } else if (ni == 2) {
    // Wedge: the inside edge (i0, i1) and the crossings of the four edges towards the outside.
    const int i0 = in[0], i1 = in[1], o0 = out[0], o1 = out[1];
    const Vec3 e0[3] = {P[i0], Crossing(P[i0], s[i0], P[o0], s[o0]),
                        Crossing(P[i0], s[i0], P[o1], s[o1])};
    const Vec3 e1[3] = {P[i1], Crossing(P[i1], s[i1], P[o0], s[o0]),
                        Crossing(P[i1], s[i1], P[o1], s[o1])};
    SplitPrism(e0, e1, &volume, count, pieces);
  } else if (ni == 3) {
    // The tetrahedron minus the corner beyond the plane: a prism between the inside face and its
    // crossings.
    const int o = out[0];
    const Vec3 f0[3] = {P[in[0]], P[in[1]], P[in[2]]};
    const Vec3 f1[3] = {Crossing(P[in[0]], s[in[0]], P[o], s[o]),
                        Crossing(P[in[1]], s[in[1]], P[o], s[o]),
                        Crossing(P[in[2]], s[in[2]], P[o], s[o])};
    SplitPrism(f0, f1, &volume, count, pieces);
  }
  return volume;
}

SurfaceCell FullCell(int x, int y, int z) {
  SurfaceCell cell;
  cell.c[0] = static_cast<uint16_t>(x);
  cell.c[1] = static_cast<uint16_t>(y);
  cell.c[2] = static_cast<uint16_t>(z);
  for (int k = 0; k < 8; ++k) {
    cell.p[k][0] = static_cast<float>(x + (k & 1));
    cell.p[k][1] = static_cast<float>(y + ((k >> 1) & 1));
    cell.p[k][2] = static_cast<float>(z + ((k >> 2) & 1));
  }
  cell.point_count = 8;
  cell.tetrahedra = 5;
  cell.volume = 1.0f;
  return cell;
}

namespace {

SurfaceCell EmptyCell(int x, int y, int z) {
  SurfaceCell cell;
  cell.c[0] = static_cast<uint16_t>(x);
  cell.c[1] = static_cast<uint16_t>(y);
  cell.c[2] = static_cast<uint16_t>(z);
  return cell;
}

// Adds the cube of `cell` intersected with the half-spaces to the cell: volume and tetrahedra from
// the 5 tetrahedra clipped by each half-space in turn, vertices (distinct) from the pieces' points
// that lie on at least 3 of the bounding planes (cube faces and half-space planes). False when the
// cell has no room for the vertices.
bool AddConvexPiece(const HalfSpace* hs, int count, SurfaceCell* cell, double* volume, int* tets) {
  const Vec3 o(cell->c[0], cell->c[1], cell->c[2]);
  std::vector<std::array<Vec3, 4>> pieces, next;
  for (const auto& t : kCubeTetrahedra) {
    std::array<Vec3, 4> q;
    for (int k = 0; k < 4; ++k) q[k] = o + Vec3(t[k] & 1, (t[k] >> 1) & 1, (t[k] >> 2) & 1);
    pieces.push_back(q);
  }
  for (int h = 0; h < count; ++h) {
    next.clear();
    int n = 0;
    for (const auto& q : pieces)
      ClipTetrahedron(q[0], q[1], q[2], q[3], hs[h].n, hs[h].d, &n, &next);
    pieces.swap(next);
  }
  for (const auto& q : pieces)
    *volume += std::fabs((q[1] - q[0]).dot((q[2] - q[0]).cross(q[3] - q[0]))) / 6.0;
  *tets += static_cast<int>(pieces.size());
  // A zero-volume piece (the surface on a voxel face) still contributes its face: take the points
  // of the pieces before dropping flat ones, which ClipTetrahedron already did; so also test the
  // cube's corners and edge crossings directly.
  std::vector<Vec3> cand;
  for (const auto& q : pieces) cand.insert(cand.end(), q.begin(), q.end());
  for (int k = 0; k < 8; ++k) {
    const Vec3 ck = o + Vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    cand.push_back(ck);
    for (int h = 0; h < count; ++h)
      for (int axis = 0; axis < 3; ++axis) {
        if (k & (1 << axis)) continue;
        const Vec3 cj = o + Vec3((k | (1 << axis)) & 1, ((k | (1 << axis)) >> 1) & 1,
                                 ((k | (1 << axis)) >> 2) & 1);
        const double sk = hs[h].n.dot(ck) - hs[h].d, sj = hs[h].n.dot(cj) - hs[h].d;
        if ((sk <= 0) != (sj <= 0)) cand.push_back(Crossing(ck, sk, cj, sj));
      }
  }
  for (const Vec3& p : cand) {
    int active = 0;
    bool inside = true;
    for (int a = 0; a < 3; ++a) active += (p[a] == o[a]) + (p[a] == o[a] + 1);
    for (int h = 0; h < count; ++h) {
      const double s = hs[h].n.dot(p) - hs[h].d;
      if (s > 1e-9) inside = false;
      active += std::fabs(s) <= 1e-9;
    }
    if (!inside || active < 3) continue;
    const float f[3] = {static_cast<float>(p[0]), static_cast<float>(p[1]),
                        static_cast<float>(p[2])};
    bool dup = false;
    for (int i = 0; i < cell->point_count && !dup; ++i)
      dup = cell->p[i][0] == f[0] && cell->p[i][1] == f[1] && cell->p[i][2] == f[2];
    if (dup) continue;
    if (cell->point_count >= SurfaceCell::kMaxPoints) return false;
    for (int a = 0; a < 3; ++a) cell->p[cell->point_count][a] = f[a];
    ++cell->point_count;
  }
  return true;
}

}  // namespace

SurfaceCell TrimmedCell(int x, int y, int z, const HalfSpace* planes, int count,
                        bool union_of_two) {
  const Vec3 o(x, y, z);
  bool whole = true;  // every corner inside every half-space: nothing to trim
  for (int h = 0; h < count; ++h)
    for (int k = 0; k < 8; ++k)
      whole = whole && planes[h].n.dot(o + Vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1)) <= planes[h].d;
  if (whole || count < 1 || (union_of_two && count != 2)) return FullCell(x, y, z);
  SurfaceCell cell = EmptyCell(x, y, z);
  double volume = 0.0;
  int tets = 0;
  bool ok;
  if (!union_of_two) {
    ok = AddConvexPiece(planes, count, &cell, &volume, &tets);
  } else {
    // A concave edge: the solid is H0 ∪ H1 = H0 + (H1 minus H0), two convex pieces.
    const HalfSpace second[2] = {planes[1], {-planes[0].n, -planes[0].d}};
    ok = AddConvexPiece(planes, 1, &cell, &volume, &tets) &&
         AddConvexPiece(second, 2, &cell, &volume, &tets);
  }
  if (!ok) return FullCell(x, y, z);
  cell.tetrahedra = static_cast<uint8_t>(std::min(tets, 255));
  cell.volume = static_cast<float>(std::clamp(volume, 0.0, 1.0));
  return cell;
}

SurfaceCell TrimmedCell(int x, int y, int z, const Vec3& n, double d0) {
  const HalfSpace h{n, d0};
  return TrimmedCell(x, y, z, &h, 1, false);
}

namespace {

constexpr int kMaxClusters = 3;
constexpr double kSameSheet = 0.9;  // |cos| between normals of one sheet (about 25 degrees)

// The surface inside one voxel, as up to kMaxClusters sheets of similar normals.
struct CellStats {
  int clusters = 0;
  bool complex = false;  // more sheets than kMaxClusters
  double area[kMaxClusters] = {0, 0, 0};
  Vec3 rep[kMaxClusters];  // the first normal of each sheet (its sign reference)
  Vec3 sum[kMaxClusters];  // area-weighted normals, signs aligned with rep
  HalfSpace plane[kMaxClusters];
  int planes = 0;
  // reach[i][j]: max of plane[i].n . p over the points p of sheet j (pass 2).
  double reach[kMaxClusters][kMaxClusters];
  int sheet_of[kMaxClusters] = {-1, -1, -1};  // plane index -> sheet, for pass 2
};

// The sheet a normal belongs to (-1: none), and the sign aligning it with that sheet.
int FindSheet(const CellStats& st, const Vec3& n, double* sign) {
  int best = -1;
  double best_dot = kSameSheet;
  for (int c = 0; c < st.clusters; ++c) {
    const double d = st.rep[c].dot(n);
    if (std::fabs(d) >= best_dot) {
      best_dot = std::fabs(d);
      best = c;
      *sign = d < 0 ? -1.0 : 1.0;
    }
  }
  return best;
}

double PolygonArea(const std::vector<Vec3>& poly) {
  double area = 0.0;
  for (size_t k = 1; k + 1 < poly.size(); ++k)
    area += 0.5 * (poly[k] - poly[0]).cross(poly[k + 1] - poly[0]).norm();
  return area;
}

}  // namespace

bool BuildSurfaceCells(const GridMesh& mesh, const VoxelGrid& grid, Context* ctx,
                       std::vector<SurfaceCell>* cells) {
  cells->clear();
  const int* dims = grid.dims;
  // Surface voxels in grid order, and their linear indices for lookups.
  std::vector<uint64_t> ids;
  for (size_t i = 0; i < grid.size(); ++i)
    if (grid.cell[i] == kCellSurface) ids.push_back(i);
  const size_t n = ids.size();
  std::vector<CellStats> stats(n);
  auto find = [&](size_t index) -> int64_t {
    auto it = std::lower_bound(ids.begin(), ids.end(), index);
    return it != ids.end() && *it == index ? it - ids.begin() : -1;
  };
  auto coords = [&](size_t i, int* x, int* y, int* z) {
    const size_t index = ids[i];
    *x = static_cast<int>(index % dims[0]);
    *y = static_cast<int>((index / dims[0]) % dims[1]);
    *z = static_cast<int>(index / (static_cast<size_t>(dims[0]) * dims[1]));
  };
  // Triangles by slab of z (a triangle in every slab its box meets): each slab is one task that
  // visits its triangles in input order, so every sum has a fixed order.
  constexpr int kSlab = 4;
  const int slabs = (dims[2] + kSlab - 1) / kSlab;
  std::vector<std::vector<uint32_t>> by_slab(slabs);
  std::vector<std::array<int, 6>> range(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tr = mesh.triangles[t];
    const Vec3 p0 = mesh.points[tr[0]], p1 = mesh.points[tr[1]], p2 = mesh.points[tr[2]];
    const Vec3 lo = p0.cwiseMin(p1).cwiseMin(p2), hi = p0.cwiseMax(p1).cwiseMax(p2);
    // The voxels whose closed box meets the triangle's box (a bound on an integer coordinate
    // touches the voxels on both sides).
    for (int a = 0; a < 3; ++a) {
      range[t][a] = std::clamp(static_cast<int>(std::ceil(lo[a])) - 1, 0, dims[a] - 1);
      range[t][a + 3] = std::clamp(static_cast<int>(std::floor(hi[a])), 0, dims[a] - 1);
    }
    for (int s = range[t][2] / kSlab; s <= range[t][5] / kSlab; ++s)
      by_slab[s].push_back(static_cast<uint32_t>(t));
  }
  // Visits, for every slab, the clipped polygon of each triangle in each surface voxel it meets.
  auto for_each_piece = [&](auto fn) {
    return ParallelFor(ctx, static_cast<size_t>(slabs), [&](size_t s) {
      std::vector<Vec3> poly;
      const int z0 = static_cast<int>(s) * kSlab, z1 = std::min(dims[2] - 1, z0 + kSlab - 1);
      for (uint32_t t : by_slab[s]) {
        const auto& tr = mesh.triangles[t];
        const Vec3 a = mesh.points[tr[0]], b = mesh.points[tr[1]], c = mesh.points[tr[2]];
        const Vec3 cr = (b - a).cross(c - a);
        const double len = cr.norm();
        if (!(len > 0)) continue;
        const Vec3 nt = cr / len;
        for (int z = std::max(z0, range[t][2]); z <= std::min(z1, range[t][5]); ++z)
          for (int y = range[t][1]; y <= range[t][4]; ++y)
            for (int x = range[t][0]; x <= range[t][3]; ++x) {
              const size_t index = grid.Index(x, y, z);
              if (grid.cell[index] != kCellSurface) continue;
              poly.clear();
              ClipTriangleToBox(a, b, c, Vec3(x, y, z), Vec3(x + 1, y + 1, z + 1), &poly);
              if (poly.size() < 3) continue;
              const int64_t id = find(index);
              if (id >= 0) fn(&stats[id], poly, nt);
            }
      }
    });
  };
  // Pass 1: the sheets of each voxel (normals within ~25 degrees, either orientation).
  if (!for_each_piece([](CellStats* st, const std::vector<Vec3>& poly, const Vec3& nt) {
        const double area = PolygonArea(poly);
        if (!(area > 0) || st->complex) return;
        double sign = 1.0;
        int c = FindSheet(*st, nt, &sign);
        if (c < 0) {
          if (st->clusters == kMaxClusters) {
            st->complex = true;
            return;
          }
          c = st->clusters++;
          st->rep[c] = nt;
          st->sum[c] = Vec3::Zero();
          sign = 1.0;
        }
        st->area[c] += area;
        st->sum[c] += sign * area * nt;
      }))
    return false;
  // Each sheet's plane, oriented away from the solid by the neighbours (inside voxels on one side,
  // outside ones on the other, as unit directions). Sheets under 2 % of the voxel's surface are
  // noise and ignored.
  if (!ParallelFor(ctx, n, [&](size_t i) {
        CellStats& st = stats[i];
        if (st.complex || st.clusters == 0) return;
        int x, y, z;
        coords(i, &x, &y, &z);
        // Two rings of neighbours: a voxel at a corner or an edge has few inside voxels next to it.
        Vec3 towards_solid = Vec3::Zero();
        for (int dz = -2; dz <= 2; ++dz)
          for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
              if (dx == 0 && dy == 0 && dz == 0) continue;
              const int X = x + dx, Y = y + dy, Z = z + dz;
              const Vec3 dir = Vec3(dx, dy, dz).normalized();
              const bool out_of_grid =
                  X < 0 || Y < 0 || Z < 0 || X >= dims[0] || Y >= dims[1] || Z >= dims[2];
              const uint8_t c =
                  out_of_grid ? static_cast<uint8_t>(kCellOutside) : grid.cell[grid.Index(X, Y, Z)];
              if (c == kCellInside)
                towards_solid += dir;
              else if (c == kCellOutside)
                towards_solid -= dir;
            }
        double total = 0.0;
        for (int c = 0; c < st.clusters; ++c) total += st.area[c];
        for (int c = 0; c < st.clusters; ++c) {
          if (st.area[c] < 0.02 * total) continue;
          const double len = st.sum[c].norm();
          if (!(len > 0)) continue;
          const Vec3 nn = st.sum[c] / len;
          const double side = nn.dot(towards_solid);
          if (std::fabs(side) < 1.0) {  // no clear inside (a thin sheet): keep the voxel whole
            st.planes = 0;
            return;
          }
          st.sheet_of[st.planes] = c;
          st.plane[st.planes].n = side > 0 ? Vec3(-nn) : nn;  // outward
          st.plane[st.planes].d = -std::numeric_limits<double>::infinity();
          for (int j = 0; j < kMaxClusters; ++j)
            st.reach[st.planes][j] = -std::numeric_limits<double>::infinity();
          ++st.planes;
        }
      }))
    return false;
  // Pass 2: each plane pushed out to the outermost point of its sheet; how far each plane's
  // direction reaches into the other sheets (convex or concave arrangement).
  if (!for_each_piece([](CellStats* st, const std::vector<Vec3>& poly, const Vec3& nt) {
        if (st->planes == 0 || st->complex) return;
        double sign = 1.0;
        const int c = FindSheet(*st, nt, &sign);
        if (c < 0) return;
        for (int h = 0; h < st->planes; ++h)
          for (const Vec3& p : poly)
            st->reach[h][c] = std::max(st->reach[h][c], st->plane[h].n.dot(p));
      }))
    return false;
  cells->resize(n);
  return ParallelFor(ctx, n, [&](size_t i) {
    CellStats& st = stats[i];
    int x, y, z;
    coords(i, &x, &y, &z);
    if (st.complex || st.planes == 0) {
      (*cells)[i] = FullCell(x, y, z);
      return;
    }
    constexpr double kTol = 0.05;  // voxels
    bool convex = true, concave = st.planes == 2;
    for (int h = 0; h < st.planes; ++h) {
      st.plane[h].d = st.reach[h][st.sheet_of[h]];
      if (!std::isfinite(st.plane[h].d)) {
        (*cells)[i] = FullCell(x, y, z);
        return;
      }
    }
    for (int h = 0; h < st.planes; ++h)
      for (int g = 0; g < st.planes; ++g) {
        if (g == h) continue;
        const double r = st.reach[h][st.sheet_of[g]];
        if (r > st.plane[h].d + kTol) convex = false;   // sheet g pokes out of plane h
        if (r < st.plane[h].d - kTol) concave = false;  // sheet g lies inside plane h
      }
    if (convex)
      (*cells)[i] = TrimmedCell(x, y, z, st.plane, st.planes, false);
    else if (concave)
      (*cells)[i] = TrimmedCell(x, y, z, st.plane, 2, true);
    else
      (*cells)[i] = FullCell(x, y, z);
  });
}

}  // namespace internal
}  // namespace vhacd
