// testVHACD: approximate convex decomposition of a mesh file.
//
// The V-HACD 2.0 positional form:
//   testVHACD input.obj resolution depth concavity planeDownsampling convexhullDownsampling
//             alpha beta gamma pca mode maxNumVerticesPerCH minVolumePerCH output.wrl log.txt
//   e.g. testVHACD input.obj 100000 20 0.0025 4 4 0.05 0.05 0.00125 0 0 64 0.0 output.wrl log.txt
// Named flags:
//   testVHACD input.obj [-o hulls.obj|.wrl|.glb|.off|.ply] [--report report.json] [--log log.txt]
//             [--preset|--quality default|high] [--resolution N] [--depth N] [--concavity X]
//             [--plane-downsampling N] [--convexhull-downsampling N] [--alpha X] [--beta X]
//             [--gamma X] [--pca 0|1] [--mode 0|1|voxel|tetra] [--max-vertices N] [--min-volume X]
//             [--max-hulls N] [--max-distance X] [--threads N] [--max-concavity D] [--hulls N]
//             [--min-opening X]
// --max-concavity D: every hull within D x the bounding-box diagonal of the surface (the reported
// concavity), as few hulls as that allows; --hulls N: exactly N hulls.
// Every mesh of the input (with its node transforms) is decomposed as one soup. The hulls are
// written as a scene with one mesh per hull. Progress goes to stderr; a summary to stdout.
// Exit status: 0 success, 1 decomposition or I/O error, 2 usage error.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "io/scene_io.h"
#include "scene/scene.h"
#include "scene_soup.h"
#include "vhacd/vhacd.h"

