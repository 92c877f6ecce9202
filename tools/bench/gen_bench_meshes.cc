// gen_bench_meshes: writes the second codec benchmark set (meshes of kinds the public corpus lacks)
// as OBJ files (and one GLB) into a folder, for codec_bench:
//
//   gen_bench_meshes OUT_FOLDER
//   codec_bench OUT_FOLDER --clock cpu
//
// Every mesh is generated in code, deterministically (a fixed-seed generator), so the set needs no
// download and is the same on every machine:
//  - CAD parts as an STL exporter tessellates them, then welded: planar faces triangulated without
//    interior vertices (fans and strips between a face's outer loop and its hole loops, hence long
//    slivers), cylinders as flat facets, right angles, many through holes (high genus), pockets,
//    gears, chamfered brackets, heat-sink fins; no normals or UVs (STL has none that matter);
//  - scan-like surfaces: dense, irregular, noisy samples of smooth shapes with missing patches;
//  - multi-component scenes of primitives with per-face UV charts (seams on every edge of a box);
//  - tiny meshes (a tetrahedron, a box, a quad, an icosahedron);
//  - a skinned character (GLB: joints and weights, normals, UVs with seams);
//  - copies of the real scans of samples/scans (GLB; origin and licence in its SOURCES.md).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_util.h"
#include "common/cli_args.h"
#include "common/file_util.h"
#include "io/scene_io.h"
#include "scene/scene.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Vec2 {
  double x, y;
};

// A triangle mesh with optional per-corner UVs (OBJ "f v/vt").
struct ObjMesh {
  std::vector<float> positions;                  // 3 per vertex
  std::vector<float> uvs;                        // 2 per UV vertex
  std::vector<uint32_t> tris;                    // position index per corner
  std::vector<uint32_t> uv_tris;                 // UV index per corner (empty: no UVs)
  std::map<std::vector<float>, uint32_t> index;  // welding: one vertex per exact position

  uint32_t Vertex(double x, double y, double z) {
    const std::vector<float> key = {float(x), float(y), float(z)};
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const uint32_t id = uint32_t(positions.size() / 3);
    positions.insert(positions.end(), key.begin(), key.end());
    index.emplace(key, id);
    return id;
  }
  uint32_t Uv(double u, double v) {
    uvs.push_back(float(u));
    uvs.push_back(float(v));
    return uint32_t(uvs.size() / 2 - 1);
  }
  void Tri(uint32_t a, uint32_t b, uint32_t c) {
    if (a == b || b == c || a == c) return;
    tris.insert(tris.end(), {a, b, c});
  }

  std::string Obj() const {
    std::string s;
    char line[128];
    for (size_t i = 0; i < positions.size(); i += 3) {
      std::snprintf(line, sizeof(line), "v %.9g %.9g %.9g\n", positions[i], positions[i + 1],
                    positions[i + 2]);
      s += line;
    }
    for (size_t i = 0; i < uvs.size(); i += 2) {
      std::snprintf(line, sizeof(line), "vt %.9g %.9g\n", uvs[i], uvs[i + 1]);
      s += line;
    }
    for (size_t i = 0; i < tris.size(); i += 3) {
      if (uv_tris.empty()) {
        std::snprintf(line, sizeof(line), "f %u %u %u\n", tris[i] + 1, tris[i + 1] + 1,
                      tris[i + 2] + 1);
      } else {
        std::snprintf(line, sizeof(line), "f %u/%u %u/%u %u/%u\n", tris[i] + 1, uv_tris[i] + 1,
                      tris[i + 1] + 1, uv_tris[i + 1] + 1, tris[i + 2] + 1, uv_tris[i + 2] + 1);
      }
      s += line;
    }
    return s;
  }
};

// Deterministic pseudo-random numbers (xorshift64*), identical on every platform.
struct Rng {
  uint64_t s = 0x9E3779B97F4A7C15ull;
  explicit Rng(uint64_t seed) : s(seed * 0x9E3779B97F4A7C15ull + 1) {}
  double Uniform() {  // [0, 1)
    s ^= s >> 12;
    s ^= s << 25;
    s ^= s >> 27;
    return double((s * 0x2545F4914F6CDD1Dull) >> 11) / double(uint64_t(1) << 53);
  }
  double Range(double a, double b) { return a + (b - a) * Uniform(); }
};

// A planar region of a CAD part's top face: an outer loop and optionally one hole loop, both
// counter-clockwise and star-shaped around `center` (without a hole: fanned from its first vertex).
// `through` holes become cylinder walls to the bottom face; otherwise the hole is a pocket `depth`
// deep with a floor.
struct Cell {
  std::vector<Vec2> outer;
  std::vector<Vec2> hole;  // empty: no hole
  Vec2 center{0, 0};
  bool through = true;
  double depth = 0;
};

std::vector<Vec2> Circle(Vec2 c, double r, int segments, double phase = 0) {
  std::vector<Vec2> p;
  for (int i = 0; i < segments; ++i) {
    const double a = phase + 2 * kPi * i / segments;
    p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return p;
}

std::vector<Vec2> Rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A rounded rectangle (the outline of a milled pocket), counter-clockwise.
std::vector<Vec2> RoundedRect(double x0, double y0, double x1, double y1, double r, int arc) {
  std::vector<Vec2> p;
  const Vec2 corners[4] = {{x1 - r, y0 + r}, {x1 - r, y1 - r}, {x0 + r, y1 - r}, {x0 + r, y0 + r}};
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i <= arc; ++i) {
      const double a = -kPi / 2 + k * kPi / 2 + (kPi / 2) * i / arc;
      p.push_back({corners[k].x + r * std::cos(a), corners[k].y + r * std::sin(a)});
    }
  }
  return p;
}

