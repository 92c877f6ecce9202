#include "shape_gen.h"

#include <cmath>
#include <cstdio>
#include <utility>

namespace hullpack {
namespace shapes {

namespace {

const double kPi = 3.14159265358979323846;

struct RZ {
  double r, z;
};

// Surface of revolution of a polyline profile (radius, height) around the z axis through (cx, cy).
// A profile traversed outward along a bottom and then up a wall faces outward; profile points on
// the axis (r == 0) become one pole vertex.
ShapeMesh Revolve(const std::vector<RZ>& profile, double cx, double cy, int segments) {
  ShapeMesh m;
  std::vector<std::vector<uint32_t>> ring(profile.size());
  for (size_t k = 0; k < profile.size(); ++k) {
    if (profile[k].r == 0.0) {
      ring[k].assign(segments, m.AddPoint(cx, cy, profile[k].z));
      continue;
    }
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * kPi * i / segments;
      ring[k].push_back(m.AddPoint(cx + profile[k].r * std::cos(a), cy + profile[k].r * std::sin(a),
                                   profile[k].z));
    }
  }
  for (size_t k = 0; k + 1 < profile.size(); ++k)
    for (int i = 0; i < segments; ++i) {
      const int j = (i + 1) % segments;
      const uint32_t a = ring[k][i], b = ring[k][j], c = ring[k + 1][j], d = ring[k + 1][i];
      if (a != b && a != c) m.AddTriangle(a, b, c);
      if (a != c && c != d) m.AddTriangle(a, c, d);
    }
  return m;
}

// (x, y, z) -> (x, z, y) about the point (0, 0, 0): a reflection, so the faces are reversed too.
void SwapYZ(ShapeMesh* m) {
  for (size_t i = 0; i < m->points.size(); i += 3) std::swap(m->points[i + 1], m->points[i + 2]);
  for (size_t t = 0; t < m->indices.size(); t += 3) std::swap(m->indices[t + 1], m->indices[t + 2]);
}

void Translate(ShapeMesh* m, double x, double y, double z) {
  for (size_t i = 0; i < m->points.size(); i += 3) {
    m->points[i] += x;
    m->points[i + 1] += y;
    m->points[i + 2] += z;
  }
}

// A grid of n x n quads from corner o along u and v (faces toward u x v).
void AddGrid(ShapeMesh* m, const double o[3], const double u[3], const double v[3], int n) {
  std::vector<uint32_t> id((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
      id[j * (n + 1) + i] = m->AddPoint(o[0] + s * u[0] + t * v[0], o[1] + s * u[1] + t * v[1],
                                        o[2] + s * u[2] + t * v[2]);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m->AddQuad(id[j * (n + 1) + i], id[j * (n + 1) + i + 1], id[(j + 1) * (n + 1) + i + 1],
                 id[(j + 1) * (n + 1) + i]);
}

}  // namespace

uint32_t ShapeMesh::AddPoint(double x, double y, double z) {
  points.insert(points.end(), {x, y, z});
  return static_cast<uint32_t>(point_count() - 1);
}

void ShapeMesh::AddTriangle(uint32_t a, uint32_t b, uint32_t c) {
  indices.insert(indices.end(), {a, b, c});
}

void ShapeMesh::AddQuad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  AddTriangle(a, b, c);
  AddTriangle(a, c, d);
}

void ShapeMesh::Append(const ShapeMesh& other) {
  const uint32_t base = static_cast<uint32_t>(point_count());
  points.insert(points.end(), other.points.begin(), other.points.end());
  for (uint32_t i : other.indices) indices.push_back(base + i);
}

void ShapeMesh::AddBackFaces() {
  ShapeMesh back = *this;
  for (size_t t = 0; t < back.indices.size(); t += 3)
    std::swap(back.indices[t + 1], back.indices[t + 2]);
  Append(back);
}

ShapeMesh Box(double x0, double y0, double z0, double x1, double y1, double z1) {
  ShapeMesh m;
  uint32_t v[8];
  for (int i = 0; i < 8; ++i) v[i] = m.AddPoint(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
  m.AddQuad(v[0], v[2], v[3], v[1]);
  m.AddQuad(v[4], v[5], v[7], v[6]);
  m.AddQuad(v[0], v[1], v[5], v[4]);
  m.AddQuad(v[2], v[6], v[7], v[3]);
  m.AddQuad(v[0], v[4], v[6], v[2]);
  m.AddQuad(v[1], v[3], v[7], v[5]);
  return m;
}

ShapeMesh Cylinder(double cx, double cy, double r, double z0, double z1, int segments) {
  return Revolve({{0, z0}, {r, z0}, {r, z1}, {0, z1}}, cx, cy, segments);
}

ShapeMesh Ring(double cx, double cy, double ri, double ro, double z0, double z1, int segments) {
  return Revolve({{ri, z0}, {ro, z0}, {ro, z1}, {ri, z1}, {ri, z0}}, cx, cy, segments);
}

ShapeMesh OpenPot(double r, double h, int segments) {
  std::vector<RZ> profile = {{0, 0}};
  for (int k = 1; k <= 4; ++k) profile.push_back({r * k / 4.0, 0});
  for (int k = 1; k <= 6; ++k) profile.push_back({r, h * k / 6.0});
  ShapeMesh m = Revolve(profile, 0, 0, segments);
  m.Append(Box(r - 0.02 * r, -0.12 * r, 0.72 * h, r + 0.3 * r, 0.12 * r, 0.82 * h));
  m.Append(Box(-r - 0.3 * r, -0.12 * r, 0.72 * h, -r + 0.02 * r, 0.12 * r, 0.82 * h));
  return m;
}

ShapeMesh Cup(double rb, double rt, double h, int segments) {
  std::vector<RZ> profile = {{0, 0}};
  for (int k = 1; k <= 3; ++k) profile.push_back({rb * k / 3.0, 0});
  for (int k = 1; k <= 8; ++k) profile.push_back({rb + (rt - rb) * k / 8.0, h * k / 8.0});
  ShapeMesh m = Revolve(profile, 0, 0, segments);
  // Handle: a ring in the xz plane beside the wall.
  const double hr = 0.3 * h;
  ShapeMesh handle = Ring(0, 0, 0.7 * hr, hr, -0.08 * rt, 0.08 * rt, segments / 2);
  SwapYZ(&handle);
  Translate(&handle, 0.5 * (rb + rt) + 0.85 * hr, 0, 0.55 * h);
  m.Append(handle);
  return m;
}

ShapeMesh LidlessBox(double w, double d, double h, int n) {
  ShapeMesh m;
  const double o0[3] = {0, 0, 0}, ux[3] = {w, 0, 0}, uy[3] = {0, d, 0}, uz[3] = {0, 0, h};
  AddGrid(&m, o0, uy, ux, n);  // bottom, facing -z
  AddGrid(&m, o0, ux, uz, n);  // y = 0, facing -y
  const double oy[3] = {0, d, 0};
  AddGrid(&m, oy, uz, ux, n);  // y = d, facing +y
  AddGrid(&m, o0, uz, uy, n);  // x = 0, facing -x
  const double ox[3] = {w, 0, 0};
  AddGrid(&m, ox, uy, uz, n);  // x = w, facing +x
  return m;
}

ShapeMesh SphereWithHole(double r, double hole_angle, int segments) {
  std::vector<RZ> profile;
  const int rows = segments / 2;
  for (int k = 0; k <= rows; ++k) {
    const double t = hole_angle + (kPi - hole_angle) * k / rows;
    profile.push_back({k == rows ? 0.0 : r * std::sin(t), -r * std::cos(t)});
  }
  return Revolve(profile, 0, 0, segments);
}

ShapeMesh PlateWithHoles() {
  ShapeMesh m;
  // A 4 x 3 plate with a square hole [0.6, 1.6] x [1, 2] and a round bore at (3, 1.5) in a boss.
  m.Append(Box(0, 0, 0, 4, 1, 0.3));
  m.Append(Box(0, 2, 0, 4, 3, 0.3));
  m.Append(Box(0, 1, 0, 0.6, 2, 0.3));
  m.Append(Box(1.6, 1, 0, 2.4, 2, 0.3));
  m.Append(Box(3.6, 1, 0, 4, 2, 0.3));
  m.Append(Ring(3, 1.5, 0.3, 0.62, 0, 0.9, 48));
  // Two pins.
  m.Append(Cylinder(0.3, 0.3, 0.15, 0.3, 1.2, 24));
  m.Append(Cylinder(3.7, 2.7, 0.15, 0.3, 1.2, 24));
  return m;
}

ShapeMesh BearingBlock() {
  ShapeMesh m = Box(-2, -1, 0, 2, 1, 0.5);
  m.Append(Box(-1, -0.8, 0.5, 1, 0.8, 1.0));
  ShapeMesh housing = Ring(0, 0, 0.5, 1.0, -0.8, 0.8, 64);  // axis along z, then turned to y
  SwapYZ(&housing);
  Translate(&housing, 0, 0, 1.5);
  m.Append(housing);
  m.Append(Ring(-1.5, 0, 0.15, 0.3, 0, 0.6, 24));  // bolt bosses with holes
  m.Append(Ring(1.5, 0, 0.15, 0.3, 0, 0.6, 24));
  return m;
}

ShapeMesh GearTrain() {
  ShapeMesh m = Box(0, -1.2, 0, 6.5, 1.2, 0.4);
  const double cx[2] = {1.6, 4.4}, rg[2] = {1.1, 1.4};
  const int teeth[2] = {14, 18};
  for (int g = 0; g < 2; ++g) {
    m.Append(Cylinder(cx[g], 0, 0.2, 0.4, 3.0, 24));
    m.Append(Box(cx[g] - 0.4, -0.4, 0.4, cx[g] + 0.4, 0.4, 1.0));  // bearing pedestal
    m.Append(Cylinder(cx[g], 0, rg[g], 2.0, 2.4, 64));
    for (int t = 0; t < teeth[g]; ++t) {
      const double a = 2 * kPi * (t + 0.5 * g) / teeth[g];
      m.Append(Cylinder(cx[g] + rg[g] * std::cos(a), rg[g] * std::sin(a), 0.12, 2.0, 2.4, 12));
    }
  }
  return m;
}

std::vector<NamedShape> BenchmarkShapes() {
  std::vector<NamedShape> out;
  out.push_back({"gen_pot_single", OpenPot(1.0, 1.2, 64)});
  out.push_back({"gen_pot_double", OpenPot(1.0, 0.9, 64)});
  out.back().mesh.AddBackFaces();
  out.push_back({"gen_cup_single", Cup(0.6, 0.8, 1.7, 48)});
  out.push_back({"gen_cup_double", Cup(0.7, 0.9, 1.4, 48)});
  out.back().mesh.AddBackFaces();
  out.push_back({"gen_box_open_single", LidlessBox(2.0, 1.4, 1.0, 8)});
  out.push_back({"gen_box_open_double", LidlessBox(1.5, 1.5, 0.8, 8)});
  out.back().mesh.AddBackFaces();
  out.push_back({"gen_plate_holes", PlateWithHoles()});
  out.push_back({"gen_bearing_block", BearingBlock()});
  out.push_back({"gen_gear_train", GearTrain()});
  out.push_back({"gen_blob_small_hole", SphereWithHole(1.0, 0.22, 48)});
  return out;
}

ShapeMesh StarPrism(const std::vector<double>& xy, double cx, double cy, double z0, double z1) {
  ShapeMesh m;
  const uint32_t n = static_cast<uint32_t>(xy.size() / 2);
  for (uint32_t i = 0; i < n; ++i) m.AddPoint(xy[2 * i], xy[2 * i + 1], z0);
  for (uint32_t i = 0; i < n; ++i) m.AddPoint(xy[2 * i], xy[2 * i + 1], z1);
  const uint32_t bottom = m.AddPoint(cx, cy, z0), top = m.AddPoint(cx, cy, z1);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t j = (i + 1) % n;
    m.AddTriangle(bottom, j, i);
    m.AddTriangle(top, n + i, n + j);
    m.AddQuad(i, j, n + j, n + i);
  }
  return m;
}

ShapeMesh Rotated(ShapeMesh mesh, double ax, double az) {
  const double kDeg = 3.14159265358979323846 / 180.0;
  const double cx = std::cos(ax * kDeg), sx = std::sin(ax * kDeg);
  const double cz = std::cos(az * kDeg), sz = std::sin(az * kDeg);
  for (size_t i = 0; i < mesh.points.size(); i += 3) {
    const double x = mesh.points[i], y = mesh.points[i + 1], z = mesh.points[i + 2];
    const double y1 = cx * y - sx * z, z1 = sx * y + cx * z;
    mesh.points[i] = cz * x - sz * y1;
    mesh.points[i + 1] = sz * x + cz * y1;
    mesh.points[i + 2] = z1;
  }
  return mesh;
}

std::vector<NamedShape> RotatedShapes() {
  // Arms 1 thick; the L's arms 3 long, the T's bar 4 wide, the cross 3 x 3.
  const std::vector<double> l = {0, 0, 3, 0, 3, 1, 1, 1, 1, 3, 0, 3};
  const std::vector<double> t = {-0.5, 0, 0.5, 0, 0.5, 2, 2, 2, 2, 3, -2, 3, -2, 2, -0.5, 2};
  const std::vector<double> cross = {-0.5, -1.5, 0.5,  -1.5, 0.5,  -0.5, 1.5,  -0.5,
                                     1.5,  0.5,  0.5,  0.5,  0.5,  1.5,  -0.5, 1.5,
                                     -0.5, 0.5,  -1.5, 0.5,  -1.5, -0.5, -0.5, -0.5};
  const double c60 = 0.5, s60 = std::sqrt(0.75);
  // Two arms 3 long and 1 thick from the origin, along x and at 60 degrees from it.
  const std::vector<double> v = {
      0, 0, 3, 0, 3, 1, c60 / s60, 1, 3 * c60, 3 * s60, 3 * c60 - s60, 3 * s60 + c60, -s60, c60};
  std::vector<NamedShape> out;
  out.push_back({"rot_l_30_45", Rotated(StarPrism(l, 0.5, 0.5, 0, 1), 30, 45)});
  out.push_back({"rot_l_45_30", Rotated(StarPrism(l, 0.5, 0.5, 0, 1), 45, 30)});
  out.push_back({"rot_t_30_45", Rotated(StarPrism(t, 0, 2.5, 0, 1), 30, 45)});
  out.push_back({"rot_cross_45_30", Rotated(StarPrism(cross, 0, 0, 0, 1), 45, 30)});
  out.push_back({"v_60", StarPrism(v, 0.1, 0.5, 0, 1)});
  return out;
}

bool WriteObj(const std::string& path, const ShapeMesh& mesh) {
  const std::string tmp = path + ".tmp";
  FILE* f = std::fopen(tmp.c_str(), "w");
  if (f == nullptr) return false;
  for (size_t i = 0; i < mesh.points.size(); i += 3)
    std::fprintf(f, "v %.17g %.17g %.17g\n", mesh.points[i], mesh.points[i + 1],
                 mesh.points[i + 2]);
  for (size_t t = 0; t < mesh.indices.size(); t += 3)
    std::fprintf(f, "f %u %u %u\n", mesh.indices[t] + 1, mesh.indices[t + 1] + 1,
                 mesh.indices[t + 2] + 1);
  if (std::fclose(f) != 0) return false;
  return std::rename(tmp.c_str(), path.c_str()) == 0;
}

}  // namespace shapes
}  // namespace hullpack
