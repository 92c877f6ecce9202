// testHACD: HACD convex decomposition of a mesh file.
//
// The original tool's positional form:
//   testHACD input.obj minNClusters maxConcavity invertInputFaces addExtraDistPoints
//            addFacesPoints ConnectedComponentsDist targetNTrianglesDecimatedMesh
//   e.g. testHACD input.obj 2 100 0 1 1 30 2000
// Named flags (after the input, or after the seven numbers): see kUsage below. Every mesh of the
// input (with its node transforms) is decomposed as one soup. Progress goes to stderr; a summary to
// stdout. Exit status: 0 success, 1 decomposition or I/O error, 64 usage error.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "hull_program.h"
#include "vhacd/hacd.h"
#include "vhacd/vhacd.h"

namespace {

using hullpack::ParseDouble;
using hullpack::ParseUint;

constexpr int kUsageError = 64;

const char kUsage[] =
    "usage: testHACD input minNClusters maxConcavity invertInputFaces addExtraDistPoints\n"
    "                addFacesPoints ConnectedComponentsDist targetNTrianglesDecimatedMesh\n"
    "         e.g. testHACD input.obj 2 100 0 1 1 30 2000   (the recommended line)\n"
    "       testHACD input [options]   (options may also follow the seven numbers)\n"
    "options (defaults: the HACD parameter table):\n"
    "  -o, --output FILE          hulls as .obj, .wrl, .glb, .off or .ply (one mesh per hull)\n"
    "  --report FILE.json         hull list, error measures, stage times\n"
    "  --log FILE                 the library's log messages\n"
    "  --preset default|recommended   the parameter table / `2 100 0 1 1 30 2000`\n"
    "  --min-clusters N           NClusters: fewest hulls [1, 100000] (1)\n"
    "  --concavity X              Concavity: largest concavity of a merge, in units of a\n"
    "                             2*scale-factor diagonal [0, 1e7] (100)\n"
    "  --invert-faces 0|1         invertInputFaces (0)\n"
    "  --extra-dist-points 0|1    AddExtraDistPoints: rays for bowl-like shapes (1)\n"
    "  --face-points 0|1          AddFacesPoints: a ray per triangle centre (1)\n"
    "  --connect-dist X           ConnectDist: join pieces closer than this; -1 = never [-1, 1e7] "
    "(30)\n"
    "  --target-triangles N       NTargetTrianglesDecimatedMesh: decimate first; 0 = off (1000)\n"
    "  --max-vertices N           NVerticesPerCH [4, 1024] (100)\n"
    "  --scale-factor X           ScaleFactor [1, 1e6] (1000)\n"
    "  --small-cluster X          SmallClusterThreshold, % of the area [0, 100] (0.25)\n"
    "  --volume-weight X          VolumeWeight [0, 1000] (0)\n"
    "  --compacity-weight X       CompacityWeight [0, 1000] (0.0001)\n"
    "  --flat-threshold X         FlatRegionThreshold, % of ScaleFactor [0, 100] (1)\n"
    "  --computation-weight X     ComputationWeight [0, 1000] (0.01)\n"
    "  --threads N                0 = every core (0)\n"
    "  --no-report                skip the error measures (faster)\n"
    "  -h, --help                 this text\n"
    "  --version                  the library version\n";

int Usage(const char* why) {
  if (why != nullptr) std::fprintf(stderr, "testHACD: %s\n", why);
  std::fputs(kUsage, stderr);
  return kUsageError;
}

bool ParseBool(const char* s, bool* out) {
  uint32_t u = 0;
  if (!ParseUint(s, &u) || u > 1) return false;
  *out = u == 1;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (std::strcmp(argv[i], "--version") == 0) {
      std::printf("testHACD (vhacd %d.%d.%d)\n", VHACD_VERSION / 10000, VHACD_VERSION / 100 % 100,
                  VHACD_VERSION % 100);
      return 0;
    }
  }
  if (argc < 2) return Usage(nullptr);
  if (argv[1][0] == '-') return Usage("the input file comes first");
  std::string input = argv[1], output, report_path, log_path;
  vhacd::HacdParameters p;
  // Positional form: 7 numbers after the input (named flags may follow).
  bool positional = argc >= 9;
  for (int i = 2; positional && i < 9; ++i) {
    double d;
    positional = ParseDouble(argv[i], &d);
  }
  if (positional) {
    double connect = 0;
    if (!ParseUint(argv[2], &p.min_clusters) || !ParseDouble(argv[3], &p.concavity) ||
        !ParseBool(argv[4], &p.invert_input_faces) ||
        !ParseBool(argv[5], &p.add_extra_dist_points) || !ParseBool(argv[6], &p.add_face_points) ||
        !ParseDouble(argv[7], &connect) || !ParseUint(argv[8], &p.target_triangles))
      return Usage("bad number in the positional parameters (flags must be 0 or 1)");
    p.connect_distance = connect;
  }
  const int first_flag = positional ? 9 : 2;
  {
    for (int i = first_flag; i + 1 < argc; i += 2) {
      if (std::strcmp(argv[i], "--preset") != 0) continue;
      if (std::strcmp(argv[i + 1], "recommended") == 0)
        p = vhacd::HacdParameters::Recommended();
      else if (std::strcmp(argv[i + 1], "default") == 0)
        p = vhacd::HacdParameters();
      else
        return Usage("--preset takes default or recommended");
    }
    for (int i = first_flag; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--no-report") {
        p.compute_report = false;
        continue;
      }
      if (i + 1 >= argc) return Usage(("missing value after " + a).c_str());
      const char* v = argv[++i];
      bool ok = true;
      if (a == "-o" || a == "--output")
        output = v;
      else if (a == "--report")
        report_path = v;
      else if (a == "--log")
        log_path = v;
      else if (a == "--preset")
        continue;
      else if (a == "--min-clusters")
        ok = ParseUint(v, &p.min_clusters);
      else if (a == "--concavity")
        ok = ParseDouble(v, &p.concavity);
      else if (a == "--invert-faces")
        ok = ParseBool(v, &p.invert_input_faces);
      else if (a == "--extra-dist-points")
        ok = ParseBool(v, &p.add_extra_dist_points);
      else if (a == "--face-points")
        ok = ParseBool(v, &p.add_face_points);
      else if (a == "--connect-dist")
        ok = ParseDouble(v, &p.connect_distance);
      else if (a == "--target-triangles")
        ok = ParseUint(v, &p.target_triangles);
      else if (a == "--max-vertices")
        ok = ParseUint(v, &p.max_vertices_per_hull);
      else if (a == "--scale-factor")
        ok = ParseDouble(v, &p.scale_factor);
      else if (a == "--small-cluster")
        ok = ParseDouble(v, &p.small_cluster_threshold);
      else if (a == "--volume-weight")
        ok = ParseDouble(v, &p.volume_weight);
      else if (a == "--compacity-weight")
        ok = ParseDouble(v, &p.compacity_weight);
      else if (a == "--flat-threshold")
        ok = ParseDouble(v, &p.flat_region_threshold);
      else if (a == "--computation-weight")
        ok = ParseDouble(v, &p.computation_weight);
      else if (a == "--threads")
        ok = ParseUint(v, &p.num_threads);
      else
        return Usage(("unknown option " + a).c_str());
      if (!ok) return Usage(("bad value for " + a).c_str());
    }
  }
  std::string why;
  if (vhacd::ValidateHacdParameters(p, &why) != vhacd::Status::kOk) return Usage(why.c_str());

  std::vector<double> points;
  std::vector<uint32_t> indices;
  const std::string read_error = hullpack::ReadSoup(input, &points, &indices);
  if (!read_error.empty()) {
    std::fprintf(stderr, "testHACD: %s\n", read_error.c_str());
    return 1;
  }
  std::printf("input: %s, %zu points, %zu triangles\n", input.c_str(), points.size() / 3,
              indices.size() / 3);
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
    std::fprintf(stderr, "\ntestHACD: %s: %s\n", vhacd::StatusName(r.status), r.message.c_str());
    if (!report_path.empty()) hullpack::WriteDecompositionReport(report_path, input, "hacd", r);
    return 1;
  }
  const vhacd::Report& rep = r.report;
  std::printf(
      "hulls: %zu (from %u triangles), concavity %.4f (mesh->hulls %.4f, hulls->mesh %.4f), IoU "
      "%s, %.2f s\n",
      r.hulls.size(), rep.parts_before_merge, rep.concavity, rep.hausdorff_mesh_to_hulls,
      rep.hausdorff_hulls_to_mesh,
      rep.volume_iou >= 0 ? hullpack::JsonNumber(rep.volume_iou).c_str() : "n/a",
      rep.seconds_total);
  if (!report_path.empty()) {
    if (!hullpack::WriteDecompositionReport(report_path, input, "hacd", r)) {
      std::fprintf(stderr, "testHACD: cannot write %s\n", report_path.c_str());
      return 1;
    }
    std::printf("wrote %s\n", report_path.c_str());
  }
  if (!output.empty()) {
    const std::string write_error = hullpack::WriteHullScene(r, output);
    if (!write_error.empty()) {
      std::fprintf(stderr, "testHACD: %s\n", write_error.c_str());
      return 1;
    }
    std::printf("wrote %s\n", output.c_str());
  }
  return 0;
}
