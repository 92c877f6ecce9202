#include "robot/mass_properties.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace hullpack {
namespace {

struct Moments {
  double volume = 0;
  double first[3] = {0, 0, 0};  // integral of x
  double second[3][3] = {{0}};  // integral of x_i x_j
};

// Adds the signed tetrahedra (origin, a, b, c) of every triangle: exact for a closed mesh.
void AddClosedMesh(const Mesh& m, const double origin[3], Moments* out) {
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    double p[3][3];
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = m.indices[t * 3 + k];
      for (int i = 0; i < 3; ++i) p[k][i] = double(m.positions[v * 3 + i]) - origin[i];
    }
    const double det = p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                       p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                       p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    double sum[3];
    for (int i = 0; i < 3; ++i) sum[i] = p[0][i] + p[1][i] + p[2][i];
    out->volume += det / 6;
    for (int i = 0; i < 3; ++i) out->first[i] += det / 24 * sum[i];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double products = p[0][i] * p[0][j] + p[1][i] * p[1][j] + p[2][i] * p[2][j];
        out->second[i][j] += det / 120 * (products + sum[i] * sum[j]);
      }
    }
  }
}

struct HullPlanes {
  std::vector<double> planes;  // nx ny nz d per triangle: inside when n.p <= d
  double lo[3], hi[3];
};

HullPlanes PlanesOf(const Mesh& m) {
  HullPlanes h;
  for (int i = 0; i < 3; ++i) h.lo[i] = 1e300, h.hi[i] = -1e300;
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    for (int i = 0; i < 3; ++i) {
      h.lo[i] = std::min(h.lo[i], double(m.positions[v * 3 + i]));
      h.hi[i] = std::max(h.hi[i], double(m.positions[v * 3 + i]));
    }
  }
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) p[k][i] = m.positions[m.indices[t * 3 + k] * 3 + i];
    const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double w[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0)) continue;  // a degenerate triangle bounds nothing
    for (double& c : n) c /= len;
    h.planes.insert(h.planes.end(),
                    {n[0], n[1], n[2], n[0] * p[0][0] + n[1] * p[0][1] + n[2] * p[0][2]});
  }
  return h;
}

bool Contains(const HullPlanes& h, const double p[3]) {
  for (int i = 0; i < 3; ++i)
    if (p[i] < h.lo[i] || p[i] > h.hi[i]) return false;
  for (size_t f = 0; f < h.planes.size(); f += 4) {
    if (h.planes[f] * p[0] + h.planes[f + 1] * p[1] + h.planes[f + 2] * p[2] > h.planes[f + 3])
      return false;
  }
  return true;
}

