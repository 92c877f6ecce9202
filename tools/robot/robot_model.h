// What the URDF, MJCF and SDF writers share: one rigid body with a visual mesh, convex collision
// meshes and its mass properties, all files named relative to the description.
#ifndef HULLPACK_TOOLS_ROBOT_ROBOT_MODEL_H_
#define HULLPACK_TOOLS_ROBOT_ROBOT_MODEL_H_

#include <string>
#include <vector>

#include "robot/mass_properties.h"

namespace hullpack {

enum class RobotFormat { kUrdf, kMjcf, kSdf };

struct RobotModel {
  std::string name;                     // sanitized (SanitizeName)
  std::string visual_file;              // relative to the description, "/" separated
  std::vector<std::string> hull_files;  // the same, one per convex hull
  MassProperties mass;
  int max_hull_vertices = 0;  // what the hulls were capped at (MJCF repeats it)
};

// "urdf", "mjcf", "sdf".
const char* RobotFormatName(RobotFormat format);
// Parses a format name (case-sensitive); false when it is none of them.
bool ParseRobotFormat(const std::string& text, RobotFormat* format);
// The description's extension and the mesh files' one: .urdf + .stl, .xml + .obj, .sdf + .stl.
const char* DescriptionExtension(RobotFormat format);
const char* MeshExtension(RobotFormat format);
// The default cap on vertices per hull for a format (see docs/guide-simulation.md).
int DefaultMaxHullVertices(RobotFormat format);
// The largest cap a format's simulators accept.
int MaxHullVerticesLimit(RobotFormat format);

// A name every format accepts as an element name and a file name: letters, digits and '_' only
// (anything else becomes '_'), not starting with a digit, never empty ("model").
std::string SanitizeName(const std::string& name);

// A number as XML attribute text: shortest round-trip form, never NaN ("0" instead).
std::string XmlNumber(double value);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_ROBOT_ROBOT_MODEL_H_