namespace {

int Usage(const char* why) {
  if (why != nullptr) std::fprintf(stderr, "testVHACD: %s\n", why);
  std::fprintf(
      stderr,
      "usage: testVHACD input resolution depth concavity planeDownsampling convexhullDownsampling "
      "alpha beta gamma pca mode maxNumVerticesPerCH minVolumePerCH output log\n"
      "       testVHACD input [-o hulls.obj|.wrl|.glb] [--report report.json] [--log log.txt]\n"
      "                 [--preset|--quality default|high] [--resolution N] [--depth N] "
      "[--concavity X]\n"
      "                 [--plane-downsampling N] [--convexhull-downsampling N] [--alpha X]\n"
      "                 [--beta X] [--gamma X] [--pca 0|1] [--mode 0|1|voxel|tetra] "
      "[--max-vertices N]\n"
      "                 [--min-volume X] [--max-hulls N] [--max-distance X] [--threads N]\n"
      "                 [--max-concavity D] [--hulls N] [--min-opening X]\n");
  return 2;
}

bool ParseDouble(const char* s, double* out) {
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (end == s || *end != '\0' || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

bool ParseUint(const char* s, uint32_t* out) {
  char* end = nullptr;
  const long long v = std::strtoll(s, &end, 10);
  if (end == s || *end != '\0' || v < 0 || v > 0xffffffffLL) return false;
  *out = static_cast<uint32_t>(v);
  return true;
}

class Progress : public vhacd::Observer {
 public:
  explicit Progress(const std::string& log_path) {
    if (!log_path.empty()) log_.open(log_path.c_str());
  }
  bool log_ok() const { return log_.good(); }
  void OnProgress(double overall, double stage, double, const char* stage_name,
                  const char* operation) override {
    const int pct = static_cast<int>(overall + 0.5);
    if (pct == last_ && stage_name == last_stage_) return;
    last_ = pct;
    last_stage_ = stage_name;
    std::fprintf(stderr, "\r%3d%% [%-16s %3d%%] %-24s", pct, stage_name,
                 static_cast<int>(stage + 0.5), operation);
    if (pct >= 100) std::fprintf(stderr, "\n");
  }
  void OnLog(const char* message) override {
    if (log_.is_open()) log_ << message << "\n";
  }

 private:
  std::ofstream log_;
  int last_ = -1;
  std::string last_stage_;
};

std::string JsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

bool WriteReport(const std::string& path, const std::string& input, const vhacd::Result& r) {
  std::ofstream f(path.c_str());
  if (!f) return false;
  const vhacd::Report& rep = r.report;
  f << "{\n  \"input\": \"";
  for (char c : input) {
    if (c == '"' || c == '\\') f << '\\';
    f << c;
  }
  f << "\",\n  \"status\": \"" << vhacd::StatusName(r.status) << "\",\n";
  f << "  \"hull_count\": " << r.hulls.size() << ",\n";
  f << "  \"closed_input\": " << (rep.closed_input ? "true" : "false") << ",\n";
  f << "  \"volume_iou\": " << JsonNumber(rep.volume_iou) << ",\n";
  f << "  \"hausdorff_mesh_to_hulls\": " << JsonNumber(rep.hausdorff_mesh_to_hulls) << ",\n";
  f << "  \"hausdorff_hulls_to_mesh\": " << JsonNumber(rep.hausdorff_hulls_to_mesh) << ",\n";
  f << "  \"concavity\": " << JsonNumber(rep.concavity) << ",\n";
  f << "  \"voxel_count\": " << rep.voxel_count << ",\n";
  f << "  \"tetrahedron_count\": " << rep.tetrahedron_count << ",\n";
  f << "  \"parts_before_merge\": " << rep.parts_before_merge << ",\n";
  f << "  \"target_reached\": " << (rep.target_reached ? "true" : "false") << ",\n";
  f << "  \"target_note\": \"";
  for (char c : rep.target_note) {
    if (c == '"' || c == '\\') f << '\\';
    f << c;
  }
  f << "\",\n";
  f << "  \"attempts\": " << rep.attempts << ",\n";
  f << "  \"seconds\": {\"voxelize\": " << JsonNumber(rep.seconds_voxelize)
    << ", \"fill\": " << JsonNumber(rep.seconds_fill)
    << ", \"tetrahedra\": " << JsonNumber(rep.seconds_tetrahedra)
    << ", \"distance\": " << JsonNumber(rep.seconds_distance)
    << ", \"clip\": " << JsonNumber(rep.seconds_clip)
    << ", \"hulls\": " << JsonNumber(rep.seconds_hulls)
    << ", \"merge\": " << JsonNumber(rep.seconds_merge)
    << ", \"simplify\": " << JsonNumber(rep.seconds_simplify)
    << ", \"report\": " << JsonNumber(rep.seconds_report)
    << ", \"total\": " << JsonNumber(rep.seconds_total) << "},\n";
  f << "  \"hulls\": [";
  for (size_t i = 0; i < rep.hulls.size(); ++i) {
    f << (i ? ",\n    " : "\n    ") << "{\"vertices\": " << rep.hulls[i].vertex_count
      << ", \"volume\": " << JsonNumber(rep.hulls[i].volume)
      << ", \"concavity\": " << JsonNumber(rep.hulls[i].concavity)
      << ", \"distance\": " << JsonNumber(rep.hulls[i].distance) << "}";
  }
  f << (rep.hulls.empty() ? "]\n" : "\n  ]\n") << "}\n";
  return f.good();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return Usage(nullptr);
  std::string input = argv[1], output, report_path, log_path;
  vhacd::Parameters p;
  // Positional form: exactly 15 arguments after the program name, numbers in slots 2..13.
  bool positional = argc == 16;
  for (int i = 2; positional && i <= 13; ++i) {
    double d;
    positional = ParseDouble(argv[i], &d);
  }
  if (positional) {
    uint32_t pca = 0, mode = 0;
    if (!ParseUint(argv[2], &p.resolution) || !ParseUint(argv[3], &p.depth) ||
        !ParseDouble(argv[4], &p.concavity) || !ParseUint(argv[5], &p.plane_downsampling) ||
        !ParseUint(argv[6], &p.convexhull_downsampling) || !ParseDouble(argv[7], &p.alpha) ||
        !ParseDouble(argv[8], &p.beta) || !ParseDouble(argv[9], &p.gamma) ||
        !ParseUint(argv[10], &pca) || !ParseUint(argv[11], &mode) ||
        !ParseUint(argv[12], &p.max_vertices_per_hull) ||
        !ParseDouble(argv[13], &p.min_volume_per_hull))
      return Usage("bad number in the positional parameters");
    if (pca > 1 || mode > 1) return Usage("pca and mode must be 0 or 1");
    p.pca = pca == 1;
    p.mode = static_cast<vhacd::Mode>(mode);
    output = argv[14];
    log_path = argv[15];
  } else {
    // The preset first, so that the other flags change it whatever their order.
    for (int i = 2; i + 1 < argc; i += 2) {
      const std::string a = argv[i];
      if (a != "--preset" && a != "--quality") continue;
      if (std::strcmp(argv[i + 1], "high") == 0)
        p = vhacd::Parameters::High();
      else if (std::strcmp(argv[i + 1], "default") == 0)
        p = vhacd::Parameters();
      else
        return Usage(("bad value for " + a).c_str());
    }
    for (int i = 2; i < argc; ++i) {
      const std::string a = argv[i];
      if (i + 1 >= argc) return Usage(("missing value after " + a).c_str());
      const char* v = argv[++i];
      uint32_t u = 0;
      double d = 0;
      bool ok = true;
      if (a == "-o" || a == "--output")
        output = v;
      else if (a == "--report")
        report_path = v;
      else if (a == "--log")
        log_path = v;
      else if (a == "--preset" || a == "--quality")
        continue;  // applied above
      else if (a == "--resolution")
        ok = ParseUint(v, &p.resolution);
      else if (a == "--depth")
        ok = ParseUint(v, &p.depth);
      else if (a == "--concavity")
        ok = ParseDouble(v, &p.concavity);
      else if (a == "--plane-downsampling")
        ok = ParseUint(v, &p.plane_downsampling);
      else if (a == "--convexhull-downsampling")
        ok = ParseUint(v, &p.convexhull_downsampling);
      else if (a == "--alpha")
        ok = ParseDouble(v, &p.alpha);
      else if (a == "--beta")
        ok = ParseDouble(v, &p.beta);
      else if (a == "--gamma")
        ok = ParseDouble(v, &p.gamma);
      else if (a == "--pca") {
        ok = ParseUint(v, &u) && u <= 1;
        p.pca = u == 1;
      } else if (a == "--mode") {
        if (std::strcmp(v, "tetra") == 0 || std::strcmp(v, "tetrahedron") == 0)
          u = 1;
        else if (std::strcmp(v, "voxel") == 0)
          u = 0;
        else
          ok = ParseUint(v, &u) && u <= 1;
        p.mode = static_cast<vhacd::Mode>(u);
      } else if (a == "--max-vertices")
        ok = ParseUint(v, &p.max_vertices_per_hull);
      else if (a == "--min-volume")
        ok = ParseDouble(v, &p.min_volume_per_hull);
      else if (a == "--max-hulls")
        ok = ParseUint(v, &p.max_convex_hulls);
      else if (a == "--max-distance")
        ok = ParseDouble(v, &d) && (p.max_distance = d, true);
      else if (a == "--threads")
        ok = ParseUint(v, &p.num_threads);
      else if (a == "--max-concavity")
        ok = ParseDouble(v, &p.max_concavity);
      else if (a == "--hulls")
        ok = ParseUint(v, &p.hull_count) && p.hull_count > 0;
      else if (a == "--min-opening")
        ok = ParseDouble(v, &p.min_opening);
      else
        return Usage(("unknown option " + a).c_str());
      if (!ok) return Usage(("bad value for " + a).c_str());
    }
  }
  std::string why;
  if (vhacd::ValidateParameters(p, &why) != vhacd::Status::kOk) return Usage(why.c_str());

  hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(input);
  if (!scene.ok()) {
    std::fprintf(stderr, "testVHACD: %s\n", scene.status().ToString().c_str());
    return 1;
  }
  std::vector<double> points;
  std::vector<uint32_t> indices;
  hullpack::FlattenScene(scene.value(), &points, &indices);
  std::printf("input: %s, %zu points, %zu triangles\n", input.c_str(), points.size() / 3,
              indices.size() / 3);

  Progress progress(log_path);
  if (!log_path.empty() && !progress.log_ok()) {
    std::fprintf(stderr, "testVHACD: cannot write %s\n", log_path.c_str());
    return 1;
  }
  const vhacd::Result r =
      vhacd::Decompose(vhacd::MeshView::FromDouble(points.data(), points.size() / 3, indices.data(),
                                                   indices.size() / 3),
                       p, &progress);
  if (!r.ok()) {
    std::fprintf(stderr, "\ntestVHACD: %s: %s\n", vhacd::StatusName(r.status), r.message.c_str());
    if (!report_path.empty()) WriteReport(report_path, input, r);
    return 1;
  }
  const vhacd::Report& rep = r.report;
  std::printf(
      "hulls: %zu (from %u parts), concavity %.4f (mesh->hulls %.4f, hulls->mesh %.4f), IoU %s, "
      "%.2f s\n",
      r.hulls.size(), rep.parts_before_merge, rep.concavity, rep.hausdorff_mesh_to_hulls,
      rep.hausdorff_hulls_to_mesh, rep.volume_iou >= 0 ? JsonNumber(rep.volume_iou).c_str() : "n/a",
      rep.seconds_total);
  if (!rep.target_reached) std::printf("target not reached: %s\n", rep.target_note.c_str());

  if (!report_path.empty()) {
    if (!WriteReport(report_path, input, r)) {
      std::fprintf(stderr, "testVHACD: cannot write %s\n", report_path.c_str());
      return 1;
    }
    std::printf("wrote %s\n", report_path.c_str());
  }
  if (!output.empty()) {
    hullpack::Scene out;
    for (size_t h = 0; h < r.hulls.size(); ++h) {
      hullpack::Mesh m;
      m.name = "hull_" + std::to_string(h);
      for (double v : r.hulls[h].points) m.positions.push_back(static_cast<float>(v));
      m.indices = r.hulls[h].triangles;
      out.meshes.push_back(std::move(m));
    }
    hullpack::AddRootNodeForAllMeshes(out, "hulls");
    const hullpack::Status st = hullpack::WriteScene(out, output);
    if (!st.ok()) {
      std::fprintf(stderr, "testVHACD: %s\n", st.ToString().c_str());
      return 1;
    }
    std::printf("wrote %s\n", output.c_str());
  }
  return 0;
}
