// testHACD: HACD convex decomposition of a mesh file.
//
// The original tool's positional form:
//   testHACD input.obj minNClusters maxConcavity invertInputFaces addExtraDistPoints
//            addFacesPoints ConnectedComponentsDist targetNTrianglesDecimatedMesh
//   e.g. testHACD input.obj 2 100 0 1 1 30 2000
// Named options (after the input, or after the seven numbers): see --help. Every mesh of the
// input (with its node transforms) is decomposed as one soup. Progress goes to stderr; a summary to
// stdout. Exit status: 0 success, 1 decomposition or I/O error, 64 usage error.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "common/cli_args.h"
#include "hull_program.h"
#include "vhacd/hacd.h"
#include "vhacd/vhacd.h"

namespace {

constexpr char kPositionalForm[] =
    "The original tool's positional form (seven numbers after INPUT; options may follow):\n"
    "  testHACD INPUT minNClusters maxConcavity invertInputFaces addExtraDistPoints\n"
    "           addFacesPoints ConnectedComponentsDist targetNTrianglesDecimatedMesh\n"
    "  e.g. testHACD in.obj 2 100 0 1 1 30 2000   (the recommended line; --preset recommended)";

struct CommandLine {
  std::string input, output, report_path, log_path;
  vhacd::HacdParameters parameters;
};

// The seven numbers of the positional form, or nothing when args[1..7] are not all numbers.
bool IsPositionalForm(const std::vector<std::string>& args) {
  if (args.size() < 8) return false;
  double d = 0;
  for (size_t i = 1; i <= 7; ++i)
    if (!hullpack::CliArgs::ParseNumber(args[i], -1e300, 1e300, &d).empty()) return false;
  return true;
}

std::optional<int> ParseCommandLine(std::vector<std::string> args, CommandLine* cmd) {
  vhacd::HacdParameters& p = cmd->parameters;
  std::vector<std::string> inputs;
  hullpack::CliArgs cli("testHACD", "INPUT [-o HULLS] [options]",
                        "HACD convex decomposition (dual-graph clustering of the surface, after "
                        "quadric\nsimplification) of every mesh of INPUT, as one soup. Defaults: "
                        "the HACD parameter table.");
  hullpack::AddFileOptions(&cli, &inputs, &cmd->output, &cmd->report_path, &cmd->log_path);
  cli.Value("--preset", "default|recommended",
            "the parameter table, or the recommended line 2 100 0 1 1 30 2000",
            [&p](const std::string& v) {
              if (v != "default" && v != "recommended")
                return "takes default or recommended, not '" + v + "'";
              p = v == "recommended" ? vhacd::HacdParameters::Recommended()
                                     : vhacd::HacdParameters();
              return std::string();
            })
      .First();
  auto flag01 = [&cli](const char* names, bool* out, const char* help) {
    cli.Value(names, "0|1", help, [out](const std::string& v) {
      if (v != "0" && v != "1") return "takes 0 or 1, not '" + v + "'";
      *out = v == "1";
      return std::string();
    });
  };
  cli.Int("--min-clusters", "N", 1, 100000, &p.min_clusters, "NClusters: fewest hulls (1)");
  cli.Double("--concavity", "X", 0, 1e7, &p.concavity,
             "Concavity: largest concavity of a merge, in units of a diagonal of\n"
             "2 * scale-factor (100)");
  flag01("--invert-faces", &p.invert_input_faces, "invertInputFaces (0)");
  flag01("--extra-dist-points", &p.add_extra_dist_points,
         "AddExtraDistPoints: rays for bowl-like shapes (1)");
  flag01("--face-points", &p.add_face_points, "AddFacesPoints: a ray per triangle centre (1)");
  cli.Double("--connect-dist", "X", -1, 1e7, &p.connect_distance,
             "ConnectDist: join pieces closer than this; -1: never (30)");
  cli.Int("--target-triangles", "N", 0, 2147483647LL, &p.target_triangles,
          "NTargetTrianglesDecimatedMesh: simplify first; 0: off (1000)");
  cli.Int("--max-vertices", "N", 4, 1024, &p.max_vertices_per_hull, "NVerticesPerCH (100)");
  cli.Double("--scale-factor", "X", 1, 1e6, &p.scale_factor, "ScaleFactor (1000)");
  cli.Double("--small-cluster", "X", 0, 100, &p.small_cluster_threshold,
             "SmallClusterThreshold, % of the area (0.25)");
  cli.Double("--volume-weight", "X", 0, 1e3, &p.volume_weight, "VolumeWeight (0)");
  cli.Double("--compacity-weight", "X", 0, 1e3, &p.compacity_weight, "CompacityWeight (0.0001)");
  cli.Double("--flat-threshold", "X", 0, 100, &p.flat_region_threshold,
             "FlatRegionThreshold, % of ScaleFactor (1)");
  cli.Double("--computation-weight", "X", 0, 1e3, &p.computation_weight,
             "ComputationWeight (0.01)");
  cli.Int("--max-hulls", "N", 0, 100000, &p.max_clusters,
          "hull budget: merge on past the concavity limit down to N (0: none)");
  cli.Double("--max-concavity", "D", 0, 1, &p.max_concavity,
             "every hull within D x the diagonal of the surface (the reported\n"
             "concavity): replaces --concavity, tightened up to 3 times");
  cli.Int("--hulls", "N", 0, 100000, &p.hull_count,
          "exactly N hulls (when the surface can give N)");
  cli.Int("--threads", "N", 0, 256, &p.num_threads, "worker threads (0: every core)");
  cli.Action("--no-report", "skip the error measures (faster)",
             [&p]() { p.compute_report = false; });
  cli.Epilog(kPositionalForm);
  std::vector<std::string> rest = args;
  if (IsPositionalForm(args)) {
    // The seven numbers become the named options they stand for, so that options given after
    // them refine them.
    const char* names[7] = {"--min-clusters",      "--concavity",   "--invert-faces",
                            "--extra-dist-points", "--face-points", "--connect-dist",
                            "--target-triangles"};
    rest.assign(1, args[0]);
    for (int i = 0; i < 7; ++i) {
      rest.push_back(names[i]);
      rest.push_back(args[1 + i]);
    }
    rest.insert(rest.end(), args.begin() + 8, args.end());
  }
  if (std::optional<int> exit_code = cli.Parse(rest)) return exit_code;
  cmd->input = inputs[0];
  std::string why;
  if (vhacd::ValidateHacdParameters(p, &why) != vhacd::Status::kOk) return cli.UsageError(why);
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cmd;
  if (std::optional<int> exit_code =
          ParseCommandLine(std::vector<std::string>(argv + 1, argv + argc), &cmd))
    return *exit_code;
  const std::string& input = cmd.input;
  const std::string& output = cmd.output;
  const std::string& report_path = cmd.report_path;
  const std::string& log_path = cmd.log_path;
  const vhacd::HacdParameters& p = cmd.parameters;

  std::vector<double> points;
  std::vector<uint32_t> indices;
  if (!hullpack::ReadInput("testHACD", input, &points, &indices)) return 1;
  hullpack::ProgressLine progress(log_path);
  if (!log_path.empty() && !progress.log_ok()) {
    std::fprintf(stderr, "testHACD: cannot write %s\n", log_path.c_str());
    return 1;
  }
  const vhacd::Result r =
      vhacd::DecomposeHacd(vhacd::MeshView::FromDouble(points.data(), points.size() / 3,
                                                       indices.data(), indices.size() / 3),
                           p, &progress);
  if (!r.ok()) {
    return hullpack::ReportFailure("testHACD", input, report_path, "hacd", r);
  }
  const vhacd::Report& rep = r.report;
  if (rep.concavity >= 0)
    std::printf(
        "hulls: %zu (from %u triangles), concavity %.4f (mesh->hulls %.4f, hulls->mesh %.4f), "
        "IoU %s, %.2f s\n",
        r.hulls.size(), rep.parts_before_merge, rep.concavity, rep.hausdorff_mesh_to_hulls,
        rep.hausdorff_hulls_to_mesh,
        rep.volume_iou >= 0 ? hullpack::JsonNumber(rep.volume_iou).c_str() : "n/a",
        rep.seconds_total);
  else
    std::printf("hulls: %zu (from %u triangles), %.2f s\n", r.hulls.size(), rep.parts_before_merge,
                rep.seconds_total);
  if (!rep.target_reached) std::printf("target not reached: %s\n", rep.target_note.c_str());
  return hullpack::WriteResults("testHACD", input, report_path, output, "hacd", r);
}
