#include "mesh/split.h"

#include <algorithm>
#include <numeric>

#include "common/buckets.h"

namespace hullpack {

bool CanSplitMesh(const Mesh& mesh) {
  return mesh.joints.empty() && mesh.weights.empty() && mesh.morph_targets.empty();
}

TriangleParts::TriangleParts(size_t part_count, const std::vector<uint32_t>& part_of)
    : count_(std::max<size_t>(part_count, 1)) {
  if (count_ == 1) return;
  if (count_ <= 256)
    small_.assign(part_of.begin(), part_of.end());
  else
    large_ = part_of;
}

std::vector<uint32_t> TriangleParts::Triangles(size_t p, size_t triangle_count) const {
  std::vector<uint32_t> out;
  for (size_t t = 0; t < triangle_count; ++t)
    if (Of(t) == p) out.push_back(static_cast<uint32_t>(t));
  return out;
}

TriangleParts SplitTriangles(const Mesh& mesh, size_t max_triangles) {
  const size_t n = mesh.triangle_count();
  max_triangles = std::max<size_t>(max_triangles, 1);
  if (n <= max_triangles || !CanSplitMesh(mesh)) return TriangleParts();
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  // The centroid (as the sum of the corners) along one axis, per triangle: one float each, not
  // three, as the split runs beside the decomposition of the same large mesh.
  std::vector<float> key(n);
  auto along = [&](uint32_t t, int axis) {
    float sum = 0;
    for (int k = 0; k < 3; ++k)
      sum += mesh.positions[3 * size_t(mesh.indices[3 * size_t(t) + k]) + axis];
    return sum;
  };
  // Ranges of `order` still too large; each is cut at a quantile along its widest axis. Ties are
  // broken by triangle id, so that the sides do not depend on the sort's implementation. The
  // finished ranges are numbered in the order they come out, first half first.
  std::vector<std::pair<size_t, size_t>> pending = {{0, n}}, done;
  while (!pending.empty()) {
    const auto [begin, end] = pending.back();
    pending.pop_back();
    if (end - begin <= max_triangles) {
      done.push_back({begin, end});
      continue;
    }
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) lo[a] = hi[a] = along(order[begin], a);
    for (size_t i = begin; i < end; ++i) {
      for (int a = 0; a < 3; ++a) {
        const float c = along(order[i], a);
        lo[a] = std::min(lo[a], c);
        hi[a] = std::max(hi[a], c);
      }
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a) {
      if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    }
    for (size_t i = begin; i < end; ++i) key[order[i]] = along(order[i], axis);
    // As few parts as the limit allows, of about equal size: each cut costs bytes (the vertices
    // along it are coded in both parts). The first side gets half of them (rounded down).
    const size_t size = end - begin;
    const size_t parts_here = (size + max_triangles - 1) / max_triangles;
    const size_t middle = begin + size * (parts_here / 2) / parts_here;
    std::nth_element(
        order.begin() + begin, order.begin() + middle, order.begin() + end,
        [&](uint32_t a, uint32_t b) { return key[a] != key[b] ? key[a] < key[b] : a < b; });
    // The second half pushed first: parts come out first half first.
    pending.push_back({middle, end});
    pending.push_back({begin, middle});
  }
  std::vector<float>().swap(key);
  std::vector<uint32_t> part_of(n);
  for (size_t p = 0; p < done.size(); ++p)
    for (size_t i = done[p].first; i < done[p].second; ++i)
      part_of[order[i]] = static_cast<uint32_t>(p);
  std::vector<uint32_t>().swap(order);
  return TriangleParts(done.size(), part_of);
}

Mesh MeshPart(const Mesh& mesh, const std::vector<uint32_t>& triangles) {
  constexpr uint32_t kUnused = UINT32_MAX;
  std::vector<uint32_t> new_id(mesh.vertex_count(), kUnused);
  for (uint32_t t : triangles) {
    for (int k = 0; k < 3; ++k) new_id[mesh.indices[3 * size_t(t) + k]] = 0;
  }
  std::vector<uint32_t> kept;  // old ids, ascending
  for (uint32_t v = 0; v < new_id.size(); ++v) {
    if (new_id[v] == kUnused) continue;
    new_id[v] = static_cast<uint32_t>(kept.size());
    kept.push_back(v);
  }
  auto gather = [&](const std::vector<float>& from, size_t width) {
    std::vector<float> to;
    if (from.empty()) return to;
    to.reserve(kept.size() * width);
    for (uint32_t v : kept)
      to.insert(to.end(), from.begin() + width * v, from.begin() + width * (v + 1));
    return to;
  };
  Mesh part;
  part.name = mesh.name;
  part.collides = mesh.collides;
  part.positions = gather(mesh.positions, 3);
  part.normals = gather(mesh.normals, 3);
  part.tangents = gather(mesh.tangents, 4);
  for (const std::vector<float>& uv : mesh.uv_sets) part.uv_sets.push_back(gather(uv, 2));
  part.colors = gather(mesh.colors, 4);
  part.indices.reserve(3 * triangles.size());
  for (uint32_t t : triangles) {
    for (int k = 0; k < 3; ++k) part.indices.push_back(new_id[mesh.indices[3 * size_t(t) + k]]);
    if (!mesh.material_ids.empty()) part.material_ids.push_back(mesh.material_ids[t]);
  }
  return part;
}

std::array<float, 6> PositionBox(const Mesh& mesh) {
  std::array<float, 6> box = {0, 0, 0, 0, 0, 0};
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const float x = mesh.positions[i];
    const size_t a = i % 3;
    if (i < 3) {
      box[a] = box[3 + a] = x;
    } else {
      box[a] = std::min(box[a], x);
      box[3 + a] = std::max(box[3 + a], x);
    }
  }
  return box;
}

Status ForEachPart(const Mesh& mesh, const std::vector<uint32_t>& groups, size_t max_triangles,
                   const std::function<Status(const PartToCode&)>& visit) {
  const TriangleParts split =
      max_triangles > 0 ? SplitTriangles(mesh, max_triangles) : TriangleParts();
  if (split.count() <= 1) return visit(PartToCode{0, 1, mesh, groups, std::nullopt});
  const std::array<float, 6> box = PositionBox(mesh);
  // A few parts list their triangles by a pass over the part ids each (the split stays one byte
  // per triangle); many parts, whose passes would add up, are grouped once.
  constexpr size_t kPassesAtMost = 16;
  const size_t n = mesh.triangle_count();
  const Buckets grouped = split.count() > kPassesAtMost
                              ? BucketBy(n, split.count(), [&](size_t t) { return split.Of(t); })
                              : Buckets();
  for (size_t p = 0; p < split.count(); ++p) {
    Mesh part;
    std::vector<uint32_t> part_groups;
    {
      const std::vector<uint32_t> triangles =
          grouped.ids.empty() ? split.Triangles(p, n)
                              : std::vector<uint32_t>(grouped.ids.begin() + grouped.start[p],
                                                      grouped.ids.begin() + grouped.start[p + 1]);
      part = MeshPart(mesh, triangles);
      if (!groups.empty()) {
        part_groups.reserve(triangles.size());
        for (uint32_t t : triangles) part_groups.push_back(groups[t]);
      }
    }
    const Status status = visit(PartToCode{p, split.count(), part, part_groups, box});
    if (!status.ok()) return status;
  }
  return Status::Ok();
}

}  // namespace hullpack