double Angle(Vec2 p, Vec2 c) { return std::atan2(p.y - c.y, p.x - c.x); }

// Triangulates the ring between `outer` and `inner` (both counter-clockwise, star-shaped around
// c) as an exporter does without inner vertices: one strip that advances on whichever loop has the
// smaller next angle. Emits triangles as index triples into `out` (2D vertex ids).
void RingStrip(const std::vector<uint32_t>& outer, const std::vector<uint32_t>& inner,
               const std::vector<Vec2>& pts, Vec2 c, std::vector<uint32_t>* out) {
  auto unwrap = [&](const std::vector<uint32_t>& loop, size_t start) {
    std::vector<double> a;
    double base = Angle(pts[loop[start]], c), prev = base;
    for (size_t k = 0; k <= loop.size(); ++k) {
      double t = Angle(pts[loop[(start + k) % loop.size()]], c);
      while (t < prev - 1e-12) t += 2 * kPi;
      if (k == loop.size()) t = base + 2 * kPi;
      a.push_back(t);
      prev = t;
    }
    return a;
  };
  // Start both loops at their vertex of smallest angle.
  auto first = [&](const std::vector<uint32_t>& loop) {
    size_t best = 0;
    for (size_t k = 1; k < loop.size(); ++k) {
      if (Angle(pts[loop[k]], c) < Angle(pts[loop[best]], c)) best = k;
    }
    return best;
  };
  const size_t so = first(outer), si = first(inner);
  const std::vector<double> ao = unwrap(outer, so), ai = unwrap(inner, si);
  size_t i = 0, j = 0;
  while (i < outer.size() || j < inner.size()) {
    const uint32_t o = outer[(so + i) % outer.size()], n = inner[(si + j) % inner.size()];
    const bool advance_outer = j == inner.size() || (i < outer.size() && ao[i + 1] <= ai[j + 1]);
    if (advance_outer) {
      out->insert(out->end(), {o, outer[(so + i + 1) % outer.size()], n});
      ++i;
    } else {
      out->insert(out->end(), {o, inner[(si + j + 1) % inner.size()], n});
      ++j;
    }
  }
}

// Extrudes cells (top face at z = height, bottom at z = 0) into a closed part: top and bottom
// faces, a wall on every boundary edge of the top face, pocket walls and floors.
void ExtrudeCells(const std::vector<Cell>& cells, double height, ObjMesh* m) {
  std::vector<Vec2> pts;
  std::map<std::pair<double, double>, uint32_t> ids;
  auto id = [&](Vec2 p) {
    auto it = ids.find({p.x, p.y});
    if (it != ids.end()) return it->second;
    pts.push_back(p);
    ids.emplace(std::make_pair(p.x, p.y), uint32_t(pts.size() - 1));
    return uint32_t(pts.size() - 1);
  };
  std::vector<uint32_t> top, through_top;  // 2D triangles of the top face
  std::map<std::pair<uint32_t, uint32_t>, int> edge_use;
  struct Pocket {
    std::vector<uint32_t> loop;
    double depth;
  };
  std::vector<Pocket> pockets;
  std::vector<uint8_t> mirrored;  // per top triangle: repeated on the bottom face
  std::vector<std::vector<uint32_t>> solid_bottoms;  // outer loops of cells with a pocket
  for (const Cell& cell : cells) {
    std::vector<uint32_t> outer, inner;
    for (Vec2 p : cell.outer) outer.push_back(id(p));
    std::vector<uint32_t> tri;
    if (cell.hole.empty()) {
      for (size_t k = 1; k + 1 < outer.size(); ++k)
        tri.insert(tri.end(), {outer[0], outer[k], outer[k + 1]});
    } else {
      for (Vec2 p : cell.hole) inner.push_back(id(p));
      RingStrip(outer, inner, pts, cell.center, &tri);
      if (!cell.through) {
        pockets.push_back({inner, cell.depth});
        solid_bottoms.push_back(outer);
      }
    }
    top.insert(top.end(), tri.begin(), tri.end());
    mirrored.insert(mirrored.end(), tri.size() / 3, uint8_t(cell.hole.empty() || cell.through));
  }
  for (size_t t = 0; t < top.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = top[t + k], b = top[t + (k + 1) % 3];
      ++edge_use[{std::min(a, b), std::max(a, b)}];
    }
  }
  auto v3 = [&](uint32_t i, double z) { return m->Vertex(pts[i].x, pts[i].y, z); };
  std::map<std::pair<uint32_t, uint32_t>, double> pocket_edge;  // directed hole edge -> depth
  for (const Pocket& p : pockets) {
    for (size_t k = 0; k < p.loop.size(); ++k) {
      pocket_edge[{p.loop[k], p.loop[(k + 1) % p.loop.size()]}] = p.depth;
    }
  }
  for (size_t t = 0; t < top.size(); t += 3) {
    m->Tri(v3(top[t], height), v3(top[t + 1], height), v3(top[t + 2], height));
    bool pocket_triangle = false;
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = top[t + k], b = top[t + (k + 1) % 3];
      if (edge_use[{std::min(a, b), std::max(a, b)}] != 1) continue;
      auto pe = pocket_edge.find({b, a});
      if (pe == pocket_edge.end()) pe = pocket_edge.find({a, b});
      const double z0 = pe == pocket_edge.end() ? 0.0 : height - pe->second;
      pocket_triangle |= pe != pocket_edge.end();
      // Outward wall (material on the left of a->b).
      m->Tri(v3(a, z0), v3(b, z0), v3(b, height));
      m->Tri(v3(a, z0), v3(b, height), v3(a, height));
    }
    (void)pocket_triangle;
  }
  // Bottom face: under through holes the top face's triangulation mirrored; under a pocket the
  // bottom is whole (an exporter tessellates each face alone: no pocket outline there), the cell's
  // outer loop fanned.
  for (size_t t = 0; t < top.size(); t += 3) {
    if (mirrored[t / 3]) m->Tri(v3(top[t], 0), v3(top[t + 2], 0), v3(top[t + 1], 0));
  }
  for (const std::vector<uint32_t>& loop : solid_bottoms) {
    for (size_t k = 1; k + 1 < loop.size(); ++k) {
      m->Tri(v3(loop[0], 0), v3(loop[k + 1], 0), v3(loop[k], 0));
    }
  }
  for (const Pocket& p : pockets) {
    const double zf = height - p.depth;
    // The pocket's loop is counter-clockwise: its floor faces +z.
    for (size_t k = 1; k + 1 < p.loop.size(); ++k) {
      m->Tri(v3(p.loop[0], zf), v3(p.loop[k], zf), v3(p.loop[k + 1], zf));
    }
  }
}

