// hullpack: convex collision hulls and compressed meshes, packed for the web.
#include <string>
#include <vector>

#include "common/malloc_policy.h"
#include "hullpack/batch_command.h"
#include "hullpack/cli_util.h"
#include "hullpack/collision_command.h"
#include "hullpack/info_command.h"
#include "hullpack/pack_command.h"
#include "hullpack/unpack_command.h"

int main(int argc, char** argv) {
  hullpack::ConfigureMalloc();
  hullpack::CliArgs cli(
      "hullpack", "COMMAND [options]",
      "Convex collision hulls and compressed meshes, packed for the web and game engines.\n"
      "commands:\n"
      "  pack INPUT... -o OUTPUT   compressed meshes + convex collision hulls in one GLB per "
      "input\n"
      "  batch INPUT... -o OUTDIR  many inputs: cached, resumable, sharded, Slurm job arrays\n"
      "  unpack IN.glb -o OUTPUT   decode a packed GLB back to plain glTF, OBJ, ...\n"
      "  info FILE [--json]        counts, attributes, bounds and topology of a mesh or scene\n"
      "  collision IN -o DIR       convex collision hulls as a URDF, MJCF or SDF description\n"
      "run 'hullpack COMMAND --help' for a command's options");
  cli.VersionDetail(hullpack::FormatVersionText());
  std::vector<std::string> operands;
  cli.Positional("COMMAND", &operands, 1, 1);
  const std::vector<std::string> args(argv + 1, argv + argc);
  // Options before the command are hullpack's own (--help, --version); the rest are the command's.
  if (args.empty() || args[0].empty() || args[0][0] == '-') {
    if (std::optional<int> exit_code = cli.Parse(args)) return *exit_code;
  }
  const std::string& command = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "batch") return hullpack::RunBatchCommand(rest);
  if (command == "collision") return hullpack::RunCollisionCommand(rest);
  if (command == "info") return hullpack::RunInfoCommand(rest);
  if (command == "pack") return hullpack::RunPackCommand(rest);
  if (command == "unpack") return hullpack::RunUnpackCommand(rest);
  return cli.UsageError("unknown command '" + command + "'");
}
