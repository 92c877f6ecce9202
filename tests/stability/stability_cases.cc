#include "stability_cases.h"

#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "common/test_shapes.h"

namespace hullpack::stability {
namespace {

struct Soup {
  std::vector<double> points;
  std::vector<uint32_t> indices;
  uint32_t Add(double x, double y, double z) {
    points.insert(points.end(), {x, y, z});
    return static_cast<uint32_t>(points.size() / 3 - 1);
  }
  void Tri(uint32_t a, uint32_t b, uint32_t c) { indices.insert(indices.end(), {a, b, c}); }
  void Quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) { Tri(a, b, c), Tri(a, c, d); }
  size_t point_count() const { return points.size() / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
  void Append(const Soup& other) {
    const uint32_t base = static_cast<uint32_t>(point_count());
    points.insert(points.end(), other.points.begin(), other.points.end());
    for (uint32_t i : other.indices) indices.push_back(base + i);
  }
};

// Deterministic numbers in [-1, 1] (the suite must not depend on a library's generator).
class Noise {
 public:
  double Next() {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return double(state_ >> 11) / double(uint64_t(1) << 52) - 1.0;
  }

 private:
  uint64_t state_ = 0x2545F4914F6CDD1Dull;
};

Soup FromShape(const test_shapes::Shape& shape) {
  Soup s;
  test_shapes::AppendPointsTo(shape, &s);
  return s;
}

// Closed, consistently outward-oriented torus around the z axis: rings x sides vertices.
Soup Torus(double major, double minor, int rings, int sides) {
  return FromShape(test_shapes::Torus(major, minor, rings, sides));
}

Soup DefaultTorus() { return Torus(1.0, 0.35, 32, 12); }

Soup Box(double x0, double y0, double z0, double x1, double y1, double z1, bool with_top = true) {
  return FromShape(test_shapes::Box(x0, y0, z0, x1, y1, z1, with_top));
}

// Merges points with equal coordinates (so that separately built parts share vertices).
Soup Weld(const Soup& in) {
  Soup out;
  std::map<std::tuple<double, double, double>, uint32_t> index;
  std::vector<uint32_t> remap(in.point_count());
  for (size_t i = 0; i < in.point_count(); ++i) {
    const auto key = std::make_tuple(in.points[i * 3], in.points[i * 3 + 1], in.points[i * 3 + 2]);
    auto it = index.find(key);
    if (it == index.end())
      it = index.emplace(key, out.Add(std::get<0>(key), std::get<1>(key), std::get<2>(key))).first;
    remap[i] = it->second;
  }
  for (uint32_t i : in.indices) out.indices.push_back(remap[i]);
  return out;
}

Soup Transformed(Soup s, double scale, double dx, double dy, double dz) {
  for (size_t i = 0; i < s.point_count(); ++i) {
    s.points[i * 3] = s.points[i * 3] * scale + dx;
    s.points[i * 3 + 1] = s.points[i * 3 + 1] * scale + dy;
    s.points[i * 3 + 2] = s.points[i * 3 + 2] * scale + dz;
  }
  return s;
}

Case Make(const std::string& name, const std::string& description, const Soup& s, Expect decompose,
          Expect codec, Expect pack) {
  Case c;
  c.name = name;
  c.description = description;
  c.points = s.points;
  c.indices = s.indices;
  c.decompose = decompose;
  c.codec = codec;
  c.pack = pack;
  return c;
}

constexpr Expect kOk = Expect::kOk, kError = Expect::kError, kEither = Expect::kEither;

Case Build(const std::string& name) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  if (name == "torus")
    return Make(name, "reference: closed torus, 768 triangles", DefaultTorus(), kOk, kOk, kOk);
  if (name == "scale_1e-30") {
    return Make(name, "the torus scaled by 1e-30", Transformed(DefaultTorus(), 1e-30, 0, 0, 0), kOk,
                kOk, kOk);
  }
  if (name == "scale_1e30") {
    return Make(name, "the torus scaled by 1e30", Transformed(DefaultTorus(), 1e30, 0, 0, 0), kOk,
                kOk, kOk);
  }
  if (name == "aspect_1e30_1e-30") {
    return Make(name, "closed box 1e30 x 1 x 1e-30", Box(0, 0, 0, 1e30, 1, 1e-30), kEither, kOk,
                kEither);
  }
  if (name == "float_extent_overflow") {
    return Make(name, "closed box from -3e38 to 3e38: the extent overflows float",
                Box(-3e38, -3e38, -3e38, 3e38, 3e38, 3e38), kEither, kEither, kEither);
  }
  if (name == "far_1e7_detail_1e-3") {
    // In double this is a fine torus; rounded to float (ulp 1 at 1e7) every point collapses onto
    // a few grid points, so the float stages see a degenerate mesh.
    return Make(name, "torus of size 1e-3 at (1e7, -1e7, 1e7)",
                Transformed(DefaultTorus(), 1e-3, 1e7, -1e7, 1e7), kOk, kOk, kEither);
  }
  if (name == "far_1e3_detail_1e-3") {
    return Make(name, "torus of size 1e-3 at (1e3, -1e3, 1e3) (float holds the detail)",
                Transformed(DefaultTorus(), 1e-3, 1e3, -1e3, 1e3), kOk, kOk, kOk);
  }
  if (name == "flat_box_1e-7") {
    return Make(name, "near-coplanar: closed box 1 x 1 x 1e-7", Box(0, 0, 0, 1, 1, 1e-7), kEither,
                kOk, kEither);
  }
  if (name == "near_coplanar_sheet") {
    Soup s;
    Noise noise;
    const int n = 33;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j)
        s.Add(double(i) / (n - 1), double(j) / (n - 1), 1e-9 * noise.Next());
    }
    for (int i = 0; i + 1 < n; ++i) {
      for (int j = 0; j + 1 < n; ++j)
        s.Quad(i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1);
    }
    return Make(name, "open 32 x 32 grid, z noise 1e-9", s, kEither, kOk, kEither);
  }
  if (name == "needle_1e-7") {
    return Make(name, "near-collinear: closed box 1 x 1e-7 x 1e-7", Box(0, 0, 0, 1, 1e-7, 1e-7),
                kEither, kOk, kEither);
  }
  if (name == "near_collinear_strip") {
    Soup s;
    Noise noise;
    for (int i = 0; i <= 100; ++i) s.Add(i / 100.0, 1e-9 * noise.Next(), 1e-9 * noise.Next());
    for (uint32_t i = 0; i + 2 <= 100; ++i) s.Tri(i, i + 1, i + 2);
    return Make(name, "99 triangles on points along x, off the line by 1e-9", s, kEither, kOk,
                kEither);
  }
  if (name == "slivers") {
    return Make(name, "closed torus of 4000 x 4 quads: 16000 triangles of aspect ~250",
                Torus(1.0, 0.35, 4000, 4), kOk, kOk, kOk);
  }
  if (name == "zero_area_triangles") {
    Soup s = DefaultTorus();
    const size_t t = s.triangle_count();
    for (size_t k = 0; k < t; k += 4) {
      const uint32_t a = s.indices[k * 3], b = s.indices[k * 3 + 1];
      s.Tri(a, a, b);  // repeated corner
      s.Tri(a, a, a);  // a point
      const uint32_t m = s.Add((s.points[a * 3] + s.points[b * 3]) / 2,
                               (s.points[a * 3 + 1] + s.points[b * 3 + 1]) / 2,
                               (s.points[a * 3 + 2] + s.points[b * 3 + 2]) / 2);
      s.Tri(a, m, b);  // collinear corners
    }
    return Make(name, "the torus plus 576 zero-area triangles (repeated, point-like, collinear)", s,
                kOk, kOk, kOk);
  }
  if (name == "duplicate_vertices") {
    const Soup t = DefaultTorus();
    Soup s;
    for (uint32_t i : t.indices) s.Add(t.points[i * 3], t.points[i * 3 + 1], t.points[i * 3 + 2]);
    for (uint32_t i = 0; i < t.indices.size(); ++i) s.indices.push_back(i);
    return Make(name, "the torus as a triangle soup: every corner its own vertex", s, kOk, kOk,
                kOk);
  }
  if (name == "duplicate_faces") {
    Soup s = DefaultTorus();
    const size_t t = s.triangle_count();
    for (size_t k = 0; k < t; ++k)
      s.Tri(s.indices[k * 3], s.indices[k * 3 + 1], s.indices[k * 3 + 2]);
    for (size_t k = 0; k < t; k += 3)
      s.Tri(s.indices[k * 3], s.indices[k * 3 + 2], s.indices[k * 3 + 1]);
    return Make(name, "the torus with every triangle twice and every third once more, reversed", s,
                kOk, kOk, kOk);
  }
  if (name == "t_junctions") {
    Soup s = Box(0, 0, 0, 1, 1, 1, /*with_top=*/false);
    const uint32_t m45 = s.Add(0.5, 0, 1), m57 = s.Add(1, 0.5, 1), m76 = s.Add(0.5, 1, 1),
                   m64 = s.Add(0, 0.5, 1), c = s.Add(0.5, 0.5, 1);
    s.Quad(4, m45, c, m64);
    s.Quad(m45, 5, m57, c);
    s.Quad(c, m57, 7, m76);
    s.Quad(m64, c, m76, 6);
    return Make(name, "unit box whose top is split 2 x 2: four T-junctions on its rim", s, kOk, kOk,
                kOk);
  }
  if (name == "open_box") {
    return Make(name, "unit box without its top face", Box(0, 0, 0, 1, 1, 1, /*with_top=*/false),
                kOk, kOk, kOk);
  }
  if (name == "open_torus") {
    Soup s = DefaultTorus();
    s.indices.resize(s.indices.size() - 4 * 12 * 6);  // the last 4 rings of quads
    return Make(name, "the torus with 4 of its 32 rings of quads removed (a C-shaped open tube)", s,
                kOk, kOk, kOk);
  }
  if (name == "non_manifold_edge") {
    Soup s = Box(0, 0, 0, 1, 1, 1);
    s.Append(Box(1, 1, 0, 2, 2, 1));
    return Make(name, "two unit boxes sharing one edge (4 faces on it)", Weld(s), kOk, kOk, kOk);
  }
  if (name == "non_manifold_fin") {
    Soup s = Box(0, 0, 0, 1, 1, 1);
    s.Tri(0, 3, 7);  // diagonal section: 3 faces on two of the box's edges
    s.Tri(0, 7, 4);
    const uint32_t tip = s.Add(2, 2, 0.5);
    s.Tri(3, tip, 7);  // an outside fin on edge 3-7
    return Make(name, "unit box with an inner diagonal wall and an outside fin", s, kOk, kOk, kOk);
  }
  if (name == "inconsistent_orientation") {
    Soup s = DefaultTorus();
    for (size_t k = 0; k < s.triangle_count(); k += 2)
      std::swap(s.indices[k * 3 + 1], s.indices[k * 3 + 2]);
    return Make(name, "the torus with every other triangle reversed", s, kOk, kOk, kOk);
  }
  if (name == "single_triangle") {
    Soup s;
    s.Tri(s.Add(0, 0, 0), s.Add(1, 0, 0), s.Add(0, 1, 0));
    return Make(name, "one triangle", s, kEither, kOk, kEither);
  }
  if (name == "all_points_identical") {
    Soup s;
    for (int k = 0; k < 4; ++k) s.Add(1, 2, 3);
    s.Tri(0, 1, 2), s.Tri(0, 2, 3), s.Tri(0, 3, 1), s.Tri(1, 3, 2);
    return Make(name, "a tetrahedron whose 4 points are equal", s, kError, kOk, kEither);
  }
  if (name == "nan_coordinate") {
    Soup s = DefaultTorus();
    s.points[5 * 3 + 1] = nan;
    return Make(name, "the torus with one NaN coordinate", s, kError, kError, kError);
  }
  if (name == "inf_coordinate") {
    Soup s = DefaultTorus();
    s.points[7 * 3] = inf;
    s.points[9 * 3 + 2] = -inf;
    return Make(name, "the torus with a +Inf and a -Inf coordinate", s, kError, kError, kError);
  }
  if (name == "empty")
    return Make(name, "no points, no triangles", Soup(), kError, kEither, kEither);
  if (name == "points_only") {
    Soup s = DefaultTorus();
    s.indices.clear();
    return Make(name, "the torus's points without triangles", s, kError, kOk, kEither);
  }
  if (name == "index_out_of_range") {
    Soup s = DefaultTorus();
    s.indices[10] = static_cast<uint32_t>(s.point_count());
    return Make(name, "the torus with one index equal to the point count", s, kError, kError,
                kError);
  }
  if (name == "index_uint32_max") {
    Soup s = DefaultTorus();
    s.indices[11] = 0xFFFFFFFFu;
    return Make(name, "the torus with one index 2^32 - 1", s, kError, kError, kError);
  }
  if (name == "torus_2m") {
    return Make(name, "closed torus of 1000 x 1000 quads: 2,000,000 triangles, 1,000,000 points",
                Torus(1.0, 0.35, 1000, 1000), kOk, kOk, kOk);
  }
  return Case();
}

}  // namespace

std::vector<std::string> CaseNames(bool heavy) {
  if (heavy) return {"torus_2m"};
  return {"torus",
          "scale_1e-30",
          "scale_1e30",
          "aspect_1e30_1e-30",
          "float_extent_overflow",
          "far_1e7_detail_1e-3",
          "far_1e3_detail_1e-3",
          "flat_box_1e-7",
          "near_coplanar_sheet",
          "needle_1e-7",
          "near_collinear_strip",
          "slivers",
          "zero_area_triangles",
          "duplicate_vertices",
          "duplicate_faces",
          "t_junctions",
          "open_box",
          "open_torus",
          "non_manifold_edge",
          "non_manifold_fin",
          "inconsistent_orientation",
          "single_triangle",
          "all_points_identical",
          "nan_coordinate",
          "inf_coordinate",
          "empty",
          "points_only",
          "index_out_of_range",
          "index_uint32_max"};
}

Case MakeCase(const std::string& name) { return Build(name); }

}  // namespace hullpack::stability