// Plate of nx * ny cells, each with a round hole (through or pocket).
ObjMesh Plate(int nx, int ny, double pitch, double radius, int segments, double thickness,
              bool through, double pocket_depth = 0, bool rounded_pockets = false) {
  std::vector<Cell> cells;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      Cell c;
      const double x0 = i * pitch, y0 = j * pitch, x1 = (i + 1) * pitch, y1 = (j + 1) * pitch;
      c.outer = Rect(x0, y0, x1, y1);
      c.center = {(x0 + x1) / 2, (y0 + y1) / 2};
      if (rounded_pockets) {
        c.hole = RoundedRect(x0 + pitch * 0.12, y0 + pitch * 0.12, x1 - pitch * 0.12,
                             y1 - pitch * 0.12, pitch * 0.1, segments / 4);
      } else {
        c.hole = Circle(c.center, radius, segments, 0.3);
      }
      c.through = through;
      c.depth = pocket_depth;
      cells.push_back(c);
    }
  }
  ObjMesh m;
  ExtrudeCells(cells, thickness, &m);
  return m;
}

// Square-hole grating (very high genus).
ObjMesh Grating(int n, double pitch, double bar, double thickness) {
  std::vector<Cell> cells;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      Cell c;
      const double x0 = i * pitch, y0 = j * pitch;
      c.outer = Rect(x0, y0, x0 + pitch, y0 + pitch);
      c.center = {x0 + pitch / 2, y0 + pitch / 2};
      c.hole = Rect(x0 + bar, y0 + bar, x0 + pitch - bar, y0 + pitch - bar);
      cells.push_back(c);
    }
  }
  ObjMesh m;
  ExtrudeCells(cells, thickness, &m);
  return m;
}

// Spur gear with a bore and optional lightening holes (a ring of sector cells).
ObjMesh Gear(int teeth, double module, double bore, int lightening_holes, double width) {
  const double rp = module * teeth / 2, ra = rp + module, rf = rp - 1.25 * module;
  std::vector<Vec2> outline;
  const int flank = 5;
  for (int t = 0; t < teeth; ++t) {
    const double a0 = 2 * kPi * t / teeth, w = 2 * kPi / teeth;
    // root land, rising flank, tip land, falling flank
    outline.push_back({rf * std::cos(a0), rf * std::sin(a0)});
    for (int k = 0; k <= flank; ++k) {
      const double f = double(k) / flank, r = rf + (ra - rf) * f;
      const double a = a0 + w * (0.25 + 0.12 * f - 0.04 * f * f);
      outline.push_back({r * std::cos(a), r * std::sin(a)});
    }
    for (int k = flank; k >= 0; --k) {
      const double f = double(k) / flank, r = rf + (ra - rf) * f;
      const double a = a0 + w * (0.75 - 0.12 * f + 0.04 * f * f);
      outline.push_back({r * std::cos(a), r * std::sin(a)});
    }
  }
  std::vector<Cell> cells;
  if (lightening_holes == 0) {
    Cell c;
    c.outer = outline;
    c.hole = Circle({0, 0}, bore, 48);
    cells.push_back(c);
  } else {
    // A ring of teeth around a web circle, the web split into sectors that each hold one
    // lightening hole (the web circle's edges are shared, so they get no wall).
    const double rw = rf - 2 * module;
    const int web_seg = 16 * lightening_holes, bore_seg = 8 * lightening_holes;
    const std::vector<Vec2> web = Circle({0, 0}, rw, web_seg),
                            bore_pts = Circle({0, 0}, bore, bore_seg);
    Cell ring;
    ring.outer = outline;
    ring.hole = web;
    cells.push_back(ring);
    for (int s = 0; s < lightening_holes; ++s) {
      Cell c;
      for (int k = 0; k <= 16; ++k) c.outer.push_back(web[(s * 16 + k) % web_seg]);
      for (int k = 8; k >= 0; --k) c.outer.push_back(bore_pts[(s * 8 + k) % bore_seg]);
      const double am = 2 * kPi * (s + 0.5) / lightening_holes, rm = (bore + rw) / 2;
      c.center = {rm * std::cos(am), rm * std::sin(am)};
      c.hole = Circle(c.center, (rw - bore) * 0.3, 32);
      cells.push_back(c);
    }
  }
  ObjMesh m;
  ExtrudeCells(cells, width, &m);
  return m;
}

