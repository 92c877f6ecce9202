#include "robot/collision_export.h"

#include <sys/stat.h>

#include <utility>

#include "common/file_util.h"
#include "mesh/flatten.h"
#include "mesh/validate.h"
#include "robot/hull_files.h"
#include "robot/mjcf_writer.h"
#include "robot/sdf_writer.h"
#include "robot/urdf_writer.h"

namespace hullpack {
namespace {

std::string Stem(const std::string& path) {
  const size_t slash = path.find_last_of("/\\");
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

bool Exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

}  // namespace

Result<CollisionExportReport> ExportCollision(Scene scene, const std::string& input_path,
                                              const std::string& output_dir,
                                              const CollisionExportOptions& options,
                                              vhacd::Observer* observer) {
  const RobotFormat format = options.format;
  const int cap =
      options.max_hull_vertices ? options.max_hull_vertices : DefaultMaxHullVertices(format);
  if (cap < 4 || cap > MaxHullVerticesLimit(format)) {
    return Status(StatusCode::kInvalidArgument,
                  std::string("the vertex cap per hull must be in [4, ") +
                      std::to_string(MaxHullVerticesLimit(format)) + "] for " +
                      RobotFormatName(format) + ", not " + std::to_string(cap));
  }
  if (!(options.density > 0) || options.density > 1e12)
    return Status(StatusCode::kInvalidArgument, "density must be in (0, 1e12] kg/m^3");
  if (scene.meshes.empty() || scene.triangle_count() == 0)
    return Status(StatusCode::kInvalidMesh, input_path + ": no triangles");

  Mesh merged = FlattenScene(std::move(scene));
  merged.name = SanitizeName(options.name.empty() ? Stem(input_path) : options.name);
  Status valid = ValidateMesh(merged);
  if (!valid.ok()) return Status(valid.code(), input_path + ": " + valid.message());

  CollisionExportReport report;
  report.name = merged.name;
  const std::string dir = output_dir.empty() ? "." : output_dir;
  const std::string ext = MeshExtension(format);
  RobotModel model;
  model.name = merged.name;
  model.max_hull_vertices = cap;
  model.visual_file = "meshes/" + model.name + "_visual" + ext;
  report.description = dir + "/" + model.name + DescriptionExtension(format);

  vhacd::Parameters params = options.parameters;
  params.max_vertices_per_hull = static_cast<uint32_t>(cap);
  Result<HullSet> hulls = DecomposeMesh(merged, params, observer);
  if (!hulls.ok())
    return Status(hulls.status().code(), input_path + ": " + hulls.status().message());
  if (hulls->hulls.empty())
    return Status(StatusCode::kInvalidMesh, input_path + ": the decomposition produced no hulls");
  for (size_t h = 0; h < hulls->hulls.size(); ++h) {
    model.hull_files.push_back("meshes/" + model.name + "_hull_" + std::to_string(h) + ext);
    report.largest_hull_vertices =
        std::max(report.largest_hull_vertices, hulls->hulls[h].vertex_count());
  }
  if (report.largest_hull_vertices > static_cast<size_t>(cap)) {
    return Status(StatusCode::kInternal, "a hull has " +
                                             std::to_string(report.largest_hull_vertices) +
                                             " vertices, above the cap of " + std::to_string(cap));
  }
  Result<MassProperties> mass = HullUnionMassProperties(hulls->hulls, options.density);
  if (!mass.ok()) return Status(mass.status().code(), input_path + ": " + mass.status().message());
  model.mass = mass.value();

  // Every target is checked before anything is written.
  const std::string text = format == RobotFormat::kUrdf   ? WriteUrdf(model)
                           : format == RobotFormat::kMjcf ? WriteMjcf(model)
                                                          : WriteSdf(model);
  std::vector<std::pair<std::string, const Mesh*>> mesh_files;
  mesh_files.emplace_back(dir + "/" + model.visual_file, &merged);
  for (size_t h = 0; h < hulls->hulls.size(); ++h)
    mesh_files.emplace_back(dir + "/" + model.hull_files[h], &hulls->hulls[h]);
  std::vector<std::string> targets;
  for (const auto& file : mesh_files) targets.push_back(file.first);
  targets.push_back(report.description);
  for (const std::string& target : targets) {
    if (SameFile(target, input_path))
      return Status(StatusCode::kInvalidArgument,
                    target + ": is the input; refusing to overwrite it");
    if (!options.force && Exists(target))
      return Status(StatusCode::kInvalidArgument, target + ": exists (use --force to replace it)");
  }
  // DIR and its missing parents, as mkdir -p makes them.
  Status made = MakeDirectories(dir + "/meshes");
  if (!made.ok()) return made;
  for (const auto& file : mesh_files) {
    Status written = WriteMeshFile(*file.second, format, file.first);
    if (!written.ok()) return written;
    report.files.push_back(file.first);
  }
  // The description last: it never points at a mesh file that was not written.
  Status written = WriteFileAtomically(report.description, text.data(), text.size());
  if (!written.ok()) return written;
  report.files.push_back(report.description);
  report.hull_count = hulls->hulls.size();
  report.mass = model.mass;
  report.decomposition = std::move(hulls->report);
  return report;
}

}  // namespace hullpack
