// Writes an SDFormat 1.7 <model> with one <link>: the inertial, the visual mesh, one <collision>
// per hull (checked by 'ign sdf -k').
#ifndef HULLPACK_TOOLS_ROBOT_SDF_WRITER_H_
#define HULLPACK_TOOLS_ROBOT_SDF_WRITER_H_

#include <string>

#include "robot/robot_model.h"

namespace hullpack {

std::string WriteSdf(const RobotModel& model);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_ROBOT_SDF_WRITER_H_
