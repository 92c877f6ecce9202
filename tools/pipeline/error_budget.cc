#include "pipeline/error_budget.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>

#include "common/parallel.h"
#include "mesh/split.h"

namespace hullpack {
namespace {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

}  // namespace

const char* RangeModeName(o3dgc::RangeMode mode) {
  switch (mode) {
    case o3dgc::RangeMode::kUniform:
      return "uniform";
    case o3dgc::RangeMode::kPerAxis:
      return "per-axis";
    case o3dgc::RangeMode::kDiagonal:
      return "diagonal";
  }
  return "?";
}

int GuaranteedPositionBits(o3dgc::RangeMode mode, const std::array<double, 3>& extent,
                           double max_error) {
  const double largest = std::max({extent[0], extent[1], extent[2]});
  const double diagonal =
      std::sqrt(extent[0] * extent[0] + extent[1] * extent[1] + extent[2] * extent[2]);
  double reach = 0;  // the bound is reach / (2^b - 1)
  switch (mode) {
    case o3dgc::RangeMode::kUniform:
      reach = std::sqrt(3.0) / 2 * largest;
      break;
    case o3dgc::RangeMode::kPerAxis:
      reach = diagonal / 2;
      break;
    case o3dgc::RangeMode::kDiagonal:
      reach = std::sqrt(3.0) / 2 * diagonal;
      break;
  }
  if (!(reach > 0) || !(max_error > 0) || !std::isfinite(reach) || !std::isfinite(max_error))
    return 1;
  const int bits = static_cast<int>(std::ceil(std::log2(reach / max_error + 1.0)));
  return std::clamp(bits, 1, 30);
}

double PositionGridError(const Mesh& mesh, o3dgc::RangeMode mode, int bits) {
  return o3dgc::PositionQuantizationError(mesh.positions.data(), 3 * sizeof(float),
                                          mesh.vertex_count(), bits, mode);
}

// o3dgc::GridEncoder's progress: Prepare (the shared stages) reports up to kPrepared, each grid's
// Encode from kGridStart on.
constexpr float kPrepared = 0.4f;
constexpr float kGridStart = 0.6f;

namespace {

// The candidate with the fewest bytes; on a tie the first, whatever the thread count.
template <typename Candidate>
size_t Smallest(const std::vector<Candidate>& candidates) {
  size_t best = 0;
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].bytes < candidates[best].bytes) best = i;
  }
  return best;
}