// L bracket (profile in x-y, extruded along z) with a chamfered outer corner and a filleted
// inner corner; each leg carries a row of round bosses' bores as pockets.
ObjMesh Bracket(double leg, double thick, double chamfer, double fillet, int arc, double length) {
  std::vector<Cell> cells(3);
  Cell& corner = cells[0];
  corner.outer = {{chamfer, 0}, {thick + fillet, 0}, {thick + fillet, thick}};
  for (int i = 1; i < arc; ++i) {  // from (thick + fillet, thick) to (thick, thick + fillet)
    const double a = -kPi / 2 - (kPi / 2) * i / arc;
    corner.outer.push_back(
        {thick + fillet + fillet * std::cos(a), thick + fillet + fillet * std::sin(a)});
  }
  corner.outer.insert(corner.outer.end(),
                      {{thick, thick + fillet}, {0, thick + fillet}, {0, chamfer}});
  cells[1].outer = Rect(thick + fillet, 0, leg, thick);
  cells[2].outer = {{0, thick + fillet}, {thick, thick + fillet}, {thick, leg}, {0, leg}};
  ObjMesh m;
  ExtrudeCells(cells, length, &m);
  return m;
}

// Stepped shaft: coaxial cylinders (flat facets, fanned caps, annular steps).
ObjMesh Shaft(int segments) {
  const double radii[] = {4, 6, 5, 8, 5, 3};
  const double lengths[] = {10, 25, 8, 4, 30, 12};
  ObjMesh m;
  double x = 0;
  for (int s = 0; s < 6; ++s) {
    std::vector<Vec2> ring = Circle({0, 0}, radii[s], segments);
    auto v = [&](int i, double xx) {
      return m.Vertex(xx, ring[i % segments].x, ring[i % segments].y);
    };
    for (int i = 0; i < segments; ++i) {
      m.Tri(v(i, x), v(i + 1, x), v(i + 1, x + lengths[s]));
      m.Tri(v(i, x), v(i + 1, x + lengths[s]), v(i, x + lengths[s]));
    }
    // Caps/steps: annulus to the neighbour's radius, or a fan at the ends.
    for (int end = 0; end < 2; ++end) {
      const double xe = end ? x + lengths[s] : x;
      const int nb = end ? s + 1 : s - 1;
      if (nb < 0 || nb > 5) {
        for (int i = 1; i + 1 < segments; ++i) {
          if (end)
            m.Tri(v(0, xe), v(i, xe), v(i + 1, xe));
          else
            m.Tri(v(0, xe), v(i + 1, xe), v(i, xe));
        }
      } else if (radii[nb] < radii[s]) {
        std::vector<Vec2> inner = Circle({0, 0}, radii[nb], segments);
        for (int i = 0; i < segments; ++i) {
          const uint32_t o0 = v(i, xe), o1 = v(i + 1, xe);
          const uint32_t i0 = m.Vertex(xe, inner[i].x, inner[i].y);
          const uint32_t i1 =
              m.Vertex(xe, inner[(i + 1) % segments].x, inner[(i + 1) % segments].y);
          if (end) {
            m.Tri(o0, o1, i1);
            m.Tri(o0, i1, i0);
          } else {
            m.Tri(o0, i1, o1);
            m.Tri(o0, i0, i1);
          }
        }
      }
    }
    x += lengths[s];
  }
  return m;
}

