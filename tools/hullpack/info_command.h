// `hullpack info FILE [--json]`: what a file holds — counts, attributes, bounds, topology, and what
// the reader could not keep.
#ifndef HULLPACK_TOOLS_HULLPACK_INFO_COMMAND_H_
#define HULLPACK_TOOLS_HULLPACK_INFO_COMMAND_H_

#include <string>
#include <vector>

namespace hullpack {

// Returns the process exit code; prints the report on stdout and errors on stderr.
int RunInfoCommand(const std::vector<std::string>& args);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_INFO_COMMAND_H_
