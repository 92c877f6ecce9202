// 3MF (3D Manufacturing Format, the 3MF Consortium's successor to STL): a ZIP package whose model
// parts are XML. Read: the core specification's objects (meshes, and components with their
// transforms), the build items, base materials, and from the materials extension colour groups
// and 2D textures; from the production extension, objects in other model parts of the package.
// Each object mesh becomes one scene mesh (shared by every node that places it), each build item
// and component a node. The root node turns 3MF's millimetres (or the model's unit) into metres
// and its +Z up into glTF's +Y up; the mesh arrays keep the file's coordinates. Colours are sRGB
// in 3MF and linear in the scene model. What is not kept (support objects, composite materials,
// multi-properties, beam lattices) is listed in Scene::dropped. A file that requires an extension
// outside these is refused, as the specification asks of a consumer that does not read it.
// Trust model: any byte sequence is safe (tools/io/zip_archive.h, tools/io/xml_scanner.h); every
// reference is checked, and components can neither nest forever nor multiply without bound.
#ifndef HULLPACK_TOOLS_IO_THREEMF_READER_H_
#define HULLPACK_TOOLS_IO_THREEMF_READER_H_

#include <cstddef>
#include <cstdint>
#include <string>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

// Reads the 3MF package at `data`. `name` (the file's path) starts every message.
Result<Scene> Parse3mf(const uint8_t* data, size_t size, const std::string& name);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_THREEMF_READER_H_
