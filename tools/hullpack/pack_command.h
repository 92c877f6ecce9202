// `hullpack pack IN... -o OUT`: one packed GLB per input (docs/packed-gltf.md).
#ifndef HULLPACK_TOOLS_HULLPACK_PACK_COMMAND_H_
#define HULLPACK_TOOLS_HULLPACK_PACK_COMMAND_H_

#include <string>
#include <vector>

namespace hullpack {

// Exit code: 0 when every input was packed, else the number that failed (at most 63); kExitUsage
// for a command-line mistake.
int RunPackCommand(const std::vector<std::string>& args);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_PACK_COMMAND_H_
