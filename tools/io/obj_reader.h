// The project's own Wavefront OBJ (+MTL) parser.
//
// Faces may mix `v`, `v/vt`, `v//vn` and `v/vt/vn` corners and use negative (relative) indices;
// polygons are fan-triangulated. Each distinct (v, vt, vn) triple becomes one vertex, as in glTF.
// `o` starts a new mesh, `usemtl` sets the per-triangle material id, `v x y z r g b` carries a
// colour. Texture coordinates are flipped to the glTF convention (v' = 1 - v). Trust model: any
// byte sequence is safe to parse; malformed input gives a kParseError naming the line.
#ifndef HULLPACK_TOOLS_IO_OBJ_READER_H_
#define HULLPACK_TOOLS_IO_OBJ_READER_H_

#include <functional>
#include <string>

#include "common/file_util.h"
#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

struct ObjParseOptions {
  // Returns the text of a material library named by `mtllib`; unset = libraries are not read
  // (and that is reported in Scene::dropped).
  std::function<Result<std::string>(const std::string& library_name)> load_material_library;
  // Threads that read the numbers of a large text ahead (0 = every core, 1 = none); the scene
  // does not depend on it.
  int threads = 0;
  // Called now and then with the fraction of the text parsed (may be empty).
  std::function<void(double)> progress;
};

// Parses OBJ text. `name` prefixes error messages (usually the path).
Result<Scene> ParseObj(const char* data, size_t size, const std::string& name,
                       const ObjParseOptions& options = {});

// The same for a file, read part by part: the file is never held whole, only the few parts being
// parsed (each at most 8 MB), so a large file costs the memory of its scene and not of its text.
Result<Scene> ParseObjFile(const RandomAccessFile& file, const std::string& name,
                           const ObjParseOptions& options = {});

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_OBJ_READER_H_
