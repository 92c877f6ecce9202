// vhacd_bench: hullpack's convex decomposition and a reference program side by side, in one run.
//
//   vhacd_bench FOLDER [--reference-bin PATH | --reference-cmd 'TEMPLATE'] [--repeats N]
//               [--ours LIST] [--preset|--quality default|high] [--mode 0|1|tetra]
//               [--csv FILE] [--work DIR] [--timeout SECONDS] [--only NAME,NAME] [--samples N]
//               [--gap X] [--threads N]
//   vhacd_bench --measure MESH HULLS.obj [--gap X] [--samples N]   (the metrics of one hull file)
//   vhacd_bench --subdivide IN OUT.obj MIN_TRIANGLES              (a dense test mesh)
//
// Every mesh of FOLDER (a non-OBJ file whose name also exists as .obj is skipped) is flattened to
// a plain OBJ (v/f lines) that both programs read. Each program runs in its own process, `repeats`
// times; wall time and peak memory (the process's maximum resident set) are the medians. The hulls
// of the first run are read back from OBJ and measured by this program's own code
// (hull_metrics.h): hull count, concavity (max of the two one-sided Hausdorff distances, fraction
// of the diagonal), IoU (closed meshes), interior coverage, hull validity. For hullpack the
// library's own report is printed next to it.
//
// hullpack configurations (--ours, comma-separated): default, high, tetra (default + mode 1),
// high+tetra, vhacd2 (the defaults with max_concavity 0: V-HACD 2.0's volume criteria), d=X
// (max_concavity X), n=N (hull_count N), match=REF (REF's hull count per mesh). Without --ours,
// one configuration from --preset/--quality and --mode.
// The reference: --reference-bin PATH runs `PATH {in}` in a fresh folder and reads the hulls from
// its decomp.obj (what V-HACD 4.x's TestVHACD writes); --reference-cmd runs a shell command in a
// fresh folder {dir} with {in} (the input OBJ) and {out} (where it must leave the hulls, one `o`
// per hull) substituted. Wall time includes reading the input and writing the hulls for both
// programs; hullpack's also includes its error report (library time without it is listed apart).
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_util.h"
#include "common/cli_args.h"
#include "hull_metrics.h"
#include "io/scene_io.h"
#include "scene_soup.h"
#include "svg_plot.h"
#include "vhacd/vhacd.h"

