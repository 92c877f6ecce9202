// `hullpack unpack IN.glb -o OUT`: decodes a packed GLB back to plain data.
#ifndef HULLPACK_TOOLS_HULLPACK_UNPACK_COMMAND_H_
#define HULLPACK_TOOLS_HULLPACK_UNPACK_COMMAND_H_

#include <string>
#include <vector>

#include "common/status.h"

namespace hullpack {

struct UnpackSummary {
  size_t meshes = 0;        // render meshes written (.glb: every mesh of the file)
  size_t hulls = 0;         // collision hulls written
  size_t triangles = 0;     // of the render meshes
  std::string hulls_path;   // where the hulls went when not into `output` (OFF, PLY)
  std::string buffer_path;  // .gltf: its binary buffer (empty when it has none)
};

// Decodes `input` (a packed or plain GLB) into `output`, by its extension:
//  - .glb: the same glTF, every compressed primitive decoded into plain accessors, the collider
//    nodes and hull meshes as they are;
//  - .gltf: the same document as JSON, its binary buffer (meshes, hulls, animations, embedded
//    images) in STEM.bin beside it, named by a relative URI;
//  - .obj, .wrl: the render meshes, then each convex collider as a closed triangle mesh (the convex
//    hull of its points) named hull_N, one OBJ object or VRML Shape each;
//  - .off, .ply (one mesh per file): the render meshes into `output`, the hulls into
//    STEM.hulls.off / STEM.hulls.ply beside it.
// Hulls are in the space of the render mesh their body node shows, as the writers write every mesh
// (without node transforms); a hull of more than 16384 points (pack writes at most 1024) is an
// error for the mesh formats. Existing outputs are replaced only with `force`.
Result<UnpackSummary> Unpack(const std::string& input, const std::string& output, bool force);

int RunUnpackCommand(const std::vector<std::string>& args);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_UNPACK_COMMAND_H_
