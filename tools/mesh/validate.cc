#include "mesh/validate.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace hullpack {
namespace {

// An attribute must be empty or hold exactly `width` values per vertex.
template <typename T>
Status CheckSize(const std::vector<T>& values, size_t width, size_t vertex_count,
                 const std::string& name) {
  if (values.empty() || values.size() == width * vertex_count) return Status::Ok();
  std::ostringstream msg;
  msg << name << ": " << values.size() << " values for " << vertex_count << " vertices (expected "
      << width * vertex_count << " = " << width << " per vertex, or none)";
  return Status(StatusCode::kInvalidMesh, msg.str());
}

// `components` names each value of one vertex ({"x", "y", "z"}, ...); its size is the width.
Status CheckFinite(const std::vector<float>& values, const std::vector<std::string>& components,
                   const std::string& name) {
  const size_t width = components.size();
  size_t bad = 0;
  size_t first = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (std::isfinite(values[i])) continue;
    if (bad++ == 0) first = i;
  }
  if (bad == 0) return Status::Ok();
  std::ostringstream msg;
  msg << name << ": " << bad << " non-finite value" << (bad == 1 ? "" : "s") << ", first at vertex "
      << first / width << " (" << components[first % width] << " = " << values[first] << ")";
  return Status(StatusCode::kInvalidMesh, msg.str());
}

}  // namespace

Status ValidateMesh(const Mesh& mesh) {
  const std::string where =
      mesh.name.empty() ? std::string("mesh: ") : "mesh '" + mesh.name + "': ";
  auto fail = [&where](const Status& status) {
    return Status(status.code(), where + status.message());
  };

  if (mesh.positions.size() % 3 != 0) {
    return fail(Status(
        StatusCode::kInvalidMesh,
        "positions: " + std::to_string(mesh.positions.size()) + " values, not a multiple of 3"));
  }
  if (mesh.indices.size() % 3 != 0) {
    return fail(
        Status(StatusCode::kInvalidMesh, "indices: " + std::to_string(mesh.indices.size()) +
                                             " values, not a multiple of 3 (triangles only)"));
  }

  const size_t n = mesh.vertex_count();
  const Status size_checks[] = {
      CheckSize(mesh.normals, 3, n, "normals"), CheckSize(mesh.tangents, 4, n, "tangents"),
      CheckSize(mesh.colors, 4, n, "colors"),   CheckSize(mesh.joints, 4, n, "joints"),
      CheckSize(mesh.weights, 4, n, "weights"),
  };
  for (const Status& s : size_checks) {
    if (!s.ok()) return fail(s);
  }
  for (size_t set = 0; set < mesh.uv_sets.size(); ++set) {
    Status s = CheckSize(mesh.uv_sets[set], 2, n, "uv set " + std::to_string(set));
    if (!s.ok()) return fail(s);
  }
  for (size_t t = 0; t < mesh.morph_targets.size(); ++t) {
    const MorphTarget& target = mesh.morph_targets[t];
    const std::string name = "morph target " + std::to_string(t);
    Status s = target.positions.size() == 3 * n
                   ? CheckSize(target.normals, 3, n, name + " normals")
                   : Status(StatusCode::kInvalidMesh,
                            name + " positions: " + std::to_string(target.positions.size()) +
                                " values for " + std::to_string(n) + " vertices");
    if (s.ok() && target.normals.empty() != mesh.morph_targets[0].normals.empty())
      s = Status(StatusCode::kInvalidMesh, name + ": every target or none must have normals");
    if (s.ok() && !target.normals.empty() && mesh.normals.empty())
      s = Status(StatusCode::kInvalidMesh, name + " has normal offsets but the mesh no normals");
    if (s.ok()) s = CheckFinite(target.positions, {"dx", "dy", "dz"}, name + " positions");
    if (s.ok()) s = CheckFinite(target.normals, {"dx", "dy", "dz"}, name + " normals");
    if (!s.ok()) return fail(s);
  }
  if (!mesh.morph_weights.empty() && mesh.morph_weights.size() != mesh.morph_targets.size()) {
    return fail(Status(StatusCode::kInvalidMesh,
                       "morph weights: " + std::to_string(mesh.morph_weights.size()) + " for " +
                           std::to_string(mesh.morph_targets.size()) + " targets"));
  }
  if (mesh.joints.empty() != mesh.weights.empty()) {
    return fail(Status(StatusCode::kInvalidMesh,
                       mesh.joints.empty() ? "weights without joints" : "joints without weights"));
  }
  if (!mesh.material_ids.empty() && mesh.material_ids.size() != mesh.triangle_count()) {
    return fail(Status(StatusCode::kInvalidMesh,
                       "material_ids: " + std::to_string(mesh.material_ids.size()) + " ids for " +
                           std::to_string(mesh.triangle_count()) + " triangles"));
  }

  size_t bad_indices = 0;
  size_t first_bad = 0;
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] < n) continue;
    if (bad_indices++ == 0) first_bad = i;
  }
  if (bad_indices > 0) {
    std::ostringstream msg;
    msg << "indices: " << bad_indices << " out of range (vertex count " << n
        << "), first in triangle " << first_bad / 3 << " (corner " << first_bad % 3 << " = "
        << mesh.indices[first_bad] << ")";
    return fail(Status(StatusCode::kInvalidMesh, msg.str()));
  }

  Status s = CheckFinite(mesh.positions, {"x", "y", "z"}, "positions");
  if (s.ok()) s = CheckFinite(mesh.normals, {"x", "y", "z"}, "normals");
  if (s.ok()) s = CheckFinite(mesh.tangents, {"x", "y", "z", "w"}, "tangents");
  if (s.ok()) s = CheckFinite(mesh.colors, {"r", "g", "b", "a"}, "colors");
  if (s.ok()) s = CheckFinite(mesh.weights, {"w0", "w1", "w2", "w3"}, "weights");
  for (size_t set = 0; s.ok() && set < mesh.uv_sets.size(); ++set) {
    s = CheckFinite(mesh.uv_sets[set], {"u", "v"}, "uv set " + std::to_string(set));
  }
  if (!s.ok()) return fail(s);
  return Status::Ok();
}

}  // namespace hullpack