// Heat sink: a base plate with a row of thin fins standing on it (separate closed boxes, as
// exported bodies often are).
void Box(ObjMesh* m, double x0, double y0, double z0, double x1, double y1, double z1,
         bool uv = false) {
  const double c[8][3] = {{x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0},
                          {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {1, 2, 6, 5}, {3, 0, 4, 7}};
  for (const auto& f : faces) {
    uint32_t v[4], t[4];
    for (int k = 0; k < 4; ++k) v[k] = m->Vertex(c[f[k]][0], c[f[k]][1], c[f[k]][2]);
    if (uv) {
      const double u0 = 0.1 * (m->uvs.size() % 7), v0 = 0.1 * (m->uvs.size() % 5);
      t[0] = m->Uv(u0, v0);
      t[1] = m->Uv(u0 + 0.1, v0);
      t[2] = m->Uv(u0 + 0.1, v0 + 0.1);
      t[3] = m->Uv(u0, v0 + 0.1);
    }
    const size_t before = m->tris.size();
    m->Tri(v[0], v[1], v[2]);
    m->Tri(v[0], v[2], v[3]);
    if (uv && m->tris.size() == before + 6) {
      m->uv_tris.insert(m->uv_tris.end(), {t[0], t[1], t[2], t[0], t[2], t[3]});
    }
  }
}

ObjMesh HeatSink(int fins) {
  ObjMesh m;
  Box(&m, 0, 0, 0, fins * 3.0, 40, 4);
  for (int i = 0; i < fins; ++i) Box(&m, i * 3.0 + 1, 0, 4, i * 3.0 + 2.2, 40, 30);
  return m;
}

// A scan-like surface: a bumpy closed shape sampled on a jittered (u, v) grid with measurement
// noise, with a few missing patches (occlusions).
ObjMesh Scan(int nu, int nv, double noise, int holes, uint64_t seed, bool terrain) {
  Rng rng(seed);
  ObjMesh m;
  std::vector<uint32_t> id(size_t(nu + 1) * (nv + 1));
  std::vector<std::pair<double, double>> hole_c;
  for (int h = 0; h < holes; ++h) hole_c.push_back({rng.Range(0.1, 0.9), rng.Range(0.1, 0.9)});
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      const bool seam_u = !terrain && i == nu;
      double u = double(seam_u ? 0 : i) / nu, v = double(j) / nv;
      if (!terrain && i > 0 && i < nu) u += rng.Range(-0.3, 0.3) / nu;
      if (j > 0 && j < nv) v += rng.Range(-0.3, 0.3) / nv;
      double x, y, z;
      if (terrain) {
        x = 100 * u;
        y = 100 * v;
        z = 6 * std::sin(7 * u) * std::cos(5 * v) + 2 * std::sin(23 * u + 11 * v) +
            0.7 * std::sin(61 * u) * std::sin(47 * v);
      } else {
        const double th = 2 * kPi * u, ph = kPi * (0.02 + 0.96 * v);
        const double r = 50 * (1 + 0.15 * std::sin(3 * th) * std::sin(4 * ph) +
                               0.05 * std::sin(11 * th + 2 * ph) + 0.02 * std::sin(29 * ph));
        x = r * std::sin(ph) * std::cos(th);
        y = r * std::sin(ph) * std::sin(th);
        z = 1.4 * r * std::cos(ph);
      }
      if (seam_u) {
        id[size_t(j) * (nu + 1) + i] = id[size_t(j) * (nu + 1)];
        continue;
      }
      x += rng.Range(-noise, noise);
      y += rng.Range(-noise, noise);
      z += rng.Range(-noise, noise);
      id[size_t(j) * (nu + 1) + i] = m.Vertex(x, y, z);
    }
  }
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const double u = (i + 0.5) / nu, v = (j + 0.5) / nv;
      bool skip = false;
      for (auto& c : hole_c)
        skip |= (u - c.first) * (u - c.first) + (v - c.second) * (v - c.second) < 0.002;
      if (skip) continue;
      const uint32_t a = id[size_t(j) * (nu + 1) + i], b = id[size_t(j) * (nu + 1) + i + 1];
      const uint32_t c = id[size_t(j + 1) * (nu + 1) + i + 1], d = id[size_t(j + 1) * (nu + 1) + i];
      if ((i + j) % 3 == 0) {  // scanners' meshers flip diagonals irregularly
        m.Tri(a, b, d);
        m.Tri(b, c, d);
      } else {
        m.Tri(a, b, c);
        m.Tri(a, c, d);
      }
    }
  }
  return m;
}

// Multi-component scene of UV-mapped primitives: boxes (a UV chart per face) and cylinders
// (wrapped UVs with a seam), randomly placed.
ObjMesh Scene(int count, int segments, uint64_t seed) {
  Rng rng(seed);
  ObjMesh m;
  for (int n = 0; n < count; ++n) {
    const double x = rng.Range(-100, 100), y = rng.Range(-100, 100), z = rng.Range(0, 20);
    if (n % 3 != 2) {
      Box(&m, x, y, z, x + rng.Range(2, 20), y + rng.Range(2, 20), z + rng.Range(2, 20), true);
      continue;
    }
    const double r = rng.Range(2, 8), h = rng.Range(5, 30);
    std::vector<uint32_t> lo, hi, tlo, thi;
    for (int i = 0; i <= segments; ++i) {
      const double a = 2 * kPi * (i % segments) / segments;
      lo.push_back(m.Vertex(x + r * std::cos(a), y + r * std::sin(a), z));
      hi.push_back(m.Vertex(x + r * std::cos(a), y + r * std::sin(a), z + h));
      tlo.push_back(m.Uv(double(i) / segments, 0.5));
      thi.push_back(m.Uv(double(i) / segments, 1.0));
    }
    for (int i = 0; i < segments; ++i) {
      m.Tri(lo[i], lo[i + 1], hi[i + 1]);
      m.uv_tris.insert(m.uv_tris.end(), {tlo[i], tlo[i + 1], thi[i + 1]});
      m.Tri(lo[i], hi[i + 1], hi[i]);
      m.uv_tris.insert(m.uv_tris.end(), {tlo[i], thi[i + 1], thi[i]});
    }
    std::vector<uint32_t> cap_t;
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * kPi * i / segments;
      cap_t.push_back(m.Uv(0.25 + 0.2 * std::cos(a), 0.25 + 0.2 * std::sin(a)));
    }
    for (int i = 1; i + 1 < segments; ++i) {
      m.Tri(lo[0], lo[i + 1], lo[i]);
      m.uv_tris.insert(m.uv_tris.end(), {cap_t[0], cap_t[i + 1], cap_t[i]});
      m.Tri(hi[0], hi[i], hi[i + 1]);
      m.uv_tris.insert(m.uv_tris.end(), {cap_t[0], cap_t[i], cap_t[i + 1]});
    }
  }
  return m;
}

ObjMesh Icosahedron() {
  const double t = (1 + std::sqrt(5.0)) / 2;
  const double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  const int f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  ObjMesh m;
  uint32_t id[12];
  for (int i = 0; i < 12; ++i) id[i] = m.Vertex(v[i][0], v[i][1], v[i][2]);
  for (const auto& t3 : f) m.Tri(id[t3[0]], id[t3[1]], id[t3[2]]);
  return m;
}

