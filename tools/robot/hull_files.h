// The mesh files a robot description points at: binary STL or OBJ.
#ifndef HULLPACK_TOOLS_ROBOT_HULL_FILES_H_
#define HULLPACK_TOOLS_ROBOT_HULL_FILES_H_

#include <cstdint>
#include <vector>

#include "robot/robot_model.h"
#include "scene/scene.h"

namespace hullpack {

// Binary STL: 80-byte header, triangle count, per triangle its unit normal, three corners and a
// zero attribute word (little-endian floats).
std::vector<uint8_t> EncodeBinaryStl(const Mesh& mesh);

// `mesh` in the format's mesh file form (MeshExtension): STL, or OBJ with normals and UVs.
std::vector<uint8_t> EncodeMeshFile(const Mesh& mesh, RobotFormat format);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_ROBOT_HULL_FILES_H_
