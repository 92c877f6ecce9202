// Writes a MuJoCo MJCF model: <asset> meshes (hulls capped with maxhullvert) and one free <body>
// with an explicit <inertial>, the visual geom (no contacts, group 2) and one collision geom per
// hull (group 3).
#ifndef HULLPACK_TOOLS_ROBOT_MJCF_WRITER_H_
#define HULLPACK_TOOLS_ROBOT_MJCF_WRITER_H_

#include <string>

#include "robot/robot_model.h"

namespace hullpack {

std::string WriteMjcf(const RobotModel& model);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_ROBOT_MJCF_WRITER_H_
