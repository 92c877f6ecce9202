#include "mesh/repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <numeric>
#include <vector>

#include "common/buckets.h"
#include "common/parallel.h"
#include "mesh/triangle_key.h"

namespace hullpack {
namespace {

constexpr uint32_t kRemoved = UINT32_MAX;

// Appends one vertex's values of a float attribute as comparable words.
void AppendFloats(const std::vector<float>& values, size_t width, size_t vertex,
                  std::vector<uint32_t>& row) {
  for (size_t i = 0; i < width && !values.empty(); ++i) {
    const float v = values[width * vertex + i] == 0.0f ? 0.0f : values[width * vertex + i];
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof(bits));
    row.push_back(bits);
  }
}

// For each vertex, the lowest-numbered vertex with identical attributes (itself if none).
std::vector<uint32_t> FindIdenticalVertices(const Mesh& mesh, int threads) {
  const size_t n = mesh.vertex_count();
  // All attributes of a vertex as one row of 32-bit words; rows of equal vertices are equal.
  std::vector<uint32_t> rows;
  std::vector<uint32_t> row;
  size_t width = 0;
  for (size_t v = 0; v < n; ++v) {
    row.clear();
    AppendFloats(mesh.positions, 3, v, row);
    AppendFloats(mesh.normals, 3, v, row);
    AppendFloats(mesh.tangents, 4, v, row);
    for (const std::vector<float>& uv : mesh.uv_sets) AppendFloats(uv, 2, v, row);
    AppendFloats(mesh.colors, 4, v, row);
    AppendFloats(mesh.weights, 4, v, row);
    for (size_t i = 0; i < 4 && !mesh.joints.empty(); ++i) row.push_back(mesh.joints[4 * v + i]);
    for (const MorphTarget& t : mesh.morph_targets) {
      AppendFloats(t.positions, 3, v, row);
      AppendFloats(t.normals, 3, v, row);
    }
    if (v == 0) {
      width = row.size();
      rows.reserve(width * n);
    }
    rows.insert(rows.end(), row.begin(), row.end());
  }
  auto row_of = [&rows, width](uint32_t v) {
    return rows.begin() + static_cast<ptrdiff_t>(width * v);
  };

  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  ParallelSort(
      order.begin(), order.end(),
      [&](uint32_t a, uint32_t b) {
        const int c = std::memcmp(&*row_of(a), &*row_of(b), width * sizeof(uint32_t));
        return c != 0 ? c < 0 : a < b;
      },
      threads);
  std::vector<uint32_t> representative(n);
  for (size_t i = 0; i < n; ++i) {
    const bool same_as_previous =
        i > 0 && std::equal(row_of(order[i]), row_of(order[i]) + static_cast<ptrdiff_t>(width),
                            row_of(order[i - 1]));
    // Ties sort by index, so the first of each run is the lowest-numbered vertex.
    representative[order[i]] = same_as_previous ? representative[order[i - 1]] : order[i];
  }
  return representative;
}

bool HasZeroArea(const Mesh& mesh, const uint32_t* corners) {
  double p[3][3];
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) p[k][i] = mesh.positions[3 * corners[k] + i];
  }
  const double e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
  const double e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
  return e1[1] * e2[2] - e1[2] * e2[1] == 0 && e1[2] * e2[0] - e1[0] * e2[2] == 0 &&
         e1[0] * e2[1] - e1[1] * e2[0] == 0;
}

// Keeps the entries of `values` (groups of `width`) whose slot maps to a new index, at that
// index. Empty arrays stay empty.
template <typename T>
void Compact(std::vector<T>& values, size_t width, const std::vector<uint32_t>& new_index,
             size_t kept) {
  if (values.empty()) return;
  std::vector<T> out(width * kept);
  for (size_t old = 0; old < new_index.size(); ++old) {
    if (new_index[old] == kRemoved) continue;
    std::copy_n(values.begin() + static_cast<ptrdiff_t>(width * old), width,
                out.begin() + static_cast<ptrdiff_t>(width * new_index[old]));
  }
  values.swap(out);
}

