// pack_speed_bench: `hullpack pack` at defaults (hulls included) on large meshes made by midpoint
// subdivision, each run in its own process: wall and CPU seconds (median over repeats), CPU / wall,
// time per triangle, peak memory against the decoded mesh arrays, the seconds of each stage, and
// the bytes checked against a single-thread run. Writes OUT/pack_speed.csv and
// OUT/pack_speed.svg (time per triangle against triangles).
//
//   pack_speed_bench MESH... -o OUT [--levels 0,1,2] [--repeats 3] [--timeout S] [--keep-meshes]
//   e.g. pack_speed_bench bunny.obj igea.obj -o /tmp/speed --levels 0,1,2
//
// Each MESH (any format hullpack reads; a scene is flattened with its node transforms) is
// subdivided 0, 1, 2, ... times (each level: 4x the triangles) and written as OBJ under OUT, so the
// runs include loading, as a user's do. On a machine shared with other work, wall time grows and
// CPU / wall falls; CPU seconds per triangle is the figure that does not depend on it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "bench/child_process.h"
#include "bench/svg_plot.h"
#include "common/cli_args.h"
#include "common/file_util.h"
#include "common/malloc_policy.h"
#include "hullpack/cli_util.h"
#include "io/scene_io.h"
#include "mesh/flatten.h"
#include "mesh/subdivide.h"
#include "pipeline/pack.h"

namespace {

using hullpack::ChildResult;
using hullpack::PayloadReader;
using hullpack::PayloadWriter;

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

const char* const kStages[] = {"load", "repair", "prune", "meshes", "assemble", "write"};
constexpr int kStageCount = 6;

struct Run {
  bool ok = false;
  std::string error;
  double wall = 0, cpu = 0, peak_mb = 0;
  double stage[kStageCount] = {};
  double total = 0;  // the report's seconds_total
};

// One `hullpack pack` in a child process.
Run PackInChild(const std::string& input, const std::string& output, int threads, double timeout) {
  const ChildResult child = hullpack::RunInChild(
      [&]() {
        hullpack::PackOptions options;
        if (threads > 0) {
          options.threads = threads;
          options.collision.parameters.num_threads = static_cast<uint32_t>(threads);
        }
        const auto start = std::chrono::steady_clock::now();
        hullpack::Result<hullpack::PackResult> packed = hullpack::PackInput(input, options);
        hullpack::Result<hullpack::PackReport> r =
            hullpack::Status(hullpack::StatusCode::kInternal, "");
        if (packed.ok()) {
          // Written as `hullpack pack` writes it; its seconds are the write stage's.
          const auto t = std::chrono::steady_clock::now();
          const hullpack::Status written = hullpack::WriteFileAtomically(output, packed->glb);
          const auto end = std::chrono::steady_clock::now();
          r = std::move(packed->report);
          r->seconds_write = std::chrono::duration<double>(end - t).count();
          r->seconds_total = std::chrono::duration<double>(end - start).count();
          if (!written.ok()) r = written;
        } else {
          r = packed.status();
        }
        PayloadWriter w;
        w.U64(r.ok() ? 1 : 0);
        if (r.ok()) {
          const double s[kStageCount] = {r->seconds_load,   r->seconds_repair,   r->seconds_prune,
                                         r->seconds_meshes, r->seconds_assemble, r->seconds_write};
          for (double x : s) w.Double(x);
          w.Double(r->seconds_total);
        } else {
          const std::string& m = r.status().message();
          w.Bytes(m.data(), m.size());
        }
        return w.Take();
      },
      timeout);
  Run run;
  run.wall = child.wall_seconds;
  run.cpu = child.cpu_seconds;
  run.peak_mb = child.peak_rss_mb;
  if (!child.ok) {
    run.error = child.error;
    return run;
  }
  PayloadReader r(child.payload);
  uint64_t ok = 0;
  r.U64(&ok);
  if (!ok) {
    run.error.assign(child.payload.begin() + 8, child.payload.end());
    return run;
  }
  for (double& s : run.stage) r.Double(&s);
  r.Double(&run.total);
  run.ok = r.ok();
  if (!run.ok) run.error = "short payload";
  return run;
}

struct Row {
  std::string name;
  size_t triangles = 0, vertices = 0;
  // Positions + indices as the scene model holds them, in the unit of the peak (ru_maxrss / 1024,
  // MiB), so that their ratio compares like with like.
  double decoded_mb = 0;
  std::vector<Run> runs;
  bool identical = false;
  double Wall() const {
    std::vector<double> v;
    for (const Run& r : runs) v.push_back(r.wall);
    return Median(v);
  }
  double Cpu() const {
    std::vector<double> v;
    for (const Run& r : runs) v.push_back(r.cpu);
    return Median(v);
  }
  double Peak() const {
    std::vector<double> v;
    for (const Run& r : runs) v.push_back(r.peak_mb);
    return Median(v);
  }
  double Stage(int s) const {
    std::vector<double> v;
    for (const Run& r : runs) v.push_back(r.stage[s]);
    return Median(v);
  }
};

}  // namespace

