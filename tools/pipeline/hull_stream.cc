#include "pipeline/hull_stream.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>

#include "pipeline/error_budget.h"

namespace hullpack {

Mesh WeldAcrossHulls(const std::vector<Mesh>& hulls, std::vector<uint32_t>* groups) {
  Mesh out;
  groups->clear();
  std::map<std::array<float, 3>, std::vector<uint32_t>> at;  // position -> welded vertices there
  std::vector<uint32_t> last_hull;  // per welded vertex: last hull using it
  for (size_t h = 0; h < hulls.size(); ++h) {
    const Mesh& hull = hulls[h];
    std::vector<uint32_t> index(hull.vertex_count());
    for (size_t v = 0; v < hull.vertex_count(); ++v) {
      const std::array<float, 3> p = {hull.positions[v * 3], hull.positions[v * 3 + 1],
                                      hull.positions[v * 3 + 2]};
      std::vector<uint32_t>& there = at[p];
      uint32_t chosen = UINT32_MAX;
      for (uint32_t w : there) {
        if (last_hull[w] != h) {
          chosen = w;
          break;
        }
      }
      if (chosen == UINT32_MAX) {
        chosen = static_cast<uint32_t>(out.vertex_count());
        out.positions.insert(out.positions.end(), p.begin(), p.end());
        last_hull.push_back(UINT32_MAX);
        there.push_back(chosen);
      }
      last_hull[chosen] = static_cast<uint32_t>(h);
      index[v] = chosen;
    }
    for (uint32_t i : hull.indices) out.indices.push_back(index[i]);
    groups->insert(groups->end(), hull.triangle_count(), static_cast<uint32_t>(h));
  }
  return out;
}

namespace {

// Encodes `all` (hull h = triangle group h) within the budget and extracts the hulls again.
Result<EncodedHulls> EncodeGrouped(const Mesh& all, const std::vector<uint32_t>& groups,
                                   const std::vector<Mesh>& hulls,
                                   const MeshCodecSettings& settings, double max_error) {
  Result<BudgetedEncoding> chosen = EncodeWithinError(all, groups, settings, max_error);
  if (!chosen.ok()) return chosen.status();
  EncodedHulls out;
  out.position_bits = chosen->position_bits;
  out.position_range = chosen->position_range;
  out.stream_vertices = all.vertex_count();
  // Per hull: the error a physics engine sees (EncodeWithinError measured it over all hulls'
  // points).
  for (size_t h = 0; h < hulls.size(); ++h) {
    out.decoded.push_back(ExtractGroup(chosen->decoded, chosen->groups, static_cast<uint32_t>(h)));
    if (out.decoded[h].vertex_count() != hulls[h].vertex_count()) {
      return Status(StatusCode::kInternal,
                    "hull " + std::to_string(h) + " lost vertices in its stream");
    }
    out.max_error = std::max(out.max_error, MaxVertexDistance(hulls[h], out.decoded[h]));
  }
  if (out.max_error > max_error)
    return Status(StatusCode::kInternal, "hull vertices moved beyond their budget");
  out.encoded = std::move(chosen->encoded);
  return out;
}

}  // namespace

Result<EncodedHulls> EncodeHulls(const std::vector<Mesh>& hulls, const MeshCodecSettings& settings,
                                 double max_error) {
  if (hulls.empty()) return Status(StatusCode::kInvalidArgument, "no hulls to encode");
  if (!(max_error > 0) || !std::isfinite(max_error))
    return Status(StatusCode::kInvalidArgument, "error budget must be positive");
  Mesh all;
  std::vector<uint32_t> groups;
  for (size_t h = 0; h < hulls.size(); ++h) {
    const uint32_t base = static_cast<uint32_t>(all.vertex_count());
    all.positions.insert(all.positions.end(), hulls[h].positions.begin(), hulls[h].positions.end());
    for (uint32_t i : hulls[h].indices) all.indices.push_back(base + i);
    groups.insert(groups.end(), hulls[h].triangle_count(), static_cast<uint32_t>(h));
  }
  Result<EncodedHulls> plain = EncodeGrouped(all, groups, hulls, settings, max_error);
  if (!plain.ok()) return plain;
  // Welding moves nothing (only bitwise-equal corners merge), so the welded stream has the same
  // error budget; it is kept when smaller.
  std::vector<uint32_t> welded_groups;
  const Mesh welded = WeldAcrossHulls(hulls, &welded_groups);
  if (welded.vertex_count() == all.vertex_count()) return plain;
  Result<EncodedHulls> shared = EncodeGrouped(welded, welded_groups, hulls, settings, max_error);
  if (!shared.ok()) return shared;
  if (shared->encoded.stream.size() >= plain->encoded.stream.size()) return plain;
  shared->welded = true;
  return shared;
}

}  // namespace hullpack
