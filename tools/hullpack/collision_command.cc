#include "hullpack/collision_command.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "hullpack/cli_util.h"
#include "io/scene_io.h"
#include "robot/collision_export.h"

namespace hullpack {
namespace {

class ProgressObserver : public vhacd::Observer {
 public:
  explicit ProgressObserver(ProgressLine& line) : line_(line) {}
  void OnProgress(double overall, double, double, const char* stage, const char*) override {
    char text[128];
    std::snprintf(text, sizeof(text), "collision %3d%% %s", static_cast<int>(overall), stage);
    line_.Update(text);
  }

 private:
  ProgressLine& line_;
};

}  // namespace

int RunCollisionCommand(const std::vector<std::string>& args) {
  std::vector<std::string> inputs;
  std::string output, format = "urdf", quality = "default";
  CollisionExportOptions options;
  bool json = false, quiet = false;
  long resolution = 0, max_hulls = -1, cap = 0;
  double concavity = -1;
  CliArgs cli(
      "hullpack collision", "INPUT -o DIR [--format urdf|mjcf|sdf] [options]",
      "Convex collision hulls as a robot description: DIR/NAME.urdf (.xml for MJCF, .sdf)\n"
      "and DIR/meshes/ with the visual mesh and one convex hull per file (STL for URDF and\n"
      "SDF, OBJ for MJCF), with the mass and inertia of the union of the hulls.");
  cli.VersionDetail(FormatVersionText());
  cli.Positional("INPUT", &inputs, 1, 1);
  cli.String("-o, --output", "DIR", &output, "the folder to write into (created when missing)")
      .Required();
  cli.Choice("--format", {"urdf", "mjcf", "sdf"}, &format, "the description (urdf)");
  cli.String("--name", "NAME", &options.name,
             "link/body/model name and file prefix (default: the input's stem)");
  cli.Double("--density", "D", 1e-9, 1e12, &options.density,
             "mass per cubic unit of the mesh (1000: water in kg/m^3, for metres)");
  cli.Int("--max-hull-vertices", "N", 4, 1024, &cap,
          "vertex cap per hull (64; at most 255 for URDF/SDF, 1024 for MJCF)");
  cli.Choice("--quality", {"default", "high"}, &quality, "decomposition preset").First();
  cli.Int("--resolution", "N", 10000, 64000000, &resolution, "voxels of the decomposition");
  cli.Int("--max-hulls", "N", 0, 100000, &max_hulls, "hull budget (0: none)");
  cli.Double("--concavity", "F", 0, 1, &concavity,
             "largest concavity of a part (V-HACD 2.0's volume criterion instead of\n"
             "the preset's --max-concavity 0.08)");
  cli.Flag("--json", &json, "print the report as JSON");
  cli.Flag("--force", &options.force, "replace existing files");
  cli.Flag("--quiet", &quiet, "no progress line");
  if (std::optional<int> exit_code = cli.Parse(args)) return *exit_code;
  const std::string& input = inputs[0];
  ParseRobotFormat(format, &options.format);
  if (cap > MaxHullVerticesLimit(options.format)) {
    return cli.UsageError("--max-hull-vertices is at most " +
                          std::to_string(MaxHullVerticesLimit(options.format)) + " for " + format);
  }
  options.max_hull_vertices = static_cast<int>(cap);
  vhacd::Parameters& p = options.parameters;
  if (quality == "high") p = vhacd::Parameters::High();
  if (resolution) p.resolution = static_cast<uint32_t>(resolution);
  if (max_hulls >= 0) p.max_convex_hulls = static_cast<uint32_t>(max_hulls);
  if (concavity >= 0) {  // V-HACD 2.0's volume criterion instead of the preset's target error
    p.concavity = concavity;
    p.max_concavity = 0;
  }

  Result<Scene> scene = ReadScene(input);
  if (!scene.ok()) {
    std::fprintf(stderr, "hullpack collision: %s\n", scene.status().message().c_str());
    return 1;
  }
  ProgressLine progress(!quiet && !json);
  ProgressObserver observer(progress);
  Result<CollisionExportReport> r =
      ExportCollision(std::move(scene).value(), input, output, options, &observer);
  progress.Clear();
  if (!r.ok()) {
    std::fprintf(stderr, "hullpack collision: %s\n", r.status().message().c_str());
    return 1;
  }
  const MassProperties& m = r->mass;
  if (json) {
    nlohmann::json j = {{"input", input},
                        {"format", RobotFormatName(options.format)},
                        {"name", r->name},
                        {"description", r->description},
                        {"files", r->files},
                        {"hull_count", r->hull_count},
                        {"largest_hull_vertices", r->largest_hull_vertices},
                        {"volume", m.volume},
                        {"mass", m.mass},
                        {"center_of_mass", m.center},
                        {"inertia",
                         {{"ixx", m.inertia[0]},
                          {"iyy", m.inertia[1]},
                          {"izz", m.inertia[2]},
                          {"ixy", m.inertia[3]},
                          {"ixz", m.inertia[4]},
                          {"iyz", m.inertia[5]}}},
                        {"concavity", r->decomposition.concavity},
                        {"volume_iou", r->decomposition.volume_iou}};
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf(
        "%s -> %s: %zu hulls (at most %zu vertices each), mass %g, centre of mass (%g, %g, %g)\n",
        input.c_str(), r->description.c_str(), r->hull_count, r->largest_hull_vertices, m.mass,
        m.center[0], m.center[1], m.center[2]);
  }
  return 0;
}

}  // namespace hullpack
