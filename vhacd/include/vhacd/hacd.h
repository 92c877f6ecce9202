// vhacd/hacd.h: HACD, hierarchical approximate convex decomposition by clustering the dual graph
// of the mesh surface (the reference blog's first decomposer).
//
// Where V-HACD fills a voxel grid, HACD clusters the *surface*: it follows open, thin and
// bowl-like shapes that a fill rule gets wrong, and needs no closed input. It uses the same
// MeshView, Result, Report, Status and Observer as vhacd::Decompose, so every tool works for both.
//
// Pipeline (see DecomposeHacd):
//   1. read and weld the mesh (as Decompose); orient each connected piece consistently (faces
//      flipped across manifold edges to agree with their neighbours, then the piece turned
//      outward by its signed volume), then invert every face when invert_input_faces is set;
//   2. when target_triangles > 0 and the mesh has more triangles, simplify it with the quadric
//      simplifier of vhacd/simplify.h;
//   3. normalize: centre on the barycentre, scale so that the bounding-box diagonal is
//      2 * scale_factor (every distance parameter below is in these units);
//   4. dual graph: one node per triangle, an edge between triangles sharing a mesh edge; when
//      connect_distance >= 0, every vertex is also joined to the nearest vertex of another
//      connected piece within connect_distance (found through a uniform grid, not all pairs);
//   5. distance points (rays) per triangle: its vertices along the vertex normals; its centre
//      along its normal (add_face_points); and the first hit of the ray from its centre along its
//      inverted normal, when the surface there faces the same way, along that surface's normal
//      (add_extra_dist_points: these rays stop a bowl's outer cluster from closing over the
//      inside);
//   6. edge collapses, cheapest first. The cost of merging two clusters is
//        concavity + compacity_weight * perimeter^2 / (4 pi area) + volume_weight * hull volume
//          + computation_weight * (distance points of the merge) / (all distance points),
//      where concavity is the longest distance from a distance point of the merged cluster,
//      along its ray, to the boundary of the merged cluster's convex hull (only rays starting
//      inside the hull count), plus the flat measure sqrt(|hull area / 2 - area|) weighted by
//      max(0, 1 - (100 * volume / (hull area / 2) / (scale_factor * flat_region_threshold))^2);
//      an edge is collapsed while its concavity is below `concavity` and more than
//      `min_clusters` clusters remain, and always when one of its clusters is smaller than
//      small_cluster_threshold % of the total area (the blog's Simplify);
//   7. one convex hull per cluster (a flat cluster is given a thickness of 1e-4 of the diagonal).
//      Extension: the hull is also extended through the solid behind its surface patch (to the
//      point halfway along the inward ray from each triangle's centre, else 3/8, 1/4 or 1/8 of
//      the way), so that the hulls of the patches around a solid meet inside it instead of
//      leaving a hollow between them. An extension is kept only when the points it adds (the
//      centroid of the extended hull and the midpoints between it and each vertex) lie inside the
//      surface (ray-parity vote) and the cluster's concavity, measured on the extended hull as in
//      step 6, does not grow: step 6 bounds the concavity of the patch's own hull, and an
//      extension bridging a concave part of the patch would otherwise reach out of the solid
//      unmeasured. Each hull is then reduced to max_vertices_per_hull vertices by largest volume
//      increment;
//   8. an error report (as Decompose's, measured on a voxel grid of the input).
// The extensions max_clusters, max_concavity and hull_count (below) change when step 6 stops.
//
// Determinism: the output is identical for any num_threads and from run to run.
#ifndef VHACD_HACD_H_
#define VHACD_HACD_H_

#include <cstdint>
#include <string>

#include "vhacd/vhacd.h"

namespace vhacd {

// The blog's parameter table: defaults and (inclusive) ranges.
struct HacdParameters {
  uint32_t target_triangles = 1000;      // decimate first to this many triangles; 0 = off [0, 2^31)
  uint32_t max_vertices_per_hull = 100;  // [4, 1024]
  double scale_factor = 1000.0;          // half the normalized diagonal [1, 1e6]
  double small_cluster_threshold =
      0.25;                            // % of the total area: smaller clusters must merge [0, 100]
  bool add_face_points = true;         // a ray from each triangle's centre
  bool add_extra_dist_points = true;   // the rays for bowl-like shapes
  bool invert_input_faces = false;     // flip every triangle before decomposing
  uint32_t min_clusters = 1;           // never fewer clusters than this [1, 100000]
  double concavity = 100.0;            // largest concavity of a merge, normalized units [0, 1e7]
  double connect_distance = 30.0;      // join pieces closer than this (normalized units); < 0 = off
                                       // [-1, 1e7]
  double volume_weight = 0.0;          // [0, 1e3]
  double compacity_weight = 0.0001;    // [0, 1e3]
  double flat_region_threshold = 1.0;  // % of scale_factor [0, 100]
  double computation_weight = 0.01;    // [0, 1e3]
  // Extensions: the targets of vhacd::Parameters, for HACD.
  // Hull budget: when > 0 and more clusters remain after the merges above, the cheapest merges go
  // on, whatever their concavity, down to this many clusters (it lowers min_clusters). A mesh
  // whose pieces are farther apart than connect_distance may keep more. [0, 100000]
  uint32_t max_clusters = 0;
  // Target error: when > 0, the concavity limit becomes max_concavity x the diagonal (`concavity`
  // is ignored) and the result is measured with the report's Hausdorff distance (Report::
  // concavity, fraction of the diagonal); while a hull is farther than that, the clustering runs
  // again with a limit 0.6 times tighter, up to 3 attempts, and the closest result is kept. The
  // report says whether it was reached (target_reached, target_note, attempts). [0, 1]
  double max_concavity = 0.0;
  // Exact hull count: when > 0, the clusters are merged (past `concavity` when needed, and small
  // clusters too) down to exactly this many, whenever the surface has that many triangles and
  // its pieces can merge; Report::target_reached / target_note say when it cannot. Takes
  // precedence over min_clusters, max_clusters and max_concavity. [0, 100000]
  uint32_t hull_count = 0;
  uint32_t num_threads = 0;    // 0 = std::thread::hardware_concurrency() [0, 256]
  bool compute_report = true;  // fill Result::report's error measures (costs time)

  static HacdParameters Default() { return HacdParameters(); }
  // The original testHACD's recommended command line `2 100 0 1 1 30 2000`.
  static HacdParameters Recommended();
};

// Returns kOk, or kInvalidParameter with the offending field named in *why (when non-null).
Status ValidateHacdParameters(const HacdParameters& params, std::string* why);

// Decomposes `mesh` into convex hulls with HACD. `observer` may be null. Report: the hull list,
// closed_input, volume_iou / solid_coverage / Hausdorff distances / concavity (as Decompose's),
// parts_before_merge = triangles clustered, seconds_simplify = decimation, seconds_clip =
// clustering, seconds_hulls = final hulls, seconds_report, seconds_total.
Result DecomposeHacd(const MeshView& mesh, const HacdParameters& params,
                     Observer* observer = nullptr);

}  // namespace vhacd

#endif  // VHACD_HACD_H_
