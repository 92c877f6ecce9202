// vhacd_meshgen: writes the generated decomposition benchmark meshes (thin open containers, single-
// and double-sided; CAD parts with holes; multi-component machinery; a blob with a small hole) as
// OBJ files into a folder, for vhacd_bench.
//
//   vhacd_meshgen OUTDIR
#include <sys/stat.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "shape_gen.h"

int main(int argc, char** argv) {
  if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::printf("usage: vhacd_meshgen OUTDIR\n");
    return 0;
  }
  if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
    std::printf("vhacd_meshgen 1\n");
    return 0;
  }
  if (argc != 2) {
    std::fprintf(stderr, "usage: vhacd_meshgen OUTDIR\n");
    return 64;
  }
  const std::string dir = argv[1];
  mkdir(dir.c_str(), 0755);
  for (const auto& s : hullpack::shapes::BenchmarkShapes()) {
    const std::string path = dir + "/" + s.name + ".obj";
    if (!hullpack::shapes::WriteObj(path, s.mesh)) {
      std::fprintf(stderr, "vhacd_meshgen: cannot write %s\n", path.c_str());
      return 1;
    }
    std::printf("%s: %zu triangles\n", path.c_str(), s.mesh.triangle_count());
  }
  return 0;
}
