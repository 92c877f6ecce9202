#include "hullpack/info_command.h"

#include <cstdio>
#include <iostream>

#include "common/file_util.h"
#include "hullpack/cli_util.h"
#include "hullpack/scene_summary.h"
#include "io/scene_io.h"
#include "mesh/validate.h"

namespace hullpack {

int RunInfoCommand(const std::vector<std::string>& args) {
  std::string path;
  bool json = false;
  for (const std::string& a : args) {
    if (a == "--json") {
      json = true;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "hullpack info: unknown option '%s'\n", a.c_str());
      return kExitUsage;
    } else if (path.empty()) {
      path = a;
    } else {
      std::fprintf(stderr, "hullpack info: one file at a time ('%s' and '%s')\n", path.c_str(),
                   a.c_str());
      return kExitUsage;
    }
  }
  if (path.empty()) {
    std::fprintf(stderr, "usage: hullpack info FILE [--json]\n");
    return kExitUsage;
  }
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
