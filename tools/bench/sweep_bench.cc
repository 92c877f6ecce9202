// sweep_bench: error against run time, memory and size over a folder of meshes, for the convex
// decomposition (resolution, concavity, max hulls) and the mesh codec (position, normal, UV bits).
// Writes OUT/sweep.csv (one row per mesh x point), OUT/*.svg plots and OUT/summary.md.
//
//   sweep_bench FOLDER -o OUT [--quick] [--decompose-only | --codec-only] [--repeats N]
//               [--decompose-repeats N] [--threads N] [--resolutions LIST] [--concavities LIST]
//               [--max-hulls LIST] [--position-bits LIST] [--normal-bits LIST] [--uv-bits LIST]
//               [--max-distance X] [--samples N] [--solid-points N] [--gap X] [--timeout S]
//               [--meshes a,b]
//               [--ext obj,glb,...] [--quiet]
//
// LIST is "a,b,c" or a range "lo:hi" (integers, step 1) or "lo:hi:step".
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/sweep.h"
#include "bench/sweep_report.h"

namespace {

void Usage(FILE* out) {
  std::fprintf(
      out,
      "usage: sweep_bench FOLDER -o OUT [options]\n"
      "  Sweeps the decomposition and the codec over every mesh of FOLDER and writes\n"
      "  OUT/sweep.csv, OUT/*.svg and OUT/summary.md.\n"
      "options:\n"
      "  --quick                 a smaller grid and 1 run per point (a few minutes on the corpus)\n"
      "  --decompose-only        only the decomposition sweep\n"
      "  --codec-only            only the codec sweep\n"
      "  --repeats N             codec runs per point, median time (default 3)\n"
      "  --decompose-repeats N   decomposition runs per point, median time (default 1)\n"
      "  --threads N             decomposition threads (default 1; 0 = every core)\n"
      "  --resolutions LIST      default 20000,50000,100000,200000,400000,1000000\n"
      "  --concavities LIST      default 0.01,0.005,0.0025,0.001,0.0005\n"
      "  --max-hulls LIST        default 4,8,16,32,0 (0 = no limit)\n"
      "  --position-bits LIST    default 8:20\n"
      "  --normal-bits LIST      default 6:12\n"
      "  --uv-bits LIST          default 8:14\n"
      "  --max-distance X        vhacd max_distance of every point (default 0.03)\n"
      "  --samples N             random surface samples per Hausdorff direction (default 20000;\n"
      "                          the vertices are measured too)\n"
      "  --solid-points N        lattice points of the IoU / coverage measure (default 262144)\n"
      "  --gap X                 hull points nearer than X (fraction of the diagonal) to another\n"
      "                          hull are inside the union of hulls (default 0.002)\n"
      "  --timeout S             per measured step (default 900)\n"
      "  --meshes a,b            only these meshes (file names without extension)\n"
      "  --ext LIST              file extensions, in order of preference (default\n"
      "                          obj,off,wrl,ply,stl,glb,gltf,fbx,dae; one file per name)\n"
      "  --quiet                 no progress lines\n"
      "LIST: a,b,c or lo:hi or lo:hi:step\n");
}

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
  std::vector<std::string> args(argv + 1, argv + argc);
  for (const std::string& a : args) {
    if (a == "--help" || a == "-h") {
      Usage(stdout);
      return 0;
    }
  }
  // --quick first: the other options refine whichever grid it chose.
  bool quick = false;
  for (const std::string& a : args) quick = quick || a == "--quick";
  hullpack::SweepOptions o =
      quick ? hullpack::QuickSweepOptions() : hullpack::DefaultSweepOptions();
  o.base.num_threads = 1;
  std::string folder, out;
  auto bad = [&](const std::string& what) {
    std::fprintf(stderr, "sweep_bench: %s\n", what.c_str());
    Usage(stderr);
    return 64;
  };
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* v) {
      if (i + 1 >= args.size()) return false;
      *v = args[++i];
      return true;
    };
    std::string v;
    double d = 0;
    if (a == "--quick") continue;
    if (a == "--decompose-only") {
      o.codec = false;
    } else if (a == "--codec-only") {
      o.decompose = false;
    } else if (a == "--quiet") {
      o.log = nullptr;
    } else if (a == "-o" || a == "--out") {
      if (!value(&out)) return bad("-o needs a folder");
    } else if (a == "--repeats" || a == "--decompose-repeats" || a == "--threads" ||
               a == "--samples" || a == "--solid-points" || a == "--gap" || a == "--timeout" ||
               a == "--max-distance") {
      if (!value(&v) || !ParseDouble(v, &d)) return bad(a + " needs a number");
      if (a == "--repeats" && d >= 1 && d <= 1000)
        o.repeats = static_cast<int>(d);
      else if (a == "--decompose-repeats" && d >= 1 && d <= 1000)
        o.decompose_repeats = static_cast<int>(d);
      else if (a == "--threads" && d >= 0 && d <= 256)
        o.base.num_threads = static_cast<uint32_t>(d);
      else if (a == "--samples" && d >= 0 && d <= 1e8)
        o.metrics.mesh_samples = o.metrics.hull_samples = static_cast<size_t>(d);
      else if (a == "--solid-points" && d >= 1 && d <= 1e9)
        o.metrics.solid_points = static_cast<size_t>(d);
      else if (a == "--gap" && d >= 0 && d <= 1)
        o.metrics.gap = d;
      else if (a == "--timeout" && d > 0)
        o.timeout_seconds = d;
      else if (a == "--max-distance" && d >= 0 && d <= 1)
        o.base.max_distance = d;
      else
        return bad(a + " " + v + ": out of range");
    } else if (a == "--resolutions") {
      if (!value(&v) || !ParseTypedList(v, 10000, 64000000, &o.grid.resolutions))
        return bad("bad --resolutions");
    } else if (a == "--concavities") {
      if (!value(&v) || !ParseTypedList(v, 0, 1, &o.grid.concavities))
        return bad("bad --concavities");
    } else if (a == "--max-hulls") {
      if (!value(&v) || !ParseTypedList(v, 0, 100000, &o.grid.max_hulls))
        return bad("bad --max-hulls");
    } else if (a == "--position-bits") {
      if (!value(&v) || !ParseTypedList(v, 1, 30, &o.grid.position_bits))
        return bad("bad --position-bits");
    } else if (a == "--normal-bits") {
      if (!value(&v) || !ParseTypedList(v, 1, 30, &o.grid.normal_bits))
        return bad("bad --normal-bits");
    } else if (a == "--uv-bits") {
      if (!value(&v) || !ParseTypedList(v, 1, 30, &o.grid.uv_bits)) return bad("bad --uv-bits");
    } else if (a == "--meshes") {
      if (!value(&v)) return bad("--meshes needs names");
      o.only = Split(v);
    } else if (a == "--ext") {
      if (!value(&v)) return bad("--ext needs extensions");
      o.extensions = Split(v);
    } else if (!a.empty() && a[0] == '-') {
      return bad("unknown option " + a);
    } else if (folder.empty()) {
      folder = a;
    } else {
      return bad("more than one folder: " + a);
    }
  }
  if (folder.empty() || out.empty()) return bad("needs a FOLDER and -o OUT");
  if (!o.decompose && !o.codec) return bad("--decompose-only and --codec-only exclude each other");

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
