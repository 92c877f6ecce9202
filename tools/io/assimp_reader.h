// The bridge to assimp for glTF/GLB, FBX, DAE, PLY and STL: converts aiScene into the scene model,
// keeping node hierarchy and transforms, materials and their textures (embedded bytes included),
// every UV set, the first colour set, tangents and skins (up to 4 joints per vertex, renormalized).
// What cannot be kept (animations, morph targets, cameras, lights, points and lines, extra colour
// sets, influences past the fourth) is listed in Scene::dropped.
#ifndef HULLPACK_TOOLS_IO_ASSIMP_READER_H_
#define HULLPACK_TOOLS_IO_ASSIMP_READER_H_

#include <cstdint>
#include <string>

#include "common/status.h"
#include "io/scene_io.h"
#include "scene/scene.h"

namespace hullpack {

// Reads a file through assimp (external resources such as .bin and .mtl files resolve next to it).
Result<Scene> ReadWithAssimp(const std::string& path, FileFormat format);

// Reads bytes through assimp; `format` selects the importer hint.
Result<Scene> ReadWithAssimpFromMemory(const uint8_t* data, size_t size, FileFormat format,
                                       const std::string& name);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_ASSIMP_READER_H_
