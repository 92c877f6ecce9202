#include "degenerate_triangles.h"

#include <cstring>

namespace o3dgc {
namespace {

constexpr uint32_t kDropped = 0xFFFFFFFFu;

const char* Row(const void* data, size_t stride, size_t row_bytes, uint32_t v) {
  return static_cast<const char*>(data) + size_t(v) * (stride ? stride : row_bytes);
}

// The rows of the vertices kept, densely.
template <typename T>
std::vector<T> KeptRows(const T* data, size_t stride, uint32_t dim,
                        const std::vector<uint32_t>& kept) {
  std::vector<T> out(kept.size() * dim);
  for (size_t i = 0; i < kept.size(); ++i)
    std::memcpy(&out[i * dim], Row(data, stride, dim * sizeof(T), kept[i]), dim * sizeof(T));
  return out;
}

// Points each attribute view at a dense copy of the kept vertices' rows, kept in `*store`. Bad
// attribute descriptions are left for the encoder to reject.
template <typename View, typename T>
void KeepAttributeRows(const std::vector<uint32_t>& kept, std::vector<View>* views,
                       std::vector<std::vector<T>>* store) {
  store->resize(views->size());
  for (size_t a = 0; a < views->size(); ++a) {
    View& view = (*views)[a];
    if (!view.data || view.dimension < 1 || view.dimension > 4) continue;
    (*store)[a] = KeptRows(view.data, view.stride, view.dimension, kept);
    view.data = (*store)[a].data();
    view.stride = 0;
  }
}

}  // namespace

bool LeaveOutDegenerateTriangles(const MeshView& mesh, KeptMesh* out) {
  const size_t nt = mesh.num_triangles, nv = mesh.num_vertices;
  auto same = [&](uint32_t a, uint32_t b) {
    float p[3], q[3];
    std::memcpy(p, Row(mesh.positions, mesh.position_stride, sizeof(p), a), sizeof(p));
    std::memcpy(q, Row(mesh.positions, mesh.position_stride, sizeof(q), b), sizeof(q));
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  };
  auto degenerate = [&](size_t t) {
    const uint32_t* c = &mesh.indices[3 * t];
    return same(c[0], c[1]) || same(c[1], c[2]) || same(c[0], c[2]);
  };
  size_t first = 0;
  while (first < nt && !degenerate(first)) ++first;
  if (first == nt) return false;

  // 0: unreferenced in the input, 1: used by left-out triangles only, 2: used by a kept one.
  std::vector<uint8_t> use(nv, 0);
  out->indices.clear();
  out->groups.clear();
  for (size_t t = 0; t < nt; ++t) {
    const uint32_t* c = &mesh.indices[3 * t];
    const bool keep = t < first || (t > first && !degenerate(t));
    for (int k = 0; k < 3; ++k) use[c[k]] = keep ? 2 : (use[c[k]] == 0 ? 1 : use[c[k]]);
    if (!keep) continue;
    out->indices.insert(out->indices.end(), c, c + 3);
    if (mesh.triangle_groups) out->groups.push_back(mesh.triangle_groups[t]);
  }
  MeshView& view = out->view;
  view = mesh;
  view.num_triangles = out->indices.size() / 3;
  if (view.num_triangles > 0) {
    view.indices = out->indices.data();
    if (mesh.triangle_groups) view.triangle_groups = out->groups.data();
  }

  std::vector<uint32_t> kept;  // input vertex of each vertex kept
  for (uint32_t v = 0; v < nv; ++v) {
    if (use[v] != 1) kept.push_back(v);
  }
  if (kept.size() == nv) return true;
  std::vector<uint32_t> new_of_old(nv, kDropped);
  for (uint32_t i = 0; i < kept.size(); ++i) new_of_old[kept[i]] = i;
  for (uint32_t& i : out->indices) i = new_of_old[i];
  view.num_vertices = kept.size();
  out->positions = KeptRows(mesh.positions, mesh.position_stride, 3, kept);
  view.positions = out->positions.data();
  view.position_stride = 0;
  if (mesh.normals) {
    out->normals = KeptRows(mesh.normals, mesh.normal_stride, 3, kept);
    view.normals = out->normals.data();
    view.normal_stride = 0;
  }
  KeepAttributeRows(kept, &view.float_attributes, &out->floats);
  KeepAttributeRows(kept, &view.int_attributes, &out->ints);
  return true;
}

}  // namespace o3dgc
