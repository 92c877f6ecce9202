#include "pipeline/pack_mesh.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <mutex>

#include "common/parallel.h"
#include "mesh/split.h"
#include "pipeline/collision.h"
#include "pipeline/error_budget.h"
#include "pipeline/hull_quantize.h"

namespace hullpack {
namespace {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// Bytes of the plain accessors the GLB writer would write for `m`.
size_t PlainGeometryBytes(const Mesh& m) {
  size_t per_vertex = 12;
  if (!m.normals.empty()) per_vertex += 12;
  if (!m.tangents.empty()) per_vertex += 16;
  per_vertex += 8 * m.uv_sets.size();
  if (!m.colors.empty()) per_vertex += 16;
  if (!m.weights.empty()) per_vertex += 16;
  if (!m.joints.empty()) per_vertex += 8;
  for (const MorphTarget& t : m.morph_targets) per_vertex += 12 + (t.normals.empty() ? 0 : 12);
  const size_t index_size = m.vertex_count() < 65536 ? 2 : 4;
  return m.vertex_count() * per_vertex + m.indices.size() * index_size;
}

// A candidate grid's working arrays per triangle of a mesh with positions only (its quantized
// positions, prediction records and coding order: about 20 bytes on igea x1, bounded here with a
// margin); each attribute coded adds a few more. The stages all grids share run once, before.
constexpr double kEncoderBytesPerTriangle = 40;
constexpr double kEncoderBytesPerAttribute = 40;

// Memory the system can still give (MemAvailable), or the largest size_t when unknown.
double AvailableMemory() {
  if (FILE* f = std::fopen("/proc/meminfo", "r")) {
    char line[256];
    unsigned long long kb = 0;
    bool found = false;
    while (!found && std::fgets(line, sizeof(line), f))
      found = std::sscanf(line, "MemAvailable: %llu kB", &kb) == 1;
    std::fclose(f);
    if (found) return 1024.0 * static_cast<double>(kb);
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return static_cast<double>(pages) * static_cast<double>(page);
  return static_cast<double>(std::numeric_limits<size_t>::max());
}

// Candidate grids encoded at once for `mesh`: up to `threads`, as many as half the available
// memory holds encoders for (at least one). Only the run's speed and peak depend on it.
int CandidateThreads(const Mesh& mesh, int threads) {
  const size_t attributes =
      (mesh.normals.empty() ? 0 : 1) + mesh.uv_sets.size() + (mesh.colors.empty() ? 0 : 1) +
      (mesh.weights.empty() ? 0 : 2) + (mesh.tangents.empty() ? 0 : 1) +
      mesh.morph_targets.size() *
          (mesh.morph_targets.empty() || mesh.morph_targets[0].normals.empty() ? 1 : 2);
  const double per_encoder =
      static_cast<double>(mesh.triangle_count()) *
      (kEncoderBytesPerTriangle + kEncoderBytesPerAttribute * static_cast<double>(attributes));
  if (threads <= 1 || per_encoder <= 0) return std::max(1, threads);
  const double fits = std::floor(0.5 * AvailableMemory() / per_encoder);
  return static_cast<int>(std::clamp(fits, 1.0, static_cast<double>(threads)));
}

MeshCodecSettings SettingsFor(const PackOptions& options) {
  MeshCodecSettings s;
  s.stream_type = options.stream_type;
  s.keep_order = options.keep_order;
  s.fast_decode = options.fast_decode;
  s.max_compression = options.max_compression;
  s.normal_bits = options.normal_bits;
  s.uv_bits = options.uv_bits;
  return s;
}

// The progress of every task at once, forwarded to the observer one call at a time.
class ProgressBoard {
 public:
  ProgressBoard(PackObserver* observer, std::vector<double> weights, double from, double to)
      : observer_(observer),
        weights_(std::move(weights)),
        done_(weights_.size(), 0),
        from_(from),
        to_(to) {
    for (double w : weights_) total_ += w;
  }
  void Set(size_t task, double fraction, const std::string& stage) {
    if (!observer_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    done_[task] = std::clamp(fraction, 0.0, 1.0);
    double sum = 0;
    for (size_t i = 0; i < done_.size(); ++i) sum += weights_[i] * done_[i];
    observer_->OnProgress(from_ + (to_ - from_) * (total_ > 0 ? sum / total_ : 1.0), stage);
  }
  bool Cancelled() {
    if (!observer_) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    return observer_->IsCancelled();
  }

 private:
  PackObserver* observer_;
  std::vector<double> weights_, done_;
  double from_, to_, total_ = 0;
  std::mutex mutex_;
};

// Forwards vhacd's progress to one task of the board.
class DecomposeProgress : public vhacd::Observer {
 public:
  DecomposeProgress(ProgressBoard& board, size_t task, std::string prefix)
      : board_(board), task_(task), prefix_(std::move(prefix)) {}
  void OnProgress(double overall, double, double, const char* stage, const char*) override {
    const int percent = static_cast<int>(overall);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    board_.Set(task_, overall / 100.0,
               prefix_ + "decompose " + std::to_string(percent) + "% (" + stage + ")");
  }
  bool IsCancelled() override { return board_.Cancelled(); }

 private:
  ProgressBoard& board_;
  size_t task_;
  std::string prefix_;
  int last_percent_ = -1;
};

// The render mesh's streams (not decoded yet: DecodeRenderMeshes): explicit bits (uniform grid, as
// given), or the smallest streams within the error budget; in parts for a large mesh
// (PackOptions::part_triangles).
// `threads` for the candidate grids; `progress` (may be empty) gets the fraction encoded.
Status EncodeRenderMesh(const Mesh& mesh, const PackOptions& options, const ThreadBudget& threads,
                        const o3dgc::ProgressFn& progress, PackedMesh& out) {
  MeshCodecSettings s = SettingsFor(options);
  s.progress = progress;
  Result<BudgetedEncoding> encoded = Status(StatusCode::kInternal, "");
  if (options.position_bits <= 0) {
    s.morph_error = options.max_error * BoundingBoxDiagonal(mesh);
    encoded =
        EncodeWithinError(mesh, mesh.material_ids, s, options.max_error * BoundingBoxDiagonal(mesh),
                          threads, options.part_triangles);
  } else {
    BudgetedEncoding e;
    s.position_bits = options.position_bits;
    const auto t = Clock::now();
    const Status status =
        ForEachPart(mesh, mesh.material_ids, options.part_triangles, [&](const PartToCode& part) {
          MeshCodecSettings part_settings = s;
          part_settings.position_box = part.box;
          Result<EncodedMesh> stream = EncodeMesh(part.mesh, part.groups, part_settings);
          if (!stream.ok()) return stream.status();
          e.streams.push_back(std::move(stream.value()));
          return Status::Ok();
        });
    if (!status.ok()) return status;
    e.seconds_encode = Seconds(t);
    e.position_bits = s.position_bits;
    e.position_range = s.position_range;
    e.max_error = PositionGridError(mesh, s.position_range, s.position_bits);
    e.streams_tried = 1;
    encoded = std::move(e);
  }
  if (!encoded.ok()) return encoded.status();
  MeshPackReport& r = out.report;
  r.position_bits = encoded->position_bits;
  r.position_range = RangeModeName(encoded->position_range);
  r.seconds_encode = encoded->seconds_encode;
  r.max_error = encoded->max_error;
  const double diagonal = BoundingBoxDiagonal(mesh);
  r.max_error_fraction = diagonal > 0 ? r.max_error / diagonal : 0;
  r.bytes_after = StreamBytes(encoded.value());
  r.parts = encoded->streams.size();
  r.bits_per_vertex = r.vertices ? 8.0 * r.bytes_after / r.vertices : 0;
  out.grouped = !mesh.material_ids.empty();
  out.collides = mesh.collides;
  out.morph_weights = mesh.morph_weights;
  for (const MorphTarget& target : mesh.morph_targets) out.target_names.push_back(target.name);
  out.streams = std::move(encoded->streams);
  return Status::Ok();
}

// The decomposition, all hulls on one grid within the hull budget, as plain quantized accessors.
Status MakeHulls(const Mesh& mesh, const PackOptions& options, vhacd::Observer* progress,
                 PackedMesh& out) {
  MeshPackReport& r = out.report;
  const auto t0 = Clock::now();
  Result<HullSet> set = DecomposeMesh(mesh, options.collision, progress);
  if (!set.ok()) return set.status();
  r.seconds_decompose = Seconds(t0);
  r.hull_count = set->hulls.size();
  r.hull_concavity = set->report.concavity;
  r.hull_iou = set->report.volume_iou;
  r.hull_target_reached = set->report.target_reached;
  r.hull_target_note = set->report.target_note;
  if (set->hulls.empty()) return Status::Ok();
  for (const Mesh& hull : set->hulls) r.hull_vertices += hull.vertex_count();
  const double diagonal = BoundingBoxDiagonal(mesh);
  const auto t1 = Clock::now();
  Result<QuantizedHulls> quantized = QuantizeHulls(set->hulls, options.hull_error * diagonal);
  if (!quantized.ok())
    return Status(quantized.status().code(),
                  "mesh '" + mesh.name + "': hulls: " + quantized.status().message());
  r.seconds_hull_encode = Seconds(t1);
  r.hull_quantization_error = diagonal > 0 ? quantized->max_error / diagonal : 0;
  r.hull_position_bits = quantized->position_bits;
  r.hull_position_range = "grid";
  out.has_hulls = true;
  for (size_t h = 0; h < set->hulls.size(); ++h) {
    Mesh hull = std::move(quantized->decoded[h]);
    hull.name = mesh.name + "_hull_" + std::to_string(h);
    const HullGrid& grid = quantized->grids[h];
    const bool wide =
        !grid.local.empty() && *std::max_element(grid.local.begin(), grid.local.end()) > 255;
    const bool floats = options.glb.fallback || !options.glb.quantized_hulls;
    r.hull_bytes += hull.vertex_count() * (floats ? 12 : wide ? 8 : 4);
    out.hulls.push_back(std::move(hull));
    out.hull_grids.push_back(std::move(quantized->grids[h]));
  }
  return Status::Ok();
}

}  // namespace

Result<std::vector<PackedMesh>> PackMeshes(const Scene& scene, const PackOptions& options,
                                           PackObserver* observer, double from, double to) {
  const size_t n = scene.meshes.size();
  std::vector<PackedMesh> packed(n);
  struct Task {
    size_t mesh;
    bool hulls;
    double weight;  // for progress and scheduling: triangles
  };
  std::vector<Task> tasks;
  for (size_t i = 0; i < n; ++i) {
    const Mesh& mesh = scene.meshes[i];
    MeshPackReport& r = packed[i].report;
    r.name = mesh.name;
    r.triangles = mesh.triangle_count();
    r.vertices = mesh.vertex_count();
    r.bytes_before = PlainGeometryBytes(mesh);
    r.no_hulls_reason = WhyNoHulls(mesh, options.collision);
    const double weight = 1.0 + static_cast<double>(mesh.triangle_count());
    tasks.push_back({i, false, weight});
    if (r.no_hulls_reason.empty()) tasks.push_back({i, true, weight});
  }
  // Largest first (decompositions before encodes of the same size): the last task to finish is
  // then a small one. Each task writes only its own mesh's fields.
  std::stable_sort(tasks.begin(), tasks.end(), [](const Task& a, const Task& b) {
    return a.weight != b.weight ? a.weight > b.weight : a.hulls > b.hulls;
  });
  std::vector<double> weights;
  for (const Task& t : tasks) weights.push_back(t.weight);
  ProgressBoard board(observer, weights, from, to);
  std::vector<Status> status(tasks.size());
  // A worker with no task left lends its core to an encode still running (its candidates).
  CoreLender lender;
  ParallelForLendingIdle(tasks.size(), ThreadCount(options.threads), &lender, [&](size_t k) {
    const Task& task = tasks[k];
    if (board.Cancelled()) {
      status[k] = Status(StatusCode::kCancelled, "cancelled");
      return;
    }
    const Mesh& mesh = scene.meshes[task.mesh];
    const std::string prefix = "mesh " + std::to_string(task.mesh + 1) + "/" + std::to_string(n) +
                               " '" + mesh.name + "': ";
    if (task.hulls) {
      board.Set(k, 0, prefix + "decompose");
      DecomposeProgress progress(board, k, prefix);
      status[k] = MakeHulls(mesh, options, &progress, packed[task.mesh]);
      board.Set(k, 1, prefix + "hulls encoded");
    } else {
      board.Set(k, 0, prefix + "encode");
      // The candidates in parallel, as many as the memory holds. Beside this mesh's
      // decomposition on one thread fewer, until a core is free: two candidates beside the
      // decomposition would add an encoder's memory to the run's peak (theirs and the
      // decomposition's are then alive at once) and slow the decomposition as much.
      const bool beside = packed[task.mesh].report.no_hulls_reason.empty();
      const int all = CandidateThreads(mesh, ThreadCount(options.threads));
      ThreadBudget threads(
          CandidateThreads(mesh, std::max(1, ThreadCount(options.threads) - (beside ? 1 : 0))));
      threads.extra = all - threads.base;
      threads.lender = &lender;
      const o3dgc::ProgressFn progress = [&board, k, &prefix](float f) {
        board.Set(k, f, prefix + "encode " + std::to_string(static_cast<int>(f * 100)) + "%");
        return !board.Cancelled();
      };
      status[k] = EncodeRenderMesh(mesh, options, threads, progress, packed[task.mesh]);
      board.Set(k, 1, prefix + "encoded");
    }
  });
  // The first error in mesh order, whatever order the tasks ran in.
  const Status* first = nullptr;
  size_t first_mesh = n;
  for (size_t k = 0; k < tasks.size(); ++k) {
    if (!status[k].ok() && tasks[k].mesh < first_mesh) {
      first = &status[k];
      first_mesh = tasks[k].mesh;
    }
  }
  if (first) return *first;
  return packed;
}

Status DecodeRenderMeshes(std::vector<PackedMesh>& packed, int threads) {
  struct Job {
    size_t mesh, part;
  };
  std::vector<Job> jobs;
  for (size_t i = 0; i < packed.size(); ++i) {
    packed[i].decoded.assign(packed[i].streams.size(), Mesh());
    packed[i].report.seconds_decode = 0;
    for (size_t p = 0; p < packed[i].streams.size(); ++p) jobs.push_back({i, p});
  }
  std::vector<Status> status(jobs.size());
  std::vector<double> seconds(jobs.size(), 0);
  ParallelFor(jobs.size(), threads, [&](size_t k) {
    PackedMesh& m = packed[jobs[k].mesh];
    const EncodedMesh& stream = m.streams[jobs[k].part];
    const std::string& name = m.report.name;
    const auto t = Clock::now();
    std::vector<uint32_t> groups;
    Result<Mesh> decoded = DecodeMesh(stream.stream.data(), stream.stream.size(), &groups, name,
                                      nullptr, &stream.gltf_targets);
    seconds[k] = Seconds(t);
    if (!decoded.ok()) {
      status[k] = Status(StatusCode::kInternal,
                         "mesh '" + name + "' does not decode: " + decoded.status().message());
      return;
    }
    Mesh& mesh = m.decoded[jobs[k].part];
    mesh = std::move(decoded.value());
    mesh.name = name;
    mesh.collides = m.collides;
    mesh.morph_weights = m.morph_weights;
    for (size_t i = 0; i < mesh.morph_targets.size() && i < m.target_names.size(); ++i)
      mesh.morph_targets[i].name = m.target_names[i];
    if (m.grouped) mesh.material_ids = std::move(groups);
  });
  for (size_t k = 0; k < jobs.size(); ++k) {
    if (!status[k].ok()) return status[k];
    packed[jobs[k].mesh].report.seconds_decode += seconds[k];
  }
  return Status::Ok();
}

}  // namespace hullpack
