// hullpack.decompose: vhacd::Decompose (V-HACD) or vhacd::DecomposeHacd (HACD) on numpy arrays.
#include <pybind11/stl.h>

#include <functional>
#include <initializer_list>
#include <optional>
#include <utility>

#include "pipeline/collision.h"
#include "py_util.h"
#include "vhacd/hacd.h"
#include "vhacd/vhacd.h"
#include "vhacd_util.h"

namespace hullpack::python {
namespace {

py::dict ReportDict(const vhacd::Report& r) {
  py::list hulls;
  for (const vhacd::HullReport& h : r.hulls) {
    py::dict d;
    d["vertex_count"] = h.vertex_count;
    d["volume"] = h.volume;
    d["concavity"] = h.concavity;
    hulls.append(d);
  }
  py::dict d;
  d["hulls"] = hulls;
  d["closed_input"] = r.closed_input;
  d["volume_iou"] = r.volume_iou;
  d["solid_coverage"] = r.solid_coverage;
  d["hausdorff_mesh_to_hulls"] = r.hausdorff_mesh_to_hulls;
  d["hausdorff_hulls_to_mesh"] = r.hausdorff_hulls_to_mesh;
  d["concavity"] = r.concavity;
  d["voxel_count"] = r.voxel_count;
  d["surface_voxel_count"] = r.surface_voxel_count;
  d["tetrahedron_count"] = r.tetrahedron_count;
  d["parts_before_merge"] = r.parts_before_merge;
  d["target_reached"] = r.target_reached;
  d["target_note"] = r.target_note;
  d["attempts"] = r.attempts;
  py::dict s;
  s["voxelize"] = r.seconds_voxelize;
  s["fill"] = r.seconds_fill;
  s["tetrahedra"] = r.seconds_tetrahedra;
  s["distance"] = r.seconds_distance;
  s["clip"] = r.seconds_clip;
  s["hulls"] = r.seconds_hulls;
  s["merge"] = r.seconds_merge;
  s["simplify"] = r.seconds_simplify;
  s["report"] = r.seconds_report;
  s["total"] = r.seconds_total;
  d["seconds"] = s;
  return d;
}

template <typename T>
void Set(const std::optional<T>& value, T* field) {
  if (value) *field = *value;
}

void SetCount(const char* name, const std::optional<int64_t>& value, uint32_t* field) {
  if (value) *field = CountArgument("decompose", name, *value);
}

// The keywords only one method takes, with whether the caller gave them.
using Given = std::initializer_list<std::pair<const char*, bool>>;

// ValueError when a keyword of the other method was given.
void RejectOthers(const std::string& method, const char* owner, const char* owner_label,
                  Given given) {
  for (const auto& [name, set] : given) {
    if (set) {
      throw py::value_error(std::string("decompose: ") + name + " is a " + owner_label +
                            " keyword (method=\"" + owner + "\"), not one of method=\"" + method +
                            "\"");
    }
  }
}

vhacd::Parameters VhacdParameters(const std::string& preset) {
  if (preset == "default") return vhacd::Parameters::Default();
  if (preset == "high") return vhacd::Parameters::High();
  if (preset == "pack") return PackCollisionParameters();
  throw py::value_error(
      "decompose: preset must be 'default', 'high' or 'pack' with "
      "method=\"vhacd\", not '" +
      preset + "'");
}

vhacd::HacdParameters HacdParameters(const std::string& preset) {
  if (preset == "default") return vhacd::HacdParameters::Default();
  if (preset == "recommended") return vhacd::HacdParameters::Recommended();
  throw py::value_error(
      "decompose: preset must be 'default' or 'recommended' with "
      "method=\"hacd\", not '" +
      preset + "'");
}

py::tuple Decompose(py::handle vertices, py::handle faces, const std::string& method,
                    const std::string& preset,
                    // Both methods.
                    std::optional<double> concavity, std::optional<int64_t> max_vertices_per_hull,
                    std::optional<int64_t> num_threads, bool compute_report,
                    // V-HACD only.
                    std::optional<int64_t> resolution, std::optional<int64_t> depth,
                    std::optional<int64_t> plane_downsampling,
                    std::optional<int64_t> convexhull_downsampling, std::optional<double> alpha,
                    std::optional<double> beta, std::optional<double> gamma,
                    std::optional<bool> pca, std::optional<std::string> mode,
                    std::optional<double> min_volume_per_hull,
                    std::optional<int64_t> max_convex_hulls, std::optional<double> max_distance,
                    std::optional<double> max_concavity, std::optional<int64_t> hulls,
                    std::optional<double> min_opening, std::optional<bool> points_in_place,
                    // HACD only.
                    std::optional<int64_t> target_triangles, std::optional<double> scale_factor,
                    std::optional<double> small_cluster_threshold,
                    std::optional<bool> add_face_points, std::optional<bool> add_extra_dist_points,
                    std::optional<bool> invert_input_faces, std::optional<int64_t> min_clusters,
                    std::optional<double> connect_distance, std::optional<double> volume_weight,
                    std::optional<double> compacity_weight,
                    std::optional<double> flat_region_threshold,
                    std::optional<double> computation_weight, py::object progress) {
  const Given vhacd_only = {{"resolution", resolution.has_value()},
                            {"depth", depth.has_value()},
                            {"plane_downsampling", plane_downsampling.has_value()},
                            {"convexhull_downsampling", convexhull_downsampling.has_value()},
                            {"alpha", alpha.has_value()},
                            {"beta", beta.has_value()},
                            {"gamma", gamma.has_value()},
                            {"pca", pca.has_value()},
                            {"mode", mode.has_value()},
                            {"min_volume_per_hull", min_volume_per_hull.has_value()},
                            {"max_distance", max_distance.has_value()},
                            {"min_opening", min_opening.has_value()},
                            {"points_in_place", points_in_place.has_value()}};
  const Given hacd_only = {{"target_triangles", target_triangles.has_value()},
                           {"scale_factor", scale_factor.has_value()},
                           {"small_cluster_threshold", small_cluster_threshold.has_value()},
                           {"add_face_points", add_face_points.has_value()},
                           {"add_extra_dist_points", add_extra_dist_points.has_value()},
                           {"invert_input_faces", invert_input_faces.has_value()},
                           {"min_clusters", min_clusters.has_value()},
                           {"connect_distance", connect_distance.has_value()},
                           {"volume_weight", volume_weight.has_value()},
                           {"compacity_weight", compacity_weight.has_value()},
                           {"flat_region_threshold", flat_region_threshold.has_value()},
                           {"computation_weight", computation_weight.has_value()}};
  std::function<vhacd::Result(const vhacd::MeshView&, vhacd::Observer*)> run;
  std::string why;
  if (method == "vhacd") {
    RejectOthers(method, "hacd", "HACD", hacd_only);
    vhacd::Parameters p = VhacdParameters(preset);
    SetCount("resolution", resolution, &p.resolution);
    SetCount("depth", depth, &p.depth);
    Set(concavity, &p.concavity);
    SetCount("plane_downsampling", plane_downsampling, &p.plane_downsampling);
    SetCount("convexhull_downsampling", convexhull_downsampling, &p.convexhull_downsampling);
    Set(alpha, &p.alpha);
    Set(beta, &p.beta);
    Set(gamma, &p.gamma);
    Set(pca, &p.pca);
    if (mode) {
      if (*mode == "voxel") {
        p.mode = vhacd::Mode::kVoxel;
      } else if (*mode == "tetrahedron") {
        p.mode = vhacd::Mode::kTetrahedron;
      } else {
        throw py::value_error("mode must be 'voxel' or 'tetrahedron', not '" + *mode + "'");
      }
    }
    SetCount("max_vertices_per_hull", max_vertices_per_hull, &p.max_vertices_per_hull);
    Set(min_volume_per_hull, &p.min_volume_per_hull);
    SetCount("max_convex_hulls", max_convex_hulls, &p.max_convex_hulls);
    Set(max_distance, &p.max_distance);
    Set(max_concavity, &p.max_concavity);
    SetCount("hulls", hulls, &p.hull_count);
    if (p.hull_count > 100000) throw py::value_error("decompose: hulls must be in [0, 100000]");
    Set(min_opening, &p.min_opening);
    Set(points_in_place, &p.points_in_place);
    SetCount("num_threads", num_threads, &p.num_threads);
    p.compute_report = compute_report;
    if (vhacd::ValidateParameters(p, &why) != vhacd::Status::kOk)
      throw py::value_error("decompose: invalid parameter: " + why);
    run = [p](const vhacd::MeshView& view, vhacd::Observer* observer) {
      return vhacd::Decompose(view, p, observer);
    };
  } else if (method == "hacd") {
    RejectOthers(method, "vhacd", "V-HACD", vhacd_only);
    vhacd::HacdParameters p = HacdParameters(preset);
    SetCount("target_triangles", target_triangles, &p.target_triangles);
    SetCount("max_vertices_per_hull", max_vertices_per_hull, &p.max_vertices_per_hull);
    Set(scale_factor, &p.scale_factor);
    Set(small_cluster_threshold, &p.small_cluster_threshold);
    Set(add_face_points, &p.add_face_points);
    Set(add_extra_dist_points, &p.add_extra_dist_points);
    Set(invert_input_faces, &p.invert_input_faces);
    SetCount("min_clusters", min_clusters, &p.min_clusters);
    Set(concavity, &p.concavity);
    Set(connect_distance, &p.connect_distance);
    Set(volume_weight, &p.volume_weight);
    Set(compacity_weight, &p.compacity_weight);
    Set(flat_region_threshold, &p.flat_region_threshold);
    Set(computation_weight, &p.computation_weight);
    SetCount("max_convex_hulls", max_convex_hulls, &p.max_clusters);
    Set(max_concavity, &p.max_concavity);
    SetCount("hulls", hulls, &p.hull_count);
    if (p.hull_count > 100000) throw py::value_error("decompose: hulls must be in [0, 100000]");
    SetCount("num_threads", num_threads, &p.num_threads);
    p.compute_report = compute_report;
    if (vhacd::ValidateHacdParameters(p, &why) != vhacd::Status::kOk)
      throw py::value_error("decompose: invalid parameter: " + why);
    run = [p](const vhacd::MeshView& view, vhacd::Observer* observer) {
      return vhacd::DecomposeHacd(view, p, observer);
    };
  } else {
    throw py::value_error("decompose: method must be 'vhacd' or 'hacd', not '" + method + "'");
  }

  const MeshIn mesh = ReadMesh(vertices, faces);
  Watch watch(std::move(progress));
  WatchObserver observer(watch);
  vhacd::Result result;
  watch.Run([&] { result = run(mesh.view, &observer); });
  if (!result.ok()) RaiseStatus("decompose", result.status, result.message);

  py::list out;
  for (vhacd::ConvexHull& h : result.hulls) {
    const size_t nv = h.vertex_count(), nt = h.triangle_count();
    out.append(py::make_tuple(OwnedArray(std::move(h.points), nv, 3),
                              OwnedArray(std::move(h.triangles), nt, 3)));
  }
  return py::make_tuple(out, ReportDict(result.report));
}

const char kDoc[] = R"(Decompose a triangle mesh into convex hulls with V-HACD 2.0 or HACD.

Keywords under "V-HACD only" are accepted with method="vhacd" only, those under "HACD only"
with method="hacd" only; giving one to the other method raises ValueError naming the keyword
and its method. A keyword left at None takes the preset's value.

Parameters
----------
vertices : array_like, shape (n, 3)
    Point coordinates, float32 or float64 (read in place when C-ordered rows), or any
    numbers (converted once). Every value must be finite.
faces : array_like, shape (m, 3)
    Triangles as indices into `vertices`: any integer dtype; uint32 C-ordered is read in
    place. Any soup is accepted (open, several parts, unoriented); degenerate triangles are
    ignored.
method : str
    "vhacd" (default): voxel (or tetrahedron) sets, recursive clipping, merge; needs a
    closed-ish surface. "hacd": clusters the surface's dual graph after QEM simplification;
    follows open, thin and bowl-like shapes and needs no closed input.
preset : str
    Starting parameters before the keywords are applied. method="vhacd": "default" (V-HACD
    2.0's defaults), "high" (finer voxels, lower thresholds, 128 vertices per hull, about 3x
    slower) or "pack" (what `hullpack pack` uses: merges driven by the stick-out bound, 24
    vertices per hull). method="hacd": "default" (the parameter table below) or
    "recommended" (the original testHACD's recommended command line: min_clusters=2,
    target_triangles=2000).

Both methods
------------
concavity : float, optional
    V-HACD: a part is cut while its concavity (hull volume minus its volume, over the volume
    of the whole shape's hull) exceeds this, 0 to 1 (default 0.0025). HACD: largest
    concavity of a merge, a distance in normalized units (see scale_factor), 0 to 1e7
    (default 100).
max_vertices_per_hull : int, optional
    Vertex cap of each hull, 4 to 1024 (default 64 for V-HACD, 100 for HACD).
num_threads : int, optional
    Worker threads, 0 to 256, 0 = every core (default). The result does not depend on it.
max_convex_hulls : int, optional
    Hull budget: hulls are merged until at most this many remain (HACD: the cheapest merges
    go on past `concavity` down to this many clusters); 0 = no budget (default).
max_concavity : float, optional
    Target error, every hull within max_concavity times the bounding-box diagonal of the
    surface (the report's "concavity"), 0 to 1; 0 = no target (default). V-HACD: parts are
    split until they are, then merged while the merged hull stays within it; concavity, gamma
    and max_distance are then ignored and the grid is refined (up to 1000000 voxels) when the
    target spans fewer than 3 voxels. HACD: the concavity limit of a merge becomes
    max_concavity times the diagonal (concavity is ignored), tightened (x0.6, up to 3
    attempts) while the measured concavity is over it. report["target_reached"] and
    report["target_note"] say whether it was met.
hulls : int, optional
    Exactly this many hulls whenever the mesh can give them (V-HACD: parts are cut further or
    merged, least stick-out first; HACD: clusters merged, past `concavity` if needed, down to
    this many); takes precedence over max_convex_hulls and max_concavity. 0 to 100000; 0 = no
    count (default). When the mesh cannot give that many, report["target_reached"] is False
    and report["target_note"] says why.
compute_report : bool
    Measure the error report (IoU, Hausdorff distances; costs time). Default True.
progress : callable, optional
    Called as progress(percent, stage) from the calling thread about every 20 ms while the
    work runs; return False to stop (raises hullpack.Cancelled). An exception it raises
    stops the run and is re-raised.

V-HACD only
-----------
resolution : int, optional
    Number of voxels of the grid, 10000 to 64000000 (default 100000).
depth : int, optional
    Maximum clipping depth, 1 to 32 (default 20).
plane_downsampling : int, optional
    Coarse cutting-plane search step in voxels, 1 to 16 (default 4).
convexhull_downsampling : int, optional
    Hull precision during the plane search, 1 to 16 (default 4).
alpha : float, optional
    Weight of the balance term of a cut, 0 to 1 (default 0.05).
beta : float, optional
    Weight of the revolution-axis term of a cut, 0 to 1 (default 0.05).
gamma : float, optional
    Largest concavity a merge of two hulls may add, 0 to 1 (default 0.00125).
pca : bool, optional
    Align the mesh on its principal axes before voxelizing (default False).
mode : str, optional
    "voxel" (default) or "tetrahedron" (voxels split into tetrahedra trimmed to the surface:
    closer volumes, slower).
min_volume_per_hull : float, optional
    Hull simplification stops adding points below this volume gain, 0 to 0.01 (default
    0.0001).
max_distance : float, optional
    Largest distance a hull may stick out of the mesh, as a fraction of the bounding-box
    diagonal, 0 to 1 (default 0.03; 0 = pure V-HACD 2.0).
min_opening : float, optional
    Fill rule for open meshes: a cavity that a ball of this diameter (fraction of the
    diagonal) reaches from outside stays empty (pots, cups, lidless boxes); smaller openings
    (holes in scans) are filled. 0 to 1 (default 0.2); 0 = parity vote only.
points_in_place : bool, optional
    Memory for time: a clean mesh's vertices (each used, none repeated, in an order local to
    the faces) are read from the array on every use instead of copied in double precision (24
    bytes per vertex). The hulls are the same; the decomposition takes about twice as long
    (default False).

HACD only
---------
target_triangles : int, optional
    Simplify the mesh first (hullpack.simplify) to at most this many triangles; 0 = off,
    below 2**31 (default 1000).
scale_factor : float, optional
    The mesh is scaled so that half its bounding-box diagonal is this; every HACD distance
    (concavity, connect_distance) is in these units, 1 to 1e6 (default 1000).
small_cluster_threshold : float, optional
    Clusters smaller than this percentage of the total area must merge, 0 to 100 (default
    0.25).
add_face_points : bool, optional
    Add a distance ray from each triangle's centre (default True).
add_extra_dist_points : bool, optional
    Add the rays that keep a bowl's outer cluster from closing over its inside (default
    True).
invert_input_faces : bool, optional
    Flip every triangle before decomposing (default False).
min_clusters : int, optional
    Never fewer clusters (hulls) than this, 1 to 100000 (default 1).
connect_distance : float, optional
    Join separate pieces closer than this (normalized units), -1 to 1e7; below 0 = off
    (default 30).
volume_weight : float, optional
    Weight of the merged hull's volume in a merge's cost, 0 to 1000 (default 0).
compacity_weight : float, optional
    Weight of perimeter**2 / (4 pi area) in a merge's cost, 0 to 1000 (default 0.0001).
flat_region_threshold : float, optional
    Below this thickness (percent of scale_factor) a cluster counts as flat and its area
    defect adds to its concavity, 0 to 100 (default 1).
computation_weight : float, optional
    Weight of a merge's share of the distance points in its cost, 0 to 1000 (default 0.01).

Returns
-------
(hulls, report)
    hulls: list of (vertices float64 (k, 3), faces uint32 (t, 3)) closed convex meshes with
    outward-facing triangles, in the input's coordinates. report: dict with "hulls" (per hull
    vertex_count, volume, concavity), "volume_iou", "solid_coverage",
    "hausdorff_mesh_to_hulls", "hausdorff_hulls_to_mesh", "concavity" (fractions of the
    bounding-box diagonal; -1 = not measured), voxel counts, "parts_before_merge" (HACD: the
    triangles clustered), "target_reached" / "target_note" (whether max_concavity or hulls
    was met and, if not, why; True and "" without a target), "attempts" (max_concavity: the
    decompositions tried) and "seconds" per stage (HACD: "simplify" = decimation, "clip" =
    clustering).

Raises
------
ValueError
    A wrong shape or dtype, a non-finite coordinate, an index out of range, an empty mesh, a
    parameter out of its range, an unknown method or preset, or a keyword of the other
    method; the message names it.
hullpack.Cancelled
    The progress callback returned False.
KeyboardInterrupt
    Ctrl-C: the run stops within about 20 ms of work.

The GIL is released while the decomposition runs.)";

}  // namespace

