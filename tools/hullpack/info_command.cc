#include "hullpack/info_command.h"

#include <cstdio>
#include <iostream>
#include <optional>

#include "common/file_util.h"
#include "hullpack/cli_util.h"
#include "hullpack/scene_summary.h"
#include "io/scene_io.h"
#include "mesh/validate.h"

namespace hullpack {

int RunInfoCommand(const std::vector<std::string>& args) {
  std::vector<std::string> files;
  bool json = false;
  CliArgs cli("hullpack info", "FILE [--json]",
              "Counts, attributes, bounds and topology of a mesh or scene file, and what the\n"
              "reader could not keep.");
  cli.VersionDetail(FormatVersionText());
  cli.Positional("FILE", &files, 1, 1);
  cli.Flag("--json", &json, "print the report as JSON");
  if (std::optional<int> exit_code = cli.Parse(args)) return *exit_code;
  const std::string& path = files[0];
  Result<Scene> scene = ReadScene(path);
  if (!scene.ok()) {
    std::fprintf(stderr, "hullpack info: %s\n", scene.status().message().c_str());
    return 1;
  }
  for (size_t i = 0; i < scene->meshes.size(); ++i) {
    Status valid = ValidateMesh(scene->meshes[i]);
    if (!valid.ok()) {
      std::fprintf(stderr, "hullpack info: %s: mesh %zu: %s\n", path.c_str(), i,
                   valid.message().c_str());
      return 1;
    }
  }
  const SceneSummary summary = Summarize(scene.value());
  const FileFormat format = FormatFromExtension(path);
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(path);
  const size_t file_size = bytes.ok() ? bytes.value().size() : 0;
  if (json) {
    nlohmann::json j = SummaryToJson(scene.value(), summary);
    j["file"] = path;
    j["format"] = FormatName(format);
    j["bytes"] = file_size;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << path << ": " << FormatName(format) << ", " << file_size << " bytes\n"
              << SummaryToText(scene.value(), summary);
  }
  return 0;
}

}  // namespace hullpack
