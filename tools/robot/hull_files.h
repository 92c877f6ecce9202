// The mesh files a robot description points at: binary STL or OBJ.
#ifndef HULLPACK_TOOLS_ROBOT_HULL_FILES_H_
#define HULLPACK_TOOLS_ROBOT_HULL_FILES_H_

#include <cstddef>
#include <functional>
#include <string>

#include "common/status.h"
#include "robot/robot_model.h"
#include "scene/scene.h"

namespace hullpack {

// Receives a file's bytes in consecutive pieces.
using ByteSink = std::function<void(const void* data, size_t size)>;

// Binary STL: 80-byte header, triangle count, per triangle its unit normal, three corners and a
// zero attribute word (little-endian floats), handed to `sink` in pieces.
void EncodeBinaryStl(const Mesh& mesh, const ByteSink& sink);

// Writes `mesh` to `path` in the format's mesh file form (MeshExtension): STL, or OBJ with normals
// and UVs. Piece by piece through a temporary file: a large visual mesh's file (50 bytes per
// triangle as STL, more as OBJ) is never held in memory whole. Errors name the path.
Status WriteMeshFile(const Mesh& mesh, RobotFormat format, const std::string& path);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_ROBOT_HULL_FILES_H_
