#include "pipeline/pack.h"

#include <algorithm>
#include <chrono>
#include <functional>

#include "common/parallel.h"
#include "pipeline/assemble.h"
#include "pipeline/check_and_repair.h"
#include "pipeline/load.h"
#include "pipeline/pack_mesh.h"
#include "pipeline/prune.h"

namespace hullpack {
namespace {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// Shares of the progress line PackScene's stages take.
constexpr double kMeshesFrom = 0.02, kMeshesTo = 0.98;

Result<PackResult> PackLoaded(Scene scene, const PackOptions& options, PackObserver* observer) {
  if (!(options.max_error > 0) && options.position_bits <= 0) {
    return Status(StatusCode::kInvalidArgument, "--max-error must be positive (or give --qp)");
  }
  if (!(options.hull_error > 0))
    return Status(StatusCode::kInvalidArgument, "--hull-error must be positive");
  const auto start = Clock::now();
  PackResult result;
  PackReport& report = result.report;
  report.not_kept = scene.dropped;

  auto t = Clock::now();
  if (observer) observer->OnProgress(0, "checks and repairs");
  Result<CheckRepairReport> repaired =
      CheckAndRepair(scene, options.repair, ThreadCount(options.threads));
  if (!repaired.ok()) return repaired.status();
  report.seconds_repair = Seconds(t);
  if (!scene.meshes.empty() && scene.triangle_count() == 0) {
    // A scene of nothing but collapsed meshes; one among others is left out by the next stage.
    const std::string more =
        scene.meshes.size() > 1
            ? " (and in the " + std::to_string(scene.meshes.size() - 1) + " other meshes)"
            : "";
    return Status(StatusCode::kInvalidMesh, "mesh '" + scene.meshes[0].name +
                                                "': no triangle with an area (none, or all "
                                                "degenerate at float precision)" +
                                                more + ": nothing to pack");
  }

  t = Clock::now();
  if (observer) observer->OnProgress(0.01, "leave out the unused");
  const PruneReport pruned = LeaveOutUnused(scene, options.prune);
  RepairReport repairs = repaired->repairs;
  AddRepairs(repairs, pruned.repairs);
  report.left_out = pruned.lines;
  if (repairs.changed()) report.left_out.push_back(DescribeRepairs(repairs));
  for (const std::string& line : repaired->lines) report.left_out.push_back(line);
  report.seconds_prune = Seconds(t);

  t = Clock::now();
  Result<std::vector<PackedMesh>> packed =
      PackMeshes(scene, options, observer, kMeshesFrom, kMeshesTo);
  if (!packed.ok()) return packed.status();
  for (const PackedMesh& m : packed.value()) report.meshes.push_back(m.report);
  report.seconds_meshes = Seconds(t);

  t = Clock::now();
  if (observer) observer->OnProgress(kMeshesTo, "write");
  scene.meshes.clear();
  Status decoded = DecodeRenderMeshes(packed.value(), ThreadCount(options.threads));
  if (!decoded.ok()) return decoded;
  for (size_t i = 0; i < packed->size(); ++i)
    report.meshes[i].seconds_decode = packed.value()[i].report.seconds_decode;
  PackedGlbStats stats;
  Result<std::vector<uint8_t>> glb =
      AssemblePackedGlb(std::move(scene), std::move(packed.value()), options.glb, &stats);
  if (!glb.ok()) return glb.status();
  report.key_frame_bytes_before = stats.key_frame_bytes;
  report.key_frame_bytes_after = stats.key_frame_stored_bytes;
  result.glb = std::move(glb.value());
  report.output_bytes = result.glb.size();
  report.seconds_assemble = Seconds(t);
  report.seconds_total = Seconds(start);
  return result;
}

}  // namespace

Result<PackResult> PackScene(Scene scene, const PackOptions& options, PackObserver* observer) {
  Result<PackResult> result = PackLoaded(std::move(scene), options, observer);
  if (result.ok() && observer) observer->OnProgress(1.0, "done");
  return result;
}

Result<PackResult> PackInput(const std::string& input, const PackOptions& options,
                             PackObserver* observer) {
  const auto start = Clock::now();
  // The whole line is the pipeline after loading; loading shows its own percentage.
  if (observer) observer->OnProgress(0, "load");
  std::function<void(double)> load_progress;
  if (observer) {
    load_progress = [observer](double f) {
      observer->OnProgress(0, "load " + std::to_string(static_cast<int>(f * 100)) + "%");
    };
  }
  Result<LoadedScene> loaded = LoadScene(input, load_progress, options.threads);
  if (!loaded.ok()) return loaded.status();
  const double seconds_load = Seconds(start);
  Result<PackResult> packed = PackLoaded(std::move(loaded->scene), options, observer);
  if (!packed.ok()) return Status(packed.status().code(), input + ": " + packed.status().message());
  PackReport& report = packed->report;
  report.images_embedded = loaded->images_embedded;
  report.images_kept_outside = std::move(loaded->images_kept_outside);
  report.image_uris = std::move(loaded->image_uris);
  report.seconds_load = seconds_load;
  report.seconds_total = Seconds(start);
  if (observer) observer->OnProgress(1.0, "done");
  return packed;
}

}  // namespace hullpack
