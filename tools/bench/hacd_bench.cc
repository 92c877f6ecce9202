// hacd_bench: HACD and V-HACD side by side in one run (the blog's "V-HACD 2.0 vs HACD" table),
// with Bullet's HACD (Debian's libbullet-extras-dev) as the reference, plus the blog's timing table
// and the simplifier against meshoptimizer's.
//
//   hacd_bench FOLDER [--hacd 'minNClusters maxConcavity invert extraDist facesPoints connectDist
//              targetTriangles'] [--only NAME,NAME] [--repeats N] [--timeout S] [--samples N]
//              [--threads N] [--csv FILE] [--no-bullet] [--no-vhacd]
//   hacd_bench --timing MESH [--targets 500,1000,...] [--hacd '12 1000 0 1 1 30 0'] [--repeats N]
//   [--hulls DIR] hacd_bench --simplify FOLDER [--only NAME,NAME] [--node PATH] [--samples N]
//
// Decomposition: every method runs in its own child process (a crash or hang of one does not stop
// the run), `repeats` times; the medians of wall and CPU seconds are listed. The hulls of the first
// run are measured by hull_metrics (concavity = larger one-sided Hausdorff distance between the
// surface and the union of hulls, fraction of the diagonal; IoU for closed meshes; validity of
// every hull; IoU* against the winding-number solid, for open meshes too: the open-bottomed
// bunny's check). hullpack HACD gets the `--hacd` line (default `2 100 0 1 1 30 2000`, the original
// tool's recommended line); Bullet's HACD, which has no decimation step, gets the same parameters
// on the mesh decimated to the same triangle count by vhacd::Simplify (its time included);
// V-HACD runs with its defaults. Both hullpack methods run on `--threads` threads (default 1, as
// Bullet's HACD is single-threaded).
//
// --timing: the blog's table (bunny decimated to 500 ... 16000 triangles, minNClusters 12,
// maxConcavity 1000), hullpack HACD only; --hulls writes each row's hulls as OBJ.
//
// --simplify: vhacd::Simplify and meshoptimizer's simplifier (npm `meshoptimizer`, run through
// node) at 50 % and 5 % of each mesh's triangles; symmetric Hausdorff distance between the input
// and the result (fraction of the diagonal), measured on random surface samples of both.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <HACD/hacdHACD.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench_util.h"
#include "common/cli_args.h"
#include "hull_metrics.h"
#include "hull_program.h"
#include "vhacd/hacd.h"
#include "vhacd/simplify.h"
#include "vhacd/vhacd.h"