void BindDecompose(py::module_& m) {
  m.def("decompose", &Decompose, kDoc, py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("method") = "vhacd", py::arg("preset") = "default",
        py::arg("concavity") = py::none(), py::arg("max_vertices_per_hull") = py::none(),
        py::arg("num_threads") = py::none(), py::arg("compute_report") = true,
        py::arg("resolution") = py::none(), py::arg("depth") = py::none(),
        py::arg("plane_downsampling") = py::none(), py::arg("convexhull_downsampling") = py::none(),
        py::arg("alpha") = py::none(), py::arg("beta") = py::none(), py::arg("gamma") = py::none(),
        py::arg("pca") = py::none(), py::arg("mode") = py::none(),
        py::arg("min_volume_per_hull") = py::none(), py::arg("max_convex_hulls") = py::none(),
        py::arg("max_distance") = py::none(), py::arg("max_concavity") = py::none(),
        py::arg("hulls") = py::none(), py::arg("min_opening") = py::none(),
        py::arg("points_in_place") = py::none(), py::arg("target_triangles") = py::none(),
        py::arg("scale_factor") = py::none(), py::arg("small_cluster_threshold") = py::none(),
        py::arg("add_face_points") = py::none(), py::arg("add_extra_dist_points") = py::none(),
        py::arg("invert_input_faces") = py::none(), py::arg("min_clusters") = py::none(),
        py::arg("connect_distance") = py::none(), py::arg("volume_weight") = py::none(),
        py::arg("compacity_weight") = py::none(), py::arg("flat_region_threshold") = py::none(),
        py::arg("computation_weight") = py::none(), py::arg("progress") = py::none());
}

}  // namespace hullpack::python
