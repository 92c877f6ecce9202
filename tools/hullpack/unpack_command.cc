#include "hullpack/unpack_command.h"

#include <cstdio>

#include "common/file_util.h"
#include "gltf/glb_reader.h"
#include "hullpack/cli_util.h"
#include "io/scene_io.h"
#include "packed/packed_glb_reader.h"

namespace hullpack {
namespace {

const char kUsage[] =
    "usage: hullpack unpack PACKED.glb -o OUTPUT [--force]\n"
    "  OUTPUT .glb: the same glTF with every compressed primitive decoded into plain accessors\n"
    "               (collision-hull extensions kept);\n"
    "  OUTPUT .obj .off .wrl .ply: the decoded meshes (hull meshes included, one `o` group each in "
    "OBJ)\n";

}  // namespace

int RunUnpackCommand(const std::vector<std::string>& args) {
  std::string input, output;
  bool force = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if ((a == "-o" || a == "--output") && i + 1 < args.size()) {
      output = args[++i];
    } else if (a == "--force") {
      force = true;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "hullpack unpack: unknown option '%s'\n%s", a.c_str(), kUsage);
      return kExitUsage;
    } else if (input.empty()) {
      input = a;
    } else {
      std::fprintf(stderr, "hullpack unpack: one input at a time\n");
      return kExitUsage;
    }
  }
  if (input.empty() || output.empty()) {
    std::fputs(kUsage, stderr);
    return kExitUsage;
  }
  const FileFormat out_format = FormatFromExtension(output);
  if (out_format == FileFormat::kUnknown) {
    std::fprintf(stderr, "hullpack unpack: %s: unknown output format (.glb .obj .off .wrl .ply)\n",
                 output.c_str());
    return kExitUsage;
  }
  Status writable = CheckOutputPath(output, {input}, force);
  if (!writable.ok()) {
    std::fprintf(stderr, "hullpack unpack: %s\n", writable.message().c_str());
    return 1;
  }
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(input);
  if (!bytes.ok()) {
    std::fprintf(stderr, "hullpack unpack: %s\n", bytes.status().message().c_str());
    return 1;
  }
  GltfDocument plain;
  Result<Scene> scene =
      ReadPackedGltf(bytes.value().data(), bytes.value().size(), input, "", &plain);
  if (!scene.ok()) {
    std::fprintf(stderr, "hullpack unpack: %s\n", scene.status().message().c_str());
    return 1;
  }
  Status written;
  if (out_format == FileFormat::kGlb) {
    Result<std::vector<uint8_t>> glb = plain.Serialize();
    written = glb.ok() ? WriteFileAtomically(output, glb.value()) : glb.status();
  } else {
    written = WriteScene(scene.value(), output);
  }
  if (!written.ok()) {
    std::fprintf(stderr, "hullpack unpack: %s\n", written.message().c_str());
    return 1;
  }
  std::printf("%s -> %s: %zu meshes, %zu triangles\n", input.c_str(), output.c_str(),
              scene->meshes.size(), scene->triangle_count());
  return 0;
}

}  // namespace hullpack