namespace {

using hullpack::bench::Fmt;
using hullpack::bench::HullMetrics;
using hullpack::bench::Median;
using hullpack::bench::MeshMeasure;
using hullpack::bench::MetricsOptions;
using hullpack::bench::Soup;
using hullpack::bench::TriangleBvh;
using hullpack::bench::V3;

double CpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

struct Mesh {
  std::vector<double> points;
  std::vector<uint32_t> indices;
  vhacd::MeshView view() const {
    return vhacd::MeshView::FromDouble(points.data(), points.size() / 3, indices.data(),
                                       indices.size() / 3);
  }
};

Soup ToSoup(const Mesh& m) {
  Soup s;
  for (size_t i = 0; i + 2 < m.points.size(); i += 3)
    s.points.emplace_back(m.points[i], m.points[i + 1], m.points[i + 2]);
  for (size_t i = 0; i + 2 < m.indices.size(); i += 3)
    s.triangles.push_back({m.indices[i], m.indices[i + 1], m.indices[i + 2]});
  return s;
}

// ---------------------------------------------------------------------------------------------
// One decomposition in a child process; the hulls and times come back through a temporary file.

struct RunOutput {
  bool ok = false;
  std::string error;
  double wall = -1, cpu = -1;
  std::vector<Soup> hulls;
};

template <typename F>
RunOutput RunInChild(double timeout_s, F&& body) {
  RunOutput out;
  char path[] = "/tmp/hacd_bench_XXXXXX";
  const int fd = mkstemp(path);
  if (fd < 0) {
    out.error = "mkstemp failed";
    return out;
  }
  close(fd);
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<Soup> hulls;
    std::string err;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = CpuSeconds();
    const bool ok = body(&hulls, &err);
    const double cpu = CpuSeconds() - c0;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    FILE* f = std::fopen(path, "wb");
    if (f == nullptr) _exit(3);
    std::fprintf(f, "%d %.9g %.9g %zu\n", ok ? 1 : 0, wall, cpu, hulls.size());
    for (const Soup& h : hulls) {
      std::fprintf(f, "%zu %zu\n", h.points.size(), h.triangles.size());
      for (const V3& p : h.points) std::fprintf(f, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
      for (const auto& t : h.triangles) std::fprintf(f, "%u %u %u\n", t[0], t[1], t[2]);
    }
    if (!ok) std::fprintf(f, "%s\n", err.c_str());
    std::fclose(f);
    _exit(0);
  }
  if (pid < 0) {
    out.error = "fork failed";
    unlink(path);
    return out;
  }
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout_s) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      out.error = "timeout";
      unlink(path);
      return out;
    }
    usleep(2000);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    out.error = WIFSIGNALED(status) ? "crashed (signal " + std::to_string(WTERMSIG(status)) + ")"
                                    : "exit " + std::to_string(WEXITSTATUS(status));
    unlink(path);
    return out;
  }
  std::ifstream f(path);
  int ok = 0;
  size_t n = 0;
  f >> ok >> out.wall >> out.cpu >> n;
  for (size_t h = 0; h < n && f; ++h) {
    size_t np = 0, nt = 0;
    f >> np >> nt;
    Soup s;
    s.points.resize(np);
    s.triangles.resize(nt);
    for (V3& p : s.points) f >> p[0] >> p[1] >> p[2];
    for (auto& t : s.triangles) f >> t[0] >> t[1] >> t[2];
    out.hulls.push_back(std::move(s));
  }
  if (!ok) {
    std::string rest;
    std::getline(f >> std::ws, out.error);
  }
  out.ok = ok == 1 && static_cast<bool>(f);
  if (ok == 1 && !f) out.error = "truncated result";
  unlink(path);
  return out;
}

std::vector<Soup> ToSoups(const vhacd::Result& r) {
  std::vector<Soup> out;
  for (const vhacd::ConvexHull& h : r.hulls) {
    Soup s;
    for (size_t i = 0; i + 2 < h.points.size(); i += 3)
      s.points.emplace_back(h.points[i], h.points[i + 1], h.points[i + 2]);
    for (size_t i = 0; i + 2 < h.triangles.size(); i += 3)
      s.triangles.push_back({h.triangles[i], h.triangles[i + 1], h.triangles[i + 2]});
    out.push_back(std::move(s));
  }
  return out;
}

bool ParseHacdLine(const std::string& line, vhacd::HacdParameters* p) {
  std::istringstream ss(line);
  double v[7];
  for (double& x : v)
    if (!(ss >> x)) return false;
  p->min_clusters = static_cast<uint32_t>(v[0]);
  p->concavity = v[1];
  p->invert_input_faces = v[2] != 0;
  p->add_extra_dist_points = v[3] != 0;
  p->add_face_points = v[4] != 0;
  p->connect_distance = v[5];
  p->target_triangles = static_cast<uint32_t>(v[6]);
  return true;
}

