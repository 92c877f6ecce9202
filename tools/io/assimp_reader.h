// The bridge to assimp for FBX, DAE, PLY and STL (and any other format assimp reads): converts
// aiScene into the scene model, keeping node hierarchy and transforms, materials and their textures
// (embedded bytes included, wrap modes as samplers; opacity below one or an opacity map as alpha
// blending, glTF alpha modes where assimp's glTF importer gives them; unshaded as unlit), every UV
// set, the first colour set, tangents, skins (up to 4 joints per vertex, renormalized), morph
// targets (anim meshes as offsets, with names and default weights) and node and morph animations
// (linear keys in seconds; each animated node's rest transform also as Node::trs; a morph channel
// drives the node of its name, else the node whose first mesh has it; a clip starting before 0 s
// shifted to 0), cameras and point, spot and directional lights (assimp_cameras_lights.h). What
// cannot be kept (mesh (vertex) animations, channels of unknown or sheared nodes, vertex-blend
// morphing, ambient and area lights, points and lines, extra colour sets, influences past the
// fourth, opacity maps other than the base colour texture) is listed, with every shift, in
// Scene::dropped.
#ifndef HULLPACK_TOOLS_IO_ASSIMP_READER_H_
#define HULLPACK_TOOLS_IO_ASSIMP_READER_H_

#include <cstdint>
#include <string>

#include "common/status.h"
#include "io/scene_io.h"
#include "scene/scene.h"

struct aiScene;

namespace hullpack {

// Reads a file through assimp (external resources such as .bin and .mtl files resolve next to it).
Result<Scene> ReadWithAssimp(const std::string& path, FileFormat format);

// Reads bytes through assimp; `format` selects the importer hint.
Result<Scene> ReadWithAssimpFromMemory(const uint8_t* data, size_t size, FileFormat format,
                                       const std::string& name);

// The conversion alone, for a scene assimp already holds (tests build aiScenes by hand).
Scene ConvertAssimpScene(const aiScene& ai, const std::string& name);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_ASSIMP_READER_H_
