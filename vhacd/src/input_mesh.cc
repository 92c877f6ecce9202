#include "input_mesh.h"

#include <algorithm>

#include "error_metrics.h"

namespace vhacd {
namespace internal {

namespace {

template <typename T>
void FreeMemory(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

// Whether every undirected edge is used by exactly two triangles. The edges are listed at their
// smaller vertex (its larger vertex, 4 bytes per edge instead of a sorted list of 8-byte pairs)
// and each vertex's short list is sorted. A large mesh's vertices are taken in a few ranges, one
// range's lists at a time: the decomposition may run beside an encoder of the same mesh, and a
// list of every edge would be as large as the triangles.
bool IsClosed(const TriangleList& triangles, size_t nv) {
  std::vector<uint32_t> start(nv + 1, 0);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  constexpr size_t kOneRangeEdges = size_t{1} << 20;
  constexpr size_t kMaxRanges = 4;
  const size_t edges = start[nv];
  const size_t ranges = std::min(kMaxRanges, (edges + kOneRangeEdges - 1) / kOneRangeEdges);
  const size_t range_edges = (edges + ranges - 1) / std::max<size_t>(ranges, 1);
  std::vector<uint32_t> other, fill;
  for (size_t first = 0; first < nv;) {
    // The vertices [first, last): as many as fit in range_edges, and at least one.
    const uint32_t base = start[first];
    size_t last = static_cast<size_t>(
        std::upper_bound(start.begin() + first + 1, start.end(), base + range_edges) -
        start.begin() - 1);
    last = std::min(std::max(last, first + 1), nv);
    other.resize(start[last] - base);
    fill.assign(start.begin() + first, start.begin() + last);
    for (const auto& t : triangles)
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = t[k], b = t[(k + 1) % 3];
        const uint32_t lo = std::min(a, b);
        if (lo >= first && lo < last) other[fill[lo - first]++ - base] = std::max(a, b);
      }
    for (size_t v = first; v < last; ++v) {
      uint32_t* begin = other.data() + (start[v] - base);
      uint32_t* end = other.data() + (start[v + 1] - base);
      std::sort(begin, end);
      for (uint32_t* i = begin; i < end;) {
        uint32_t* j = i;
        while (j < end && *j == *i) ++j;
        if (j - i != 2) return false;
        i = j;
      }
    }
    first = last;
  }
  return true;
}

// Whether consecutive triangles use points near each other in the input's order, so that the
// decomposition, reading them in that order, stays in few cache lines at a time. Sampled windows
// of consecutive triangles count their distinct points and the distinct blocks of 64 points these
// lie in: a file written along its surface has many points per block (15-40 on scans and CAD
// parts), a scrambled one (welded through a hash table, say) about one, and the lexicographic
// order is then the faster one.
bool LocalOrder(const MeshView& m) {
  constexpr size_t kWindow = 1024, kWindows = 64;
  constexpr int kBlockShift = 6;
  std::vector<uint32_t> ids;
  size_t points = 0, blocks = 0;
  const size_t windows = std::min(kWindows, (m.triangle_count + kWindow - 1) / kWindow);
  for (size_t w = 0; w < windows; ++w) {
    const size_t first = m.triangle_count * w / windows;
    const size_t last = std::min(m.triangle_count, first + kWindow);
    ids.clear();
    for (size_t t = first; t < last; ++t)
      for (int k = 0; k < 3; ++k) ids.push_back(m.indices[t * m.triangle_stride + k]);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    points += ids.size();
    for (size_t i = 0; i < ids.size(); ++i)
      blocks += i == 0 || (ids[i] >> kBlockShift) != (ids[i - 1] >> kBlockShift);
  }
  return 2 * blocks <= points;
}

}  // namespace

Status ReadMesh(const MeshView& m, Context* ctx, InputMesh* out, std::string* why,
                const ReadOptions& options) {
  if (m.point_count == 0 || m.triangle_count == 0) {
    *why = "the mesh has no points or no triangles";
    return Status::kEmptyMesh;
  }
  if ((m.points_f == nullptr) == (m.points_d == nullptr)) {
    *why = "exactly one of points_f and points_d must be set";
    return Status::kInvalidMesh;
  }
  if (m.indices == nullptr) {
    *why = "indices is null";
    return Status::kInvalidMesh;
  }
  if (m.point_stride < 3 || m.triangle_stride < 3) {
    *why = "strides must be at least 3";
    return Status::kInvalidMesh;
  }
  if (m.point_count >= 0xffffffffu || m.triangle_count >= (size_t{1} << 31)) {
    *why = "the mesh is too large";
    return Status::kInvalidMesh;
  }
  const size_t np = m.point_count;
  // The view's points in double (no copy: float inputs would double in size).
  const PointSource point{m.points_f, m.points_d, m.point_stride, np};
  std::vector<char> used(np, 0);
  for (size_t t = 0; t < m.triangle_count; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = m.indices[t * m.triangle_stride + k];
      if (v >= np) {
        *why = "triangle " + std::to_string(t) + " refers to point " + std::to_string(v) + " of " +
               std::to_string(np);
        return Status::kIndexOutOfRange;
      }
      used[v] = 1;
    }
  for (size_t i = 0; i < np; ++i)
    if (used[i] && !point[i].allFinite()) {
      *why = "point " + std::to_string(i) + " has a non-finite coordinate";
      return Status::kInvalidMesh;
    }
  auto cancelled = [&]() {
    if (!ctx->Cancelled()) return false;
    *why = "cancelled";
    return true;
  };
  if (cancelled()) return Status::kCancelled;
  // Weld bit-identical positions: equal positions are neighbours in their lexicographic order.
  std::vector<uint32_t> order;
  for (uint32_t i = 0; i < np; ++i)
    if (used[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const Vec3 pa = point[a], pb = point[b];
    if (pa[0] != pb[0]) return pa[0] < pb[0];
    if (pa[1] != pb[1]) return pa[1] < pb[1];
    if (pa[2] != pb[2]) return pa[2] < pb[2];
    return a < b;
  });
  // Sized before they are filled: the mesh stays for the whole decomposition, and grown one
  // element at a time it would hold up to twice its size.
  size_t distinct = 0;
  for (size_t k = 0; k < order.size(); ++k)
    distinct += k == 0 || point[order[k]] != point[order[k - 1]];
  // Every point used and distinct, in an order local to the triangles: with may_borrow, the
  // welded points are the input's, in order.
  const bool keep_order = options.may_borrow && distinct == np && LocalOrder(m);
  std::vector<uint32_t> remap(keep_order ? 0 : np, 0);  // input point -> welded (else the same)
  if (options.keep_sources) out->point_source.reserve(distinct);
  if (keep_order) {
    if (options.points_in_place) {
      out->view_points = point;
    } else {
      out->points.reserve(np);
      for (uint32_t i = 0; i < np; ++i) out->points.push_back(point[i]);
    }
    if (options.keep_sources)
      for (uint32_t i = 0; i < np; ++i) out->point_source.push_back(i);
    // The points at every stride-th rank of the lexicographic order: those a lexicographically
    // numbered mesh samples (see SampleSurface).
    const size_t stride = VertexSampleStride(distinct);
    for (size_t k = 0; k < order.size(); k += stride) out->vertex_samples.push_back(order[k]);
  } else {
    out->points.reserve(distinct);
    for (size_t k = 0; k < order.size(); ++k) {
      const Vec3 p = point[order[k]];
      if (k == 0 || p != out->points.back()) {
        out->points.push_back(p);
        if (options.keep_sources) out->point_source.push_back(order[k]);
      }
      remap[order[k]] = static_cast<uint32_t>(out->points.size() - 1);
    }
  }
  // Each working array is freed once done: the decomposition beside which this may run (a
  // pipeline also encodes the mesh) feels the sum of what is alive at once.
  FreeMemory(used);
  FreeMemory(order);
  if (cancelled()) return Status::kCancelled;
  // Triangles: drop degenerate and duplicate (same vertex set) ones, keep the first. Equal vertex
  // sets share their smallest vertex: the triangles are grouped by it (a counting pass, 4 bytes
  // per triangle) and each group, a few triangles, is sorted alone.
  auto welded = [&](size_t t) {
    std::array<uint32_t, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = m.indices[t * m.triangle_stride + k];
      tri[k] = keep_order ? v : remap[v];
    }
    return tri;
  };
  const size_t nw = out->point_count();
  std::vector<uint8_t> drop(m.triangle_count, 0);
  {
    std::vector<uint32_t> end(nw + 1, 0);
    for (size_t t = 0; t < m.triangle_count; ++t) {
      const std::array<uint32_t, 3> tri = welded(t);
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
        drop[t] = 1;
        continue;
      }
      ++end[std::min({tri[0], tri[1], tri[2]}) + 1];
    }
    for (size_t v = 0; v < nw; ++v) end[v + 1] += end[v];
    std::vector<uint32_t> by_smallest(end[nw]);
    for (size_t t = 0; t < m.triangle_count; ++t) {
      if (drop[t]) continue;
      const std::array<uint32_t, 3> tri = welded(t);
      by_smallest[end[std::min({tri[0], tri[1], tri[2]})]++] = static_cast<uint32_t>(t);
    }
    // end[v] is now the end of v's group, where v + 1's starts.
    std::vector<std::pair<std::array<uint32_t, 3>, uint32_t>> group;
    for (size_t v = 0, begin = 0; v < nw; begin = end[v++]) {
      if (end[v] - begin < 2) continue;
      group.clear();
      for (size_t e = begin; e < end[v]; ++e) {
        std::array<uint32_t, 3> key = welded(by_smallest[e]);
        std::sort(key.begin(), key.end());
        group.emplace_back(key, by_smallest[e]);
      }
      std::sort(group.begin(), group.end());
      for (size_t k = 1; k < group.size(); ++k)
        if (group[k].first == group[k - 1].first) drop[group[k].second] = 1;
    }
  }
  const size_t kept = static_cast<size_t>(std::count(drop.begin(), drop.end(), uint8_t{0}));
  if (options.keep_sources) out->triangle_source.reserve(kept);
  if (keep_order && kept == m.triangle_count && m.triangle_stride == 3) {
    out->triangles = TriangleList::Borrow(m.indices, m.triangle_count);
    if (options.keep_sources)
      for (size_t t = 0; t < m.triangle_count; ++t)
        out->triangle_source.push_back(static_cast<uint32_t>(t));
  } else {
    out->triangles.reserve(kept);
    for (size_t t = 0; t < m.triangle_count; ++t) {
      if (drop[t]) continue;
      out->triangles.push_back(welded(t));
      if (options.keep_sources) out->triangle_source.push_back(static_cast<uint32_t>(t));
    }
  }
  FreeMemory(drop);
  FreeMemory(remap);
  if (out->triangles.empty()) {
    *why = "every triangle is degenerate";
    return Status::kEmptyMesh;
  }
  if (cancelled()) return Status::kCancelled;
  out->closed = IsClosed(out->triangles, out->point_count());
  return Status::kOk;
}

}  // namespace internal
}  // namespace vhacd