bool RunBullet(const Mesh& mesh, const vhacd::HacdParameters& p, std::vector<Soup>* hulls,
               std::string* err) {
  Mesh m = mesh;
  if (p.target_triangles > 0 && mesh.indices.size() / 3 > p.target_triangles) {
    vhacd::SimplifyParameters sp;
    sp.target_triangles = p.target_triangles;
    const vhacd::SimplifyResult s = vhacd::Simplify(mesh.view(), sp);
    if (!s.ok()) {
      *err = "simplify: " + s.message;
      return false;
    }
    m.points = s.points;
    m.indices = s.indices;
  }
  std::vector<HACD::Vec3<HACD::Real>> pts(m.points.size() / 3);
  std::vector<HACD::Vec3<long>> tris(m.indices.size() / 3);
  for (size_t i = 0; i < pts.size(); ++i)
    pts[i] = HACD::Vec3<HACD::Real>(m.points[3 * i], m.points[3 * i + 1], m.points[3 * i + 2]);
  for (size_t i = 0; i < tris.size(); ++i)
    tris[i] = HACD::Vec3<long>(m.indices[3 * i], m.indices[3 * i + 1], m.indices[3 * i + 2]);
  HACD::HACD h;
  h.SetPoints(pts.data());
  h.SetNPoints(pts.size());
  h.SetTriangles(tris.data());
  h.SetNTriangles(tris.size());
  h.SetCompacityWeight(p.compacity_weight);
  h.SetVolumeWeight(p.volume_weight);
  h.SetNClusters(p.min_clusters);
  h.SetNVerticesPerCH(p.max_vertices_per_hull);
  h.SetConcavity(p.concavity);
  h.SetAddExtraDistPoints(p.add_extra_dist_points);
  h.SetAddFacesPoints(p.add_face_points);
  h.SetConnectDist(p.connect_distance);
  h.SetScaleFactor(p.scale_factor);
  if (!h.Compute()) {
    *err = "HACD::Compute failed";
    return false;
  }
  for (size_t c = 0; c < h.GetNClusters(); ++c) {
    const size_t np = h.GetNPointsCH(c), nt = h.GetNTrianglesCH(c);
    std::vector<HACD::Vec3<HACD::Real>> hp(np);
    std::vector<HACD::Vec3<long>> ht(nt);
    h.GetCH(c, hp.data(), ht.data());
    Soup s;
    for (auto& q : hp) s.points.emplace_back(q.X(), q.Y(), q.Z());
    for (auto& t : ht)
      s.triangles.push_back({static_cast<uint32_t>(t.X()), static_cast<uint32_t>(t.Y()),
                             static_cast<uint32_t>(t.Z())});
    hulls->push_back(std::move(s));
  }
  return true;
}

struct Row {
  std::string mesh, method;
  size_t triangles = 0;
  bool closed = false;
  RunOutput run;
  double wall = -1, cpu = -1;
  HullMetrics m;
};

std::vector<std::string> Split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string x;
  while (std::getline(ss, x, sep))
    if (!x.empty()) out.push_back(x);
  return out;
}

bool LoadMesh(const std::string& path, Mesh* m) {
  const std::string err = hullpack::ReadSoup(path, &m->points, &m->indices);
  if (!err.empty()) {
    std::fprintf(stderr, "hacd_bench: %s\n", err.c_str());
    return false;
  }
  return true;
}

std::vector<std::string> MeshFiles(const std::string& folder, const std::string& only) {
  std::vector<std::string> names, out;
  if (!hullpack::ListFiles(folder, {"obj", "glb", "gltf", "ply", "off", "stl"}, &names)) return out;
  const std::vector<std::string> keep = Split(only, ',');
  for (const std::string& n : names) {
    const std::string stem = n.substr(0, n.rfind('.'));
    if (n.substr(n.rfind('.')) != ".obj" &&
        std::find(names.begin(), names.end(), stem + ".obj") != names.end())
      continue;
    if (!keep.empty() && std::find(keep.begin(), keep.end(), stem) == keep.end()) continue;
    out.push_back(n);
  }
  return out;
}

