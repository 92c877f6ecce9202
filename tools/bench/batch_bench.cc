// batch_bench: `hullpack batch` against calling `hullpack pack` directly, over many small assets
// made for the run: generated parts (tori and non-convex star prisms of varied sizes and
// resolutions) and corpus-derived patches (the T triangles nearest to P seed points of every
// corpus mesh). Three runs of the same binary, each a child process timed by wall clock and CPU
// (wait4): `pack ALL -o DIR/` (the direct call), `batch` with an empty cache (cold), `batch` again
// (warm: all cache hits). Reports assets per second, batch's overhead per asset against pack
// (wall and CPU), how busy the cores were (CPU / (wall * jobs)), the warm run as a fraction of the
// cold one, and whether batch's outputs equal pack's byte for byte.
//
//   batch_bench --hullpack BIN [--corpus DIR] [--generated N] [--patches P] [--patch-triangles T]
//               [--jobs J] [--repeats R] [--work DIR] [-- PACK OPTIONS]
#include <dirent.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "common/cli_args.h"
#include "common/file_util.h"
#include "io/scene_io.h"

namespace {

using hullpack::Mesh;

struct Timing {
  int exit_code = -1;
  double wall = 0, cpu = 0;
  // Seconds every thread of the child was running or waiting for a core (/proc/PID/task/*/
  // schedstat, sampled every 50 ms), over the wall time: how many cores the child kept asking for,
  // which other load on the machine does not lower (as it lowers CPU / wall).
  double runnable_threads = 0;
};

// Adds each thread's running + run-queue-waiting seconds to `seconds` (by thread id).
void SampleThreads(pid_t pid, std::map<long, double>* seconds) {
  const std::string dir = "/proc/" + std::to_string(pid) + "/task";
  DIR* tasks = opendir(dir.c_str());
  if (!tasks) return;
  while (dirent* e = readdir(tasks)) {
    if (e->d_name[0] == '.') continue;
    std::ifstream in(dir + "/" + e->d_name + "/schedstat");
    double running = 0, waiting = 0;
    if (in >> running >> waiting) (*seconds)[std::atol(e->d_name)] = (running + waiting) * 1e-9;
  }
  closedir(tasks);
}

// Runs argv with stdout and stderr to `log`; wall and CPU time (user + system of the child and
// everything it waited for).
Timing Run(const std::vector<std::string>& argv, const std::string& log) {
  Timing t;
  std::fflush(stdout);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    if (!freopen(log.c_str(), "w", stdout) || !freopen(log.c_str(), "a", stderr)) _exit(126);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  std::map<long, double> thread_seconds;
  pid_t done = 0;
  while (pid > 0 && (done = wait4(pid, &status, WNOHANG, &usage)) == 0) {
    SampleThreads(pid, &thread_seconds);
    usleep(50000);
  }
  if (pid > 0 && done == pid) {
    t.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    t.cpu = usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6 + usage.ru_stime.tv_sec +
            usage.ru_stime.tv_usec * 1e-6;
  }
  t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& [tid, seconds] : thread_seconds) t.runnable_threads += seconds;
  t.runnable_threads /= t.wall;
  return t;
}

void WriteObj(const std::string& path, const std::vector<double>& v,
              const std::vector<uint32_t>& f) {
  std::ofstream out(path);
  char line[128];
  for (size_t i = 0; i < v.size(); i += 3) {
    std::snprintf(line, sizeof(line), "v %.6f %.6f %.6f\n", v[i], v[i + 1], v[i + 2]);
    out << line;
  }
  for (size_t i = 0; i < f.size(); i += 3)
    out << "f " << f[i] + 1 << ' ' << f[i + 1] + 1 << ' ' << f[i + 2] + 1 << '\n';
}

