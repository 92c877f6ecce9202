#include "hullpack/info_command.h"

#include <cstdio>
#include <iostream>

#include "common/file_util.h"
#include "hullpack/cli_util.h"
#include "hullpack/scene_summary.h"
#include "io/scene_io.h"
#include "mesh/validate.h"
#include "packed/packed_glb_reader.h"

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
  // Collision hulls as a physics engine builds them (the collider nodes' shapes).
  std::vector<CollisionHull> hulls;
  if (bytes.ok() && format == FileFormat::kGlb) {
    GltfDocument doc;
    Result<Scene> read = ReadPackedGltf(bytes->data(), bytes->size(), path, "", &doc);
    Result<std::vector<CollisionHull>> found =
        read.ok() ? ReadCollisionHulls(doc, path)
                  : Result<std::vector<CollisionHull>>(std::vector<CollisionHull>());
    if (!found.ok()) {
      std::fprintf(stderr, "hullpack info: %s\n", found.status().message().c_str());
      return 1;
    }
    hulls = std::move(found.value());
  }
  size_t hull_points = 0;
  for (const CollisionHull& h : hulls) hull_points += h.hull.vertex_count();
  if (json) {
    nlohmann::json j = SummaryToJson(scene.value(), summary);
    j["file"] = path;
    j["format"] = FormatName(format);
    j["bytes"] = file_size;
    j["collision_hulls"] = hulls.size();
    j["collision_hull_points"] = hull_points;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << path << ": " << FormatName(format) << ", " << file_size << " bytes\n"
              << SummaryToText(scene.value(), summary);
    if (!hulls.empty())
      std::cout << "  collision hulls " << hulls.size() << " (convex colliders), " << hull_points
                << " points\n";
  }
  return 0;
}

}  // namespace hullpack
