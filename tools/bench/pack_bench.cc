// pack_bench: `hullpack pack` against Draco at equal error, on every .obj/.glb of a folder, in one
// run. For each file: the packed GLB's geometry bytes (mesh streams + hull streams) at --max-error,
// the error reached, and the same pruned meshes compressed by Draco (-cl 7) without hulls, each
// mesh at the fewest position bits whose measured error stays within the same budget (Draco's usual
// quantization: a cube of the largest extent). The bar: packed-with-hulls <= Draco-without-hulls in
// median. Every file is also read back (unpack(pack(x))) and checked against x: same triangle,
// vertex and skin counts, position error within the budget. Also per file: the GLB's JSON bytes
// (the hulls' meshes, accessors, shapes and collider nodes add to it; not geometry) and seconds per
// stage.
//
//   pack_bench FOLDER [--max-error 0.0005] [--hull-error F] [--max-hulls N] [--max-vertices N]
//              [--gamma F] [--csv out.csv]   (see --help)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/draco_bridge.h"
#include "common/cli_args.h"
#include "io/scene_io.h"
#include "o3dgc/o3dgc.h"
#include "packed/packed_glb_reader.h"
#include "pipeline/check_and_repair.h"
#include "pipeline/codec_weld.h"
#include "pipeline/mesh_codec.h"
#include "pipeline/pack.h"

namespace {

// Length of a GLB's JSON chunk (0 when the header is not a GLB's).
size_t JsonChunkBytes(const std::vector<uint8_t>& glb) {
  if (glb.size() < 20) return 0;
  return size_t(glb[12]) | size_t(glb[13]) << 8 | size_t(glb[14]) << 16 | size_t(glb[15]) << 24;
}

}  // namespace

