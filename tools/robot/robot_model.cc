#include "robot/robot_model.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace hullpack {

const char* RobotFormatName(RobotFormat format) {
  switch (format) {
    case RobotFormat::kUrdf:
      return "urdf";
    case RobotFormat::kMjcf:
      return "mjcf";
    case RobotFormat::kSdf:
      return "sdf";
  }
  return "?";
}

bool ParseRobotFormat(const std::string& text, RobotFormat* format) {
  for (RobotFormat f : {RobotFormat::kUrdf, RobotFormat::kMjcf, RobotFormat::kSdf}) {
    if (text == RobotFormatName(f)) {
      *format = f;
      return true;
    }
  }
  return false;
}

const char* DescriptionExtension(RobotFormat format) {
  return format == RobotFormat::kUrdf ? ".urdf" : format == RobotFormat::kMjcf ? ".xml" : ".sdf";
}

// STL is what every URDF and SDF consumer reads (ROS tools, Gazebo classic and later, PyBullet,
// Isaac's importer); MuJoCo reads OBJ and STL, and OBJ keeps the visual mesh's normals and UVs.
const char* MeshExtension(RobotFormat format) {
  return format == RobotFormat::kMjcf ? ".obj" : ".stl";
}

// 64 is V-HACD's own default: enough for hulls whose stick-out is bounded anyway, and cheap for
// GJK-based contact (MuJoCo, Bullet, DART) alike.
int DefaultMaxHullVertices(RobotFormat) { return 64; }

// PhysX (Isaac Sim's URDF and SDF importers) rejects convex meshes with more than 255 vertices;
// MuJoCo has no hard limit (maxhullvert is unlimited by default), so the library's own bound
// applies.
int MaxHullVerticesLimit(RobotFormat format) { return format == RobotFormat::kMjcf ? 1024 : 255; }

std::string SanitizeName(const std::string& name) {
  std::string out;
  for (unsigned char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    out += ok ? static_cast<char>(c) : '_';
  }
  if (out.empty()) return "model";
  if (out[0] >= '0' && out[0] <= '9') out = "m_" + out;
  return out;
}

std::string XmlNumber(double value) {
  if (!std::isfinite(value)) return "0";
  char buffer[32];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

}  // namespace hullpack
