#include "mesh/topology.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <utility>
#include <vector>

#include "common/buckets.h"
#include "mesh/triangle_key.h"

namespace hullpack {
namespace {

// Disjoint sets over 0..n-1 with path halving; enough for a few million elements.
class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  uint32_t Find(uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void Union(uint32_t a, uint32_t b) {
    a = Find(a);
    b = Find(b);
    if (a == b) return;
    // Keep the smaller id as root so results do not depend on union order.
    if (a < b) std::swap(a, b);
    parent_[a] = b;
  }

 private:
  std::vector<uint32_t> parent_;
};

using PositionKey = std::array<uint32_t, 3>;

PositionKey KeyOf(const float* p) {
  PositionKey key;
  for (int i = 0; i < 3; ++i) {
    // -0 and +0 are the same point; everything else compares by its bits.
    const float v = p[i] == 0.0f ? 0.0f : p[i];
    std::memcpy(&key[i], &v, sizeof(float));
  }
  return key;
}

// Maps every vertex index to a welded point id (0..point_count-1); returns the point count.
size_t WeldPositions(const Mesh& mesh, std::vector<uint32_t>& point_of) {
  const size_t n = mesh.vertex_count();
  std::vector<PositionKey> keys(n);
  for (size_t v = 0; v < n; ++v) keys[v] = KeyOf(&mesh.positions[3 * v]);
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&keys](uint32_t a, uint32_t b) {
    return keys[a] != keys[b] ? keys[a] < keys[b] : a < b;
  });
  point_of.assign(n, 0);
  size_t points = 0;
  for (size_t i = 0; i < n; ++i) {
    if (i > 0 && keys[order[i]] != keys[order[i - 1]]) ++points;
    point_of[order[i]] = static_cast<uint32_t>(points);
  }
  return n == 0 ? 0 : points + 1;
}

struct Vec3 {
  double x, y, z;
};
Vec3 Sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 Cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double Dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Per edge component figures gathered for the closed / genus / volume decisions.
struct ComponentStats {
  size_t triangles = 0;
  size_t edges = 0;
  size_t points = 0;
  size_t open_or_non_manifold_edges = 0;
  bool has_non_manifold_vertex = false;
  double volume = 0;
};

}  // namespace

