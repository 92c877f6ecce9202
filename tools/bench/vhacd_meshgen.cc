// vhacd_meshgen: writes the generated decomposition benchmark meshes (thin open containers, single-
// and double-sided; CAD parts with holes; multi-component machinery; a blob with a small hole) as
// OBJ files into a folder, for vhacd_bench.
#include <sys/stat.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "common/cli_args.h"
#include "shape_gen.h"

int main(int argc, char** argv) {
  std::vector<std::string> operands;
  hullpack::CliArgs cli("vhacd_meshgen", "OUTDIR",
                        "Writes the generated decomposition benchmark meshes (open pots, cups and\n"
                        "lidless boxes as single- and double-sided shells, CAD parts with holes,\n"
                        "machinery, a blob with a small hole) into OUTDIR as OBJ files.");
  bool rotated = false;
  cli.Flag("--rotated", &rotated,
           "write the rotated L, T and cross and the 60-degree V instead (shapes whose natural\n"
           "cuts are not along the grid axes)");
  cli.Positional("OUTDIR", &operands, 1, 1);
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  const std::string dir = operands[0];
  mkdir(dir.c_str(), 0755);
  for (const auto& s :
       rotated ? hullpack::shapes::RotatedShapes() : hullpack::shapes::BenchmarkShapes()) {
    const std::string path = dir + "/" + s.name + ".obj";
    if (!hullpack::shapes::WriteObj(path, s.mesh)) {
      std::fprintf(stderr, "vhacd_meshgen: cannot write %s\n", path.c_str());
      return 1;
    }
    std::printf("%s: %zu triangles\n", path.c_str(), s.mesh.triangle_count());
  }
  return 0;
}
