#include "hullpack/unpack_command.h"

#include <cstdio>
#include <optional>

#include "common/file_util.h"
#include "gltf/glb_reader.h"
#include "gltf/packed_glb_reader.h"
#include "hullpack/cli_util.h"
#include "io/scene_io.h"

namespace hullpack {
int RunUnpackCommand(const std::vector<std::string>& args) {
  std::vector<std::string> inputs;
  std::string output;
  bool force = false;
  CliArgs cli("hullpack unpack", "PACKED.glb -o OUTPUT [--force]",
              "Decodes a packed GLB.\n"
              "  OUTPUT .glb: the same glTF with every compressed primitive decoded into plain\n"
              "               accessors (collision-hull extensions kept);\n"
              "  OUTPUT .obj .off .wrl .ply: the decoded meshes (hull meshes included, one `o` "
              "group\n"
              "               each in OBJ)");
  cli.VersionDetail(FormatVersionText());
  cli.Positional("PACKED.glb", &inputs, 1, 1);
  cli.String("-o, --output", "OUTPUT", &output, "the file to write (.glb .obj .off .wrl .ply)")
      .Required();
  cli.Flag("--force", &force, "replace an existing OUTPUT");
  if (std::optional<int> exit_code = cli.Parse(args)) return *exit_code;
  const std::string& input = inputs[0];
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