TopologyReport AnalyzeTopology(const Mesh& mesh, const TopologyOptions& options) {
  TopologyReport report;
  const size_t vertex_count = mesh.vertex_count();
  const size_t triangle_count = mesh.triangle_count();
  report.vertices = vertex_count;
  report.triangles = triangle_count;

  std::vector<uint32_t> welded;
  const size_t welded_count = WeldPositions(mesh, welded);
  std::vector<uint32_t> point_of;
  size_t point_count = welded_count;
  if (options.connectivity == Connectivity::kWeldedPositions) {
    point_of = welded;
  } else {
    point_of.resize(vertex_count);
    std::iota(point_of.begin(), point_of.end(), 0u);
    point_count = vertex_count;
  }

  // Referenced vertices, their welded points and their bounds.
  std::vector<uint8_t> vertex_used(vertex_count, 0);
  std::vector<uint8_t> position_used(welded_count, 0);
  for (uint32_t index : mesh.indices) vertex_used[index] = 1;
  bool any_referenced = false;
  for (size_t v = 0; v < vertex_count; ++v) {
    if (!vertex_used[v]) continue;
    ++report.referenced_vertices;
    position_used[welded[v]] = 1;
    const float* p = &mesh.positions[3 * v];
    for (int i = 0; i < 3; ++i) {
      report.bbox_min[i] = any_referenced ? std::min(report.bbox_min[i], p[i]) : p[i];
      report.bbox_max[i] = any_referenced ? std::max(report.bbox_max[i], p[i]) : p[i];
    }
    any_referenced = true;
  }
  report.unique_positions =
      static_cast<size_t>(std::count(position_used.begin(), position_used.end(), uint8_t{1}));
  welded.clear();
  welded.shrink_to_fit();

  // Triangles as welded point triples; degenerate ones drop out here.
  std::vector<std::array<uint32_t, 3>> tri(triangle_count);
  std::vector<uint8_t> degenerate(triangle_count, 0);
  for (size_t t = 0; t < triangle_count; ++t) {
    for (int k = 0; k < 3; ++k) tri[t][k] = point_of[mesh.indices[3 * t + k]];
    if (tri[t][0] == tri[t][1] || tri[t][1] == tri[t][2] || tri[t][2] == tri[t][0]) {
      degenerate[t] = 1;
      ++report.degenerate_triangles;
    }
  }

  // Duplicates: rotate each triangle so its smallest point comes first (keeps the winding); equal
  // rotated triples are duplicates, equal sorted triples with the other winding are opposite
  // pairs. Equal triples share their smallest point: they are looked for among its triangles.
  {
    const Buckets by_smallest = BucketBy(triangle_count, point_count, [&](size_t t) {
      return degenerate[t] ? kNoBucket : std::min({tri[t][0], tri[t][1], tri[t][2]});
    });
    std::vector<TriangleKey> canon;
    for (size_t p = 0; p < point_count; ++p) {
      const uint32_t first = by_smallest.start[p], last = by_smallest.start[p + 1];
      if (last - first < 2) continue;
      canon.clear();
      for (uint32_t e = first; e < last; ++e) {
        canon.push_back(TriangleKey::Of(tri[by_smallest.ids[e]].data()));
      }
      std::sort(canon.begin(), canon.end());
      for (size_t i = 0; i < canon.size();) {
        size_t j = i;
        size_t same_winding[2] = {0, 0};
        while (j < canon.size() && canon[j].sorted == canon[i].sorted)
          ++same_winding[canon[j++].flipped];
        for (size_t count : same_winding) report.duplicate_triangles += count > 0 ? count - 1 : 0;
        report.opposite_triangle_pairs += std::min(same_winding[0], same_winding[1]);
        i = j;
      }
    }
  }

  // Edges: every non-degenerate triangle's three sides (side 3t + k runs from corner k to k + 1),
  // grouped by their smaller point; the sides of one edge share both points.
  auto side_points = [&tri](uint32_t side) {
    const auto& t = tri[side / 3];
    return std::pair<uint32_t, uint32_t>(t[side % 3], t[(side % 3 + 1) % 3]);
  };
  auto larger = [&side_points](uint32_t side) {
    const auto ends = side_points(side);
    return std::max(ends.first, ends.second);
  };

  // Walk the edges once: classify them, join triangles into components, and join the corners
  // that meet across a manifold edge into fans.
  UnionFind triangle_sets(triangle_count);
  UnionFind corner_fans(3 * triangle_count);
  struct EdgeRecord {
    uint32_t triangle;  // any triangle using it, to find its component later
    bool bad;           // boundary or non-manifold
  };
  std::vector<EdgeRecord> edge_records;
  {
    const Buckets by_smaller = BucketBy(3 * triangle_count, point_count, [&](size_t side) {
      if (degenerate[side / 3]) return kNoBucket;
      const auto ends = side_points(static_cast<uint32_t>(side));
      return std::min(ends.first, ends.second);
    });
    std::vector<uint32_t> sides;
    for (size_t p = 0; p < point_count; ++p) {
      sides.assign(by_smaller.ids.begin() + by_smaller.start[p],
                   by_smaller.ids.begin() + by_smaller.start[p + 1]);
      // By the larger point, then by triangle (ascending ids: the side order within a triangle
      // never ties, a triangle has one side between two points).
      std::sort(sides.begin(), sides.end(), [&](uint32_t x, uint32_t y) {
        const uint32_t lx = larger(x), ly = larger(y);
        return lx != ly ? lx < ly : x < y;
      });
      for (size_t i = 0; i < sides.size();) {
        size_t j = i + 1;
        while (j < sides.size() && larger(sides[j]) == larger(sides[i])) ++j;
        const size_t uses = j - i;
        ++report.edges;
        if (uses == 1) ++report.boundary_edges;
        if (uses > 2) ++report.non_manifold_edges;
        const uint32_t t1 = sides[i] / 3;
        for (size_t k = i + 1; k < j; ++k) triangle_sets.Union(t1, sides[k] / 3);
        if (uses == 2) {
          const uint32_t s1 = sides[i], s2 = sides[i + 1];
          const uint32_t t2 = s2 / 3, c1_start = s1 % 3, c2_start = s2 % 3;
          const auto e1 = side_points(s1), e2 = side_points(s2);
          if ((e1.first < e1.second) == (e2.first < e2.second)) ++report.inconsistent_edges;
          // Corners of the first side at its two ends, matched with the second's at the same
          // points.
          for (uint32_t end = 0; end < 2; ++end) {
            const uint32_t c1 = (c1_start + end) % 3;
            const uint32_t point = tri[t1][c1];
            const uint32_t c2 = tri[t2][c2_start] == point ? c2_start : (c2_start + 1) % 3;
            corner_fans.Union(3 * t1 + c1, 3 * t2 + c2);
          }
        }
        edge_records.push_back({t1, uses != 2});
        i = j;
      }
    }
  }
  report.consistently_oriented = report.inconsistent_edges == 0;

  // Components by shared points.
  {
    UnionFind point_sets(point_count);
    std::vector<uint8_t> point_in_triangle(point_count, 0);
    for (size_t t = 0; t < triangle_count; ++t) {
      if (degenerate[t]) continue;
      point_sets.Union(tri[t][0], tri[t][1]);
      point_sets.Union(tri[t][1], tri[t][2]);
      for (uint32_t p : tri[t]) point_in_triangle[p] = 1;
    }
    for (size_t p = 0; p < point_count; ++p) {
      if (point_in_triangle[p] && point_sets.Find(static_cast<uint32_t>(p)) == p) {
        ++report.components_by_vertex;
      }
    }
  }

  // Number the edge components densely.
  std::vector<uint32_t> component_of(triangle_count, UINT32_MAX);
  std::vector<ComponentStats> stats;
  for (size_t t = 0; t < triangle_count; ++t) {
    if (degenerate[t]) continue;
    const uint32_t root = triangle_sets.Find(static_cast<uint32_t>(t));
    if (component_of[root] == UINT32_MAX) {
      component_of[root] = static_cast<uint32_t>(stats.size());
      stats.emplace_back();
    }
    component_of[t] = component_of[root];
    ++stats[component_of[t]].triangles;
  }
  report.components = stats.size();
  for (const EdgeRecord& e : edge_records) {
    ComponentStats& c = stats[component_of[e.triangle]];
    ++c.edges;
    if (e.bad) ++c.open_or_non_manifold_edges;
  }
  edge_records.clear();
  edge_records.shrink_to_fit();

  // Fans: a point is manifold when all its corners fall into one fan. The corners at a point,
  // sorted by (component, fan), put its components and fans next to each other; a fan never spans
  // two components since fans are joined across edges.
  {
    struct CornerAt {
      uint32_t component, fan;
      bool operator<(const CornerAt& o) const {
        return component != o.component ? component < o.component : fan < o.fan;
      }
    };
    const Buckets at_point = BucketBy(3 * triangle_count, point_count, [&](size_t corner) {
      return degenerate[corner / 3] ? kNoBucket : tri[corner / 3][corner % 3];
    });
    std::vector<CornerAt> corners;
    for (size_t p = 0; p < point_count; ++p) {
      const uint32_t first = at_point.start[p], last = at_point.start[p + 1];
      if (first == last) continue;
      corners.clear();
      for (uint32_t e = first; e < last; ++e) {
        const uint32_t corner = at_point.ids[e];
        corners.push_back({component_of[corner / 3], corner_fans.Find(corner)});
      }
      std::sort(corners.begin(), corners.end());
      bool several_fans = false;
      for (const CornerAt& c : corners) several_fans |= c.fan != corners[0].fan;
      if (several_fans) ++report.non_manifold_vertices;
      for (size_t k = 0; k < corners.size(); ++k) {
        ComponentStats& c = stats[corners[k].component];
        // One count per (point, component): the component's V in chi = V - E + F.
        if (k == 0 || corners[k].component != corners[k - 1].component) ++c.points;
        if (several_fans) c.has_non_manifold_vertex = true;
      }
    }
  }

  // Area of every triangle; signed volume per component, taken about the bounds' centre so
  // that meshes far from the origin do not lose precision.
  const Vec3 origin = {(double{report.bbox_min[0]} + report.bbox_max[0]) / 2,
                       (double{report.bbox_min[1]} + report.bbox_max[1]) / 2,
                       (double{report.bbox_min[2]} + report.bbox_max[2]) / 2};
  for (size_t t = 0; t < triangle_count; ++t) {
    if (degenerate[t]) continue;
    Vec3 p[3];
    for (int k = 0; k < 3; ++k) {
      const float* v = &mesh.positions[3 * mesh.indices[3 * t + k]];
      p[k] = Sub({v[0], v[1], v[2]}, origin);
    }
    const Vec3 normal = Cross(Sub(p[1], p[0]), Sub(p[2], p[0]));
    report.area += 0.5 * std::sqrt(Dot(normal, normal));
    stats[component_of[t]].volume += Dot(p[0], Cross(p[1], p[2])) / 6.0;
  }

  bool all_closed_manifold = !stats.empty();
  int genus = 0;
  for (const ComponentStats& c : stats) {
    const bool closed = c.open_or_non_manifold_edges == 0;
    if (closed) {
      ++report.closed_components;
      report.volume += c.volume;
    }
    if (!closed || c.has_non_manifold_vertex) {
      all_closed_manifold = false;
      continue;
    }
    ++report.closed_manifold_components;
    const long long chi = static_cast<long long>(c.points) - static_cast<long long>(c.edges) +
                          static_cast<long long>(c.triangles);
    // An odd chi means a non-orientable surface; genus in the handle sense is undefined.
    if ((2 - chi) % 2 != 0) all_closed_manifold = false;
    genus += static_cast<int>((2 - chi) / 2);
  }
  report.closed = triangle_count > report.degenerate_triangles && report.boundary_edges == 0 &&
                  report.non_manifold_edges == 0;
  report.genus = all_closed_manifold ? genus : -1;
  return report;
}

}  // namespace hullpack
