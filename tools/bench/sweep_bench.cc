// sweep_bench: error against run time, memory and size over a folder of meshes, for the convex
// decomposition (resolution, concavity, max hulls) and the mesh codec (position, normal, UV bits).
// Writes OUT/sweep.csv (one row per mesh x point), OUT/*.svg plots and OUT/summary.md.
//
//   sweep_bench FOLDER -o OUT [--quick] [--decompose-only | --codec-only] [--repeats N]
//               [--decompose-repeats N] [--threads N] [--resolutions LIST] [--concavities LIST]
//               [--max-hulls LIST] [--position-bits LIST] [--normal-bits LIST] [--uv-bits LIST]
//               [--max-distance X] [--samples N] [--solid-points N] [--gap X] [--timeout S]
//               [--only a,b]
//               [--ext obj,glb,...] [--quiet]
//
// LIST is "a,b,c" or a range "lo:hi" (integers, step 1) or "lo:hi:step".
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "bench/sweep.h"
#include "bench/sweep_report.h"
#include "common/cli_args.h"

namespace {

std::vector<std::string> Split(const std::string& s) {
  std::vector<std::string> out;
  size_t at = 0;
  while (at <= s.size()) {
    const size_t comma = s.find(',', at);
    const std::string part =
        s.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    if (!part.empty()) out.push_back(part);
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return out;
}

bool ParseDouble(const std::string& s, double* v) {
  char* end = nullptr;
  *v = std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == '\0';
}

// "a,b,c", "lo:hi" or "lo:hi:step".
bool ParseList(const std::string& s, std::vector<double>* out) {
  out->clear();
  if (s.find(':') != std::string::npos) {
    std::vector<double> p;
    size_t at = 0;
    while (true) {
      const size_t colon = s.find(':', at);
      double v;
      if (!ParseDouble(s.substr(at, colon == std::string::npos ? std::string::npos : colon - at),
                       &v))
        return false;
      p.push_back(v);
      if (colon == std::string::npos) break;
      at = colon + 1;
    }
    if (p.size() < 2 || p.size() > 3) return false;
    const double step = p.size() == 3 ? p[2] : 1;
    if (!(step > 0) || p[1] < p[0] || (p[1] - p[0]) / step > 10000) return false;
    for (double v = p[0]; v <= p[1] + step * 1e-9; v += step) out->push_back(v);
    return true;
  }
  for (const std::string& part : Split(s)) {
    double v;
    if (!ParseDouble(part, &v)) return false;
    out->push_back(v);
  }
  return !out->empty();
}

template <typename T>
bool ParseTypedList(const std::string& s, double lo, double hi, std::vector<T>* out) {
  std::vector<double> v;
  if (!ParseList(s, &v)) return false;
  out->clear();
  for (double x : v) {
    if (!(x >= lo && x <= hi)) return false;
    out->push_back(static_cast<T>(x));
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  hullpack::SweepOptions o = hullpack::DefaultSweepOptions();
  o.base.num_threads = 1;
  std::vector<std::string> folders;
  std::string out;
  bool decompose_only = false, codec_only = false;
  hullpack::CliArgs cli("sweep_bench", "FOLDER -o OUT [options]",
                        "Sweeps the decomposition and the codec over every mesh of FOLDER and "
                        "writes\nOUT/sweep.csv, OUT/*.svg and OUT/summary.md.");
  cli.Positional("FOLDER", &folders, 1, 1);
  cli.String("-o, --output, --out", "OUT", &out, "the folder to write").Required();
  cli.Action("--quick", "a smaller grid and 1 run per point; the other options refine it",
             [&o]() {
               o = hullpack::QuickSweepOptions();
               o.base.num_threads = 1;
             })
      .First();
  cli.Flag("--decompose-only", &decompose_only, "only the decomposition sweep");
  cli.Flag("--codec-only", &codec_only, "only the codec sweep");
  cli.Int("--repeats", "N", 1, 1000, &o.repeats, "codec runs per point, median time (3)");
  cli.Int("--decompose-repeats", "N", 1, 1000, &o.decompose_repeats,
          "decomposition runs per point, median time (1)");
  cli.Int("--threads", "N", 0, 256, &o.base.num_threads,
          "decomposition threads (default 1; 0 = every core)");
  // A LIST option: "a,b,c", "lo:hi" or "lo:hi:step", each value in [lo, hi].
  auto list = [&cli](const std::string& name, double lo, double hi, auto* values,
                     const std::string& help) {
    cli.Value(name, "LIST", help, [lo, hi, values](const std::string& v) {
      if (ParseTypedList(v, lo, hi, values)) return std::string();
      char range[64];
      std::snprintf(range, sizeof(range), "[%g, %g]", lo, hi);
      return "takes a,b,c or lo:hi or lo:hi:step of numbers in " + std::string(range) + ", not '" +
             v + "'";
    });
  };
  list("--resolutions", 10000, 64000000, &o.grid.resolutions,
       "default 20000,50000,100000,200000,400000,1000000");
  list("--concavities", 0, 1, &o.grid.concavities, "default 0.01,0.005,0.0025,0.001,0.0005");
  list("--max-hulls", 0, 100000, &o.grid.max_hulls, "default 4,8,16,32,0 (0 = no limit)");
  list("--position-bits", 1, 30, &o.grid.position_bits, "default 8:20");
  list("--normal-bits", 1, 30, &o.grid.normal_bits, "default 6:12");
  list("--uv-bits", 1, 30, &o.grid.uv_bits, "default 8:14");
  cli.Double("--max-distance", "X", 0, 1, &o.base.max_distance,
             "vhacd max_distance of every point (default 0.03)");
  cli.Value("--samples", "N",
            "random surface samples per Hausdorff direction (default 20000;\n"
            "the vertices are measured too)",
            [&o](const std::string& v) {
              long long n = 0;
              std::string why = hullpack::CliArgs::ParseWholeNumber(v, 0, 100000000, &n);
              if (why.empty()) o.metrics.mesh_samples = o.metrics.hull_samples = size_t(n);
              return why;
            });
  cli.Int("--solid-points", "N", 1, 1000000000, &o.metrics.solid_points,
          "lattice points of the IoU / coverage measure (default 262144)");
  cli.Double("--gap", "X", 0, 1, &o.metrics.gap,
             "hull points nearer than X (fraction of the diagonal) to another\n"
             "hull are inside the union of hulls (default 0.002)");
  cli.Double("--timeout", "S", 1e-3, 1e9, &o.timeout_seconds,
             "seconds per measured step (default 900)");
  cli.Value("--only, --meshes", "A,B", "only these meshes (file names without extension)",
            [&o](const std::string& v) {
              o.only = Split(v);
              return std::string();
            });
  cli.Value("--ext", "LIST",
            "file extensions, in order of preference (default\n"
            "obj,off,wrl,ply,stl,glb,gltf,fbx,dae; one file per name)",
            [&o](const std::string& v) {
              o.extensions = Split(v);
              return std::string();
            });
  cli.Action("--quiet", "no progress lines", [&o]() { o.log = nullptr; });
  if (std::optional<int> exit_code = cli.Parse(args)) return *exit_code;
  if (decompose_only && codec_only)
    return cli.UsageError("--decompose-only and --codec-only exclude each other");
  if (decompose_only) o.codec = false;
  if (codec_only) o.decompose = false;
  const std::string& folder = folders[0];

  std::string command = "sweep_bench";
  for (const std::string& a : args) command += " " + a;
  hullpack::Result<hullpack::SweepResult> result = hullpack::RunSweep(folder, o);
  if (!result.ok()) {
    std::fprintf(stderr, "sweep_bench: %s\n", result.status().message().c_str());
    return 1;
  }
  const hullpack::Status written = hullpack::WriteSweepOutputs(result.value(), o, out, command);
  if (!written.ok()) {
    std::fprintf(stderr, "sweep_bench: %s\n", written.message().c_str());
    return 1;
  }
  size_t failed = 0;
  for (const hullpack::SweepRow& r : result->rows) failed += r.status != "ok";
  std::printf(
      "sweep_bench: %zu meshes, %zu points (%zu failed), %zu files skipped, %.0f s; wrote "
      "%s/summary.md\n",
      result->meshes.size(), result->rows.size(), failed, result->skipped.size(), result->seconds,
      out.c_str());
  return failed == 0 ? 0 : 1;
}
