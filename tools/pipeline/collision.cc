#include "pipeline/collision.h"

#include <algorithm>
#include <cctype>

namespace hullpack {

vhacd::Parameters PackCollisionParameters() {
  vhacd::Parameters p;
  p.max_concavity = kPackMaxConcavity;
  p.max_vertices_per_hull = 24;
  return p;
}

vhacd::HacdParameters PackHacdParameters() {
  vhacd::HacdParameters p = vhacd::HacdParameters::Recommended();
  p.max_vertices_per_hull = 24;
  return p;
}

bool NameMarksNonColliding(const std::string& name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  for (const char* mark : {"nocol", "no_col", "no-col", "nocollision", "-noimp"}) {
    if (lower.find(mark) != std::string::npos) return true;
  }
  return false;
}

std::string WhyNoHulls(const Mesh& mesh, const CollisionSettings& settings) {
  switch (settings.policy) {
    case HullPolicy::kAll:
      return "";
    case HullPolicy::kNone:
      return "--hulls none";
    case HullPolicy::kAuto:
      break;
  }
  if (!mesh.collides) return "marked non-colliding in the source";
  if (NameMarksNonColliding(mesh.name)) return "named non-colliding ('" + mesh.name + "')";
  if (mesh.has_skin() && !settings.skinned_meshes)
    return "skinned (use --hulls all to decompose its bind pose)";
  return "";
}

namespace {

Result<HullSet> ToHullSet(const Mesh& mesh, vhacd::Result r) {
  if (!r.ok()) {
    const StatusCode code =
        r.status == vhacd::Status::kCancelled ? StatusCode::kCancelled : StatusCode::kInvalidMesh;
    return Status(code, "mesh '" + mesh.name + "': decomposition: " + vhacd::StatusName(r.status) +
                            (r.message.empty() ? "" : " (" + r.message + ")"));
  }
  HullSet set;
  set.report = std::move(r.report);
  for (size_t h = 0; h < r.hulls.size(); ++h) {
    const vhacd::ConvexHull& hull = r.hulls[h];
    Mesh m;
    m.name = mesh.name + "_hull_" + std::to_string(h);
    m.positions.assign(hull.points.begin(), hull.points.end());
    m.indices = hull.triangles;
    set.hulls.push_back(std::move(m));
  }
  return set;
}

vhacd::MeshView ViewOf(const Mesh& mesh) {
  return vhacd::MeshView::FromFloat(mesh.positions.data(), mesh.vertex_count(), mesh.indices.data(),
                                    mesh.triangle_count());
}

// From this many vertices the decomposition reads the mesh's points in place: their copy in
// double precision (and the part hulls' copies) would be a large share of the run's memory, and
// beside the render-mesh encode part of the slower reads' time is hidden (docs/benchmarks.md).
constexpr size_t kPointsInPlaceFrom = size_t{1} << 20;

}  // namespace

Result<HullSet> DecomposeMesh(const Mesh& mesh, const vhacd::Parameters& parameters,
                              vhacd::Observer* observer) {
  vhacd::Parameters p = parameters;
  p.points_in_place = p.points_in_place || mesh.vertex_count() >= kPointsInPlaceFrom;
  return ToHullSet(mesh, vhacd::Decompose(ViewOf(mesh), p, observer));
}

Result<HullSet> DecomposeMesh(const Mesh& mesh, const CollisionSettings& settings,
                              vhacd::Observer* observer) {
  if (settings.method == DecompositionMethod::kHacd)
    return ToHullSet(mesh, vhacd::DecomposeHacd(ViewOf(mesh), settings.hacd_parameters, observer));
  return DecomposeMesh(mesh, settings.parameters, observer);
}

}  // namespace hullpack
