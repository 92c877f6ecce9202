// `hullpack collision INPUT -o DIR --format urdf|mjcf|sdf`: convex collision hulls as a robot
// description (docs/guide-simulation.md).
#ifndef HULLPACK_TOOLS_HULLPACK_COLLISION_COMMAND_H_
#define HULLPACK_TOOLS_HULLPACK_COLLISION_COMMAND_H_

#include <string>
#include <vector>

namespace hullpack {

// Exit code: 0 on success, 1 when the input cannot be read, decomposed or written, kExitUsage for a
// command-line mistake.
int RunCollisionCommand(const std::vector<std::string>& args);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_COLLISION_COMMAND_H_
