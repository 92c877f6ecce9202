// Reading and writing whole scenes, dispatched by file extension (and, for reading, by content).
//
// Readers: OBJ (+MTL), OFF, VRML .wrl, PLY, 3MF and glTF/GLB use the project's own parsers (GLB
// files packed by `hullpack pack` are decoded on the way in); FBX, DAE and STL go through assimp.
// Every reader triangulates polygons, keeps what the scene model can hold and lists in
// Scene::dropped what it could not keep. Errors name the file and the problem.
//
// Writers: .obj (one `o` group per mesh, `usemtl` per material id), .off, .wrl (one Shape per
// mesh), .ply (binary little-endian) and .glb (plain, uncompressed glTF 2.0). A hull set is written
// as a scene with one mesh per hull. Writes go to a temporary file in the target folder, then
// rename.
#ifndef HULLPACK_TOOLS_IO_SCENE_IO_H_
#define HULLPACK_TOOLS_IO_SCENE_IO_H_

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

enum class FileFormat { kUnknown, kObj, kOff, kWrl, kPly, kStl, kGltf, kGlb, kFbx, kDae, kThreeMf };

// The format a path names by its extension (case-insensitive).
FileFormat FormatFromExtension(const std::string& path);
const char* FormatName(FileFormat format);

struct ReadOptions {
  // Called with the fraction of the file read so far (from the reading thread; the OBJ parser
  // calls it as it goes, other formats once at the end). May be empty.
  std::function<void(double)> progress;
  // Threads a parser may use (0 = every core); the scene does not depend on it.
  int threads = 0;
};

// Reads any supported file. The Status message starts with the path.
Result<Scene> ReadScene(const std::string& path, const ReadOptions& options = {});

// Reads a file already in memory; `format` must not be kUnknown. `name` is used in messages.
Result<Scene> ReadSceneFromMemory(const uint8_t* data, size_t size, FileFormat format,
                                  const std::string& name);

// Writes `scene` in the format the extension of `path` names, atomically.
Status WriteScene(const Scene& scene, const std::string& path);

// Encodes `scene` in `format` into memory (what WriteScene writes).
Result<std::vector<uint8_t>> EncodeScene(const Scene& scene, FileFormat format);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_SCENE_IO_H_