// Removes from `m` what the grid cells inside k > 1 hulls counted k - 1 times too often.
void SubtractOverlaps(const std::vector<HullPlanes>& hulls, const double origin[3], int cells,
                      Moments* m) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const HullPlanes& h : hulls) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], h.lo[i]), hi[i] = std::max(hi[i], h.hi[i]);
  }
  const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double step = longest / std::max(cells, 1);
  if (!(step > 0)) return;
  size_t n[3];
  for (int i = 0; i < 3; ++i)
    n[i] = std::max<size_t>(1, static_cast<size_t>(std::ceil((hi[i] - lo[i]) / step)));
  std::vector<uint8_t> marked(n[0] * n[1] * n[2], 0);
  bool any = false;
  for (size_t a = 0; a < hulls.size(); ++a) {
    for (size_t b = a + 1; b < hulls.size(); ++b) {
      size_t c0[3], c1[3];
      bool overlap = true;
      for (int i = 0; i < 3; ++i) {
        const double l = std::max(hulls[a].lo[i], hulls[b].lo[i]);
        const double h = std::min(hulls[a].hi[i], hulls[b].hi[i]);
        if (l >= h) overlap = false;
        c0[i] = static_cast<size_t>(std::max(0.0, std::floor((l - lo[i]) / step)));
        c1[i] =
            std::min(n[i] - 1, static_cast<size_t>(std::max(0.0, std::floor((h - lo[i]) / step))));
      }
      if (!overlap) continue;
      any = true;
      for (size_t z = c0[2]; z <= c1[2]; ++z)
        for (size_t y = c0[1]; y <= c1[1]; ++y)
          for (size_t x = c0[0]; x <= c1[0]; ++x) marked[(z * n[1] + y) * n[0] + x] = 1;
    }
  }
  if (!any) return;
  const double cell_volume = step * step * step;
  const double cell_second = cell_volume * step * step / 12;  // a cube's own integral of x^2
  for (size_t z = 0; z < n[2]; ++z) {
    for (size_t y = 0; y < n[1]; ++y) {
      for (size_t x = 0; x < n[0]; ++x) {
        if (!marked[(z * n[1] + y) * n[0] + x]) continue;
        const double p[3] = {lo[0] + (x + 0.5) * step, lo[1] + (y + 0.5) * step,
                             lo[2] + (z + 0.5) * step};
        int inside = 0;
        for (const HullPlanes& h : hulls) inside += Contains(h, p) ? 1 : 0;
        if (inside < 2) continue;
        const double extra = inside - 1;
        const double r[3] = {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
        m->volume -= extra * cell_volume;
        for (int i = 0; i < 3; ++i) {
          m->first[i] -= extra * cell_volume * r[i];
          for (int j = 0; j < 3; ++j)
            m->second[i][j] -= extra * (cell_volume * r[i] * r[j] + (i == j ? cell_second : 0));
        }
      }
    }
  }
}

}  // namespace

Result<MassProperties> HullUnionMassProperties(const std::vector<Mesh>& hulls, double density,
                                               int overlap_cells) {
  if (!(density > 0) || !std::isfinite(density))
    return Status(StatusCode::kInvalidArgument, "density must be a positive number");
  if (hulls.empty()) return Status(StatusCode::kInvalidArgument, "no hulls");
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (size_t h = 0; h < hulls.size(); ++h) {
    for (float c : hulls[h].positions) {
      if (!std::isfinite(c))
        return Status(StatusCode::kInvalidMesh,
                      "hull " + std::to_string(h) + ": non-finite coordinate");
    }
    for (size_t v = 0; v < hulls[h].vertex_count(); ++v) {
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], double(hulls[h].positions[v * 3 + i]));
        hi[i] = std::max(hi[i], double(hulls[h].positions[v * 3 + i]));
      }
    }
  }
  // Moments about the middle of the hulls keep the sums of large coordinates well conditioned.
  const double origin[3] = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  Moments m;
  std::vector<HullPlanes> planes;
  for (size_t h = 0; h < hulls.size(); ++h) {
    Moments one;
    AddClosedMesh(hulls[h], origin, &one);
    if (!(one.volume > 0)) {
      return Status(StatusCode::kInvalidMesh,
                    "hull " + std::to_string(h) + " has no volume (not closed or inside out)");
    }
    m.volume += one.volume;
    for (int i = 0; i < 3; ++i) {
      m.first[i] += one.first[i];
      for (int j = 0; j < 3; ++j) m.second[i][j] += one.second[i][j];
    }
    planes.push_back(PlanesOf(hulls[h]));
  }
  SubtractOverlaps(planes, origin, overlap_cells, &m);
  if (!(m.volume > 0)) return Status(StatusCode::kInternal, "the hull union has no volume");

  MassProperties out;
  out.volume = m.volume;
  out.mass = density * m.volume;
  double c[3];
  for (int i = 0; i < 3; ++i) c[i] = m.first[i] / m.volume;
  double s[3][3];  // second moments about the centre of mass
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[i][j] = m.second[i][j] - m.volume * c[i] * c[j];
  for (int i = 0; i < 3; ++i) out.center[i] = origin[i] + c[i];
  out.inertia = {density * (s[1][1] + s[2][2]),
                 density * (s[0][0] + s[2][2]),
                 density * (s[0][0] + s[1][1]),
                 -density * s[0][1],
                 -density * s[0][2],
                 -density * s[1][2]};
  return out;
}

}  // namespace hullpack