namespace {

using hullpack::bench::Fmt;
using hullpack::bench::HullMetrics;
using hullpack::bench::Median;
using hullpack::bench::MeshMeasure;
using hullpack::bench::MetricsOptions;
using hullpack::bench::Soup;
using hullpack::bench::V3;

// ---------------------------------------------------------------------------------------------
// OBJ: `v` and `f` lines only; every `o`/`g` line starts a new part (when split is set).

bool ReadObjParts(const std::string& path, bool split, std::vector<Soup>* parts, std::string* why) {
  std::ifstream f(path.c_str());
  if (!f) {
    *why = "cannot read " + path;
    return false;
  }
  std::vector<V3> verts;
  std::vector<std::vector<std::array<int64_t, 3>>> faces(1);
  std::string line;
  while (std::getline(f, line)) {
    if (line.size() < 2) continue;
    if (line[0] == 'v' && (line[1] == ' ' || line[1] == '\t')) {
      V3 p;
      if (std::sscanf(line.c_str() + 2, "%lf %lf %lf", &p[0], &p[1], &p[2]) != 3) {
        *why = path + ": bad vertex line";
        return false;
      }
      verts.push_back(p);
    } else if (line[0] == 'f' && (line[1] == ' ' || line[1] == '\t')) {
      std::istringstream ss(line.substr(2));
      std::string tok;
      std::vector<int64_t> poly;
      while (ss >> tok) {
        const long long v = std::atoll(tok.c_str());
        if (v == 0) {
          *why = path + ": bad face index";
          return false;
        }
        poly.push_back(v > 0 ? v - 1 : static_cast<int64_t>(verts.size()) + v);
      }
      for (size_t k = 2; k < poly.size(); ++k)
        faces.back().push_back({poly[0], poly[k - 1], poly[k]});
    } else if (split && (line[0] == 'o' || line[0] == 'g') && (line[1] == ' ' || line[1] == '\t')) {
      if (!faces.back().empty()) faces.emplace_back();
    }
  }
  parts->clear();
  for (const auto& fl : faces) {
    if (fl.empty()) continue;
    Soup s;
    std::map<int64_t, uint32_t> local;
    for (const auto& t : fl) {
      std::array<uint32_t, 3> tri;
      for (int k = 0; k < 3; ++k) {
        if (t[k] < 0 || t[k] >= static_cast<int64_t>(verts.size())) {
          *why = path + ": face index out of range";
          return false;
        }
        auto it = local.find(t[k]);
        if (it == local.end()) {
          it = local.emplace(t[k], static_cast<uint32_t>(s.points.size())).first;
          s.points.push_back(verts[t[k]]);
        }
        tri[k] = it->second;
      }
      s.triangles.push_back(tri);
    }
    parts->push_back(std::move(s));
  }
  return true;
}

bool WriteObjParts(const std::string& path, const std::vector<Soup>& parts) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return false;
  size_t base = 1;
  for (size_t h = 0; h < parts.size(); ++h) {
    if (parts.size() > 1) std::fprintf(f, "o hull_%zu\n", h);
    for (const V3& p : parts[h].points) std::fprintf(f, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    for (const auto& t : parts[h].triangles)
      std::fprintf(f, "f %zu %zu %zu\n", base + t[0], base + t[1], base + t[2]);
    base += parts[h].points.size();
  }
  return std::fclose(f) == 0;
}

// ---------------------------------------------------------------------------------------------
// The hullpack side, run as a child process: vhacd_bench --run-ours IN OUT PRESET MODE THREADS.

int RunOurs(int argc, char** argv) {
  if (argc != 10) return hullpack::kExitUsage;
  const std::string in = argv[2], out = argv[3], preset = argv[4];
  vhacd::Parameters p = preset == "high" ? vhacd::Parameters::High() : vhacd::Parameters::Default();
  p.mode = std::atoi(argv[5]) == 1 ? vhacd::Mode::kTetrahedron : vhacd::Mode::kVoxel;
  p.num_threads = static_cast<uint32_t>(std::atoi(argv[6]));
  if (std::atof(argv[7]) >= 0) p.max_concavity = std::atof(argv[7]);  // < 0: the preset's
  p.hull_count = static_cast<uint32_t>(std::atoi(argv[8]));
  p.oriented_cuts = static_cast<vhacd::OrientedCuts>(std::atoi(argv[9]));
  std::vector<Soup> parts;
  std::string why;
  if (!ReadObjParts(in, false, &parts, &why) || parts.size() != 1) {
    std::fprintf(stderr, "%s\n", why.c_str());
    return 1;
  }
  std::vector<double> pts;
  std::vector<uint32_t> idx;
  for (const V3& q : parts[0].points) pts.insert(pts.end(), {q[0], q[1], q[2]});
  for (const auto& t : parts[0].triangles) idx.insert(idx.end(), {t[0], t[1], t[2]});
  const vhacd::Result r = vhacd::Decompose(
      vhacd::MeshView::FromDouble(pts.data(), pts.size() / 3, idx.data(), idx.size() / 3), p);
  std::ofstream rep((out + ".report").c_str());
  rep << "status " << vhacd::StatusName(r.status) << "\n";
  if (!r.ok()) {
    std::fprintf(stderr, "%s: %s\n", vhacd::StatusName(r.status), r.message.c_str());
    return 1;
  }
  const vhacd::Report& R = r.report;
  rep.precision(9);
  rep << "concavity " << R.concavity << "\nmesh_to_hulls " << R.hausdorff_mesh_to_hulls
      << "\nhulls_to_mesh " << R.hausdorff_hulls_to_mesh << "\niou " << R.volume_iou
      << "\ncoverage " << R.solid_coverage << "\nseconds_total " << R.seconds_total
      << "\nseconds_report " << R.seconds_report << "\ntarget_reached " << R.target_reached << "\n";
  std::vector<Soup> hulls(r.hulls.size());
  for (size_t h = 0; h < r.hulls.size(); ++h) {
    for (size_t v = 0; v < r.hulls[h].vertex_count(); ++v)
      hulls[h].points.emplace_back(r.hulls[h].points[3 * v], r.hulls[h].points[3 * v + 1],
                                   r.hulls[h].points[3 * v + 2]);
    for (size_t t = 0; t < r.hulls[h].triangle_count(); ++t)
      hulls[h].triangles.push_back({r.hulls[h].triangles[3 * t], r.hulls[h].triangles[3 * t + 1],
                                    r.hulls[h].triangles[3 * t + 2]});
  }
  return WriteObjParts(out, hulls) && rep.good() ? 0 : 1;
}

// ---------------------------------------------------------------------------------------------
// Child processes.

struct RunStats {
  bool ok = false;
  bool timed_out = false;
  int exit_code = -1;
  double seconds = 0.0;
  double cpu_seconds =
      0.0;  // user + system time of the child (wall time is noisy on a shared machine)
  double peak_mb = 0.0;
};

// Runs argv (or `sh -c command` when argv is empty) in `dir`, output to dir/log.txt.
RunStats RunProcess(const std::vector<std::string>& args, const std::string& command,
                    const std::string& dir, double timeout_s) {
  RunStats st;
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return st;
  if (pid == 0) {
    setpgid(0, 0);
    if (chdir(dir.c_str()) != 0) _exit(127);
    const int fd = open("log.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    if (args.empty()) {
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    } else {
      std::vector<char*> av;
      for (const std::string& a : args) av.push_back(const_cast<char*>(a.c_str()));
      av.push_back(nullptr);
      execv(av[0], av.data());
    }
    _exit(127);
  }
  setpgid(pid, pid);
  int status = 0;
  rusage ru{};
  for (;;) {
    const pid_t w = wait4(pid, &status, WNOHANG, &ru);
    if (w == pid) break;
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (w < 0 || el > timeout_s) {
      kill(-pid, SIGKILL);
      wait4(pid, &status, 0, &ru);
      st.timed_out = w >= 0;
      break;
    }
    usleep(2000);
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  st.peak_mb = ru.ru_maxrss / 1024.0;
  st.cpu_seconds =
      ru.ru_utime.tv_sec + ru.ru_stime.tv_sec + 1e-6 * (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  st.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  st.ok = !st.timed_out && st.exit_code == 0;
  return st;
}

std::string ShellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string Substitute(std::string t, const std::string& key, const std::string& value) {
  for (size_t pos = 0; (pos = t.find(key, pos)) != std::string::npos; pos += value.size())
    t.replace(pos, key.size(), value);
  return t;
}

// ---------------------------------------------------------------------------------------------

struct Config {
  std::string name;
  bool reference = false;
  std::string command;  // a named reference's template (--reference NAME=TEMPLATE)
  std::string preset = "default";
  int mode = 0;
  double max_concavity = -1.0;  // d=X (0: V-HACD 2.0's criteria, < 0: the preset's)
  int hulls = 0;                // n=N
  std::string match;            // match=REF: the hull count REF gave on the same mesh
};

struct Row {
  std::string mesh;
  size_t triangles = 0;
  bool closed = false;
  std::string status = "ok";
  HullMetrics m;
  std::map<std::string, double> own;  // hullpack's own report
  double seconds = 0.0, cpu_seconds = 0.0, library_seconds = -1.0, peak_mb = 0.0;
};

std::vector<std::string> SplitComma(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

// The bars: match=REF against REF mesh by mesh (concavity ratio, time ratio, exact count),
// d=X (meshes whose measured concavity reaches X), n=N (meshes given exactly N hulls).
void PrintTargets(const std::vector<Config>& configs,
                  std::map<std::string, std::vector<Row>>& rows) {
  bool header = false;
  auto head = [&]() {
    if (!header) std::printf("\n== targets ==\n");
    header = true;
  };
  for (const Config& c : configs) {
    const std::vector<Row>& ours = rows[c.name];
    if (!c.match.empty()) {
      const std::vector<Row>& ref = rows[c.match];
      std::vector<double> ratio, time_ratio;
      int le = 0, exact = 0;
      for (size_t i = 0; i < ours.size() && i < ref.size(); ++i) {
        if (ours[i].status != "ok" || ref[i].status != "ok") continue;
        const double a = ours[i].m.concavity, b = ref[i].m.concavity;
        if (b > 0) ratio.push_back(a / b);
        le += a <= b;
        exact += ours[i].m.hulls == ref[i].m.hulls;
        if (ref[i].seconds > 0) time_ratio.push_back(ours[i].seconds / ref[i].seconds);
      }
      head();
      std::printf(
          "%-22s at %s's hull count: %zu meshes, ours <= %s on %d (%.0f %%), median concavity "
          "ratio %s, median time ratio %s, same hull count on %d\n",
          c.name.c_str(), c.match.c_str(), ratio.size(), c.match.c_str(), le,
          ratio.empty() ? 0.0 : 100.0 * le / ratio.size(), Fmt(Median(ratio), "%.3f").c_str(),
          Fmt(Median(time_ratio), "%.3f").c_str(), exact);
    } else if (c.max_concavity > 0 || c.hulls > 0) {
      int ok = 0, hit = 0;
      std::vector<double> h;
      for (const Row& r : ours) {
        if (r.status != "ok") continue;
        ++ok;
        h.push_back(static_cast<double>(r.m.hulls));
        if (c.max_concavity > 0)
          hit += r.m.concavity <= c.max_concavity;
        else
          hit += static_cast<int>(r.m.hulls) == c.hulls;
      }
      head();
      std::printf("%-22s %s on %d of %d meshes, median hulls %s\n", c.name.c_str(),
                  c.max_concavity > 0 ? "concavity reached" : "exact hull count", hit, ok,
                  Fmt(Median(h), "%.1f").c_str());
    }
  }
}

// Median concavity against median hull count, one series per family of configurations.
bool WritePlot(const std::string& path, const std::vector<Config>& configs,
               std::map<std::string, std::vector<Row>>& rows, const std::string& folder) {
  hullpack::Plot plot;
  plot.title = "Concavity against hull count (medians over the meshes)";
  plot.x.label = "median hull count";
  plot.x.log = true;
  plot.y.label = "median concavity (Hausdorff, fraction of the diagonal)";
  plot.y.log = true;
  plot.note = folder + "; concavity by tools/bench/hull_metrics for every program";
  std::map<std::string, hullpack::PlotSeries> series;
  std::vector<std::string> order;
  for (const Config& c : configs) {
    std::string family;
    if (c.reference)
      family = c.name.rfind("coacd", 0) == 0 ? "CoACD (-t)" : c.name;
    else if (c.hulls > 0)
      family = "hullpack --hulls N";
    else if (c.max_concavity > 0)
      family = "hullpack --max-concavity D";
    else if (!c.match.empty())
      family = "hullpack at the reference's count";
    else
      family = "hullpack presets";
    std::vector<double> h, cc;
    for (const Row& r : rows[c.name])
      if (r.status == "ok") {
        h.push_back(static_cast<double>(r.m.hulls));
        cc.push_back(r.m.concavity);
      }
    if (h.empty()) continue;
    if (!series.count(family)) {
      order.push_back(family);
      series[family].name = family;
      series[family].colour = static_cast<int>(order.size() - 1);
    }
    series[family].points.emplace_back(Median(h), Median(cc));
  }
  for (const std::string& f : order) {
    hullpack::PlotSeries sr = series[f];
    std::sort(sr.points.begin(), sr.points.end());
    plot.series.push_back(sr);
  }
  FILE* out = std::fopen(path.c_str(), "w");
  if (out == nullptr) return false;
  const std::string doc = hullpack::RenderSvg(plot);
  const bool ok = std::fwrite(doc.data(), 1, doc.size(), out) == doc.size();
  return std::fclose(out) == 0 && ok;
}

std::string SelfPath() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n <= 0) return "";
  buf[n] = '\0';
  return buf;
}

}  // namespace

// vhacd_bench --measure MESH HULLS.obj [--gap X] [--samples N]: the metrics of one hull file.
int MeasureOne(const std::string& mesh_path, const std::string& hulls_path,
               const MetricsOptions& mo) {
  hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(mesh_path);
  if (!scene.ok()) {
    std::fprintf(stderr, "%s\n", scene.status().ToString().c_str());
    return 1;
  }
  std::vector<double> pts;
  std::vector<uint32_t> idx;
  hullpack::SceneSoup(scene.value(), &pts, &idx);
  Soup soup;
  for (size_t i = 0; i < pts.size(); i += 3)
    soup.points.emplace_back(pts[i], pts[i + 1], pts[i + 2]);
  for (size_t i = 0; i + 2 < idx.size(); i += 3)
    soup.triangles.push_back({idx[i], idx[i + 1], idx[i + 2]});
  std::vector<Soup> hulls;
  std::string why;
  if (!ReadObjParts(hulls_path, true, &hulls, &why)) {
    std::fprintf(stderr, "%s\n", why.c_str());
    return 1;
  }
  const MeshMeasure measure(std::move(soup), mo);
  const HullMetrics m = measure.Measure(hulls);
  std::printf("hulls %zu (max %zu vertices), invalid %zu %s\n", m.hulls, m.max_hull_vertices,
              m.invalid_hulls, m.first_problem.c_str());
  std::printf(
      "concavity %.5f: mesh->hulls %.5f at (%.6g %.6g %.6g), hulls->mesh %.5f at (%.6g %.6g %.6g) "
      "on hull %zu\n",
      m.concavity, m.mesh_to_hulls, m.worst_mesh_point[0], m.worst_mesh_point[1],
      m.worst_mesh_point[2], m.hulls_to_mesh, m.worst_hull_point[0], m.worst_hull_point[1],
      m.worst_hull_point[2], m.worst_hull);
  std::printf("  that hull point is %s the solid, %.5f from the nearest other hull\n",
              m.worst_hull_point_in_solid ? "inside" : "outside", m.worst_hull_point_gap);
  std::printf("IoU %s, coverage %s, closed %s, diagonal %.6g\n", Fmt(m.iou).c_str(),
              Fmt(m.coverage).c_str(), measure.closed() ? "yes" : "no", measure.diagonal());
  return 0;
}

// vhacd_bench --subdivide IN OUT.obj MIN_TRIANGLES: a dense test mesh. Each round splits every
// triangle in 4 at its edge midpoints while that stays under MIN_TRIANGLES, then splits each at its
// centroid in 3 until there are at least MIN_TRIANGLES (both keep a closed mesh closed).
int Subdivide(const std::string& in, const std::string& out, size_t target) {
  hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(in);
  if (!scene.ok()) {
    std::fprintf(stderr, "%s\n", scene.status().ToString().c_str());
    return 1;
  }
  std::vector<double> pts;
  std::vector<uint32_t> idx;
  hullpack::SceneSoup(scene.value(), &pts, &idx);
  Soup s;
  for (size_t i = 0; i < pts.size(); i += 3) s.points.emplace_back(pts[i], pts[i + 1], pts[i + 2]);
  // Weld identical positions so that shared edges get one midpoint.
  {
    std::map<std::array<double, 3>, uint32_t> at;
    std::vector<V3> welded;
    std::vector<uint32_t> remap(s.points.size());
    for (size_t i = 0; i < s.points.size(); ++i) {
      auto it = at.emplace(std::array<double, 3>{s.points[i][0], s.points[i][1], s.points[i][2]},
                           static_cast<uint32_t>(welded.size()));
      if (it.second) welded.push_back(s.points[i]);
      remap[i] = it.first->second;
    }
    s.points.swap(welded);
    for (size_t i = 0; i + 2 < idx.size(); i += 3)
      s.triangles.push_back({remap[idx[i]], remap[idx[i + 1]], remap[idx[i + 2]]});
  }
  while (s.triangles.size() * 4 <= target) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      s.points.push_back(0.5 * (s.points[a] + s.points[b]));
      return mid[key] = static_cast<uint32_t>(s.points.size() - 1);
    };
    std::vector<std::array<uint32_t, 3>> next;
    next.reserve(s.triangles.size() * 4);
    for (const auto& t : s.triangles) {
      const uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]),
                     ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    s.triangles.swap(next);
  }
  while (s.triangles.size() < target) {
    std::vector<std::array<uint32_t, 3>> next;
    next.reserve(s.triangles.size() * 3);
    for (const auto& t : s.triangles) {
      s.points.push_back((s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0);
      const uint32_t m = static_cast<uint32_t>(s.points.size() - 1);
      next.push_back({t[0], t[1], m});
      next.push_back({t[1], t[2], m});
      next.push_back({t[2], t[0], m});
    }
    s.triangles.swap(next);
  }
  if (!WriteObjParts(out, {s})) {
    std::fprintf(stderr, "cannot write %s\n", out.c_str());
    return 1;
  }
  std::printf("%s: %zu points, %zu triangles\n", out.c_str(), s.points.size(), s.triangles.size());
  return 0;
}

