#include "hullpack/info_command.h"

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <map>
#include <optional>

#include "common/file_util.h"
#include "hullpack/cli_util.h"
#include "hullpack/scene_summary.h"
#include "io/scene_io.h"
#include "mesh/validate.h"
#include "packed/packed_glb_reader.h"

namespace hullpack {

namespace {

// Hull meshes stored as points (docs/packed-gltf.md) have no triangles for the scene model: they
// are reported as collision hulls instead of as empty meshes, and the reader's notes about them go.
void LeaveOutPointHulls(const std::vector<CollisionHull>& hulls, Scene& scene) {
  std::vector<bool> drop(scene.meshes.size(), false);
  size_t dropped = 0;
  for (const CollisionHull& h : hulls) {
    const size_t m = static_cast<size_t>(h.gltf_mesh);
    if (m < drop.size() && !drop[m] && scene.meshes[m].triangle_count() == 0) {
      drop[m] = true;
      ++dropped;
    }
  }
  if (dropped == 0) return;
  std::vector<bool> keep(drop.size());
  for (size_t m = 0; m < drop.size(); ++m) keep[m] = !drop[m];
  KeepMeshes(scene, keep);
  std::vector<std::string> notes;
  for (const std::string& line : scene.dropped) {
    bool about_hull = line == "dropped " + std::to_string(dropped) + " point/line primitives";
    for (size_t m = 0; m < drop.size() && !about_hull; ++m)
      about_hull = drop[m] && line == "meshes[" + std::to_string(m) + "] has no triangles";
    if (!about_hull) notes.push_back(line);
  }
  scene.dropped = std::move(notes);
}

// The scene reader lists the physics extensions among those it ignored; once their colliders are
// read as collision hulls, they are not.
void ForgetReadCollisionExtensions(Scene& scene) {
  const std::string prefix = "ignored extensions: ";
  std::vector<std::string> notes;
  for (const std::string& line : scene.dropped) {
    if (line.compare(0, prefix.size(), prefix) != 0) {
      notes.push_back(line);
      continue;
    }
    std::string kept;
    size_t from = prefix.size();
    while (from <= line.size()) {
      size_t to = line.find(", ", from);
      if (to == std::string::npos) to = line.size();
      const std::string ext = line.substr(from, to - from);
      const bool read = std::find(std::begin(kCollisionExtensions), std::end(kCollisionExtensions),
                                  ext) != std::end(kCollisionExtensions);
      if (!read && !ext.empty()) kept += (kept.empty() ? "" : ", ") + ext;
      from = to + 2;
    }
    if (!kept.empty()) notes.push_back(prefix + kept);
  }
  scene.dropped = std::move(notes);
}

}  // namespace

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
  const FileFormat format = FormatFromExtension(path);
  // The file is read again whole only for a GLB's hulls: a large mesh file would otherwise be held
  // beside its scene just for its size.
  struct stat st;
  size_t file_size = stat(path.c_str(), &st) == 0 ? static_cast<size_t>(st.st_size) : 0;
  // Collision hulls as a physics engine builds them (the collider nodes' shapes).
  std::vector<CollisionHull> hulls;
  std::map<std::string, size_t> stream_versions;  // of the compressed primitives' streams
  Result<std::vector<uint8_t>> bytes = std::vector<uint8_t>();
  const bool gltf = format == FileFormat::kGlb || format == FileFormat::kGltf;
  if (gltf) bytes = ReadFileBytes(path);
  if (bytes.ok() && gltf) {
    file_size = bytes->size();
    GltfDocument doc;
    const std::string folder = FolderOf(path);
    Result<Scene> read = ReadPackedGltf(bytes->data(), bytes->size(), path, folder, &doc);
    Status adopted = read.ok() ? AdoptBufferFiles(doc, folder, path, true) : Status::Ok();
    Result<std::vector<CollisionHull>> found =
        !adopted.ok() ? Result<std::vector<CollisionHull>>(adopted)
        : read.ok()   ? ReadCollisionHulls(doc, path)
                      : Result<std::vector<CollisionHull>>(std::vector<CollisionHull>());
    if (!found.ok()) {
      std::fprintf(stderr, "hullpack info: %s\n", found.status().message().c_str());
      return 1;
    }
    hulls = std::move(found.value());
    Result<GltfDocument> parsed = ParseGltfBytes(bytes->data(), bytes->size(), path);
    if (parsed.ok()) stream_versions = StreamVersions(parsed.value());
  }
  LeaveOutPointHulls(hulls, scene.value());
  if (!hulls.empty()) ForgetReadCollisionExtensions(scene.value());
  const SceneSummary summary = Summarize(scene.value());
  size_t hull_points = 0;
  for (const CollisionHull& h : hulls) hull_points += h.hull.vertex_count();
  if (json) {
    nlohmann::json j = SummaryToJson(scene.value(), summary);
    j["file"] = path;
    j["format"] = FormatName(format);
    j["bytes"] = file_size;
    j["collision_hulls"] = hulls.size();
    j["collision_hull_points"] = hull_points;
    j["stream_versions"] = stream_versions;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << path << ": " << FormatName(format) << ", " << file_size << " bytes\n"
              << SummaryToText(scene.value(), summary);
    if (!hulls.empty())
      std::cout << "  collision hulls " << hulls.size() << " (convex colliders), " << hull_points
                << " points\n";
    if (!stream_versions.empty()) {
      // Which decoder releases read the file: each stream needs its format version.
      size_t streams = 0;
      std::string by_version;
      for (const auto& [version, count] : stream_versions) {
        streams += count;
        by_version += (by_version.empty() ? "" : ", ") + version + ": " + std::to_string(count);
      }
      std::cout << "  compressed streams " << streams << " (format " << by_version << ")\n";
    }
  }
  return 0;
}

}  // namespace hullpack
