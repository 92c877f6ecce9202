// Writes a URDF <robot> with one <link>: the inertial from the hull union, the visual mesh, one
// <collision> per hull (ROS's urdf XML, checked by check_urdf).
#ifndef HULLPACK_TOOLS_ROBOT_URDF_WRITER_H_
#define HULLPACK_TOOLS_ROBOT_URDF_WRITER_H_

#include <string>

#include "robot/robot_model.h"

namespace hullpack {

std::string WriteUrdf(const RobotModel& model);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_ROBOT_URDF_WRITER_H_
