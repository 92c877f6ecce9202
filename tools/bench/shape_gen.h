// Generated benchmark and test shapes of kinds a scanned-object corpus lacks: thin open containers
// (single-sided, or double-sided as two coincident layers of faces), CAD parts with through holes,
// multi-component machinery, and a closed blob with a small hole (a scan open at its base).
#ifndef HULLPACK_TOOLS_BENCH_SHAPE_GEN_H_
#define HULLPACK_TOOLS_BENCH_SHAPE_GEN_H_

#include <cstdint>
#include <string>
#include <vector>

namespace hullpack {
namespace shapes {

struct ShapeMesh {
  std::vector<double> points;     // xyz
  std::vector<uint32_t> indices;  // 3 per triangle, counter-clockwise seen from outside

  size_t point_count() const { return points.size() / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
  uint32_t AddPoint(double x, double y, double z);
  void AddTriangle(uint32_t a, uint32_t b, uint32_t c);
  void AddQuad(uint32_t a, uint32_t b, uint32_t c, uint32_t d);
  void Append(const ShapeMesh& other);
  // Every face again, reversed, on its own copy of the vertices: a double-sided shell whose two
  // layers coincide.
  void AddBackFaces();
};

// Closed box [x0, x1] x [y0, y1] x [z0, z1].
ShapeMesh Box(double x0, double y0, double z0, double x1, double y1, double z1);
// Closed cylinder along z, centre (cx, cy), from z0 to z1.
ShapeMesh Cylinder(double cx, double cy, double r, double z0, double z1, int segments);
// Closed ring along z (a washer or a tube): inner radius ri, outer ro.
ShapeMesh Ring(double cx, double cy, double ri, double ro, double z0, double z1, int segments);
// An open pot: a cylindrical wall of radius r and height h on a flat bottom, open at the top, with
// two solid handles. One layer of faces (single-sided).
ShapeMesh OpenPot(double r, double h, int segments);
// A cup: a tapered open wall (bottom radius rb, top radius rt, height h) on a flat bottom, one
// layer, with a closed ring handle.
ShapeMesh Cup(double rb, double rt, double h, int segments);
// A box without a lid: 5 walls of w x d x h, each split into n x n quads, one layer.
ShapeMesh LidlessBox(double w, double d, double h, int n);
// A UV sphere of radius r with the cap within `hole_angle` radians of the -z pole left open.
ShapeMesh SphereWithHole(double r, double hole_angle, int segments);
// CAD-like parts: a plate with square and round through holes (closed, overlapping components); a
// flanged bearing block with a bore.
ShapeMesh PlateWithHoles();
ShapeMesh BearingBlock();
// Machinery: a base with two shafts carrying gears (touching and overlapping closed components).
ShapeMesh GearTrain();

// A closed prism along z from z0 to z1 over a polygon (xy, counter-clockwise) that is star-shaped
// about (cx, cy): an L, a T, a cross.
ShapeMesh StarPrism(const std::vector<double>& xy, double cx, double cy, double z0, double z1);
// The mesh rotated by ax degrees about x, then by az degrees about z.
ShapeMesh Rotated(ShapeMesh mesh, double ax, double az);

struct NamedShape {
  std::string name;
  ShapeMesh mesh;
};
// The benchmark set written by vhacd_meshgen.
std::vector<NamedShape> BenchmarkShapes();

// Shapes whose natural cuts are not along the grid axes: L, T and cross profiles rotated about
// two axes, and a V of two arms at 60 degrees (vhacd_meshgen --rotated).
std::vector<NamedShape> RotatedShapes();

// Plain OBJ (v and f lines). False when the file cannot be written.
bool WriteObj(const std::string& path, const ShapeMesh& mesh);

}  // namespace shapes
}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_SHAPE_GEN_H_
