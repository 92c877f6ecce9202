#include "common/test_shapes.h"

#include <cmath>

namespace test_shapes {
namespace {

constexpr double kPi = 3.14159265358979323846;

void AddVertex(Shape* s, double x, double y, double z) {
  s->positions.push_back(x);
  s->positions.push_back(y);
  s->positions.push_back(z);
}

void AddQuad(Shape* s, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  s->triangles.insert(s->triangles.end(), {a, b, c, a, c, d});
}

}  // namespace

Shape Torus(double major, double minor, int rings, int sides, double cx) {
  Shape s;
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      const double u = 2 * kPi * i / rings, v = 2 * kPi * j / sides;
      const double d = major + minor * std::cos(v);
      AddVertex(&s, cx + d * std::cos(u), d * std::sin(u), minor * std::sin(v));
      s.normals.insert(s.normals.end(),
                       {std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)});
    }
  }
  auto at = [&](int i, int j) { return static_cast<uint32_t>((i % rings) * sides + (j % sides)); };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j)
      AddQuad(&s, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  }
  return s;
}

Shape Box(double x0, double y0, double z0, double x1, double y1, double z1, bool with_top) {
  static constexpr uint32_t kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                            {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  Shape s;
  for (int k = 0; k < 8; ++k) AddVertex(&s, k & 1 ? x1 : x0, k & 2 ? y1 : y0, k & 4 ? z1 : z0);
  for (int f = 0; f < 6; ++f) {
    if (f == 1 && !with_top) continue;
    AddQuad(&s, kFaces[f][0], kFaces[f][1], kFaces[f][2], kFaces[f][3]);
  }
  return s;
}

Shape Sphere(double radius, int slices, int stacks,
             const std::function<bool(int row, int slice)>& skip) {
  Shape s;
  AddVertex(&s, 0, 0, -radius);
  s.normals.insert(s.normals.end(), {0, 0, -1});
  for (int j = 1; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const double th = kPi * j / stacks, ph = 2 * kPi * i / slices;
      AddVertex(&s, radius * std::sin(th) * std::cos(ph), radius * std::sin(th) * std::sin(ph),
                -radius * std::cos(th));
      s.normals.insert(s.normals.end(),
                       {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), -std::cos(th)});
    }
  }
  AddVertex(&s, 0, 0, radius);
  s.normals.insert(s.normals.end(), {0, 0, 1});
  const uint32_t north = static_cast<uint32_t>(s.vertex_count() - 1);
  auto ring = [&](int j, int i) {
    return static_cast<uint32_t>(1 + (j - 1) * slices + (i % slices));
  };
  auto kept = [&](int row, int slice) { return !skip || !skip(row, slice); };
  for (int i = 0; i < slices; ++i) {
    if (kept(1, i)) s.triangles.insert(s.triangles.end(), {0, ring(1, i + 1), ring(1, i)});
    if (kept(stacks, i)) {
      s.triangles.insert(s.triangles.end(), {north, ring(stacks - 1, i), ring(stacks - 1, i + 1)});
    }
  }
  for (int j = 1; j + 1 < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      if (kept(j + 1, i))
        AddQuad(&s, ring(j, i), ring(j, i + 1), ring(j + 1, i + 1), ring(j + 1, i));
    }
  }
  return s;
}

Shape Grid(int nx, int ny) {
  Shape s;
  for (int y = 0; y <= ny; ++y) {
    for (int x = 0; x <= nx; ++x) {
      AddVertex(&s, x, y, 0);
      s.normals.insert(s.normals.end(), {0, 0, 1});
    }
  }
  const uint32_t row = static_cast<uint32_t>(nx + 1);
  for (uint32_t y = 0; y < static_cast<uint32_t>(ny); ++y) {
    for (uint32_t x = 0; x < static_cast<uint32_t>(nx); ++x) {
      const uint32_t a = y * row + x, b = a + 1, c = a + row, d = c + 1;
      s.triangles.insert(s.triangles.end(), {a, b, d, a, d, c});
    }
  }
  return s;
}

}  // namespace test_shapes
