#include "pipeline/error_budget.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace hullpack {
namespace {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// A measured error this far below the budget makes one bit fewer worth a try (one bit fewer about
// doubles the error).
constexpr double kTryFewerBits = 0.6;

struct Candidate {
  bool ok = false;
  BudgetedEncoding e;
};

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

Result<BudgetedEncoding> EncodeWithinError(const Mesh& mesh, const std::vector<uint32_t>& groups,
                                           const MeshCodecSettings& settings, double max_error) {
  // Every grid keeps a mesh of zero size (empty, or all positions equal) exactly, so such a mesh
  // meets even a zero budget (max_error x its diagonal of 0).
  const bool zero_size = PositionRange(mesh) == 0;
  if (!(max_error > 0 || (max_error == 0 && zero_size)) || !std::isfinite(max_error)) {
    return Status(StatusCode::kInvalidArgument, "error budget must be positive");
  }
  double seconds_encode = 0;
  int tried = 0;
  // Encodes and measures one grid.
  auto attempt = [&](o3dgc::RangeMode mode, int bits) -> Result<Candidate> {
    MeshCodecSettings s = settings;
    s.position_bits = bits;
    s.position_range = mode;
    auto t = Clock::now();
    Result<EncodedMesh> encoded = EncodeMesh(mesh, groups, s);
    seconds_encode += Seconds(t);
    if (!encoded.ok()) return encoded.status();
    ++tried;
    Candidate c;
    t = Clock::now();
    Result<Mesh> decoded =
        DecodeMesh(encoded->stream.data(), encoded->stream.size(), &c.e.groups, mesh.name);
    c.e.seconds_decode = Seconds(t);
    if (!decoded.ok()) {
      return Status(StatusCode::kInternal,
                    "mesh '" + mesh.name + "' does not decode: " + decoded.status().message());
    }
    c.e.max_error = MaxVertexDistance(mesh, decoded.value());
    c.ok = c.e.max_error <= max_error;
    c.e.encoded = std::move(encoded.value());
    c.e.decoded = std::move(decoded.value());
    c.e.position_bits = bits;
    c.e.position_range = mode;
    return c;
  };

  const std::array<double, 3> extent = PositionExtent(mesh);
  const int uniform_bits = GuaranteedPositionBits(o3dgc::RangeMode::kUniform, extent, max_error);
  Candidate best;
  for (o3dgc::RangeMode mode :
       {o3dgc::RangeMode::kPerAxis, o3dgc::RangeMode::kUniform, o3dgc::RangeMode::kDiagonal}) {
    int bits = GuaranteedPositionBits(mode, extent, max_error);
    // With more bits than kUniform needs, the diagonal grid is finer than the uniform one.
    if (mode == o3dgc::RangeMode::kDiagonal && bits > uniform_bits) continue;
    Result<Candidate> c = attempt(mode, bits);
    if (!c.ok()) return c.status();
    // Float rounding of the decoded values can push a guaranteed grid just past the budget.
    while (!c->ok && bits < 30) {
      c = attempt(mode, ++bits);
      if (!c.ok()) return c.status();
    }
    while (c->ok && bits > 1 && c->e.max_error <= kTryFewerBits * max_error) {
      Result<Candidate> fewer = attempt(mode, bits - 1);
      if (!fewer.ok()) return fewer.status();
      if (!fewer->ok) break;
      c = std::move(fewer);
      --bits;
    }
    if (c->ok && (!best.ok || c->e.encoded.stream.size() < best.e.encoded.stream.size()))
      best = std::move(c.value());
  }
  if (!best.ok) {
    return Status(StatusCode::kInternal,
                  "mesh '" + mesh.name + "': no position grid keeps the error within the budget");
  }
  best.e.streams_tried = tried;
  best.e.seconds_encode = seconds_encode;
  return std::move(best.e);
}

}  // namespace hullpack
