#include "io/wrl_format.h"

#include <cstring>

#include "io/text_scanner.h"
#include "io/text_writer.h"

namespace hullpack {
namespace {

// A distinct, deterministic colour per shape (golden-ratio hue walk).
void ShapeColor(size_t i, float rgb[3]) {
  const double h = static_cast<double>(i) * 0.6180339887498949;
  const double f = (h - static_cast<int64_t>(h)) * 6.0;
  const int sector = static_cast<int>(f);
  const float x = static_cast<float>(f - sector);
  const float table[6][3] = {{1, x, 0},     {1 - x, 1, 0}, {0, 1, x},
                             {0, 1 - x, 1}, {x, 0, 1},     {1, 0, 1 - x}};
  for (int k = 0; k < 3; ++k) rgb[k] = 0.25f + 0.7f * table[sector % 6][k];
}

}  // namespace

std::string EncodeWrl(const Scene& scene) {
  TextWriter w;
  w << "#VRML V2.0 utf8\n# written by hullpack\n";
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    const Mesh& m = scene.meshes[mi];
    float rgb[3];
    ShapeColor(mi, rgb);
    w << "DEF "
      << "shape_" << static_cast<uint64_t>(mi) << " Shape {\n"
      << "  appearance Appearance {\n    material Material {\n      diffuseColor " << rgb[0] << ' '
      << rgb[1] << ' ' << rgb[2] << "\n      transparency 0.5\n    }\n  }\n"
      << "  geometry IndexedFaceSet {\n    ccw TRUE\n    solid TRUE\n    convex TRUE\n"
      << "    coord Coordinate {\n      point [\n";
    for (size_t i = 0; i < m.vertex_count(); ++i) {
      w << "        " << m.positions[i * 3] << ' ' << m.positions[i * 3 + 1] << ' '
        << m.positions[i * 3 + 2] << ",\n";
    }
    w << "      ]\n    }\n    coordIndex [\n";
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      w << "      " << m.indices[t * 3] << ", " << m.indices[t * 3 + 1] << ", "
        << m.indices[t * 3 + 2] << ", -1,\n";
    }
    w << "    ]\n  }\n}\n";
  }
  return std::move(w.str());
}

Result<Scene> ParseWrl(const char* data, size_t size, const std::string& name) {
  TextScanner s(data, data + size);
  auto error = [&](const std::string& what) {
    return Status(StatusCode::kParseError,
                  name + ": line " + std::to_string(s.line()) + ": " + what);
  };
  if (size < 10 || std::strncmp(data, "#VRML V2.0", 10) != 0)
    return error("missing '#VRML V2.0' header");
  if (std::memchr(data, '\0', size) != nullptr)
    return error("binary data (NUL byte): not a VRML file");
  Scene scene;
  Mesh mesh;
  bool have_points = false;
  auto finish_mesh = [&]() -> Status {
    if (!have_points) return Status::Ok();
    for (uint32_t i : mesh.indices) {
      if (i >= mesh.vertex_count()) {
        return error("coordIndex " + std::to_string(i) + " out of range (" +
                     std::to_string(mesh.vertex_count()) + " points)");
      }
    }
    scene.source_vertex_records += mesh.vertex_count();
    scene.meshes.push_back(std::move(mesh));
    mesh = Mesh();
    have_points = false;
    return Status::Ok();
  };
  size_t short_faces = 0;
  while (!s.AtEnd()) {
    s.SkipWhitespace(true);
    if (s.AtEnd()) break;
    const std::string_view word = s.Word();
    if (word.empty()) {
      s.Advance();  // a lone delimiter such as '{' or '['
      continue;
    }
    const bool is_point = word == "point";
    const bool is_index = word == "coordIndex";
    if (!is_point && !is_index) continue;
    s.SkipWhitespace(true);
    if (!s.Consume('[')) return error(std::string(word) + " without '['");
    if (is_point) {
      Status st = finish_mesh();  // a new Coordinate node starts a new shape
      if (!st.ok()) return st;
      have_points = true;
      for (;;) {
        s.SkipWhitespace(true);
        if (s.Consume(']')) break;
        if (s.AtEnd()) return error("unterminated point list (truncated file?)");
        double v;
        if (!s.ParseDouble(&v)) return error("malformed number in point list");
        mesh.positions.push_back(static_cast<float>(v));
      }
      if (mesh.positions.size() % 3 != 0) return error("point list length is not a multiple of 3");
    } else {
      if (!have_points) return error("coordIndex before any point list");
      std::vector<uint32_t> polygon;
      for (;;) {
        s.SkipWhitespace(true);
        if (s.AtEnd()) return error("unterminated coordIndex list (truncated file?)");
        const bool closing = s.Consume(']');
        int64_t index = -1;
        if (!closing && !s.ParseInt64(&index)) return error("malformed coordIndex");
        if (index >= 0) {
          if (index > 0xFFFFFFFELL) return error("coordIndex out of range");
          polygon.push_back(static_cast<uint32_t>(index));
          continue;
        }
        if (!polygon.empty()) {
          if (polygon.size() < 3) ++short_faces;
          for (size_t k = 1; k + 1 < polygon.size(); ++k) {
            mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[k], polygon[k + 1]});
          }
          polygon.clear();
        }
        if (closing) break;
      }
    }
  }
  Status st = finish_mesh();
  if (!st.ok()) return st;
  if (short_faces)
    scene.dropped.push_back(std::to_string(short_faces) +
                            " faces with fewer than 3 corners not kept");
  AddRootNodeForAllMeshes(scene, name);
  return scene;
}

}  // namespace hullpack