// Marks extra copies of triangles (same cyclic order) and, if asked, the opposite-winding
// partners of earlier triangles; counts both.
// A triangle's key and its index.
struct Canonical {
  TriangleKey key;
  uint32_t triangle;
  bool operator<(const Canonical& o) const {
    if (key.sorted != o.key.sorted || key.flipped != o.key.flipped) return key < o.key;
    return triangle < o.triangle;
  }
};

// MarkDuplicateTriangles for the triangles of `canon` (sorted).
void MarkCopiesAmong(const std::vector<Canonical>& canon, const RepairOptions& options,
                     std::vector<uint8_t>& remove, RepairReport& report) {
  for (size_t i = 0; i < canon.size();) {
    size_t j = i;
    size_t per_winding[2] = {0, 0};
    const Canonical* first = &canon[i];  // the earliest triangle of the group
    for (; j < canon.size() && canon[j].key.sorted == canon[i].key.sorted; ++j) {
      const Canonical& c = canon[j];
      if (c.triangle < first->triangle) first = &c;
      // Within one winding, the first entry (lowest triangle index) is the one kept.
      if (per_winding[c.key.flipped]++ > 0 && options.remove_duplicate_triangles) {
        remove[c.triangle] = 1;
        ++report.duplicate_triangles_removed;
      }
    }
    // Pairs among the triangles that stay: one per winding when copies are removed.
    size_t kept[2] = {per_winding[0], per_winding[1]};
    if (options.remove_duplicate_triangles) {
      for (size_t& count : kept) count = std::min<size_t>(count, 1);
    }
    report.opposite_triangle_pairs += std::min(kept[0], kept[1]);
    if (options.remove_opposite_duplicates && per_winding[0] > 0 && per_winding[1] > 0) {
      for (size_t k = i; k < j; ++k) {
        const Canonical& c = canon[k];
        if (c.key.flipped == first->key.flipped || remove[c.triangle]) continue;
        remove[c.triangle] = 1;
        ++report.opposite_triangles_removed;
      }
    }
    i = j;
  }
}

void MarkDuplicateTriangles(const Mesh& mesh, const RepairOptions& options,
                            std::vector<uint8_t>& remove, RepairReport& report) {
  // Equal vertex sets share their smallest vertex: copies are looked for among its triangles.
  const Buckets by_smallest = BucketBy(mesh.triangle_count(), mesh.vertex_count(), [&](size_t t) {
    const uint32_t* p = &mesh.indices[3 * t];
    return remove[t] ? kNoBucket : std::min({p[0], p[1], p[2]});
  });
  std::vector<Canonical> canon;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const uint32_t first = by_smallest.start[v], last = by_smallest.start[v + 1];
    if (last - first < 2) continue;  // one triangle (or none): no copy
    canon.clear();
    for (uint32_t e = first; e < last; ++e) {
      const uint32_t t = by_smallest.ids[e];
      canon.push_back({TriangleKey::Of(&mesh.indices[3 * size_t(t)]), t});
    }
    std::sort(canon.begin(), canon.end());
    MarkCopiesAmong(canon, options, remove, report);
  }
}

}  // namespace

