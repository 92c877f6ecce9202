// `hullpack unpack IN.glb -o OUT`: decodes a packed GLB back to plain data.
#ifndef HULLPACK_TOOLS_HULLPACK_UNPACK_COMMAND_H_
#define HULLPACK_TOOLS_HULLPACK_UNPACK_COMMAND_H_

#include <string>
#include <vector>

namespace hullpack {

int RunUnpackCommand(const std::vector<std::string>& args);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_UNPACK_COMMAND_H_
