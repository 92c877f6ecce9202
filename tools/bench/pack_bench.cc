// pack_bench: `hullpack pack` against Draco at equal error, on every .obj/.glb of a folder, in one run.
// For each file: the packed GLB's geometry bytes (mesh streams + hull streams) at --max-error, the
// error reached, and the same pruned meshes compressed by Draco (-cl 7) at the same position bits,
// without hulls. The bar: packed-with-hulls <= Draco-without-hulls in median.
//
//   pack_bench FOLDER [--max-error 0.0005] [--csv out.csv]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/draco_bridge.h"
#include "io/scene_io.h"
#include "pipeline/pack.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: pack_bench FOLDER [--max-error F] [--csv FILE]\n");
    return 64;
  }
  const std::string folder = argv[1];
  hullpack::PackOptions options;
  std::string csv;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--max-error") {
      options.max_error = std::atof(argv[i + 1]);
    } else if (flag == "--csv") {
      csv = argv[i + 1];
    } else {
      std::fprintf(stderr, "pack_bench: unknown option %s\n", flag.c_str());
      return 64;
    }
  }
  std::vector<std::string> files;
  if (!hullpack::ListFiles(folder, {"obj", "glb"}, &files)) {
    std::fprintf(stderr, "pack_bench: %s: cannot open folder\n", folder.c_str());
    return 1;
  }
  std::printf("%-22s %8s | %9s %9s %9s %5s | %9s | %6s | %9s %7s\n", "file", "tris", "mesh B", "hulls B", "packed B",
              "hulls", "draco B", "ratio", "max err", "seconds");
  std::string text = "file,triangles,mesh_bytes,hull_bytes,packed_geometry_bytes,hulls,draco_bytes,ratio,max_error_fraction,seconds,glb_bytes\n";
  std::vector<double> ratios;
  int failures = 0;
  for (const std::string& file : files) {
    hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(folder + "/" + file);
    if (!scene.ok()) {
      std::fprintf(stderr, "pack_bench: %s\n", scene.status().message().c_str());
      ++failures;
      continue;
    }
    hullpack::Result<hullpack::PackResult> packed = hullpack::Status(hullpack::StatusCode::kInternal, "");
    const double ms = hullpack::MedianMs(1, [&] { packed = hullpack::PackScene(scene.value(), options); });
    if (!packed.ok()) {
      std::fprintf(stderr, "pack_bench: %s: %s\n", file.c_str(), packed.status().message().c_str());
      ++failures;
      continue;
    }
    // Draco gets the same meshes the packer encoded (after leaving out what is unused).
    hullpack::Scene pruned = scene.value();
    hullpack::LeaveOutUnused(pruned, options.prune);
    size_t mesh_bytes = 0, hull_bytes = 0, hulls = 0, draco_bytes = 0, triangles = 0;
    double worst = 0;
    for (size_t m = 0; m < pruned.meshes.size(); ++m) {
      const hullpack::MeshPackReport& r = packed->report.meshes[m];
      mesh_bytes += r.bytes_after;
      hull_bytes += r.hull_bytes;
      hulls += r.hull_count;
      triangles += r.triangles;
      worst = std::max(worst, r.max_error_fraction);
      std::unique_ptr<draco::Mesh> d = hullpack::ToDracoMesh(pruned.meshes[m]);
      const std::vector<uint8_t> bytes = d ? hullpack::DracoEncode(*d, r.position_bits, options.normal_bits, options.uv_bits, 7)
                                           : std::vector<uint8_t>();
      draco_bytes += bytes.size();
    }
    const size_t packed_bytes = mesh_bytes + hull_bytes;
    const double ratio = draco_bytes ? double(packed_bytes) / draco_bytes : 0;
    ratios.push_back(ratio);
    std::printf("%-22s %8zu | %9zu %9zu %9zu %5zu | %9zu | %6.3f | %9.6f %7.2f\n", file.c_str(), triangles, mesh_bytes,
                hull_bytes, packed_bytes, hulls, draco_bytes, ratio, worst, ms / 1000);
    char line[512];
    std::snprintf(line, sizeof(line), "%s,%zu,%zu,%zu,%zu,%zu,%zu,%.4f,%.6g,%.3f,%zu\n", file.c_str(), triangles,
                  mesh_bytes, hull_bytes, packed_bytes, hulls, draco_bytes, ratio, worst, ms / 1000,
                  packed->glb.size());
    text += line;
  }
  if (!ratios.empty()) {
    std::vector<double> sorted = ratios;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.size() % 2 ? sorted[sorted.size() / 2]
                                            : 0.5 * (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]);
    std::printf("median packed-with-hulls / Draco-without-hulls: %.3f over %zu files (max-error %g)\n", median,
                ratios.size(), options.max_error);
  }
  if (!csv.empty()) {
    hullpack::Status st = hullpack::WriteFileAtomically(csv, text.data(), text.size());
    if (!st.ok()) {
      std::fprintf(stderr, "pack_bench: %s\n", st.message().c_str());
      return 1;
    }
  }
  return failures;
}