int main(int argc, char** argv) {
  hullpack::PackOptions options;
  vhacd::Parameters& p = options.collision.parameters;
  std::string csv;
  std::vector<std::string> folders;
  hullpack::CliArgs cli(
      "pack_bench", "FOLDER [options]",
      "`hullpack pack` against Draco at equal error on every .obj/.glb of FOLDER: packed geometry\n"
      "bytes (meshes + hulls) against Draco -cl 7 without hulls, the error reached, a round trip\n"
      "check and seconds per stage.");
  cli.VersionDetail(std::string("o3dgc stream format ") + o3dgc::FormatVersionString());
  cli.Positional("FOLDER", &folders, 1, 1);
  cli.Double("--max-error", "F", 1e-9, 0.5, &options.max_error,
             "largest position error, fraction of each mesh's bbox diagonal (0.0005)");
  cli.Double("--hull-error", "F", 1e-9, 0.5, &options.hull_error,
             "largest hull vertex error, fraction of the bbox diagonal (0.002)");
  cli.Int("--max-hulls", "N", 0, 100000, &p.max_convex_hulls, "most hulls per mesh (0: no limit)");
  cli.Int("--max-vertices", "N", 4, 1024, &p.max_vertices_per_hull, "most vertices per hull");
  cli.Double("--gamma", "F", 0, 1, &p.gamma, "largest concavity while merging hulls");
  cli.String("--csv", "FILE", &csv, "also write the table as CSV");
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  const std::string& folder = folders[0];
  std::vector<std::string> files;
  if (!hullpack::ListFiles(folder, {"obj", "glb"}, &files)) {
    std::fprintf(stderr, "pack_bench: %s: cannot open folder\n", folder.c_str());
    return 1;
  }
  std::printf("%-22s %7s %5s | %8s %7s %8s | %8s %2s | %6s | %9s %9s | %6s %6s | %6s %6s %6s %6s\n",
              "file", "tris", "hulls", "mesh B", "hulls B", "packed B", "draco B", "qp", "ratio",
              "rt err", "draco err", "json B", "glb B", "enc s", "dec s", "vhacd s", "hull s");
  std::string text =
      "file,triangles,hulls,mesh_bytes,hull_bytes,packed_geometry_bytes,draco_bytes,draco_position_"
      "bits,ratio,"
      "max_error_fraction,round_trip_error_fraction,draco_max_error_fraction,glb_bytes,json_bytes,"
      "seconds_prune,seconds_encode,seconds_decode,"
      "seconds_decompose,seconds_hull_encode,seconds_write,seconds_total\n";
  std::vector<double> ratios;
  int failures = 0;
  for (const std::string& file : files) {
    hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(folder + "/" + file);
    if (!scene.ok()) {
      std::fprintf(stderr, "pack_bench: %s\n", scene.status().message().c_str());
      ++failures;
      continue;
    }
    hullpack::Result<hullpack::PackResult> packed =
        hullpack::Status(hullpack::StatusCode::kInternal, "");
    const double ms =
        hullpack::MedianMs(1, [&] { packed = hullpack::PackScene(scene.value(), options); });
    if (!packed.ok()) {
      std::fprintf(stderr, "pack_bench: %s: %s\n", file.c_str(), packed.status().message().c_str());
      ++failures;
      continue;
    }
    // Draco gets the same meshes the packer encoded (after repairs and leaving out what is unused).
    hullpack::Scene pruned = scene.value();
    if (!hullpack::CheckAndRepair(pruned, options.repair).ok()) continue;  // PackScene succeeded
    hullpack::LeaveOutUnused(pruned, options.prune);
    // unpack(pack(x)) against x: the GLB read back as any user reads it; same triangle and vertex
    // counts (connectivity kept; vertices whose normals the codec stores alike welded, as the
    // encoder welds them), skin attributes present, worst position error.
    hullpack::GltfDocument inflated;
    hullpack::Result<hullpack::Scene> unpacked =
        hullpack::ReadPackedGltf(packed->glb.data(), packed->glb.size(), file, "", &inflated);
    double round_trip = 0;
    bool kept = unpacked.ok() && unpacked->meshes.size() >= pruned.meshes.size();
    for (size_t m = 0; kept && m < pruned.meshes.size(); ++m) {
      const hullpack::Mesh& a = pruned.meshes[m];
      const hullpack::Mesh& b = unpacked->meshes[m];
      const std::optional<hullpack::Mesh> welded =
          options.keep_order ? std::nullopt
                             : hullpack::WeldNormalsStoredAlike(a, options.normal_bits);
      const hullpack::Mesh& expect = welded ? *welded : a;
      kept = expect.triangle_count() == b.triangle_count() &&
             expect.vertex_count() == b.vertex_count() && expect.joints.size() == b.joints.size() &&
             expect.weights.size() == b.weights.size();
      const double diagonal = hullpack::BoundingBoxDiagonal(a);
      if (diagonal > 0)
        round_trip = std::max(round_trip, hullpack::MaxVertexDistance(a, b) / diagonal);
    }
    if (!kept) {
      std::fprintf(stderr, "pack_bench: %s: the unpacked file lost data: %s\n", file.c_str(),
                   unpacked.ok() ? "mesh, triangle, vertex or skin counts differ"
                                 : unpacked.status().message().c_str());
      ++failures;
    }
    size_t mesh_bytes = 0, hull_bytes = 0, hulls = 0, draco_bytes = 0, triangles = 0;
    double worst = 0, draco_worst = 0, s_encode = 0, s_decode = 0, s_decompose = 0, s_hulls = 0;
    int draco_bits_max = 0;
    for (size_t m = 0; m < pruned.meshes.size(); ++m) {
      const hullpack::MeshPackReport& r = packed->report.meshes[m];
      const hullpack::Mesh& mesh = pruned.meshes[m];
      mesh_bytes += r.bytes_after;
      hull_bytes += r.hull_bytes;
      hulls += r.hull_count;
      triangles += r.triangles;
      worst = std::max(worst, r.max_error_fraction);
      s_encode += r.seconds_encode;
      s_decode += r.seconds_decode;
      s_decompose += r.seconds_decompose;
      s_hulls += r.seconds_hull_encode;
      std::unique_ptr<draco::Mesh> d = hullpack::ToDracoMesh(mesh);
      if (!d) continue;
      // Draco at equal error: from one bit below the uniform grid's guarantee up, the first
      // position bits whose decoded positions stay within the budget (or --qp when given).
      const double diagonal = hullpack::BoundingBoxDiagonal(mesh);
      const double budget = options.max_error * diagonal;
      int bits = options.position_bits > 0
                     ? options.position_bits
                     : std::max(1, hullpack::PositionBitsForMaxError(hullpack::PositionRange(mesh),
                                                                     budget) -
                                       1);
      std::vector<uint8_t> bytes;
      double error = 0;
      for (; bits <= 30; ++bits) {
        bytes = hullpack::DracoEncode(*d, bits, options.normal_bits, options.uv_bits, 7);
        error = hullpack::MaxVertexDistance(mesh, hullpack::DracoDecodePositions(bytes));
        if (options.position_bits > 0 || error <= budget) break;
      }
      draco_bytes += bytes.size();
      draco_worst = std::max(draco_worst, diagonal > 0 ? error / diagonal : 0);
      draco_bits_max = std::max(draco_bits_max, bits);
    }
    const size_t packed_bytes = mesh_bytes + hull_bytes;
    const double ratio = draco_bytes ? double(packed_bytes) / draco_bytes : 0;
    if (round_trip > options.max_error && options.position_bits <= 0) {
      std::fprintf(stderr, "pack_bench: %s: round-trip error %g over the budget\n", file.c_str(),
                   round_trip);
      ++failures;
    }
    ratios.push_back(ratio);
    const size_t json_bytes = JsonChunkBytes(packed->glb);
    const hullpack::PackReport& pr = packed->report;
    std::printf(
        "%-22s %7zu %5zu | %8zu %7zu %8zu | %8zu %2d | %6.3f | %9.6f %9.6f | %6zu %6zu | %6.2f "
        "%6.2f %6.2f %6.2f\n",
        file.c_str(), triangles, hulls, mesh_bytes, hull_bytes, packed_bytes, draco_bytes,
        draco_bits_max, ratio, round_trip, draco_worst, json_bytes, packed->glb.size(), s_encode,
        s_decode, s_decompose, s_hulls);
    char line[768];
    std::snprintf(line, sizeof(line),
                  "%s,%zu,%zu,%zu,%zu,%zu,%zu,%d,%.4f,%.6g,%.6g,%.6g,%zu,%zu,%.3f,%.3f,%.3f,%.3f,%."
                  "3f,%.3f,%.3f\n",
                  file.c_str(), triangles, hulls, mesh_bytes, hull_bytes, packed_bytes, draco_bytes,
                  draco_bits_max, ratio, worst, round_trip, draco_worst, packed->glb.size(),
                  json_bytes, pr.seconds_prune, s_encode, s_decode, s_decompose, s_hulls,
                  pr.seconds_write, ms / 1000);
    text += line;
  }
  if (!ratios.empty()) {
    std::vector<double> sorted = ratios;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.size() % 2
                              ? sorted[sorted.size() / 2]
                              : 0.5 * (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]);
    std::printf(
        "median packed-with-hulls / Draco-without-hulls: %.3f over %zu files (max-error %g)\n",
        median, ratios.size(), options.max_error);
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