// A skinned character as a DCC exporter writes it to glTF: a skeleton of 17 joints (hips, spine,
// chest, neck, head, arms, legs, feet) and a body of capped tubes along the bones (torso, head,
// arms, legs, feet), with smooth normals, a cylindrical UV map (a seam down every tube: split
// vertices) and per-vertex JOINTS_0/WEIGHTS_0 (4 slots; two joints blend over a band around each
// joint, unused slots are joint 0 with weight 0).
hullpack::Scene SkinnedCharacter() {
  struct Bone {
    const char* name;
    int parent;
    double head[3];  // bind-pose start; the tail is the first child's head (or `tail`)
    double tail[3];
  };
  const Bone bones[] = {
      {"hips", -1, {0, 0.95, 0}, {0, 1.05, 0}},
      {"spine", 0, {0, 1.05, 0}, {0, 1.3, 0}},
      {"chest", 1, {0, 1.3, 0}, {0, 1.5, 0}},
      {"neck", 2, {0, 1.5, 0}, {0, 1.6, 0}},
      {"head", 3, {0, 1.6, 0}, {0, 1.86, 0.02}},
      {"upper_arm.L", 2, {0.2, 1.45, 0}, {0.47, 1.42, -0.02}},
      {"forearm.L", 5, {0.47, 1.42, -0.02}, {0.73, 1.4, 0.02}},
      {"hand.L", 6, {0.73, 1.4, 0.02}, {0.86, 1.39, 0.03}},
      {"upper_arm.R", 2, {-0.2, 1.45, 0}, {-0.47, 1.42, -0.02}},
      {"forearm.R", 8, {-0.47, 1.42, -0.02}, {-0.73, 1.4, 0.02}},
      {"hand.R", 9, {-0.73, 1.4, 0.02}, {-0.86, 1.39, 0.03}},
      {"thigh.L", 0, {0.1, 0.95, 0}, {0.11, 0.52, 0.01}},
      {"shin.L", 11, {0.11, 0.52, 0.01}, {0.11, 0.1, -0.01}},
      {"foot.L", 12, {0.11, 0.1, -0.01}, {0.11, 0.03, 0.16}},
      {"thigh.R", 0, {-0.1, 0.95, 0}, {-0.11, 0.52, 0.01}},
      {"shin.R", 14, {-0.11, 0.52, 0.01}, {-0.11, 0.1, -0.01}},
      {"foot.R", 15, {-0.11, 0.1, -0.01}, {-0.11, 0.03, 0.16}},
  };
  constexpr int kBones = int(sizeof(bones) / sizeof(bones[0]));
  hullpack::Mesh m;
  m.name = "body";
  m.uv_sets.resize(1);
  std::vector<float>& uv = m.uv_sets[0];
  auto add = [&](const double p[3], const double n[3], double u, double v, int j0, int j1,
                 double w1) {
    for (int k = 0; k < 3; ++k) m.positions.push_back(float(p[k]));
    for (int k = 0; k < 3; ++k) m.normals.push_back(float(n[k]));
    uv.insert(uv.end(), {float(u), float(v)});
    const float b = float(w1);
    m.joints.insert(m.joints.end(), {uint16_t(j0), uint16_t(w1 > 0 ? j1 : 0), 0, 0});
    m.weights.insert(m.weights.end(), {1.0f - b, w1 > 0 ? b : 0.0f, 0, 0});
    return uint32_t(m.positions.size() / 3 - 1);
  };
  // A capped tube along the chain of bones `chain` (each the next one's parent), radius r(t) at
  // arc-length fraction t, `segments` around, a ring every `step` along; its UV chart is the
  // rectangle [u0, u0 + 0.25] x [v0, v0 + 0.25].
  auto tube = [&](std::vector<int> chain, int segments, double step, double u0, double v0,
                  auto radius) {
    std::vector<double> start_len;  // arc length at each bone's head
    double total = 0;
    for (int b : chain) {
      start_len.push_back(total);
      double d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += std::pow(bones[b].tail[k] - bones[b].head[k], 2);
      total += std::sqrt(d2);
    }
    const int rings = std::max(2, int(std::ceil(total / step)) + 1);
    const double band = 0.04;  // half-width of the blend around a joint
    std::vector<std::vector<uint32_t>> ring_ids;
    std::vector<std::array<double, 3>> axis_at;
    for (int r = 0; r < rings; ++r) {
      const double s = total * r / (rings - 1);
      size_t i = 0;
      while (i + 1 < chain.size() && s >= start_len[i + 1]) ++i;
      const Bone& bone = bones[chain[i]];
      const double len = (i + 1 < chain.size() ? start_len[i + 1] : total) - start_len[i];
      const double f = len > 0 ? (s - start_len[i]) / len : 0;
      double c[3], dir[3];
      for (int k = 0; k < 3; ++k) {
        c[k] = bone.head[k] + f * (bone.tail[k] - bone.head[k]);
        dir[k] = (bone.tail[k] - bone.head[k]) / len;
      }
      // Weights: the bone itself, blended with its child past the joint's band and with its
      // parent in the chain before it.
      int j0 = chain[i], j1 = chain[i];
      double w1 = 0;
      if (i + 1 < chain.size() && start_len[i + 1] - s < band) {
        j1 = chain[i + 1];
        w1 = 0.5 * (1 - (start_len[i + 1] - s) / band);
      } else if (i > 0 && s - start_len[i] < band) {
        j1 = chain[i - 1];
        w1 = 0.5 * (1 - (s - start_len[i]) / band);
      }
      w1 = std::round(w1 * 255) / 255;  // exporters often store 8-bit weights
      const double ref[3] = {0, 0, std::fabs(dir[2]) > 0.95 ? 0.0 : 1.0};
      const double ref2[3] = {1, 0, 0};
      const double* rr = ref[2] != 0 ? ref : ref2;
      double n1[3] = {dir[1] * rr[2] - dir[2] * rr[1], dir[2] * rr[0] - dir[0] * rr[2],
                      dir[0] * rr[1] - dir[1] * rr[0]};
      const double l1 = std::sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]);
      for (double& x : n1) x /= l1;
      const double n2[3] = {dir[1] * n1[2] - dir[2] * n1[1], dir[2] * n1[0] - dir[0] * n1[2],
                            dir[0] * n1[1] - dir[1] * n1[0]};
      const double rad = radius(s / total);
      std::vector<uint32_t> ids;
      for (int k = 0; k <= segments; ++k) {  // k == segments: the seam's split vertex
        const double a = 2 * kPi * (k % segments) / segments;
        double n[3], p[3];
        for (int q = 0; q < 3; ++q) {
          n[q] = std::cos(a) * n1[q] + std::sin(a) * n2[q];
          p[q] = c[q] + rad * n[q];
        }
        ids.push_back(add(p, n, u0 + 0.25 * k / segments, v0 + 0.25 * s / total, j0, j1, w1));
      }
      ring_ids.push_back(ids);
      axis_at.push_back({c[0], c[1], c[2]});
      if (r == 0 || r == rings - 1) {
        // A cap: a fan around the centre, normal along the axis.
        const double sign = r == 0 ? -1 : 1;
        const double n[3] = {sign * dir[0], sign * dir[1], sign * dir[2]};
        const uint32_t centre = add(c, n, u0 + 0.125, v0 + (r == 0 ? 0.0 : 0.25), j0, j1, w1);
        for (int k = 0; k < segments; ++k) {
          if (r == 0) {
            m.indices.insert(m.indices.end(), {centre, ids[k + 1], ids[k]});
          } else {
            m.indices.insert(m.indices.end(), {centre, ids[k], ids[k + 1]});
          }
        }
      }
    }
    for (int r = 0; r + 1 < rings; ++r) {
      for (int k = 0; k < segments; ++k) {
        const uint32_t a = ring_ids[r][k], b = ring_ids[r][k + 1], c = ring_ids[r + 1][k],
                       d = ring_ids[r + 1][k + 1];
        m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
      }
    }
  };
  auto profile = [](std::vector<std::pair<double, double>> knots) {
    return [knots](double t) {
      for (size_t i = 0; i + 1 < knots.size(); ++i) {
        if (t <= knots[i + 1].first) {
          const double f = (t - knots[i].first) / (knots[i + 1].first - knots[i].first);
          return knots[i].second + f * (knots[i + 1].second - knots[i].second);
        }
      }
      return knots.back().second;
    };
  };
  tube({0, 1, 2, 3}, 32, 0.015, 0, 0,
       profile({{0, 0.14}, {0.2, 0.15}, {0.45, 0.12}, {0.75, 0.17}, {0.85, 0.12}, {1, 0.06}}));
  tube({4}, 24, 0.015, 0.25, 0,
       [](double t) { return 0.03 + 0.09 * std::sqrt(std::max(0.0, std::sin(kPi * t))); });
  for (int side = 0; side < 2; ++side) {
    const int arm = 5 + 3 * side, leg = 11 + 3 * side;
    tube({arm, arm + 1, arm + 2}, 20, 0.015, 0.5, 0.25 * side,
         profile({{0, 0.055}, {0.4, 0.045}, {0.75, 0.035}, {0.85, 0.04}, {1, 0.02}}));
    tube({leg, leg + 1}, 24, 0.015, 0.75, 0.25 * side,
         profile({{0, 0.085}, {0.45, 0.06}, {0.55, 0.055}, {1, 0.04}}));
    tube({leg + 2}, 16, 0.015, 0.5, 0.5 + 0.25 * side,
         profile({{0, 0.045}, {0.5, 0.05}, {1, 0.03}}));
  }
  hullpack::Scene scene;
  scene.meshes.push_back(std::move(m));
  hullpack::Skin skin;
  skin.name = "armature";
  for (int b = 0; b < kBones; ++b) {
    hullpack::Node n;
    n.name = bones[b].name;
    n.parent = bones[b].parent;
    for (int k = 0; k < 3; ++k) {
      const double parent_head = bones[b].parent < 0 ? 0.0 : bones[bones[b].parent].head[k];
      n.local_transform[12 + k] = bones[b].head[k] - parent_head;
    }
    scene.nodes.push_back(n);
    skin.joints.push_back(b);
    hullpack::Matrix4 inverse_bind = hullpack::kIdentity;
    for (int k = 0; k < 3; ++k) inverse_bind[12 + k] = -bones[b].head[k];
    skin.inverse_bind_matrices.insert(skin.inverse_bind_matrices.end(), inverse_bind.begin(),
                                      inverse_bind.end());
  }
  for (int b = 0; b < kBones; ++b) {
    if (bones[b].parent >= 0) scene.nodes[size_t(bones[b].parent)].children.push_back(b);
  }
  skin.skeleton = 0;
  scene.skins.push_back(skin);
  hullpack::Node body;
  body.name = "character";
  body.meshes.push_back(0);
  body.skin = 0;
  scene.nodes.push_back(body);
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> operands;
  hullpack::CliArgs cli(
      "gen_bench_meshes", "OUT_FOLDER",
      "Writes the second codec benchmark set into OUT_FOLDER, for codec_bench: 23\n"
      "meshes generated in code (CAD parts as exported to STL, noisy scan-like\n"
      "surfaces, UV-mapped scenes, tiny meshes as OBJ files; a skinned character\n"
      "as GLB) and copies of the real scans of --scans (GLB).");
  std::string scans = HULLPACK_SAMPLE_SCANS;
  cli.Positional("OUT_FOLDER", &operands, 1, 1);
  cli.String("--scans", "DIR", &scans,
             "copy every .glb of DIR too (default: samples/scans of the source tree)");
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  const std::string dir = operands[0];
  {
    // The real scans (samples/scans/SOURCES.md) join the generated meshes as they are.
    std::vector<std::string> files;
    if (!hullpack::ListFiles(scans, {"glb"}, &files)) {
      std::fprintf(stderr, "gen_bench_meshes: %s: cannot open the scans folder\n", scans.c_str());
      return 1;
    }
    for (const std::string& f : files) {
      const hullpack::Result<std::vector<uint8_t>> bytes = hullpack::ReadFileBytes(scans + "/" + f);
      hullpack::Status s =
          bytes.ok() ? hullpack::WriteFileAtomically(dir + "/" + f, bytes.value()) : bytes.status();
      if (!s.ok()) {
        std::fprintf(stderr, "gen_bench_meshes: %s\n", s.message().c_str());
        return 1;
      }
      std::printf("%-24s copied from %s\n", (dir + "/" + f).c_str(), scans.c_str());
    }
  }
  std::vector<std::pair<std::string, ObjMesh>> meshes;
  meshes.emplace_back("cad_plate_4x4", Plate(4, 4, 25, 7, 32, 6, true));
  meshes.emplace_back("cad_plate_12x8", Plate(12, 8, 10, 3, 24, 4, true));
  meshes.emplace_back("cad_sheet_perf_30x20", Plate(30, 20, 5, 1.6, 16, 0.8, true));
  meshes.emplace_back("cad_plate_fine_6x6", Plate(6, 6, 20, 6, 96, 10, true));
  meshes.emplace_back("cad_grating_16", Grating(16, 10, 1.5, 3));
  meshes.emplace_back("cad_pocket_block_3x3", Plate(3, 3, 40, 0, 32, 30, false, 18, true));
  meshes.emplace_back("cad_pocket_block_8x5", Plate(8, 5, 16, 0, 16, 12, false, 8, true));
  meshes.emplace_back("cad_bored_block_5x5", Plate(5, 5, 20, 6, 40, 25, false, 12, false));
  meshes.emplace_back("cad_gear_24", Gear(24, 2, 6, 0, 12));
  meshes.emplace_back("cad_gear_80_holes", Gear(80, 1.5, 12, 8, 10));
  meshes.emplace_back("cad_bracket", Bracket(60, 6, 4, 5, 16, 40));
  meshes.emplace_back("cad_shaft", Shaft(64));
  meshes.emplace_back("cad_heat_sink", HeatSink(24));
  meshes.emplace_back("scan_bumpy_120k", Scan(300, 200, 0.08, 5, 1, false));
  meshes.emplace_back("scan_terrain_200k", Scan(320, 320, 0.05, 8, 2, true));
  meshes.emplace_back("scan_small_20k", Scan(100, 100, 0.15, 3, 3, false));
  meshes.emplace_back("scene_boxes_uv", Scene(120, 24, 4));
  meshes.emplace_back("scene_mixed_uv_fine", Scene(60, 96, 5));
  meshes.emplace_back("tiny_tetra", [] {
    ObjMesh m;
    const uint32_t a = m.Vertex(0, 0, 0), b = m.Vertex(1, 0, 0), c = m.Vertex(0, 1, 0),
                   d = m.Vertex(0, 0, 1);
    m.Tri(a, c, b);
    m.Tri(a, b, d);
    m.Tri(b, c, d);
    m.Tri(c, a, d);
    return m;
  }());
  meshes.emplace_back("tiny_box", [] {
    ObjMesh m;
    Box(&m, 0, 0, 0, 1, 2, 3);
    return m;
  }());
  meshes.emplace_back("tiny_quad_uv", [] {
    ObjMesh m;
    Box(&m, 0, 0, 0, 1, 1, 1, true);
    return m;
  }());
  meshes.emplace_back("tiny_icosahedron", Icosahedron());
  {
    // The skinned character is a glTF file: OBJ has no skins.
    const hullpack::Scene character = SkinnedCharacter();
    const std::string path = dir + "/skin_character.glb";
    const hullpack::Status s = hullpack::WriteScene(character, path);
    if (!s.ok()) {
      std::fprintf(stderr, "gen_bench_meshes: %s\n", s.message().c_str());
      return 1;
    }
    std::printf("%-24s %8zu vertices %8zu triangles\n", path.c_str(), character.vertex_count(),
                character.triangle_count());
  }
  for (const auto& [name, mesh] : meshes) {
    const std::string text = mesh.Obj();
    const std::string path = dir + "/" + name + ".obj";
    const hullpack::Status s = hullpack::WriteFileAtomically(path, text.data(), text.size());
    if (!s.ok()) {
      std::fprintf(stderr, "gen_bench_meshes: %s\n", s.message().c_str());
      return 1;
    }
    std::printf("%-24s %8zu vertices %8zu triangles\n", path.c_str(), mesh.positions.size() / 3,
                mesh.tris.size() / 3);
  }
  return 0;
}
