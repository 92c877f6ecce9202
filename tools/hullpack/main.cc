// hullpack: convex collision hulls and compressed meshes, packed for the web.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "hullpack/cli_util.h"
#include "hullpack/collision_command.h"
#include "hullpack/info_command.h"
#include "hullpack/pack_command.h"
#include "hullpack/unpack_command.h"

namespace {

void PrintUsage(FILE* out) {
  std::fprintf(
      out,
      "usage: hullpack COMMAND [options]\n"
      "commands:\n"
      "  pack IN... -o OUT    compressed meshes + convex collision hulls in one GLB per input\n"
      "  unpack IN.glb -o OUT decode a packed GLB back to plain glTF, OBJ, ...\n"
      "  info FILE [--json]   counts, attributes, bounds and topology of a mesh or scene file\n"
      "  collision IN -o DIR  convex collision hulls as a URDF, MJCF or SDF robot description\n"
      "run 'hullpack COMMAND --help' for a command's options\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    PrintUsage(argc < 2 ? stderr : stdout);
    return argc < 2 ? hullpack::kExitUsage : 0;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (command == "collision") return hullpack::RunCollisionCommand(args);
  if (command == "info") return hullpack::RunInfoCommand(args);
  if (command == "pack") return hullpack::RunPackCommand(args);
  if (command == "unpack") return hullpack::RunUnpackCommand(args);
  std::fprintf(stderr, "hullpack: unknown command '%s'\n", command.c_str());
  PrintUsage(stderr);
  return hullpack::kExitUsage;
}
