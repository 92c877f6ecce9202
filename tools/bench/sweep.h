// The error-against-run-time sweep: over every mesh of a folder, decompose at a grid of
// (resolution, concavity, max hulls) and encode at a grid of (position, normal, UV bits), and
// record for each point the error, the time, the peak memory and the size.
//
// Each grid is swept one parameter at a time around a base point (the other parameters at their
// base value): the decomposition at the V-HACD 2.0 defaults, the codec at 14/10/12 bits (what
// `hullpack pack` uses by default). Every measured step runs in a forked child (see
// child_process.h): its peak memory is the child's ru_maxrss, a crash or a hang costs one point.
//
// Decomposition error: hull_metrics.h (sampled one-sided Hausdorff distances both ways, IoU of
// closed meshes and interior coverage on a lattice), measured on the input triangles and the hulls,
// independently of vhacd's own report, as vhacd_bench measures. It is computed in this process
// after the mesh's timed children have run, so its memory is not in their peak.
// Decomposition size: the hulls as `hullpack pack` stores them (one o3dgc stream, one triangle
// group per hull, positions quantized to `hull_error` of the mesh's diagonal). Codec error:
// codec_error.h, on a keep-order stream at the same bits, after checking that the size-optimised
// (reordered) stream decodes to exactly the same vertex values.
#ifndef HULLPACK_TOOLS_BENCH_SWEEP_H_
#define HULLPACK_TOOLS_BENCH_SWEEP_H_

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/hull_metrics.h"
#include "common/status.h"
#include "vhacd/vhacd.h"

namespace hullpack {

struct SweepGrid {
  std::vector<uint32_t> resolutions;
  std::vector<double> concavities;
  std::vector<uint32_t> max_hulls;  // 0 = no budget
  std::vector<int> position_bits, normal_bits, uv_bits;
};

struct SweepOptions {
  bool decompose = true;
  bool codec = true;
  SweepGrid grid;
  vhacd::Parameters base;  // the decomposition's base point (resolution, concavity, max hulls, ...)
  int base_position_bits = 14, base_normal_bits = 10, base_uv_bits = 12;
  int repeats = 3;                // codec: encode and decode times are medians of this many runs
  int decompose_repeats = 1;      // decomposition: median of this many runs
  double hull_error = 0.002;      // hull quantization for the hull bytes, fraction of the diagonal
  bench::MetricsOptions metrics;  // decomposition error measure (samples, lattice, gap, threads)
  double timeout_seconds = 900;   // per measured step
  // File extensions read (lower case, no dot), in order of preference: when two files of the
  // folder share a stem (bunny.obj, bunny.glb), only the first in this order is measured.
  std::vector<std::string> extensions = {"obj", "off",  "wrl", "ply", "stl",
                                         "glb", "gltf", "fbx", "dae"};
  std::vector<std::string> only;  // mesh names (file stems) to measure; empty = all
  FILE* log = stderr;             // one progress line per point; null = quiet
};

// The default grid (about 10-20 minutes over the 15-mesh corpus on 2 shared cores): resolution
// 20k..1M (6 values), concavity 0.01..0.0005 (5), max hulls 4..32 and unlimited, position
// bits 8..20, normal bits 6..12, UV bits 8..14 (every bit), one decomposition and 3 codec runs per
// point; 20000 surface samples per Hausdorff direction.
SweepOptions DefaultSweepOptions();
// A few minutes: 3 resolutions, 3 concavities, 2 hull budgets, every other bit, 1 run per point,
// 10000 samples.
SweepOptions QuickSweepOptions();

// -1 marks "not applicable / not measured" in every numeric field.
struct SweepRow {
  std::string mesh;
  std::string stage;  // "decompose" or "codec"
  std::string
      sweep;  // the sweeps this point lies on, '+'-separated: "resolution+concavity+max_hulls"
  std::string status;  // "ok" or why the point failed
  size_t triangles = 0, vertices = 0;
  bool closed = false;
  // Parameters of the point.
  double resolution = -1, concavity = -1, max_hulls = -1;
  double position_bits = -1, normal_bits = -1, uv_bits = -1;
  // Decomposition results.
  double hull_count = -1, hull_vertices = -1;
  double hausdorff_mesh_to_hulls = -1, hausdorff_hulls_to_mesh = -1, iou = -1;
  double coverage = -1;                // |solid ∩ hulls| / |solid| (every mesh)
  double hulls_to_mesh_in_solid = -1;  // 1: the hulls -> mesh maximum is a crack inside the solid
  double invalid_hulls = -1;           // hulls that are not closed, outward and convex
  // Codec results.
  double position_max_error = -1, position_rms_error = -1;
  double normal_max_deg = -1, normal_mean_deg = -1, uv_max_error = -1;
  double same_values = -1;  // 1: the reordered stream decodes to the keep-order stream's values
  // Size: the hull stream (decompose) or the mesh stream (codec).
  double bytes = -1, bits_per_vertex = -1;
  // Time and memory of the decomposition, or of the encoder; decode_* for the decoder.
  double time_ms = -1, cpu_ms = -1, peak_mb = -1, base_mb = -1;
  double decode_ms = -1, decode_cpu_ms = -1, decode_peak_mb = -1;
};

struct SweepMesh {
  std::string name, file;
  size_t triangles = 0, vertices = 0;
  bool closed = false, normals = false, uvs = false;
};

struct SweepResult {
  std::vector<SweepMesh> meshes;
  std::vector<SweepRow> rows;        // one per mesh x point, in measurement order
  std::vector<std::string> skipped;  // files not measured, with the reason
  double seconds = 0;                // wall time of the whole sweep
};

// Runs the sweep over the folder's meshes. Fails only when the folder cannot be listed or the
// options are invalid; a mesh that cannot be read or measured is listed in `skipped` or gets rows
// whose status says what failed.
Result<SweepResult> RunSweep(const std::string& folder, const SweepOptions& options);

// The sweep memberships of a decomposition / codec point under `options` ("" when on none).
std::string DecomposeSweeps(const SweepOptions& options, uint32_t resolution, double concavity,
                            uint32_t max_hulls);
std::string CodecSweeps(const SweepOptions& options, int position_bits, int normal_bits,
                        int uv_bits);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_SWEEP_H_
