// Small helpers the benchmark programs share.
#ifndef HULLPACK_TOOLS_BENCH_BENCH_UTIL_H_
#define HULLPACK_TOOLS_BENCH_BENCH_UTIL_H_

#include <dirent.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "common/file_util.h"
#include "mesh/flatten.h"
#include "mesh/repair.h"
#include "scene/scene.h"

namespace hullpack {

// Sorted names of the files in `folder` whose lower-case extension is one of `extensions`; false
// when the folder cannot be read.
inline bool ListFiles(const std::string& folder, const std::vector<std::string>& extensions,
                      std::vector<std::string>* out) {
  DIR* dir = opendir(folder.c_str());
  if (!dir) return false;
  while (dirent* e = readdir(dir)) {
    const std::string name = e->d_name;
    if (std::find(extensions.begin(), extensions.end(), LowerExtension(name)) != extensions.end())
      out->push_back(name);
  }
  closedir(dir);
  std::sort(out->begin(), out->end());
  return true;
}

namespace bench {

// The median of `v` (the mean of the two middle values for an even count); -1 when `v` is empty,
// which Fmt prints as "-".
inline double Median(std::vector<double> v) {
  if (v.empty()) return -1.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// `v` printed with the printf format `f`; "-" for a negative value (not measured).
inline std::string Fmt(double v, const char* f = "%.4f") {
  if (v < 0) return "-";
  char b[64];
  std::snprintf(b, sizeof(b), f, v);
  return b;
}

}  // namespace bench

// Median wall time of `repeats` calls, in milliseconds.
template <typename F>
double MedianMs(int repeats, F&& run) {
  std::vector<double> ms;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    run();
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

// Every mesh of a scene as one, with the attributes the benchmarks compare (positions, normals,
// the first UV set: what both codecs and the decomposition are given; with `keep_skin` also the
// joints and weights); see FlattenScene. Vertices that differed only in an attribute left out (a
// UV set only some meshes have, colours) are welded, as Draco's mesh builder welds them, so that
// every codec is given the same vertices; nothing else is repaired.
inline Mesh MergeGeometry(const Scene& scene, bool keep_skin = false) {
  Mesh out = FlattenScene(scene);
  out.colors.clear();
  if (!keep_skin || !out.has_skin()) {
    out.joints.clear();
    out.weights.clear();
  }
  out.material_ids.clear();
  RepairOptions weld_only;
  weld_only.remove_degenerate_triangles = false;
  weld_only.remove_duplicate_triangles = false;
  weld_only.remove_unused_vertices = false;
  RepairMesh(out, weld_only);
  return out;
}

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_BENCH_UTIL_H_