RepairReport RepairMesh(Mesh& mesh, const RepairOptions& options) {
  RepairReport report;
  const size_t vertex_count = mesh.vertex_count();
  const size_t triangle_count = mesh.triangle_count();

  std::vector<uint32_t> representative(vertex_count);
  if (options.weld_duplicate_vertices) {
    representative = FindIdenticalVertices(mesh, options.threads);
    for (uint32_t& index : mesh.indices) index = representative[index];
  } else {
    std::iota(representative.begin(), representative.end(), 0u);
  }

  // Degenerate and zero-area triangles, in ranges on the threads (each counts its own).
  std::vector<uint8_t> remove(triangle_count, 0);
  const int threads = std::max(1, options.threads);
  const size_t ranges =
      threads > 1 && triangle_count >= 65536 ? 4 * static_cast<size_t>(threads) : 1;
  std::vector<size_t> degenerate(ranges, 0), zero_area(ranges, 0);
  ParallelFor(ranges, threads, [&](size_t r) {
    for (size_t t = triangle_count * r / ranges; t < triangle_count * (r + 1) / ranges; ++t) {
      const uint32_t* p = &mesh.indices[3 * t];
      if (options.remove_degenerate_triangles && (p[0] == p[1] || p[1] == p[2] || p[2] == p[0])) {
        remove[t] = 1;
        ++degenerate[r];
      } else if (options.remove_zero_area_triangles && HasZeroArea(mesh, p)) {
        remove[t] = 1;
        ++zero_area[r];
      }
    }
  });
  for (size_t r = 0; r < ranges; ++r) {
    report.degenerate_triangles_removed += degenerate[r];
    report.zero_area_triangles_removed += zero_area[r];
  }
  MarkDuplicateTriangles(mesh, options, remove, report);

  // Drop removed triangles (and their material ids) in place, keeping the order.
  size_t kept_triangles = 0;
  for (size_t t = 0; t < triangle_count; ++t) {
    if (remove[t]) continue;
    std::copy_n(mesh.indices.begin() + static_cast<ptrdiff_t>(3 * t), 3,
                mesh.indices.begin() + static_cast<ptrdiff_t>(3 * kept_triangles));
    if (!mesh.material_ids.empty()) mesh.material_ids[kept_triangles] = mesh.material_ids[t];
    ++kept_triangles;
  }
  mesh.indices.resize(3 * kept_triangles);
  if (!mesh.material_ids.empty()) mesh.material_ids.resize(kept_triangles);

  // Decide which vertices survive and renumber them in their old order.
  std::vector<uint8_t> used(vertex_count, 0);
  for (uint32_t index : mesh.indices) used[index] = 1;
  std::vector<uint32_t> new_index(vertex_count, kRemoved);
  uint32_t kept_vertices = 0;
  for (size_t v = 0; v < vertex_count; ++v) {
    if (representative[v] != v) {
      ++report.welded_vertices;
      continue;
    }
    if (options.remove_unused_vertices && !used[v]) {
      ++report.unused_vertices_removed;
      continue;
    }
    new_index[v] = kept_vertices++;
  }
  if (kept_vertices == vertex_count) return report;

  for (uint32_t& index : mesh.indices) index = new_index[index];
  Compact(mesh.positions, 3, new_index, kept_vertices);
  Compact(mesh.normals, 3, new_index, kept_vertices);
  Compact(mesh.tangents, 4, new_index, kept_vertices);
  for (std::vector<float>& uv : mesh.uv_sets) Compact(uv, 2, new_index, kept_vertices);
  Compact(mesh.colors, 4, new_index, kept_vertices);
  Compact(mesh.joints, 4, new_index, kept_vertices);
  Compact(mesh.weights, 4, new_index, kept_vertices);
  for (MorphTarget& t : mesh.morph_targets) {
    Compact(t.positions, 3, new_index, kept_vertices);
    Compact(t.normals, 3, new_index, kept_vertices);
  }
  return report;
}

std::string DescribeRepairs(const RepairReport& report) {
  std::vector<std::string> parts;
  auto add = [&parts](size_t count, const char* verb, const char* singular, const char* plural) {
    if (count == 0) return;
    parts.push_back(std::string(verb) + " " + std::to_string(count) + " " +
                    (count == 1 ? singular : plural));
  };
  add(report.welded_vertices, "welded", "duplicate vertex", "duplicate vertices");
  add(report.degenerate_triangles_removed, "removed", "degenerate triangle",
      "degenerate triangles");
  add(report.zero_area_triangles_removed, "removed", "zero-area triangle", "zero-area triangles");
  add(report.duplicate_triangles_removed, "removed", "duplicate triangle", "duplicate triangles");
  add(report.opposite_triangles_removed, "removed", "opposite-winding copy",
      "opposite-winding copies");
  add(report.opposite_triangle_pairs -
          std::min(report.opposite_triangle_pairs, report.opposite_triangles_removed),
      "kept", "two-sided face", "two-sided faces");
  add(report.unused_vertices_removed, "removed", "unused vertex", "unused vertices");
  if (parts.empty()) return "no repairs needed";
  std::string line = parts[0];
  for (size_t i = 1; i < parts.size(); ++i) line += ", " + parts[i];
  return line;
}

}  // namespace hullpack
