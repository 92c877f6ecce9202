// Scenes and files the I/O tests share: generated meshes, temporary folders, and files in formats
// the project does not write (DAE, STL, FBX, glTF) made with assimp's exporters from our own OBJ
// output.
#ifndef HULLPACK_TESTS_TOOLS_IO_IO_TEST_UTIL_H_
#define HULLPACK_TESTS_TOOLS_IO_IO_TEST_UTIL_H_

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <unistd.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "common/test_shapes.h"
#include "io/obj_writer.h"
#include "scene/scene.h"

namespace hullpack::testing {

// A torus with normals, one UV set and, optionally, colours and two materials (inner/outer half).
inline Scene TorusScene(int rings = 16, int sides = 8, bool colors = false,
                        bool materials = false) {
  Mesh m;
  m.name = "torus";
  test_shapes::AppendTo(test_shapes::Torus(1, 0.3, rings, sides), &m);
  m.uv_sets.emplace_back();
  for (int i = 0; i < rings; ++i) {  // vertex i * sides + j
    for (int j = 0; j < sides; ++j) {
      m.uv_sets[0].insert(m.uv_sets[0].end(), {float(i) / rings, float(j) / sides});
      if (colors) m.colors.insert(m.colors.end(), {float(i) / rings, float(j) / sides, 0.5f, 1.0f});
      if (materials) m.material_ids.insert(m.material_ids.end(), 2, j < sides / 2 ? 0u : 1u);
    }
  }
  Scene s;
  s.meshes.push_back(std::move(m));
  if (materials) {
    s.materials.resize(2);
    s.materials[0].name = "outer";
    s.materials[1].name = "inner";
  }
  AddRootNodeForAllMeshes(s, "root");
  return s;
}

// A scene of `n` tetrahedra, one mesh each: the shape of a hull set.
inline Scene TetrahedraScene(int n) {
  Scene s;
  for (int k = 0; k < n; ++k) {
    Mesh m;
    m.name = "hull_" + std::to_string(k);
    const float o = 2.0f * k;
    m.positions = {o, 0, 0, o + 1, 0, 0, o, 1, 0, o, 0, 1};
    m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    s.meshes.push_back(std::move(m));
  }
  AddRootNodeForAllMeshes(s, "hulls");
  return s;
}

class TempDir {
 public:
  TempDir() {
    char tmpl[] = "/tmp/hullpack-test-XXXXXX";
    path_ = mkdtemp(tmpl) ? tmpl : "/tmp";
  }
  ~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

inline void WriteBytes(const std::string& path, const void* data, size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
}

// Converts `scene` to `assimp_format` (an Assimp::Exporter id such as "collada", "stlb", "fbx",
// "glb2") through our OBJ writer and assimp's OBJ importer. Empty on failure.
inline std::vector<uint8_t> ExportWithAssimp(const Scene& scene, const char* assimp_format) {
  const std::string obj = EncodeObj(scene);
  Assimp::Importer importer;
  const aiScene* ai =
      importer.ReadFileFromMemory(obj.data(), obj.size(), aiProcess_Triangulate, "obj");
  if (!ai) return {};
  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(ai, assimp_format);
  if (!blob) return {};
  const uint8_t* p = static_cast<const uint8_t*>(blob->data);
  return std::vector<uint8_t>(p, p + blob->size);
}

inline std::vector<uint8_t> RandomBytes(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<uint8_t> out(n);
  for (uint8_t& b : out) b = static_cast<uint8_t>(rng());
  return out;
}

}  // namespace hullpack::testing

#endif  // HULLPACK_TESTS_TOOLS_IO_IO_TEST_UTIL_H_
