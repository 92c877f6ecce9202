#include "io/off_format.h"

#include <cstring>

#include "io/text_scanner.h"
#include "io/text_writer.h"

namespace hullpack {

Result<Scene> ParseOff(const char* data, size_t size, const std::string& name) {
  TextScanner s(data, data + size);
  auto error = [&](const std::string& what) {
    return Status(StatusCode::kParseError,
                  name + ": line " + std::to_string(s.line()) + ": " + what);
  };
  if (std::memchr(data, '\0', size) != nullptr)
    return error("binary data (NUL byte): not an OFF file");
  s.SkipWhitespace(true);
  const std::string_view magic = s.Word();
  bool colors = false;
  if (magic == "COFF") {
    colors = true;
  } else if (magic != "OFF") {
    return error("missing OFF header (the file starts with '" + std::string(magic.substr(0, 16)) +
                 "')");
  }
  int64_t nv = 0, nf = 0, ne = 0;
  s.SkipWhitespace(true);
  if (!s.ParseInt64(&nv)) return error("missing vertex count");
  s.SkipWhitespace(true);
  if (!s.ParseInt64(&nf)) return error("missing face count");
  s.SkipWhitespace(true);
  if (!s.ParseInt64(&ne)) return error("missing edge count");
  // Each vertex needs at least 6 bytes ("0 0 0\n") and each face 8: bound the allocations by the
  // file.
  if (nv < 0 || nf < 0 || static_cast<uint64_t>(nv) > size / 6 ||
      static_cast<uint64_t>(nf) > size / 8) {
    return error("vertex/face counts " + std::to_string(nv) + "/" + std::to_string(nf) +
                 " do not fit in a file of " + std::to_string(size) + " bytes");
  }
  Scene scene;
  Mesh mesh;
  mesh.positions.resize(static_cast<size_t>(nv) * 3);
  if (colors) mesh.colors.resize(static_cast<size_t>(nv) * 4, 1.0f);
  for (int64_t i = 0; i < nv; ++i) {
    for (int k = 0; k < (colors ? 7 : 3); ++k) {
      double v;
      s.SkipWhitespace(true);
      if (!s.ParseDouble(&v)) {
        return error("vertex " + std::to_string(i) + " of " + std::to_string(nv) +
                     " is malformed or missing (truncated file?)");
      }
      if (k < 3) {
        mesh.positions[i * 3 + k] = static_cast<float>(v);
      } else {
        // COFF colours are 0..255 integers or 0..1 floats; normalize the former.
        mesh.colors[i * 4 + (k - 3)] = static_cast<float>(v > 1.0 ? v / 255.0 : v);
      }
    }
  }
  size_t short_faces = 0;
  std::vector<uint32_t> polygon;
  for (int64_t f = 0; f < nf; ++f) {
    int64_t count;
    s.SkipWhitespace(true);
    if (!s.ParseInt64(&count) || count < 0 || count > nv + 2) {
      return error("face " + std::to_string(f) + " of " + std::to_string(nf) +
                   " is malformed or missing (truncated file?)");
    }
    polygon.clear();
    for (int64_t k = 0; k < count; ++k) {
      int64_t index;
      s.SkipBlanks();
      if (!s.ParseInt64(&index)) return error("face " + std::to_string(f) + " is truncated");
      if (index < 0 || index >= nv) {
        return error("face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                     " of " + std::to_string(nv));
      }
      polygon.push_back(static_cast<uint32_t>(index));
    }
    s.SkipLine();  // per-face colours are not kept
    if (polygon.size() < 3) {
      ++short_faces;
      continue;
    }
    for (size_t k = 1; k + 1 < polygon.size(); ++k) {
      mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[k], polygon[k + 1]});
    }
  }
  if (short_faces)
    scene.dropped.push_back(std::to_string(short_faces) +
                            " faces with fewer than 3 corners not kept");
  scene.source_vertex_records = static_cast<size_t>(nv);
  scene.meshes.push_back(std::move(mesh));
  AddRootNodeForAllMeshes(scene, name);
  return scene;
}

std::string EncodeOff(const Scene& scene) {
  size_t nv = 0, nf = 0;
  bool colors = !scene.meshes.empty();
  for (const Mesh& m : scene.meshes) {
    nv += m.vertex_count();
    nf += m.triangle_count();
    colors = colors && m.colors.size() == m.vertex_count() * 4;
  }
  TextWriter w;
  w << (colors ? "COFF\n" : "OFF\n") << static_cast<uint64_t>(nv) << ' '
    << static_cast<uint64_t>(nf) << " 0\n";
  for (const Mesh& m : scene.meshes) {
    for (size_t i = 0; i < m.vertex_count(); ++i) {
      w << m.positions[i * 3] << ' ' << m.positions[i * 3 + 1] << ' ' << m.positions[i * 3 + 2];
      if (colors) {
        for (int k = 0; k < 4; ++k) w << ' ' << m.colors[i * 4 + k];
      }
      w << '\n';
    }
  }
  uint64_t base = 0;
  for (const Mesh& m : scene.meshes) {
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      w << "3 " << (base + m.indices[t * 3]) << ' ' << (base + m.indices[t * 3 + 1]) << ' '
        << (base + m.indices[t * 3 + 2]) << '\n';
    }
    base += m.vertex_count();
  }
  return std::move(w.str());
}

}  // namespace hullpack