// EncodeWithinError at the UV range of `settings`.
Result<BudgetedEncoding> EncodeOnGrids(const Mesh& mesh, const std::vector<uint32_t>& groups,
                                       const MeshCodecSettings& settings, double max_error,
                                       const ThreadBudget& threads, size_t max_part_triangles) {
  // Every grid keeps a mesh of zero size (empty, or all positions equal) exactly, so such a mesh
  // meets even a zero budget (max_error x its diagonal of 0).
  const bool zero_size = PositionRange(mesh) == 0;
  if (!(max_error > 0 || (max_error == 0 && zero_size)) || !std::isfinite(max_error)) {
    return Status(StatusCode::kInvalidArgument, "error budget must be positive");
  }
  struct Candidate {
    o3dgc::RangeMode mode;
    int bits;
    double error;
    std::vector<EncodedMesh> parts;  // one stream per part
    size_t bytes = 0;
  };
  std::vector<Candidate> candidates;
  const std::array<double, 3> extent = PositionExtent(mesh);
  const int uniform_bits = GuaranteedPositionBits(o3dgc::RangeMode::kUniform, extent, max_error);
  for (o3dgc::RangeMode mode :
       {o3dgc::RangeMode::kPerAxis, o3dgc::RangeMode::kUniform, o3dgc::RangeMode::kDiagonal}) {
    int bits = GuaranteedPositionBits(mode, extent, max_error);
    // With more bits than kUniform needs, the diagonal grid is finer than the uniform one.
    if (mode == o3dgc::RangeMode::kDiagonal && bits > uniform_bits) continue;
    double error = PositionGridError(mesh, mode, bits);
    if (error < 0) {
      return Status(StatusCode::kInvalidMesh,
                    "mesh '" + mesh.name + "': positions the encoder cannot quantize");
    }
    // Float rounding of the decoded values can push a guaranteed grid just past the budget.
    while (error > max_error && bits < 30) error = PositionGridError(mesh, mode, ++bits);
    if (error > max_error) continue;
    // A budget well above the guarantee's bound (points off the grid's worst case) may allow
    // fewer bits.
    while (bits > 1) {
      const double fewer = PositionGridError(mesh, mode, bits - 1);
      if (!(fewer <= max_error)) break;
      error = fewer;
      --bits;
    }
    candidates.push_back({mode, bits, error, {}, 0});
  }
  if (candidates.empty()) {
    return Status(StatusCode::kInternal,
                  "mesh '" + mesh.name + "': no position grid keeps the error within the budget");
  }
  const int tried = static_cast<int>(candidates.size());
  auto t = Clock::now();
  // A large mesh is coded in parts, one after the other, each on the whole mesh's grid (so that
  // the vertices two parts share decode alike): the encoder's memory is then a part's.
  std::mutex progress_mutex;
  float prepared = 0;
  std::vector<float> done(candidates.size(), 0.0f);
  const Status parts_status =
      ForEachPart(mesh, groups, max_part_triangles, [&](const PartToCode& part) {
        // The fraction of the whole: the parts before this one, then this part's Prepare share and
        // its candidates' (each from kGridStart to 1).
        prepared = 0;
        std::fill(done.begin(), done.end(), 0.0f);
        auto report = [&]() {
          float sum = 0;
          for (float d : done) sum += d;
          const float part_done =
              prepared * kPrepared + (1 - kPrepared) * sum / static_cast<float>(done.size());
          return settings.progress((static_cast<float>(part.index) + part_done) /
                                   static_cast<float>(part.count));
        };
        MeshCodecSettings part_settings = settings;
        part_settings.position_box = part.box;
        // The stages every grid shares run once; then the candidates, in parallel.
        // The view of `in` points into these: they live as long as it.
        CodecInput in;
        Status status = MakeCodecInput(part.mesh, part.groups, part_settings, &in);
        if (!status.ok()) return status;
        in.params.progress = [&](float f) {
          if (!settings.progress) return true;
          std::lock_guard<std::mutex> lock(progress_mutex);
          prepared = std::min(f / kPrepared, 1.0f);
          return report();
        };
        // Freed before the next part.
        std::unique_ptr<o3dgc::GridEncoder> shared(new o3dgc::GridEncoder);
        const o3dgc::GridEncoder& grids = *shared;
        status = EncoderStatus(shared->Prepare(in.view, in.params), mesh.name);
        if (!status.ok()) return status;
        std::vector<Status> statuses(candidates.size());
        for (Candidate& c : candidates) c.parts.emplace_back();
        ParallelFor(candidates.size(), threads, [&](size_t i) {
          const o3dgc::ProgressFn progress = [&, i](float f) {
            if (!settings.progress) return true;
            std::lock_guard<std::mutex> lock(progress_mutex);
            done[i] = std::max(0.0f, (f - kGridStart) / (1 - kGridStart));
            return report();
          };
          EncodedMesh& encoded = candidates[i].parts.back();
          encoded.gltf_attributes = in.attributes.gltf_attributes;
          encoded.gltf_targets = in.attributes.gltf_targets;
          statuses[i] = EncoderStatus(grids.Encode(candidates[i].bits, candidates[i].mode,
                                                   &encoded.stream, &encoded.info, progress),
                                      mesh.name);
        });
        for (size_t i = 0; i < candidates.size(); ++i) {
          if (!statuses[i].ok()) return statuses[i];
          candidates[i].bytes += candidates[i].parts.back().stream.size();
        }
        // The other parts only on the grid that coded the first smallest: a part of a mesh large
        // enough to be split is a large sample of it, and coding every candidate in every part
        // was most of the run's time.
        if (part.index == 0 && part.count > 1) {
          candidates.erase(candidates.begin(), candidates.begin() + Smallest(candidates));
          candidates.resize(1);
          done.resize(1);
        }
        return Status::Ok();
      });
  if (!parts_status.ok()) return parts_status;
  BudgetedEncoding out;
  out.seconds_encode = Seconds(t);
  Candidate& chosen = candidates[Smallest(candidates)];
  out.streams = std::move(chosen.parts);
  out.position_bits = chosen.bits;
  out.position_range = chosen.mode;
  out.max_error = chosen.error;
  out.streams_tried = tried;
  return out;
}

}  // namespace

size_t StreamBytes(const BudgetedEncoding& e) {
  size_t bytes = 0;
  for (const EncodedMesh& s : e.streams) bytes += s.stream.size();
  return bytes;
}

Result<BudgetedEncoding> EncodeWithinError(const Mesh& mesh, const std::vector<uint32_t>& groups,
                                           const MeshCodecSettings& settings, double max_error,
                                           const ThreadBudget& threads, size_t max_part_triangles) {
  Result<BudgetedEncoding> out =
      EncodeOnGrids(mesh, groups, settings, max_error, threads, max_part_triangles);
  if (!out.ok() || settings.uv_range != o3dgc::RangeMode::kUniform || !UvExtentsDiffer(mesh)) {
    return out;
  }
  // As EncodeMesh: per-axis UV cells are no larger, and sometimes code smaller.
  MeshCodecSettings per_axis = settings;
  per_axis.uv_range = o3dgc::RangeMode::kPerAxis;
  Result<BudgetedEncoding> other =
      EncodeOnGrids(mesh, groups, per_axis, max_error, threads, max_part_triangles);
  if (!other.ok()) return other.status();
  BudgetedEncoding& a = out.value();
  BudgetedEncoding& b = other.value();
  const int tried = a.streams_tried + b.streams_tried;
  const double seconds_encode = a.seconds_encode + b.seconds_encode;
  BudgetedEncoding& best = StreamBytes(b) < StreamBytes(a) ? b : a;
  best.streams_tried = tried;
  best.seconds_encode = seconds_encode;
  return std::move(best);
}

}  // namespace hullpack
