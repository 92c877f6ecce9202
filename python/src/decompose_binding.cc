// hullpack.decompose: vhacd::Decompose on numpy arrays.
#include <pybind11/stl.h>

#include <optional>

#include "pipeline/collision.h"
#include "py_util.h"
#include "vhacd/vhacd.h"

namespace hullpack::python {
namespace {

class WatchObserver : public vhacd::Observer {
 public:
  explicit WatchObserver(Watch& watch) : watch_(watch) {}
  void OnProgress(double overall, double, double, const char* stage, const char*) override {
    watch_.Report(overall, stage);
  }
  bool IsCancelled() override { return watch_.cancelled(); }

 private:
  Watch& watch_;
};

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

[[noreturn]] void Raise(const vhacd::Result& r) {
  const std::string what = std::string("decompose: ") + vhacd::StatusName(r.status) +
                           (r.message.empty() ? "" : ": " + r.message);
  switch (r.status) {
    case vhacd::Status::kInvalidParameter:
    case vhacd::Status::kEmptyMesh:
    case vhacd::Status::kInvalidMesh:
    case vhacd::Status::kIndexOutOfRange:
      throw py::value_error(what);
    case vhacd::Status::kCancelled:
      ThrowCancelled(what);
    case vhacd::Status::kOutOfMemory:
      throw std::bad_alloc();
    default:
      throw std::runtime_error(what);
  }
}

template <typename T>
void Set(const std::optional<T>& value, T* field) {
  if (value) *field = *value;
}

py::tuple Decompose(py::handle vertices, py::handle faces, const std::string& method,
                    const std::string& preset, std::optional<uint32_t> resolution,
                    std::optional<uint32_t> depth, std::optional<double> concavity,
                    std::optional<uint32_t> plane_downsampling,
                    std::optional<uint32_t> convexhull_downsampling, std::optional<double> alpha,
                    std::optional<double> beta, std::optional<double> gamma,
                    std::optional<bool> pca, std::optional<std::string> mode,
                    std::optional<uint32_t> max_vertices_per_hull,
                    std::optional<double> min_volume_per_hull,
                    std::optional<uint32_t> max_convex_hulls, std::optional<double> max_distance,
                    std::optional<uint32_t> num_threads, bool compute_report, py::object progress) {
  if (method != "vhacd") {
    throw py::value_error("method must be 'vhacd' (the only decomposition in this build), not '" +
                          method + "'");
  }
  vhacd::Parameters p;
  if (preset == "default") {
    p = vhacd::Parameters::Default();
  } else if (preset == "high") {
    p = vhacd::Parameters::High();
  } else if (preset == "pack") {
    p = PackCollisionParameters();
  } else {
    throw py::value_error("preset must be 'default', 'high' or 'pack', not '" + preset + "'");
  }
  Set(resolution, &p.resolution);
  Set(depth, &p.depth);
  Set(concavity, &p.concavity);
  Set(plane_downsampling, &p.plane_downsampling);
  Set(convexhull_downsampling, &p.convexhull_downsampling);
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
  Set(max_vertices_per_hull, &p.max_vertices_per_hull);
  Set(min_volume_per_hull, &p.min_volume_per_hull);
  Set(max_convex_hulls, &p.max_convex_hulls);
  Set(max_distance, &p.max_distance);
  Set(num_threads, &p.num_threads);
  p.compute_report = compute_report;
  std::string why;
  if (vhacd::ValidateParameters(p, &why) != vhacd::Status::kOk)
    throw py::value_error("decompose: invalid parameter: " + why);

  const PointsIn points = ReadPoints(vertices, "vertices", 3, false);
  const IndicesIn triangles = ReadIndices(faces, "faces", points.count);
  vhacd::MeshView view =
      points.f
          ? vhacd::MeshView::FromFloat(points.f, points.count, triangles.data, triangles.count)
          : vhacd::MeshView::FromDouble(points.d, points.count, triangles.data, triangles.count);
  view.point_stride = points.stride;

  Watch watch(std::move(progress));
  WatchObserver observer(watch);
  vhacd::Result result;
  watch.Run([&] { result = vhacd::Decompose(view, p, &observer); });
  if (!result.ok()) Raise(result);

  py::list hulls;
  for (vhacd::ConvexHull& h : result.hulls) {
    const size_t nv = h.vertex_count(), nt = h.triangle_count();
    hulls.append(py::make_tuple(OwnedArray(std::move(h.points), nv, 3),
                                OwnedArray(std::move(h.triangles), nt, 3)));
  }
  return py::make_tuple(hulls, ReportDict(result.report));
}

const char kDoc[] = R"(Decompose a triangle mesh into convex hulls (V-HACD 2.0).

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
    "vhacd": voxel (or tetrahedron) sets, recursive clipping, merge.
preset : str
    Starting parameters before the keywords below are applied: "default" (V-HACD 2.0's
    defaults), "high" (finer voxels, lower thresholds, 128 vertices per hull, about 3x
    slower) or "pack" (what `hullpack pack` uses: merges driven by the stick-out bound, 24
    vertices per hull).
resolution : int, optional
    Number of voxels of the grid, 10000 to 64000000 (default 100000).
depth : int, optional
    Maximum clipping depth, 1 to 32 (default 20).
concavity : float, optional
    A part is cut while its concavity (hull volume minus its volume, over the volume of the
    whole shape's hull) exceeds this, 0 to 1 (default 0.0025).
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
max_vertices_per_hull : int, optional
    Vertex cap of each hull, 4 to 1024 (default 64).
min_volume_per_hull : float, optional
    Hull simplification stops adding points below this volume gain, 0 to 0.01 (default
    0.0001).
max_convex_hulls : int, optional
    Hull budget: hulls are merged until at most this many remain; 0 = no budget.
max_distance : float, optional
    Largest distance a hull may stick out of the mesh, as a fraction of the bounding-box
    diagonal, 0 to 1 (default 0.03; 0 = pure V-HACD 2.0).
num_threads : int, optional
    Worker threads, 0 = every core (default). The result does not depend on it.
compute_report : bool
    Measure the error report (IoU, Hausdorff distances; costs time). Default True.
progress : callable, optional
    Called as progress(percent, stage) from the calling thread about every 20 ms while the
    work runs; return False to stop (raises hullpack.Cancelled). An exception it raises
    stops the run and is re-raised.

Returns
-------
(hulls, report)
    hulls: list of (vertices float64 (k, 3), faces uint32 (t, 3)) closed convex meshes with
    outward-facing triangles, in the input's coordinates. report: dict with "hulls" (per hull
    vertex_count, volume, concavity), "volume_iou", "solid_coverage",
    "hausdorff_mesh_to_hulls", "hausdorff_hulls_to_mesh", "concavity" (fractions of the
    bounding-box diagonal; -1 = not measured), voxel counts and "seconds" per stage.

Raises
------
ValueError
    A wrong shape or dtype, a non-finite coordinate, an index out of range, an empty mesh or
    a parameter out of its range; the message names it.
hullpack.Cancelled
    The progress callback returned False.
KeyboardInterrupt
    Ctrl-C: the run stops within about 20 ms of work.

The GIL is released while the decomposition runs.)";

}  // namespace

void BindDecompose(py::module_& m) {
  m.def("decompose", &Decompose, kDoc, py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("method") = "vhacd", py::arg("preset") = "default",
        py::arg("resolution") = py::none(), py::arg("depth") = py::none(),
        py::arg("concavity") = py::none(), py::arg("plane_downsampling") = py::none(),
        py::arg("convexhull_downsampling") = py::none(), py::arg("alpha") = py::none(),
        py::arg("beta") = py::none(), py::arg("gamma") = py::none(), py::arg("pca") = py::none(),
        py::arg("mode") = py::none(), py::arg("max_vertices_per_hull") = py::none(),
        py::arg("min_volume_per_hull") = py::none(), py::arg("max_convex_hulls") = py::none(),
        py::arg("max_distance") = py::none(), py::arg("num_threads") = py::none(),
        py::arg("compute_report") = true, py::arg("progress") = py::none());
}

}  // namespace hullpack::python