int Decomposition(const std::string& folder, const std::map<std::string, std::string>& opt) {
  vhacd::HacdParameters hp;
  if (!ParseHacdLine(opt.count("--hacd") ? opt.at("--hacd") : "2 100 0 1 1 30 2000", &hp)) {
    std::fprintf(stderr, "hacd_bench: --hacd takes 7 numbers\n");
    return 64;
  }
  const int repeats = opt.count("--repeats") ? std::atoi(opt.at("--repeats").c_str()) : 1;
  const double timeout = opt.count("--timeout") ? std::atof(opt.at("--timeout").c_str()) : 600;
  const uint32_t threads =
      opt.count("--threads") ? static_cast<uint32_t>(std::atoi(opt.at("--threads").c_str())) : 1;
  MetricsOptions mo;
  if (opt.count("--samples"))
    mo.mesh_samples = mo.hull_samples = std::atol(opt.at("--samples").c_str());
  hp.num_threads = threads;
  hp.compute_report = false;
  vhacd::Parameters vp;
  vp.num_threads = threads;
  vp.compute_report = false;
  std::vector<std::string> methods = {"hacd"};
  if (!opt.count("--no-bullet")) methods.push_back("bullet-hacd");
  if (!opt.count("--no-vhacd")) methods.push_back("vhacd");
  std::vector<Row> rows;
  std::printf("%-20s %7s %-12s %6s %9s %9s %9s %7s %7s %8s %8s %s\n", "mesh", "tris", "method",
              "hulls", "concav", "mesh>hull", "hull>mesh", "IoU", "IoU*", "wall_s", "cpu_s",
              "invalid");
  for (const std::string& name : MeshFiles(folder, opt.count("--only") ? opt.at("--only") : "")) {
    Mesh mesh;
    if (!LoadMesh(folder + "/" + name, &mesh)) continue;
    const MeshMeasure measure(ToSoup(mesh), mo);
    for (const std::string& method : methods) {
      Row row;
      row.mesh = name.substr(0, name.rfind('.'));
      row.method = method;
      row.triangles = mesh.indices.size() / 3;
      row.closed = measure.closed();
      std::vector<double> walls, cpus;
      for (int r = 0; r < std::max(1, repeats); ++r) {
        RunOutput out = RunInChild(timeout, [&](std::vector<Soup>* hulls, std::string* err) {
          if (method == "bullet-hacd") return RunBullet(mesh, hp, hulls, err);
          const vhacd::Result res = method == "hacd" ? vhacd::DecomposeHacd(mesh.view(), hp)
                                                     : vhacd::Decompose(mesh.view(), vp);
          if (!res.ok()) {
            *err = res.message;
            return false;
          }
          *hulls = ToSoups(res);
          return true;
        });
        if (!out.ok) {
          row.run = std::move(out);
          break;
        }
        walls.push_back(out.wall);
        cpus.push_back(out.cpu);
        if (r == 0) row.run = std::move(out);
      }
      if (row.run.ok) {
        row.wall = Median(walls);
        row.cpu = Median(cpus);
        row.m = measure.Measure(row.run.hulls);
      }
      std::printf("%-20s %7zu %-12s %6s %9s %9s %9s %7s %7s %8s %8s %s\n", row.mesh.c_str(),
                  row.triangles, method.c_str(),
                  row.run.ok ? std::to_string(row.m.hulls).c_str() : "-",
                  Fmt(row.m.concavity).c_str(), Fmt(row.m.mesh_to_hulls).c_str(),
                  Fmt(row.m.hulls_to_mesh).c_str(), Fmt(row.m.iou, "%.3f").c_str(),
                  Fmt(row.m.solid_iou, "%.3f").c_str(), Fmt(row.wall, "%.3f").c_str(),
                  Fmt(row.cpu, "%.3f").c_str(),
                  row.run.ok ? (std::to_string(row.m.invalid_hulls) +
                                (row.m.invalid_hulls ? " (" + row.m.first_problem + ")" : ""))
                                   .c_str()
                             : row.run.error.c_str());
      std::fflush(stdout);
      rows.push_back(std::move(row));
    }
  }
  std::printf("\nmedians over the meshes every method finished:\n");
  std::printf("%-12s %6s %6s %9s %7s %8s %8s %s\n", "method", "meshes", "hulls", "concav", "IoU",
              "wall_s", "cpu_s", "meshes with an invalid hull");
  std::map<std::string, int> finished;
  for (const Row& r : rows)
    if (r.run.ok) ++finished[r.mesh];
  for (const std::string& method : methods) {
    std::vector<double> h, c, iou, w, cpu;
    int invalid = 0, n = 0;
    for (const Row& r : rows) {
      if (r.method != method || finished[r.mesh] != static_cast<int>(methods.size())) continue;
      ++n;
      h.push_back(static_cast<double>(r.m.hulls));
      c.push_back(r.m.concavity);
      if (r.m.iou >= 0) iou.push_back(r.m.iou);
      w.push_back(r.wall);
      cpu.push_back(r.cpu);
      invalid += r.m.invalid_hulls > 0;
    }
    std::printf("%-12s %6d %6s %9s %7s %8s %8s %d\n", method.c_str(), n,
                Fmt(Median(h), "%.1f").c_str(), Fmt(Median(c)).c_str(),
                Fmt(Median(iou), "%.3f").c_str(), Fmt(Median(w), "%.3f").c_str(),
                Fmt(Median(cpu), "%.3f").c_str(), invalid);
  }
  if (opt.count("--csv")) {
    std::ofstream f(opt.at("--csv").c_str());
    f << "mesh,triangles,closed,method,status,hulls,concavity,mesh_to_hulls,hulls_to_mesh,iou,"
         "coverage,solid_iou,wall_s,cpu_s,invalid_hulls\n";
    for (const Row& r : rows)
      f << r.mesh << ',' << r.triangles << ',' << r.closed << ',' << r.method << ','
        << (r.run.ok ? "ok" : r.run.error) << ',' << r.m.hulls << ',' << r.m.concavity << ','
        << r.m.mesh_to_hulls << ',' << r.m.hulls_to_mesh << ',' << r.m.iou << ',' << r.m.coverage
        << ',' << r.m.solid_iou << ',' << r.wall << ',' << r.cpu << ',' << r.m.invalid_hulls
        << '\n';
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------

int Timing(const std::string& path, const std::map<std::string, std::string>& opt) {
  vhacd::HacdParameters hp;
  if (!ParseHacdLine(opt.count("--hacd") ? opt.at("--hacd") : "12 1000 0 1 1 30 0", &hp)) return 64;
  hp.num_threads = opt.count("--threads") ? std::atoi(opt.at("--threads").c_str()) : 0;
  hp.compute_report = false;
  const int repeats = opt.count("--repeats") ? std::atoi(opt.at("--repeats").c_str()) : 1;
  Mesh mesh;
  if (!LoadMesh(path, &mesh)) return 1;
  std::vector<std::string> targets =
      Split(opt.count("--targets") ? opt.at("--targets") : "500,1000,2000,4000,8000,16000", ',');
  std::printf("%s: %zu triangles, threads %u\n%9s %8s %6s %8s %8s\n", path.c_str(),
              mesh.indices.size() / 3, hp.num_threads, "target", "blog_s", "hulls", "wall_s",
              "cpu_s");
  const std::map<int, double> blog = {{500, 2.8}, {1000, 4.6}, {2000, 10},
                                      {4000, 21}, {8000, 70},  {16000, 192}};
  for (const std::string& t : targets) {
    hp.target_triangles = static_cast<uint32_t>(std::atoi(t.c_str()));
    std::vector<double> walls, cpus;
    vhacd::Result r;
    for (int k = 0; k < std::max(1, repeats); ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = CpuSeconds();
      r = vhacd::DecomposeHacd(mesh.view(), hp);
      cpus.push_back(CpuSeconds() - c0);
      walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    const double wall = Median(walls), cpu = Median(cpus);
    const auto it = blog.find(static_cast<int>(hp.target_triangles));
    std::printf("%9u %8s %6zu %8.3f %8.3f\n", hp.target_triangles,
                it != blog.end() ? Fmt(it->second, "%.1f").c_str() : "-", r.hulls.size(), wall,
                cpu);
    if (opt.count("--hulls") && r.ok()) {
      const std::string out = opt.at("--hulls") + "/hulls_" + t + ".obj";
      const std::string err = hullpack::WriteHullScene(r, out);
      if (!err.empty()) std::fprintf(stderr, "hacd_bench: %s\n", err.c_str());
    }
    std::fflush(stdout);
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------

// Area-weighted random surface points plus the vertices.
std::vector<V3> Sample(const Soup& s, size_t n, uint64_t seed) {
  std::vector<V3> out(s.points);
  std::vector<double> cum;
  double total = 0;
  for (const auto& t : s.triangles) {
    total += 0.5 * (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).norm();
    cum.push_back(total);
  }
  if (!(total > 0)) return out;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (size_t i = 0; i < n; ++i) {
    const size_t k = std::lower_bound(cum.begin(), cum.end(), u(rng) * total) - cum.begin();
    const auto& t = s.triangles[std::min(k, s.triangles.size() - 1)];
    double a = u(rng), b = u(rng);
    if (a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    out.push_back(s.points[t[0]] + a * (s.points[t[1]] - s.points[t[0]]) +
                  b * (s.points[t[2]] - s.points[t[0]]));
  }
  return out;
}

double OneSided(const std::vector<V3>& from, const TriangleBvh& to) {
  double m = 0;
  for (const V3& p : from) m = std::max(m, to.Distance(p));
  return m;
}

// meshoptimizer through node: positions (float32) and indices (uint32) in, indices out.
bool MeshoptSimplify(const std::string& node, const Mesh& m, size_t target, Soup* out,
                     double* seconds) {
  const std::string dir = "/tmp/hacd_bench_mo_" + std::to_string(getpid());
  if (system(("mkdir -p " + dir).c_str()) != 0) return false;
  {
    std::ofstream f(dir + "/in.bin", std::ios::binary);
    const uint32_t nv = static_cast<uint32_t>(m.points.size() / 3),
                   ni = static_cast<uint32_t>(m.indices.size());
    f.write(reinterpret_cast<const char*>(&nv), 4);
    f.write(reinterpret_cast<const char*>(&ni), 4);
    for (double v : m.points) {
      const float x = static_cast<float>(v);
      f.write(reinterpret_cast<const char*>(&x), 4);
    }
    f.write(reinterpret_cast<const char*>(m.indices.data()), 4 * m.indices.size());
  }
  {
    std::ofstream js(dir + "/run.mjs");
    js << "import fs from 'fs';\n"
          "const { MeshoptSimplifier } = await import(process.argv[5]);\n"
          "const b = fs.readFileSync(process.argv[2]);\n"
          "const nv = b.readUInt32LE(0), ni = b.readUInt32LE(4);\n"
          "const pos = new Float32Array(b.buffer.slice(b.byteOffset + 8, b.byteOffset + 8 + nv * "
          "12));\n"
          "const idx = new Uint32Array(b.buffer.slice(b.byteOffset + 8 + nv * 12, b.byteOffset + 8 "
          "+ nv * 12 + ni * 4));\n"
          "await MeshoptSimplifier.ready;\n"
          "const t0 = process.hrtime.bigint();\n"
          "const [res] = MeshoptSimplifier.simplify(idx, pos, 3, Number(process.argv[4]) * 3, 1.0, "
          "[]);\n"
          "const t1 = process.hrtime.bigint();\n"
          "fs.writeFileSync(process.argv[3], Buffer.from(res.buffer, res.byteOffset, "
          "res.byteLength));\n"
          "console.log(Number(t1 - t0) / 1e9);\n";
  }
  char real[4096];
  if (realpath((node + "/meshoptimizer/index.js").c_str(), real) == nullptr) return false;
  const std::string cmd = "node " + dir + "/run.mjs " + dir + "/in.bin " + dir + "/out.bin " +
                          std::to_string(target) + " file://" + real + " > " + dir + "/t.txt";
  if (system(cmd.c_str()) != 0) return false;
  std::ifstream t(dir + "/t.txt");
  t >> *seconds;
  std::ifstream f(dir + "/out.bin", std::ios::binary | std::ios::ate);
  const size_t bytes = static_cast<size_t>(f.tellg());
  f.seekg(0);
  std::vector<uint32_t> idx(bytes / 4);
  f.read(reinterpret_cast<char*>(idx.data()), bytes);
  *out = ToSoup(m);
  out->triangles.clear();
  for (size_t i = 0; i + 2 < idx.size(); i += 3)
    out->triangles.push_back({idx[i], idx[i + 1], idx[i + 2]});
  return true;
}

int SimplifyBench(const std::string& folder, const std::map<std::string, std::string>& opt) {
  const std::string node_modules =
      opt.count("--node") ? opt.at("--node") : std::string("node_modules");
  const size_t samples = opt.count("--samples") ? std::atol(opt.at("--samples").c_str()) : 50000;
  std::printf("%-20s %8s %6s %9s %9s %10s %10s %8s %8s %6s\n", "mesh", "tris", "ratio", "ours_tris",
              "mo_tris", "ours_hd", "mo_hd", "ours_s", "mo_s", "flips");
  // All meshes, and only those where both reach the same count (within 5 %: meshoptimizer stops
  // early on some borders and seams).
  std::map<double, std::vector<double>> ours_hd, mo_hd, ours_same, mo_same;
  for (const std::string& name : MeshFiles(folder, opt.count("--only") ? opt.at("--only") : "")) {
    Mesh mesh;
    if (!LoadMesh(folder + "/" + name, &mesh)) continue;
    const Soup in = ToSoup(mesh);
    const TriangleBvh in_bvh(in);
    const std::vector<V3> in_samples = Sample(in, samples, 1);
    V3 lo = in.points[0], hi = lo;
    for (const V3& p : in.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const double diag = (hi - lo).norm();
    for (double ratio : {0.5, 0.05}) {
      const size_t target = std::max<size_t>(4, static_cast<size_t>(ratio * in.triangles.size()));
      vhacd::SimplifyParameters sp;
      sp.target_triangles = static_cast<uint32_t>(target);
      const auto t0 = std::chrono::steady_clock::now();
      const vhacd::SimplifyResult s = vhacd::Simplify(mesh.view(), sp);
      const double ours_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      Mesh sm;
      sm.points = s.points;
      sm.indices = s.indices;
      const Soup ours = ToSoup(sm);
      Soup mo;
      double mo_s = -1;
      const bool mo_ok = MeshoptSimplify(node_modules, mesh, target, &mo, &mo_s);
      auto hd = [&](const Soup& out) {
        if (out.triangles.empty()) return -1.0;
        const TriangleBvh bvh(out);
        return std::max(OneSided(in_samples, bvh), OneSided(Sample(out, samples, 2), in_bvh)) /
               diag;
      };
      const double a = s.ok() ? hd(ours) : -1, b = mo_ok ? hd(mo) : -1;
      size_t flips = 0;
      for (size_t t = 0; t < s.triangle_count(); ++t) {
        const auto& tri = ours.triangles[t];
        const V3 n = (ours.points[tri[1]] - ours.points[tri[0]])
                         .cross(ours.points[tri[2]] - ours.points[tri[0]]);
        // Flipped: facing away from the input triangle it descends from.
        const auto& src = in.triangles[s.triangle_source[t]];
        const V3 m =
            (in.points[src[1]] - in.points[src[0]]).cross(in.points[src[2]] - in.points[src[0]]);
        flips += n.dot(m) <= 0;
      }
      if (a >= 0 && b >= 0) {
        ours_hd[ratio].push_back(a);
        mo_hd[ratio].push_back(b);
        const double na = static_cast<double>(ours.triangles.size()),
                     nb = static_cast<double>(mo.triangles.size());
        if (std::fabs(na - nb) <= 0.05 * std::max(na, nb)) {
          ours_same[ratio].push_back(a);
          mo_same[ratio].push_back(b);
        }
      }
      std::printf("%-20s %8zu %6.2f %9zu %9zu %10s %10s %8.3f %8s %6zu\n",
                  name.substr(0, name.rfind('.')).c_str(), in.triangles.size(), ratio,
                  ours.triangles.size(), mo.triangles.size(), Fmt(a, "%.5f").c_str(),
                  Fmt(b, "%.5f").c_str(), ours_s, Fmt(mo_s, "%.3f").c_str(), flips);
      std::fflush(stdout);
    }
  }
  for (double ratio : {0.5, 0.05})
    std::printf(
        "median symmetric Hausdorff at %.0f %%: hullpack %s, meshoptimizer %s (%zu meshes)\n",
        ratio * 100, Fmt(Median(ours_hd[ratio]), "%.5f").c_str(),
        Fmt(Median(mo_hd[ratio]), "%.5f").c_str(), ours_hd[ratio].size());
  for (double ratio : {0.5, 0.05})
    std::printf(
        "  where both reach the same count at %.0f %%: hullpack %s, meshoptimizer %s (%zu "
        "meshes)\n",
        ratio * 100, Fmt(Median(ours_same[ratio]), "%.5f").c_str(),
        Fmt(Median(mo_same[ratio]), "%.5f").c_str(), ours_same[ratio].size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> opt;
  std::vector<std::string> pos;
  hullpack::CliArgs cli(
      "hacd_bench", "FOLDER [options] | --timing MESH | --simplify FOLDER",
      "hullpack's HACD, V-HACD and Bullet's HACD side by side on every mesh of "
      "FOLDER, measured by\nhull_metrics; the blog's timing table; the simplifier "
      "against meshoptimizer's.");
  cli.Positional("FOLDER", &pos, 0, 1);
  auto text = [&](const char* names, const char* value, const char* help) {
    const std::string key = std::string(names).substr(std::string(names).rfind(' ') + 1);
    cli.Value(names, value, help, [&opt, key](const std::string& v) {
      opt[key] = v;
      return std::string();
    });
  };
  text("--hacd", "LINE", "the seven testHACD numbers (default '2 100 0 1 1 30 2000')");
  text("--only", "A,B", "only these meshes (file names without extension)");
  text("--repeats", "N", "runs per method and mesh (per row with --timing); times are medians (1)");
  text("--timeout", "S", "seconds before a run is stopped (600)");
  text("--samples", "N", "surface samples per measure");
  text("--threads", "N", "threads of hullpack's methods (decomposition 1, timing 0 = every core)");
  text("--csv", "FILE", "every row as CSV");
  text("--timing", "MESH", "the blog's timing table on MESH (bunny)");
  text("--targets", "LIST", "triangle counts of --timing (500,1000,2000,4000,8000,16000)");
  text("--hulls", "DIR", "with --timing, write each row's hulls there");
  text("--simplify", "FOLDER", "the simplifier against meshoptimizer's at 50 % and 5 %");
  text("--node", "DIR", "the node_modules folder holding meshoptimizer (node_modules)");
  cli.Action("--no-bullet", "leave Bullet's HACD out", [&opt]() { opt["--no-bullet"] = "1"; });
  cli.Action("--no-vhacd", "leave V-HACD out", [&opt]() { opt["--no-vhacd"] = "1"; });
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  if (opt.count("--timing")) return Timing(opt.at("--timing"), opt);
  if (opt.count("--simplify")) return SimplifyBench(opt.at("--simplify"), opt);
  if (pos.size() != 1) return cli.UsageError("give FOLDER, --timing MESH or --simplify FOLDER");
  return Decomposition(pos[0], opt);
}
