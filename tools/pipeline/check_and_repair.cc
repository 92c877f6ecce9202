#include "pipeline/check_and_repair.h"

#include "common/parallel.h"
#include "gltf/skin_weights.h"
#include "mesh/validate.h"

namespace hullpack {

void AddRepairs(RepairReport& total, const RepairReport& r) {
  total.welded_vertices += r.welded_vertices;
  total.degenerate_triangles_removed += r.degenerate_triangles_removed;
  total.zero_area_triangles_removed += r.zero_area_triangles_removed;
  total.duplicate_triangles_removed += r.duplicate_triangles_removed;
  total.opposite_triangle_pairs += r.opposite_triangle_pairs;
  total.opposite_triangles_removed += r.opposite_triangles_removed;
  total.unused_vertices_removed += r.unused_vertices_removed;
}

Result<CheckRepairReport> CheckAndRepair(Scene& scene, const CheckRepairOptions& options,
                                         int threads) {
  const size_t n = scene.meshes.size();
  std::vector<Status> valid(n);
  std::vector<CheckRepairReport> per_mesh(n);
  // One mesh (or few): the threads sort inside RepairMesh instead.
  RepairOptions repairs = options.repairs;
  if (n < static_cast<size_t>(threads)) repairs.threads = threads;
  ParallelFor(n, threads, [&](size_t i) {
    Mesh& mesh = scene.meshes[i];
    valid[i] = ValidateMesh(mesh);
    if (!valid[i].ok()) return;
    CheckRepairReport& r = per_mesh[i];
    if (options.normalize_skin_weights && mesh.weights.size() == mesh.vertex_count() * 4)
      r.skin_weights_normalized = NormalizeSkinWeights(mesh.weights.data(), mesh.vertex_count());
    if (options.clear_unweighted_joints && mesh.has_skin() &&
        mesh.joints.size() == mesh.weights.size()) {
      for (size_t k = 0; k < mesh.joints.size(); ++k) {
        if (mesh.weights[k] == 0 && mesh.joints[k] != 0) {
          mesh.joints[k] = 0;
          ++r.unweighted_joints_cleared;
        }
      }
    }
    r.repairs = RepairMesh(mesh, repairs);
  });
  CheckRepairReport report;
  for (size_t i = 0; i < n; ++i) {
    if (!valid[i].ok())
      return Status(valid[i].code(), "mesh " + std::to_string(i) + ": " + valid[i].message());
    report.skin_weights_normalized += per_mesh[i].skin_weights_normalized;
    report.unweighted_joints_cleared += per_mesh[i].unweighted_joints_cleared;
    AddRepairs(report.repairs, per_mesh[i].repairs);
  }
  if (report.unweighted_joints_cleared) {
    report.lines.push_back("cleared " + std::to_string(report.unweighted_joints_cleared) +
                           " joint indices that carry no weight");
  }
  if (report.skin_weights_normalized) {
    report.lines.push_back("renormalized the skin weights of " +
                           std::to_string(report.skin_weights_normalized) +
                           " vertices (their sum was not 1)");
  }
  return report;
}

}  // namespace hullpack
