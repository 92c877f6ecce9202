// hullpack: convex collision hulls and compressed meshes, packed for the web.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "hullpack/info_command.h"

namespace {

void PrintUsage(FILE* out) {
  std::fprintf(out,
               "usage: hullpack COMMAND [options]\n"
               "commands:\n"
               "  info FILE [--json]   counts, attributes, bounds and topology of a mesh or scene file\n"
               "run 'hullpack COMMAND --help' for a command's options\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    PrintUsage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (command == "info") return hullpack::RunInfoCommand(args);
  std::fprintf(stderr, "hullpack: unknown command '%s'\n", command.c_str());
  PrintUsage(stderr);
  return 2;
}