int main(int argc, char** argv) {
  hullpack::ConfigureMalloc();  // as hullpack does: the packs run in children of this process
  std::vector<std::string> meshes;
  std::string out, level_list = "0,1,2";
  int repeats = 3;
  double timeout = 900;
  bool keep_meshes = false;
  hullpack::CliArgs cli("pack_speed_bench", "MESH... -o OUT [options]",
                        "hullpack pack at defaults (with hulls) on each MESH subdivided 0, 1, 2, "
                        "... times\n"
                        "  (4x the triangles per level), each run in its own process; writes\n"
                        "  OUT/pack_speed.csv and OUT/pack_speed.svg");
  cli.Positional("MESH", &meshes, 1);
  cli.String("-o, --output", "OUT", &out, "an existing folder for the meshes, CSV and plot")
      .Required();
  cli.String("--levels", "L,L,...", &level_list, "subdivision levels (default 0,1,2; each 0-6)");
  cli.Int("--repeats", "N", 1, 100, &repeats, "runs per mesh, median (default 3)");
  cli.Double("--timeout", "S", 1, 1e6, &timeout, "longest run, seconds (default 900)");
  cli.Flag("--keep-meshes", &keep_meshes,
           "keep the subdivided OBJ files in OUT (to profile a run of them)");
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  std::vector<int> levels;
  for (const char* p = level_list.c_str(); *p;) {
    char* end = nullptr;
    const long v = std::strtol(p, &end, 10);
    if (end == p || v < 0 || v > 6 || (*end && *end != ',')) {
      return cli.UsageError("--levels takes levels 0-6 separated by commas, not '" + level_list +
                            "'");
    }
    levels.push_back(static_cast<int>(v));
    p = *end == ',' ? end + 1 : end;
  }
  if (!hullpack::IsDirectory(out)) return cli.UsageError(out + ": no such folder");

  std::vector<Row> rows;
  for (const std::string& mesh : meshes) {
    for (int level : levels) {
      Row row;
      row.name = hullpack::FileStem(mesh) + "_x" + std::to_string(level);
      const std::string obj = out + "/" + row.name + ".obj";
      // Made in a child, so this process stays small and each run's peak is its own.
      const ChildResult made = hullpack::RunInChild(
          [&]() {
            PayloadWriter w;
            hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(mesh);
            if (!scene.ok()) return w.Take();
            hullpack::Scene dense;
            dense.meshes.push_back(
                hullpack::SubdivideMidpoint(hullpack::FlattenScene(scene.value()), level));
            dense.meshes[0].name = row.name;
            if (!hullpack::WriteScene(dense, obj).ok()) return w.Take();
            w.U64(dense.meshes[0].triangle_count());
            w.U64(dense.meshes[0].vertex_count());
            return w.Take();
          },
          timeout);
      uint64_t triangles = 0, vertices = 0;
      PayloadReader r(made.payload);
      if (!made.ok || !r.U64(&triangles) || !r.U64(&vertices)) {
        std::fprintf(stderr, "pack_speed_bench: %s: cannot read or subdivide it\n", mesh.c_str());
        return 1;
      }
      row.triangles = triangles;
      row.vertices = vertices;
      row.decoded_mb = (12.0 * vertices + 12.0 * triangles) / (1024.0 * 1024.0);
      std::fprintf(stderr, "%s: %zu triangles\n", row.name.c_str(), row.triangles);
      const std::string packed = out + "/" + row.name + ".packed.glb";
      const std::string single = out + "/" + row.name + ".1thread.glb";
      for (int k = 0; k < repeats; ++k) {
        row.runs.push_back(PackInChild(obj, packed, 0, timeout));
        if (!row.runs.back().ok) {
          std::fprintf(stderr, "pack_speed_bench: %s: %s\n", row.name.c_str(),
                       row.runs.back().error.c_str());
          return 1;
        }
      }
      const Run one = PackInChild(obj, single, 1, timeout);
      const hullpack::Result<std::vector<uint8_t>> a = hullpack::ReadFileBytes(packed);
      const hullpack::Result<std::vector<uint8_t>> b = hullpack::ReadFileBytes(single);
      row.identical = one.ok && a.ok() && b.ok() && a.value() == b.value();
      if (!keep_meshes) std::remove(obj.c_str());
      rows.push_back(std::move(row));
    }
  }

  // The table, the CSV and the plot.
  std::string csv =
      "mesh,triangles,vertices,wall_s,cpu_s,cpu_per_wall,us_per_triangle_wall,"
      "us_per_triangle_cpu,peak_mb,decoded_mb,peak_per_decoded,load_s,repair_s,prune_s,meshes_s,"
      "assemble_s,write_s,stage_sum_s,identical_to_1_thread\n";
  std::printf("%-16s %9s %8s %8s %7s %9s %9s %8s %7s %s\n", "mesh", "triangles", "wall s", "CPU s",
              "CPU/wl", "us/tri wl", "us/tri CPU", "peak MB", "xmesh", "same as 1 thread");
  hullpack::Plot plot;
  plot.title = "hullpack pack at defaults (with hulls): time per triangle";
  plot.x = {"triangles", true};
  plot.y = {"microseconds per triangle (median)", false};
  hullpack::PlotSeries wall{"wall", {}}, cpu{"CPU (user + system, all threads)", {}};
  double lo = 1e300, hi = 0;
  bool all_identical = true;
  for (const Row& row : rows) {
    const double w = row.Wall(), c = row.Cpu(), t = static_cast<double>(row.triangles);
    double stage_sum = 0;
    for (int s = 0; s < kStageCount; ++s) stage_sum += row.Stage(s);
    std::printf("%-16s %9zu %8.2f %8.2f %7.2f %9.2f %9.2f %8.0f %7.2f %s\n", row.name.c_str(),
                row.triangles, w, c, c / w, 1e6 * w / t, 1e6 * c / t, row.Peak(),
                row.Peak() / row.decoded_mb, row.identical ? "yes" : "NO");
    char line[512];
    std::snprintf(line, sizeof(line), "%s,%zu,%zu,%.4f,%.4f,%.3f,%.4f,%.4f,%.1f,%.1f,%.2f",
                  row.name.c_str(), row.triangles, row.vertices, w, c, c / w, 1e6 * w / t,
                  1e6 * c / t, row.Peak(), row.decoded_mb, row.Peak() / row.decoded_mb);
    csv += line;
    for (int s = 0; s < kStageCount; ++s) {
      std::snprintf(line, sizeof(line), ",%.4f", row.Stage(s));
      csv += line;
    }
    std::snprintf(line, sizeof(line), ",%.4f,%s\n", stage_sum, row.identical ? "yes" : "no");
    csv += line;
    wall.points.emplace_back(t, 1e6 * w / t);
    cpu.points.emplace_back(t, 1e6 * c / t);
    if (row.triangles >= 100000) {
      lo = std::min(lo, 1e6 * w / t);
      hi = std::max(hi, 1e6 * w / t);
    }
    all_identical = all_identical && row.identical;
  }
  std::printf("\nseconds per stage (median):\n%-16s", "mesh");
  for (const char* s : kStages) std::printf(" %8s", s);
  std::printf(" %8s %8s\n", "sum", "wall");
  for (const Row& row : rows) {
    double sum = 0;
    std::printf("%-16s", row.name.c_str());
    for (int s = 0; s < kStageCount; ++s) {
      std::printf(" %8.3f", row.Stage(s));
      sum += row.Stage(s);
    }
    std::printf(" %8.3f %8.3f\n", sum, row.Wall());
  }
  if (hi > 0)
    std::printf("\ntime per triangle (wall) from 100k triangles up: max / min = %.2f\n", hi / lo);
  std::printf("bytes identical to a single-thread run: %s\n", all_identical ? "yes" : "NO");
  // One line from the smallest mesh to the largest, whichever input each came from.
  for (hullpack::PlotSeries* series : {&wall, &cpu})
    std::sort(series->points.begin(), series->points.end());
  plot.series = {wall, cpu};
  plot.note = "each point: median of the runs of one subdivided mesh; " + std::to_string(repeats) +
              " runs, each in its own process";
  const std::string svg = hullpack::RenderSvg(plot);
  if (!hullpack::WriteFileAtomically(out + "/pack_speed.svg", svg.data(), svg.size()).ok() ||
      !hullpack::WriteFileAtomically(out + "/pack_speed.csv", csv.data(), csv.size()).ok()) {
    std::fprintf(stderr, "pack_speed_bench: cannot write under %s\n", out.c_str());
    return 1;
  }
  return all_identical ? 0 : 1;
}
