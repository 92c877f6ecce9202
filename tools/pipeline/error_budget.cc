#include "pipeline/error_budget.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

#include "common/parallel.h"

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

// o3dgc::Encode's progress once the connectivity is coded.
constexpr float kConnectivityCoded = 0.4f;

Result<BudgetedEncoding> EncodeWithinError(const Mesh& mesh, const std::vector<uint32_t>& groups,
                                           const MeshCodecSettings& settings, double max_error,
                                           int threads) {
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
    Result<EncodedMesh> encoded = Status(StatusCode::kInternal, "not encoded");
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
    candidates.push_back({mode, bits, error});
  }
  if (candidates.empty()) {
    return Status(StatusCode::kInternal,
                  "mesh '" + mesh.name + "': no position grid keeps the error within the budget");
  }
  auto t = Clock::now();
  std::mutex progress_mutex;
  std::vector<float> done(candidates.size(), 0.0f);
  // An encode holds its largest arrays while it codes the connectivity (the first 40 % of its
  // progress): parallel candidates take turns there and overlap only after it.
  std::mutex connectivity_turn;
  ParallelFor(candidates.size(), threads, [&](size_t i) {
    MeshCodecSettings s = settings;
    s.position_bits = candidates[i].bits;
    s.position_range = candidates[i].mode;
    std::unique_lock<std::mutex> turn(connectivity_turn, std::defer_lock);
    if (threads > 1) turn.lock();
    s.progress = [&, i](float f) {
      if (f >= kConnectivityCoded && turn.owns_lock()) turn.unlock();
      if (!settings.progress) return true;
      std::lock_guard<std::mutex> lock(progress_mutex);
      done[i] = f;
      float sum = 0;
      for (float d : done) sum += d;
      return settings.progress(sum / static_cast<float>(done.size()));
    };
    candidates[i].encoded = EncodeMesh(mesh, groups, s);
  });
  BudgetedEncoding out;
  out.seconds_encode = Seconds(t);
  // The smallest stream; on a tie the first candidate, whatever the thread count.
  size_t best = 0;
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (!candidates[i].encoded.ok()) return candidates[i].encoded.status();
    if (candidates[i].encoded->stream.size() < candidates[best].encoded->stream.size()) best = i;
  }
  Candidate& chosen = candidates[best];
  t = Clock::now();
  Result<Mesh> decoded = DecodeMesh(chosen.encoded->stream.data(), chosen.encoded->stream.size(),
                                    &out.groups, mesh.name);
  if (!decoded.ok()) {
    return Status(StatusCode::kInternal,
                  "mesh '" + mesh.name + "' does not decode: " + decoded.status().message());
  }
  out.seconds_decode = Seconds(t);
  out.encoded = std::move(chosen.encoded.value());
  out.decoded = std::move(decoded.value());
  out.position_bits = chosen.bits;
  out.position_range = chosen.mode;
  out.max_error = chosen.error;
  out.streams_tried = static_cast<int>(candidates.size());
  return out;
}

}  // namespace hullpack
