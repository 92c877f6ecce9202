#include "hull_program.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "common/file_util.h"
#include "io/scene_io.h"
#include "scene/scene.h"
#include "scene_soup.h"

namespace hullpack {

ProgressLine::ProgressLine(const std::string& log_path) {
  if (!log_path.empty()) log_.open(log_path.c_str());
}

void ProgressLine::OnProgress(double overall, double stage, double, const char* stage_name,
                              const char* operation) {
  const int pct = static_cast<int>(overall + 0.5);
  if (pct == last_ && stage_name == last_stage_) return;
  last_ = pct;
  last_stage_ = stage_name;
  std::fprintf(stderr, "\r%3d%% [%-16s %3d%%] %-24s", pct, stage_name,
               static_cast<int>(stage + 0.5), operation);
  if (pct >= 100) std::fprintf(stderr, "\n");
}

void ProgressLine::OnLog(const char* message) {
  if (log_.is_open()) log_ << message << "\n";
}

std::string JsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

bool WriteDecompositionReport(const std::string& path, const std::string& input,
                              const std::string& method, const vhacd::Result& r) {
  std::ostringstream f;
  const vhacd::Report& rep = r.report;
  f << "{\n  \"input\": \"";
  for (char c : input) {
    if (c == '"' || c == '\\') f << '\\';
    f << c;
  }
  f << "\",\n  \"method\": \"" << method << "\",\n";
  f << "  \"status\": \"" << vhacd::StatusName(r.status) << "\",\n";
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
  const std::string text = f.str();
  return WriteFileAtomically(path, text.data(), text.size()).ok();
}

std::string WriteHullScene(const vhacd::Result& r, const std::string& output) {
  Scene out;
  for (size_t h = 0; h < r.hulls.size(); ++h) {
    Mesh m;
    m.name = "hull_" + std::to_string(h);
    for (double v : r.hulls[h].points) m.positions.push_back(static_cast<float>(v));
    m.indices = r.hulls[h].triangles;
    out.meshes.push_back(std::move(m));
  }
  AddRootNodeForAllMeshes(out, "hulls");
  const Status st = WriteScene(out, output);
  return st.ok() ? "" : st.ToString();
}

std::string ReadSoup(const std::string& input, std::vector<double>* points,
                     std::vector<uint32_t>* indices) {
  Result<Scene> scene = ReadScene(input);
  if (!scene.ok()) return scene.status().ToString();
  SceneSoup(scene.value(), points, indices);
  return "";
}

void AddFileOptions(CliArgs* cli, std::vector<std::string>* inputs, std::string* output,
                    std::string* report_path, std::string* log_path) {
  cli->Positional("INPUT", inputs, 1, 1);
  cli->String("-o, --output", "HULLS", output,
              "the hulls, one mesh each (.obj .wrl .glb .off .ply)");
  cli->String("--report", "FILE.json", report_path,
              "hull count, error measures, per-stage seconds, per-hull volume");
  cli->String("--log", "FILE", log_path, "the library's log messages");
}

bool ReadInput(const char* program, const std::string& input, std::vector<double>* points,
               std::vector<uint32_t>* indices) {
  const std::string read_error = ReadSoup(input, points, indices);
  if (!read_error.empty()) {
    std::fprintf(stderr, "%s: %s\n", program, read_error.c_str());
    return false;
  }
  std::printf("input: %s, %zu points, %zu triangles\n", input.c_str(), points->size() / 3,
              indices->size() / 3);
  return true;
}

int ReportFailure(const char* program, const std::string& input, const std::string& report_path,
                  const std::string& method, const vhacd::Result& r) {
  std::fprintf(stderr, "\n%s: %s: %s\n", program, vhacd::StatusName(r.status), r.message.c_str());
  if (!report_path.empty()) WriteDecompositionReport(report_path, input, method, r);
  return 1;
}

int WriteResults(const char* program, const std::string& input, const std::string& report_path,
                 const std::string& output, const std::string& method, const vhacd::Result& r) {
  if (!report_path.empty()) {
    if (!WriteDecompositionReport(report_path, input, method, r)) {
      std::fprintf(stderr, "%s: cannot write %s\n", program, report_path.c_str());
      return 1;
    }
    std::printf("wrote %s\n", report_path.c_str());
  }
  if (!output.empty()) {
    const std::string write_error = WriteHullScene(r, output);
    if (!write_error.empty()) {
      std::fprintf(stderr, "%s: %s\n", program, write_error.c_str());
      return 1;
    }
    std::printf("wrote %s\n", output.c_str());
  }
  return 0;
}

}  // namespace hullpack