int main(int argc, char** argv) {
  // The child process of a measured run (internal: the arguments are this program's own).
  if (argc >= 2 && std::strcmp(argv[1], "--run-ours") == 0) return RunOurs(argc, argv);
  std::string ref_bin, ref_cmd, csv, work, ours_list, preset = "default", svg;
  std::vector<std::pair<std::string, std::string>> named_refs;  // --reference NAME=TEMPLATE
  bool reuse = false;
  int repeats = 1, mode = 0, threads = 0;
  vhacd::OrientedCuts oriented_cuts = vhacd::OrientedCuts::kAuto;
  double timeout = 600.0;
  std::vector<std::string> only, operands;
  MetricsOptions mo;
  bool measure_one = false, subdivide = false;
  hullpack::CliArgs cli(
      "vhacd_bench", "FOLDER [options]",
      "hullpack's convex decomposition and a reference program side by side on every mesh of\n"
      "FOLDER, each in its own process: wall time and peak memory (medians), hull count,\n"
      "concavity, IoU and coverage measured by this program's own code.\n"
      "  vhacd_bench --measure MESH HULLS.obj [--gap X] [--samples N]   metrics of one hull file\n"
      "  vhacd_bench --subdivide IN OUT.obj MIN_TRIANGLES               a dense test mesh");
  cli.Positional("FOLDER", &operands, 1, 3);
  cli.String("--reference-bin", "PATH", &ref_bin,
             "run `PATH {in}` in a fresh folder, read the hulls from its decomp.obj");
  cli.String("--reference-cmd", "TEMPLATE", &ref_cmd,
             "a shell command run in a fresh folder {dir}; {in} is the input OBJ,\n"
             "{out} the OBJ it must write (one `o` per hull)");
  cli.Int("--repeats", "N", 1, 1000, &repeats, "runs per program, median time and memory (1)");
  cli.String("--ours", "LIST", &ours_list,
             "hullpack configurations: default, high, tetra, high+tetra, vhacd2, d=X, n=N, "
             "match=REF (comma-separated)");
  cli.Choice("--quality, --preset", {"default", "high"}, &preset,
             "without --ours: the preset of the one configuration");
  cli.Value("--mode", "voxel|tetra", "without --ours: voxel (0) or tetrahedron (1) sets",
            [&mode](const std::string& v) {
              if (v == "0" || v == "voxel") {
                mode = 0;
              } else if (v == "1" || v == "tetra" || v == "tetrahedron") {
                mode = 1;
              } else {
                return "takes voxel, tetra, 0 or 1, not '" + v + "'";
              }
              return std::string();
            });
  cli.String("--csv", "FILE", &csv, "also write the table as CSV");
  cli.String("--work", "DIR", &work, "where the runs happen (default /tmp/vhacd_bench.PID)");
  cli.Double("--timeout", "S", 1e-3, 1e9, &timeout, "seconds per run (600)");
  cli.Value("--only", "A,B", "only these meshes (file names without extension)",
            [&only](const std::string& v) {
              only = SplitComma(v);
              return std::string();
            });
  cli.Value("--samples", "N", "random surface samples per Hausdorff direction",
            [&mo](const std::string& v) {
              long long n = 0;
              std::string why = hullpack::CliArgs::ParseWholeNumber(v, 0, 100000000, &n);
              if (why.empty()) mo.mesh_samples = mo.hull_samples = size_t(n);
              return why;
            });
  cli.Double("--gap", "X", 0, 1, &mo.gap,
             "hull points nearer than X (fraction of the diagonal) to another hull are inside");
  cli.Int("--threads", "N", 0, 256, &threads, "decomposition threads (0: every core)");
  cli.Action("--oriented-cuts",
             "hullpack configurations always cut along the parts' own axes too\n"
             "(Parameters::oriented_cuts kAlways; by default kAuto)",
             [&oriented_cuts] { oriented_cuts = vhacd::OrientedCuts::kAlways; });
  cli.Action("--no-oriented-cuts", "hullpack configurations cut by voxel slices only (kOff)",
             [&oriented_cuts] { oriented_cuts = vhacd::OrientedCuts::kOff; });
  cli.Value("--reference", "NAME=TEMPLATE",
            "a named reference (repeatable): TEMPLATE as for --reference-cmd; its\n"
            "configuration is NAME, and match=NAME runs hullpack at its hull counts",
            [&named_refs](const std::string& v) {
              const size_t eq = v.find('=');
              if (eq == std::string::npos || eq == 0) return "needs NAME=TEMPLATE, not '" + v + "'";
              named_refs.emplace_back(v.substr(0, eq), v.substr(eq + 1));
              return std::string();
            });
  cli.Flag("--reuse", &reuse,
           "read the reference runs from --work (hulls and recorded time and memory)\n"
           "instead of running them; a reference without a finished run is 'not run'");
  cli.String("--svg", "FILE", &svg, "plot median concavity against median hull count");
  cli.Flag("--measure", &measure_one, "measure one hull file: operands MESH HULLS.obj");
  cli.Flag("--subdivide", &subdivide, "write a dense test mesh: operands IN OUT.obj MIN_TRIANGLES");
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  if (measure_one && subdivide)
    return cli.UsageError("--measure and --subdivide exclude each other");
  if (measure_one) {
    if (operands.size() != 2) return cli.UsageError("--measure needs MESH and HULLS.obj");
    return MeasureOne(operands[0], operands[1], mo);
  }
  if (subdivide) {
    long long target = 0;
    if (operands.size() != 3 ||
        !hullpack::CliArgs::ParseWholeNumber(operands[2], 1, 1LL << 40, &target).empty())
      return cli.UsageError("--subdivide needs IN OUT.obj MIN_TRIANGLES");
    return Subdivide(operands[0], operands[1], static_cast<size_t>(target));
  }
  if (operands.size() != 1) return cli.UsageError("one FOLDER");
  const std::string& folder = operands[0];
  if (!ref_bin.empty() && !ref_cmd.empty())
    return cli.UsageError("give --reference-bin or --reference-cmd, not both");
  if (!ref_bin.empty() && ref_bin[0] != '/') {
    char cwd[4096];
    if (getcwd(cwd, sizeof(cwd))) ref_bin = std::string(cwd) + "/" + ref_bin;
  }

  // References first: a match=REF configuration needs REF's hull count on the same mesh.
  std::vector<Config> configs;
  for (const auto& nr : named_refs) {
    Config r;
    r.name = nr.first;
    r.reference = true;
    r.command = nr.second;
    configs.push_back(r);
  }
  if (!ref_bin.empty() || !ref_cmd.empty()) {
    Config r;
    r.name = "reference";
    r.reference = true;
    configs.push_back(r);
  }
  if (ours_list.empty()) ours_list = preset + (mode == 1 ? "+tetra" : "");
  for (const std::string& c : SplitComma(ours_list)) {
    Config cfg;
    cfg.name = c;
    if (c == "none") continue;
    if (c == "default") {
    } else if (c == "high")
      cfg.preset = "high";
    else if (c == "tetra" || c == "default+tetra")
      cfg.mode = 1;
    else if (c == "high+tetra") {
      cfg.preset = "high";
      cfg.mode = 1;
    } else if (c == "vhacd2") {  // V-HACD 2.0's volume criteria, the defaults before the target
      cfg.max_concavity = 0.0;
    } else if (c.rfind("d=", 0) == 0 && std::atof(c.c_str() + 2) > 0)
      cfg.max_concavity = std::atof(c.c_str() + 2);
    else if (c.rfind("n=", 0) == 0 && std::atoi(c.c_str() + 2) > 0)
      cfg.hulls = std::atoi(c.c_str() + 2);
    else if (c.rfind("match=", 0) == 0) {
      cfg.match = c.substr(6);
      bool known = false;
      for (const Config& r : configs) known = known || (r.reference && r.name == cfg.match);
      if (!known) return cli.UsageError("match= names no reference: " + c);
    } else
      return cli.UsageError("unknown configuration " + c);
    configs.push_back(cfg);
  }

  std::vector<std::string> files;
  if (!hullpack::ListFiles(folder, {"obj", "off", "wrl", "ply", "stl", "gltf", "glb", "fbx", "dae"},
                           &files))
    return cli.UsageError("cannot read folder " + folder);
  auto stem = [](const std::string& f) { return f.substr(0, f.rfind('.')); };
  std::vector<std::string> meshes;
  for (const std::string& f : files) {
    if (hullpack::LowerExtension(f) != "obj" &&
        std::find(files.begin(), files.end(), stem(f) + ".obj") != files.end())
      continue;
    if (!only.empty() && std::find(only.begin(), only.end(), stem(f)) == only.end()) continue;
    meshes.push_back(f);
  }
  if (work.empty()) work = "/tmp/vhacd_bench." + std::to_string(getpid());
  mkdir(work.c_str(), 0755);
  const std::string self = SelfPath();

  std::map<std::string, std::vector<Row>> rows;  // by configuration
  for (const std::string& file : meshes) {
    const std::string name = stem(file);
    hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(folder + "/" + file);
    if (!scene.ok()) {
      std::fprintf(stderr, "%s: %s\n", file.c_str(), scene.status().ToString().c_str());
      for (const Config& c : configs) {
        Row r;
        r.mesh = name;
        r.status = "unreadable";
        rows[c.name].push_back(r);
      }
      continue;
    }
    std::vector<double> pts;
    std::vector<uint32_t> idx;
    hullpack::SceneSoup(scene.value(), &pts, &idx);
    Soup soup;
    for (size_t i = 0; i < pts.size(); i += 3)
      soup.points.emplace_back(pts[i], pts[i + 1], pts[i + 2]);
    for (size_t i = 0; i + 2 < idx.size(); i += 3)
      soup.triangles.push_back({idx[i], idx[i + 1], idx[i + 2]});
    const std::string input = work + "/" + name + ".obj";
    if (!WriteObjParts(input, {soup})) {
      std::fprintf(stderr, "cannot write %s\n", input.c_str());
      return 1;
    }
    const size_t ntri = soup.triangles.size();
    mo.threads = threads;
    const MeshMeasure measure(std::move(soup), mo);
    std::fprintf(stderr, "%s: %zu triangles, %s, %zu solid lattice points\n", name.c_str(), ntri,
                 measure.closed() ? "closed" : "open", measure.solid_point_count());

    for (const Config& c : configs) {
      Row row;
      row.mesh = name;
      row.triangles = ntri;
      row.closed = measure.closed();
      std::vector<double> secs, cpus, mem;
      std::vector<Soup> hulls;
      int hull_count = c.hulls;
      if (!c.match.empty()) {
        const Row& ref = rows[c.match].back();
        hull_count = ref.status == "ok" ? static_cast<int>(ref.m.hulls) : 0;
        if (hull_count == 0) {
          row.status = "no ref";
          rows[c.name].push_back(row);
          continue;
        }
      }
      for (int rep = 0; rep < repeats; ++rep) {
        const std::string dir = work + "/" + name + "." + c.name + "." + std::to_string(rep);
        mkdir(dir.c_str(), 0755);
        const std::string out = dir + "/hulls.obj";
        if (!(c.reference && reuse)) std::remove(out.c_str());
        RunStats st;
        std::string produced = out;
        const std::string stats = dir + "/stats.txt";
        double reused_s = -1, reused_mb = -1;
        if (c.reference && reuse) {
          std::ifstream sf(stats.c_str());
          if (!(sf >> reused_s >> reused_mb)) reused_s = -1;
        }
        if (c.reference && reuse && reused_s < 0) {
          row.status = "not run";  // --reuse never runs a reference
          break;
        }
        if (c.reference && reused_s >= 0) {
          // --reuse: this reference's earlier run of the same input in the same work folder.
          st.ok = true;
          st.seconds = reused_s;
          st.peak_mb = reused_mb;
          if (c.command.empty() && !ref_bin.empty()) produced = dir + "/decomp.obj";
        } else if (!c.reference) {
          st = RunProcess(
              {self, "--run-ours", input, out, c.preset, std::to_string(c.mode),
               std::to_string(threads), std::to_string(c.max_concavity), std::to_string(hull_count),
               std::to_string(static_cast<int>(oriented_cuts))},
              "", dir, timeout);
        } else if (!c.command.empty()) {
          std::string cmd = Substitute(c.command, "{in}", ShellQuote(input));
          cmd = Substitute(cmd, "{out}", ShellQuote(out));
          cmd = Substitute(cmd, "{dir}", ShellQuote(dir));
          st = RunProcess({}, cmd, dir, timeout);
        } else if (!ref_bin.empty()) {
          produced = dir + "/decomp.obj";
          std::remove(produced.c_str());
          std::remove(stats.c_str());
          st = RunProcess({ref_bin, input}, "", dir, timeout);
        } else {
          std::string cmd = Substitute(ref_cmd, "{in}", ShellQuote(input));
          cmd = Substitute(cmd, "{out}", ShellQuote(out));
          cmd = Substitute(cmd, "{dir}", ShellQuote(dir));
          st = RunProcess({}, cmd, dir, timeout);
        }
        if (!st.ok) {
          row.status = st.timed_out ? "timeout" : "exit " + std::to_string(st.exit_code);
          break;
        }
        if (c.reference && reused_s < 0) {
          std::ofstream sf(stats.c_str());
          sf << st.seconds << " " << st.peak_mb << "\n";
        }
        secs.push_back(st.seconds);
        cpus.push_back(st.cpu_seconds);
        mem.push_back(st.peak_mb);
        if (rep == 0) {
          std::string why;
          if (!ReadObjParts(produced, true, &hulls, &why) || hulls.empty()) {
            row.status = "no hulls";
            break;
          }
          if (!c.reference) {
            std::ifstream rf((out + ".report").c_str());
            std::string key;
            double val;
            while (rf >> key) {
              if (key == "status") {
                rf >> key;
                continue;
              }
              if (rf >> val) row.own[key] = val;
            }
            if (row.own.count("seconds_total"))
              row.library_seconds = row.own["seconds_total"] - row.own["seconds_report"];
          }
        }
      }
      if (row.status == "ok") {
        row.seconds = Median(secs);
        row.cpu_seconds = Median(cpus);
        row.peak_mb = Median(mem);
        row.m = measure.Measure(hulls);
      }
      std::fprintf(
          stderr,
          "  %-12s %-8s hulls %3zu  concavity %s (own %s)  IoU %s  cover %s  %.2f s  %.0f MB\n",
          c.name.c_str(), row.status.c_str(), row.m.hulls, Fmt(row.m.concavity).c_str(),
          row.own.count("concavity") ? Fmt(row.own["concavity"]).c_str() : "-",
          Fmt(row.m.iou).c_str(), Fmt(row.m.coverage).c_str(), row.seconds, row.peak_mb);
      if (!row.m.first_problem.empty())
        std::fprintf(stderr, "    %s\n", row.m.first_problem.c_str());
      rows[c.name].push_back(row);
    }
  }

  // Tables.
  for (const Config& c : configs) {
    std::printf("\n== %s%s ==\n", c.reference ? "reference: " : "hullpack ",
                c.reference ? (!c.command.empty() ? c.command.c_str()
                               : ref_bin.empty()  ? ref_cmd.c_str()
                                                  : ref_bin.c_str())
                            : c.name.c_str());
    std::printf("%-18s %8s %6s %-8s %5s %7s %7s %7s %7s %6s %6s %6s %7s %7s %7s\n", "mesh", "tris",
                "closed", "status", "hulls", "conc", "m->h", "h->m", "own", "IoU", "ownIoU",
                "cover", "time_s", "lib_s", "peakMB");
    for (const Row& r : rows[c.name]) {
      auto own = [&](const char* k) { return r.own.count(k) ? r.own.at(k) : -1.0; };
      std::printf("%-18s %8zu %6s %-8s %5zu %7s %7s %7s %7s %6s %6s %6s %7.2f %7s %7.0f\n",
                  r.mesh.c_str(), r.triangles, r.closed ? "yes" : "no", r.status.c_str(), r.m.hulls,
                  Fmt(r.m.concavity).c_str(), Fmt(r.m.mesh_to_hulls).c_str(),
                  Fmt(r.m.hulls_to_mesh).c_str(), Fmt(own("concavity")).c_str(),
                  Fmt(r.m.iou, "%.3f").c_str(), Fmt(own("iou"), "%.3f").c_str(),
                  Fmt(r.m.coverage, "%.3f").c_str(), r.seconds,
                  Fmt(r.library_seconds, "%.2f").c_str(), r.peak_mb);
    }
  }
  std::printf("\n== medians over the meshes that succeeded ==\n");
  std::printf("%-12s %7s %6s %7s %7s %7s %7s %7s %7s %7s %8s %7s\n", "config", "ok", "hulls",
              "conc", "ownconc", "IoU", "cover", "time_s", "max_s", "peakMB", "maxMB", "invalid");
  for (const Config& c : configs) {
    std::vector<double> h, cc, oc, iou, cov, t, mem;
    int ok = 0, invalid = 0;
    for (const Row& r : rows[c.name]) {
      if (r.m.invalid_hulls > 0) ++invalid;
      if (r.status != "ok") continue;
      ++ok;
      h.push_back(static_cast<double>(r.m.hulls));
      cc.push_back(r.m.concavity);
      if (r.own.count("concavity")) oc.push_back(r.own.at("concavity"));
      if (r.m.iou >= 0) iou.push_back(r.m.iou);
      cov.push_back(r.m.coverage);
      t.push_back(r.seconds);
      mem.push_back(r.peak_mb);
    }
    const double tmax = t.empty() ? -1 : *std::max_element(t.begin(), t.end());
    const double mmax = mem.empty() ? -1 : *std::max_element(mem.begin(), mem.end());
    std::printf("%-12s %3d/%-3zu %6s %7s %7s %7s %7s %7s %7s %7s %8s %7d\n", c.name.c_str(), ok,
                rows[c.name].size(), Fmt(Median(h), "%.1f").c_str(), Fmt(Median(cc)).c_str(),
                Fmt(Median(oc)).c_str(), Fmt(Median(iou), "%.3f").c_str(),
                Fmt(Median(cov), "%.3f").c_str(), Fmt(Median(t), "%.2f").c_str(),
                Fmt(tmax, "%.2f").c_str(), Fmt(Median(mem), "%.0f").c_str(),
                Fmt(mmax, "%.0f").c_str(), invalid);
  }

  PrintTargets(configs, rows);
  if (!svg.empty() && !WritePlot(svg, configs, rows, folder)) {
    std::fprintf(stderr, "cannot write %s\n", svg.c_str());
    return 1;
  }

  if (!csv.empty()) {
    FILE* f = std::fopen(csv.c_str(), "w");
    if (f == nullptr) {
      std::fprintf(stderr, "cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(
        f,
        "mesh,config,triangles,closed,status,hulls,max_hull_vertices,concavity,mesh_to_hulls,hulls_"
        "to_mesh,iou,"
        "coverage,own_concavity,own_mesh_to_hulls,own_hulls_to_mesh,own_iou,own_coverage,seconds,"
        "library_seconds,peak_mb,invalid_hulls,cpu_seconds\n");
    for (const Config& c : configs)
      for (const Row& r : rows[c.name]) {
        auto own = [&](const char* k) { return r.own.count(k) ? r.own.at(k) : -1.0; };
        std::fprintf(f,
                     "%s,%s,%zu,%d,%s,%zu,%zu,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%."
                     "4f,%.4f,%.1f,%zu,%.4f\n",
                     r.mesh.c_str(), c.name.c_str(), r.triangles, r.closed ? 1 : 0,
                     r.status.c_str(), r.m.hulls, r.m.max_hull_vertices, r.m.concavity,
                     r.m.mesh_to_hulls, r.m.hulls_to_mesh, r.m.iou, r.m.coverage, own("concavity"),
                     own("mesh_to_hulls"), own("hulls_to_mesh"), own("iou"), own("coverage"),
                     r.seconds, r.library_seconds, r.peak_mb, r.m.invalid_hulls, r.cpu_seconds);
      }
    std::fclose(f);
    std::printf("wrote %s\n", csv.c_str());
  }
  return 0;
}
