#include "hullpack/collision_command.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "hullpack/cli_util.h"
#include "io/scene_io.h"
#include "robot/collision_export.h"

namespace hullpack {
namespace {

const char kUsage[] =
    "usage: hullpack collision INPUT -o DIR [--format urdf|mjcf|sdf] [options]\n"
    "  writes DIR/NAME.urdf (or .xml for MJCF, .sdf) and DIR/meshes/: the visual mesh and one\n"
    "  convex hull per file (STL for URDF and SDF, OBJ for MJCF), mass and inertia of the hulls\n"
    "options:\n"
    "  --format F         urdf (default), mjcf or sdf\n"
    "  --name NAME        link/body/model name and file prefix (default: the input's stem)\n"
    "  --density D        kg per cubic unit of the mesh (1000: water, in metres)\n"
    "  --max-hull-vertices N   vertex cap per hull (64; at most 255 for URDF/SDF, 1024 for MJCF)\n"
    "  --quality default|high  decomposition preset\n"
    "  --resolution N --max-hulls N --concavity F   decomposition parameters\n"
    "  --json             print the report as JSON\n"
    "  --force            replace existing files\n"
    "  --quiet            no progress line\n";

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
  std::string input, output;
  CollisionExportOptions options;
  bool json = false, quiet = false, high_quality = false;
  long resolution = 0, max_hulls = -1, cap = 0;
  double concavity = -1;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* out) {
      if (i + 1 >= args.size()) {
        std::fprintf(stderr, "hullpack collision: %s needs a value\n", a.c_str());
        return false;
      }
      *out = args[++i];
      return true;
    };
    std::string v;
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "-o" || a == "--output") {
      if (!value(&output)) return kExitUsage;
    } else if (a == "--format") {
      if (!value(&v) || !ParseRobotFormat(v, &options.format)) {
        std::fprintf(stderr, "hullpack collision: --format takes urdf, mjcf or sdf\n");
        return kExitUsage;
      }
    } else if (a == "--name") {
      if (!value(&options.name)) return kExitUsage;
    } else if (a == "--density") {
      if (!value(&v) || !ParseDouble(a, v, 1e-9, 1e12, &options.density)) return kExitUsage;
    } else if (a == "--max-hull-vertices") {
      if (!value(&v) || !ParseInt(a, v, 4, 1024, &cap)) return kExitUsage;
    } else if (a == "--quality") {
      if (!value(&v) || (v != "default" && v != "high")) {
        std::fprintf(stderr, "hullpack collision: --quality takes default or high\n");
        return kExitUsage;
      }
      high_quality = v == "high";
    } else if (a == "--resolution") {
      if (!value(&v) || !ParseInt(a, v, 10000, 64000000, &resolution)) return kExitUsage;
    } else if (a == "--max-hulls") {
      if (!value(&v) || !ParseInt(a, v, 0, 100000, &max_hulls)) return kExitUsage;
    } else if (a == "--concavity") {
      if (!value(&v) || !ParseDouble(a, v, 0, 1, &concavity)) return kExitUsage;
    } else if (a == "--json") {
      json = true;
    } else if (a == "--force") {
      options.force = true;
    } else if (a == "--quiet") {
      quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "hullpack collision: unknown option '%s'\n%s", a.c_str(), kUsage);
      return kExitUsage;
    } else if (input.empty()) {
      input = a;
    } else {
      std::fprintf(stderr, "hullpack collision: one input at a time ('%s' and '%s')\n",
                   input.c_str(), a.c_str());
      return kExitUsage;
    }
  }
  if (input.empty() || output.empty()) {
    std::fputs(kUsage, stderr);
    return kExitUsage;
  }
  if (cap > MaxHullVerticesLimit(options.format)) {
    std::fprintf(stderr, "hullpack collision: --max-hull-vertices is at most %d for %s\n",
                 MaxHullVerticesLimit(options.format), RobotFormatName(options.format));
    return kExitUsage;
  }
  options.max_hull_vertices = static_cast<int>(cap);
  vhacd::Parameters& p = options.parameters;
  if (high_quality) p = vhacd::Parameters::High();
  if (resolution) p.resolution = static_cast<uint32_t>(resolution);
  if (max_hulls >= 0) p.max_convex_hulls = static_cast<uint32_t>(max_hulls);
  if (concavity >= 0) p.concavity = concavity;

  Result<Scene> scene = ReadScene(input);
  if (!scene.ok()) {
    std::fprintf(stderr, "hullpack collision: %s\n", scene.status().message().c_str());
    return 1;
  }
  ProgressLine progress(!quiet && !json);
  ProgressObserver observer(progress);
  Result<CollisionExportReport> r =
      ExportCollision(scene.value(), input, output, options, &observer);
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