void Torus(double R, double r, int u, int w, std::vector<double>* v, std::vector<uint32_t>* f) {
  const double pi = 3.14159265358979;
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < w; ++j) {
      const double a = 2 * pi * i / u, b = 2 * pi * j / w;
      v->insert(v->end(), {(R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
                           r * std::sin(b)});
    }
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < w; ++j) {
      const uint32_t p = i * w + j, q = (i + 1) % u * w + j, s = (i + 1) % u * w + (j + 1) % w,
                     t = i * w + (j + 1) % w;
      f->insert(f->end(), {p, q, s, p, s, t});
    }
}

// A closed prism over a star polygon with `points` tips: non-convex, like a machined part.
void StarPrism(int points, double inner, double height, std::vector<double>* v,
               std::vector<uint32_t>* f) {
  const double pi = 3.14159265358979;
  const int n = 2 * points;
  for (int z = 0; z < 2; ++z) {
    v->insert(v->end(), {0, 0, z * height});  // cap centre
    for (int i = 0; i < n; ++i) {
      const double a = pi * i / points, radius = i % 2 ? inner : 1.0;
      v->insert(v->end(), {radius * std::cos(a), radius * std::sin(a), z * height});
    }
  }
  const uint32_t top = n + 1;
  for (int i = 0; i < n; ++i) {
    const uint32_t a = 1 + i, b = 1 + (i + 1) % n;
    f->insert(f->end(), {0, b, a, top, top + a, top + b, a, b, top + b, a, top + b, top + a});
  }
}

// The `count` triangles whose centroids lie nearest to triangle `seed`'s, as a new mesh.
void Patch(const Mesh& mesh, size_t seed, size_t count, std::vector<double>* v,
           std::vector<uint32_t>* f) {
  const size_t tris = mesh.triangle_count();
  auto centroid = [&](size_t t, int axis) {
    double s = 0;
    for (int k = 0; k < 3; ++k) s += mesh.positions[3 * mesh.indices[3 * t + k] + axis];
    return s / 3;
  };
  std::vector<std::pair<double, size_t>> by_distance(tris);
  for (size_t t = 0; t < tris; ++t) {
    double d = 0;
    for (int axis = 0; axis < 3; ++axis) d += std::pow(centroid(t, axis) - centroid(seed, axis), 2);
    by_distance[t] = {d, t};
  }
  count = std::min(count, tris);
  std::nth_element(by_distance.begin(), by_distance.begin() + static_cast<long>(count) - 1,
                   by_distance.end());
  std::vector<int64_t> remap(mesh.vertex_count(), -1);
  std::vector<size_t> chosen;
  for (size_t i = 0; i < count; ++i) chosen.push_back(by_distance[i].second);
  std::sort(chosen.begin(), chosen.end());
  for (size_t t : chosen)
    for (int k = 0; k < 3; ++k) {
      const uint32_t old = mesh.indices[3 * t + k];
      if (remap[old] < 0) {
        remap[old] = static_cast<int64_t>(v->size() / 3);
        for (int axis = 0; axis < 3; ++axis) v->push_back(mesh.positions[3 * old + axis]);
      }
      f->push_back(static_cast<uint32_t>(remap[old]));
    }
}

bool SameFiles(const std::string& a, const std::string& b) {
  auto x = hullpack::ReadFileBytes(a), y = hullpack::ReadFileBytes(b);
  return x.ok() && y.ok() && x.value() == y.value();
}

std::string LoadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string line;
  std::getline(in, line);
  return line + "\n";
}

