// testVHACD: approximate convex decomposition of a mesh file.
//
// Two command lines: V-HACD 2.0's positional form (kept so that its scripts run unchanged) and
// named options (see --help). Every mesh of the input (with its node transforms) is decomposed as
// one soup; the hulls are written as a scene with one mesh per hull. Progress goes to stderr, a
// summary to stdout. Exit status: 0 success, 1 decomposition or I/O error, 64 usage error.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/cli_args.h"
#include "hull_program.h"
#include "vhacd/vhacd.h"

namespace {

constexpr char kPositionalForm[] =
    "V-HACD 2.0's positional form (all 15 arguments):\n"
    "  testVHACD INPUT resolution depth concavity planeDownsampling convexhullDownsampling\n"
    "            alpha beta gamma pca mode maxNumVerticesPerCH minVolumePerCH OUTPUT LOG\n"
    "  e.g. testVHACD in.obj 100000 20 0.0025 4 4 0.05 0.05 0.00125 0 0 64 0.0 out.wrl log.txt";

bool ParseDouble(const std::string& s, double* out) {
  return hullpack::CliArgs::ParseNumber(s, -1e300, 1e300, out).empty();
}

bool ParseUint(const std::string& s, uint32_t* out) {
  long long v = 0;
  if (!hullpack::CliArgs::ParseWholeNumber(s, 0, 0xffffffffLL, &v).empty()) return false;
  *out = static_cast<uint32_t>(v);
  return true;
}

// V-HACD 2.0's positional form: exactly 15 arguments, numbers in slots 2..13.
bool IsPositionalForm(const std::vector<std::string>& args) {
  if (args.size() != 15) return false;
  double d;
  for (size_t i = 1; i <= 12; ++i) {
    if (!ParseDouble(args[i], &d)) return false;
  }
  return true;
}

// What the command line asks for.
struct CommandLine {
  std::string input, output, report_path, log_path;
  vhacd::Parameters parameters;
};

std::optional<int> ParsePositionalForm(const hullpack::CliArgs& cli,
                                       const std::vector<std::string>& a, CommandLine* cmd) {
  vhacd::Parameters& p = cmd->parameters;
  uint32_t pca = 0, mode = 0;
  if (!ParseUint(a[1], &p.resolution) || !ParseUint(a[2], &p.depth) ||
      !ParseDouble(a[3], &p.concavity) || !ParseUint(a[4], &p.plane_downsampling) ||
      !ParseUint(a[5], &p.convexhull_downsampling) || !ParseDouble(a[6], &p.alpha) ||
      !ParseDouble(a[7], &p.beta) || !ParseDouble(a[8], &p.gamma) || !ParseUint(a[9], &pca) ||
      !ParseUint(a[10], &mode) || !ParseUint(a[11], &p.max_vertices_per_hull) ||
      !ParseDouble(a[12], &p.min_volume_per_hull))
    return cli.UsageError("bad number in the positional parameters");
  if (pca > 1 || mode > 1) return cli.UsageError("pca and mode must be 0 or 1");
  p.pca = pca == 1;
  p.mode = static_cast<vhacd::Mode>(mode);
  cmd->input = a[0];
  cmd->output = a[13];
  cmd->log_path = a[14];
  return std::nullopt;
}

std::optional<int> ParseCommandLine(const std::vector<std::string>& args, CommandLine* cmd) {
  vhacd::Parameters& p = cmd->parameters;
  std::vector<std::string> inputs;
  hullpack::CliArgs cli("testVHACD", "INPUT [-o HULLS] [options]",
                        "Approximate convex decomposition (V-HACD 2.0) of every mesh of INPUT "
                        "(.obj .off .wrl .ply .stl\n.glb .gltf .fbx .dae), as one soup.");
  hullpack::AddFileOptions(&cli, &inputs, &cmd->output, &cmd->report_path, &cmd->log_path);
  cli.Value("--quality, --preset", "default|high", "parameter preset the other options refine",
            [&p](const std::string& v) {
              if (v != "default" && v != "high") return "takes default or high, not '" + v + "'";
              p = v == "high" ? vhacd::Parameters::High() : vhacd::Parameters();
              return std::string();
            })
      .First();
  const long long kU32 = 0xffffffffLL;
  cli.Int("--resolution", "N", 0, kU32, &p.resolution, "voxel count");
  cli.Int("--depth", "N", 0, kU32, &p.depth, "most clipping levels");
  cli.Double("--concavity", "X", -1e300, 1e300, &p.concavity,
             "largest concavity of a part, fraction of the diagonal");
  cli.Int("--plane-downsampling", "N", 0, kU32, &p.plane_downsampling,
          "granularity of the search for the best clipping plane");
  cli.Int("--convexhull-downsampling", "N", 0, kU32, &p.convexhull_downsampling,
          "precision of the hull generation while clipping");
  cli.Double("--alpha", "X", -1e300, 1e300, &p.alpha, "bias toward clipping along symmetry planes");
  cli.Double("--beta", "X", -1e300, 1e300, &p.beta, "bias toward clipping along revolution axes");
  cli.Double("--gamma", "X", -1e300, 1e300, &p.gamma, "largest concavity while merging");
  cli.Value("--pca", "0|1", "normalize the mesh by its principal axes first",
            [&p](const std::string& v) {
              if (v != "0" && v != "1") return "takes 0 or 1, not '" + v + "'";
              p.pca = v == "1";
              return std::string();
            });
  cli.Value("--mode", "voxel|tetra", "voxel (0) or tetrahedron (1) sets",
            [&p](const std::string& v) {
              if (v == "0" || v == "voxel") {
                p.mode = vhacd::Mode::kVoxel;
              } else if (v == "1" || v == "tetra" || v == "tetrahedron") {
                p.mode = vhacd::Mode::kTetrahedron;
              } else {
                return "takes voxel, tetra, 0 or 1, not '" + v + "'";
              }
              return std::string();
            });
  cli.Int("--max-vertices", "N", 0, kU32, &p.max_vertices_per_hull, "most vertices per hull");
  cli.Double("--min-volume", "X", -1e300, 1e300, &p.min_volume_per_hull,
             "smallest hull volume, adaptive sampling");
  cli.Int("--max-hulls", "N", 0, kU32, &p.max_convex_hulls, "hull budget (0: no limit)");
  cli.Double("--max-distance", "X", -1e300, 1e300, &p.max_distance,
             "split and merge hulls while they stick out by at most X of the diagonal");
  cli.Int("--threads", "N", 0, kU32, &p.num_threads, "worker threads (0: every core)");
  cli.Double("--max-concavity", "D", -1e300, 1e300, &p.max_concavity,
             "every hull within D x the diagonal of the surface (the reported concavity), as few "
             "hulls as that allows");
  cli.Int("--hulls", "N", 0, kU32, &p.hull_count, "exactly N hulls (when the mesh can give N)");
  cli.Action("--oriented-cuts",
             "with --hulls or --max-concavity on a closed mesh: cut along the parts' own axes\n"
             "too, always (by default both ways are tried and the closer result kept)",
             [&p] { p.oriented_cuts = vhacd::OrientedCuts::kAlways; });
  cli.Action("--no-oriented-cuts", "voxel slices only (no trial with oriented cuts)",
             [&p] { p.oriented_cuts = vhacd::OrientedCuts::kOff; });
  cli.Double("--min-opening", "X", -1e300, 1e300, &p.min_opening,
             "fill rule: cavities behind openings wider than X of the diagonal stay empty");
  cli.Flag("--points-in-place", &p.points_in_place,
           "read a clean mesh's points in place instead of copying them (24 bytes per point\n"
           "less; about twice the time; the same hulls)");
  cli.Epilog(kPositionalForm);
  if (IsPositionalForm(args)) {
    if (std::optional<int> exit_code = ParsePositionalForm(cli, args, cmd)) return exit_code;
  } else {
    if (std::optional<int> exit_code = cli.Parse(args)) return exit_code;
    cmd->input = inputs[0];
  }
  std::string why;
  if (vhacd::ValidateParameters(p, &why) != vhacd::Status::kOk) return cli.UsageError(why);
  return std::nullopt;
}

// Reads every mesh of the input as one soup and decomposes it. An exit code when it cannot.
std::optional<int> Run(const CommandLine& cmd, vhacd::Result* result) {
  std::vector<double> points;
  std::vector<uint32_t> indices;
  if (!hullpack::ReadInput("testVHACD", cmd.input, &points, &indices)) return 1;
  hullpack::ProgressLine progress(cmd.log_path);
  if (!cmd.log_path.empty() && !progress.log_ok()) {
    std::fprintf(stderr, "testVHACD: cannot write %s\n", cmd.log_path.c_str());
    return 1;
  }
  *result = vhacd::Decompose(vhacd::MeshView::FromDouble(points.data(), points.size() / 3,
                                                         indices.data(), indices.size() / 3),
                             cmd.parameters, &progress);
  return std::nullopt;
}

// The summary line on stdout, the report and the hulls; returns the exit code.
int Report(const CommandLine& cmd, const vhacd::Result& r) {
  if (!r.ok()) {
    return hullpack::ReportFailure("testVHACD", cmd.input, cmd.report_path, "vhacd", r);
  }
  const vhacd::Report& rep = r.report;
  std::printf(
      "hulls: %zu (from %u parts), concavity %.4f (mesh->hulls %.4f, hulls->mesh %.4f), IoU %s, "
      "%.2f s\n",
      r.hulls.size(), rep.parts_before_merge, rep.concavity, rep.hausdorff_mesh_to_hulls,
      rep.hausdorff_hulls_to_mesh,
      rep.volume_iou >= 0 ? hullpack::JsonNumber(rep.volume_iou).c_str() : "n/a",
      rep.seconds_total);
  if (!rep.target_reached) std::printf("target not reached: %s\n", rep.target_note.c_str());
  return hullpack::WriteResults("testVHACD", cmd.input, cmd.report_path, cmd.output, "vhacd", r);
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cmd;
  if (std::optional<int> exit_code =
          ParseCommandLine(std::vector<std::string>(argv + 1, argv + argc), &cmd))
    return *exit_code;
  vhacd::Result result;
  if (std::optional<int> exit_code = Run(cmd, &result)) return *exit_code;
  return Report(cmd, result);
}