std::string Stem(const std::string& name) { return name.substr(0, name.find_last_of('.')); }

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::string hullpack_bin, corpus, work = "/tmp/hullpack-batch-bench";
  long generated = 800, patches = 16, patch_triangles = 1500, jobs = 2, repeats = 1;
  std::vector<std::string> pack_options;
  hullpack::CliArgs cli(
      "batch_bench", "--hullpack BIN [options] [-- PACK OPTION...]",
      "`hullpack batch` against `hullpack pack ALL -o DIR/` over generated and corpus-derived\n"
      "  assets: wall and CPU seconds, assets/s, threads running or ready, the second (cached) "
      "run.");
  cli.String("--hullpack", "BIN", &hullpack_bin, "the hullpack program to measure").Required();
  cli.String("--corpus", "DIR", &corpus, "meshes (.obj, .glb) to cut patches from");
  cli.Int("--generated", "N", 0, 1000000, &generated, "generated parts (default 800)");
  cli.Int("--patches", "P", 0, 10000, &patches, "patches per corpus mesh (default 16)");
  cli.Int("--patch-triangles", "T", 4, 10000000, &patch_triangles,
          "triangles per patch (default 1500)");
  cli.Int("--jobs", "J", 1, 256, &jobs, "--jobs of both programs (default 2)");
  cli.Int("--repeats", "R", 1, 100, &repeats, "runs of each; medians are reported (default 1)");
  cli.String("--work", "DIR", &work, "scratch folder, emptied first (/tmp/hullpack-batch-bench)");
  cli.Positional("PACK OPTION", &pack_options, 0);
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  if (std::system(("rm -rf '" + work + "'").c_str()) != 0 ||
      !hullpack::MakeDirectories(work + "/assets").ok()) {
    std::fprintf(stderr, "batch_bench: cannot prepare %s\n", work.c_str());
    return 1;
  }

  // The assets.
  std::vector<std::string> names;
  for (long i = 0; i < generated; ++i) {
    std::vector<double> v;
    std::vector<uint32_t> f;
    char name[64];
    if (i % 2 == 0) {
      Torus(1 + (i % 11) * 0.1, 0.15 + (i % 7) * 0.04, 12 + static_cast<int>(i % 13),
            6 + static_cast<int>(i % 5), &v, &f);
      std::snprintf(name, sizeof(name), "torus%04ld.obj", i);
    } else {
      StarPrism(4 + static_cast<int>(i % 9), 0.3 + (i % 5) * 0.1, 0.2 + (i % 6) * 0.15, &v, &f);
      std::snprintf(name, sizeof(name), "star%04ld.obj", i);
    }
    WriteObj(work + "/assets/" + name, v, f);
    names.push_back(name);
  }
  size_t derived = 0;
  std::vector<std::string> corpus_files;
  if (!corpus.empty()) hullpack::ListFiles(corpus, {"obj", "glb"}, &corpus_files);
  for (const std::string& file : corpus_files) {
    if (hullpack::LowerExtension(file) == "glb" &&
        std::find(corpus_files.begin(), corpus_files.end(), Stem(file) + ".obj") !=
            corpus_files.end())
      continue;  // the same asset as its .obj
    auto scene = hullpack::ReadScene(corpus + "/" + file);
    if (!scene.ok()) continue;
    const Mesh mesh = hullpack::MergeGeometry(scene.value());
    if (mesh.triangle_count() < 64) continue;
    for (long p = 0; p < patches; ++p) {
      std::vector<double> v;
      std::vector<uint32_t> f;
      const size_t seed = static_cast<size_t>(p) * 7919 % mesh.triangle_count();
      Patch(mesh, seed, static_cast<size_t>(patch_triangles), &v, &f);
      const std::string name = Stem(file) + "_patch" + std::to_string(p) + ".obj";
      WriteObj(work + "/assets/" + name, v, f);
      names.push_back(name);
      ++derived;
    }
  }
  {
    std::ofstream manifest(work + "/assets/manifest.txt");
    for (const std::string& n : names) manifest << n << '\n';
  }
  const size_t count = names.size();
  std::printf("assets: %zu (%ld generated, %zu corpus-derived patches of %ld triangles)\n", count,
              generated, derived, patch_triangles);
  std::printf("jobs %ld, pack options:", jobs);
  for (const std::string& o : pack_options) std::printf(" %s", o.c_str());
  std::printf("\n");

  const std::string j = std::to_string(jobs);
  std::vector<double> direct_wall, direct_cpu, cold_wall, cold_cpu, warm_wall, warm_cpu,
      direct_threads, cold_threads;
  bool identical = true;
  int failures = 0;
  for (long r = 0; r < repeats; ++r) {
    const std::string direct = work + "/direct" + std::to_string(r) + "/";
    const std::string batch = work + "/batch" + std::to_string(r);
    hullpack::MakeDirectories(direct);
    std::vector<std::string> pack = {hullpack_bin, "pack"};
    for (const std::string& n : names) pack.push_back(work + "/assets/" + n);
    pack.insert(pack.end(), {"-o", direct, "--jobs", j, "--quiet", "--force"});
    pack.insert(pack.end(), pack_options.begin(), pack_options.end());
    std::vector<std::string> run = {
        hullpack_bin, "batch", "--manifest", work + "/assets/manifest.txt", "-o", batch,
        "--jobs",     j,       "--quiet"};
    run.insert(run.end(), pack_options.begin(), pack_options.end());
    // Alternate which goes first, so that neither always meets a cold page cache.
    Timing d, c;
    if (r % 2 == 0) {
      d = Run(pack, work + "/direct.log");
      c = Run(run, work + "/cold.log");
    } else {
      c = Run(run, work + "/cold.log");
      d = Run(pack, work + "/direct.log");
    }
    const Timing w = Run(run, work + "/warm.log");
    if (d.exit_code != 0 || c.exit_code != 0 || w.exit_code != 0) ++failures;
    direct_wall.push_back(d.wall);
    direct_cpu.push_back(d.cpu);
    cold_wall.push_back(c.wall);
    cold_cpu.push_back(c.cpu);
    direct_threads.push_back(d.runnable_threads);
    cold_threads.push_back(c.runnable_threads);
    warm_wall.push_back(w.wall);
    warm_cpu.push_back(w.cpu);
    for (const std::string& n : names) {
      const std::string out = Stem(n) + ".packed.glb";
      if (!SameFiles(direct + out, batch + "/" + out)) identical = false;
    }
    std::printf(
        "run %ld: pack %.1f s (cpu %.1f s, exit %d), batch cold %.1f s (cpu %.1f s, exit "
        "%d), warm %.2f s (cpu %.2f s)\n",
        r, d.wall, d.cpu, d.exit_code, c.wall, c.cpu, c.exit_code, w.wall, w.cpu);
  }
  const double dw = Median(direct_wall), dc = Median(direct_cpu), cw = Median(cold_wall),
               cc = Median(cold_cpu), ww = Median(warm_wall);
  std::printf(
      "\n| | wall s | CPU s | assets/s | CPU / (wall x %ld) | threads running or ready |\n"
      "|---|---|---|---|---|---|\n",
      jobs);
  std::printf("| pack ALL -o DIR/ | %.1f | %.1f | %.1f | %.0f %% | %.2f |\n", dw, dc, count / dw,
              100 * dc / (dw * jobs), Median(direct_threads));
  std::printf("| batch, empty cache | %.1f | %.1f | %.1f | %.0f %% | %.2f |\n", cw, cc, count / cw,
              100 * cc / (cw * jobs), Median(cold_threads));
  std::printf("| batch again (all hits) | %.2f | %.2f | %.0f | | |\n", ww, Median(warm_cpu),
              count / ww);
  std::printf("load average at the end: %s", LoadAverage().c_str());
  std::printf(
      "\nbatch overhead per asset vs pack: wall %+.2f ms (%+.1f %%), CPU %+.2f ms (%+.1f %%)\n",
      1000 * (cw - dw) / count, 100 * (cw - dw) / dw, 1000 * (cc - dc) / count,
      100 * (cc - dc) / dc);
  std::printf("second run / first run: %.2f %% of the wall time\n", 100 * ww / cw);
  std::printf("batch outputs byte-identical to pack's: %s\n", identical ? "yes" : "NO");
  if (failures) std::printf("%d runs exited non-zero (see %s/*.log)\n", failures, work.c_str());
  return identical && failures == 0 ? 0 : 1;
}
