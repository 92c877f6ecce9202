// hullpack.simplify: vhacd::Simplify (quadric-error edge collapses) on numpy arrays.
#include <pybind11/stl.h>

#include <optional>
#include <utility>

#include "py_util.h"
#include "vhacd/simplify.h"
#include "vhacd_util.h"

namespace hullpack::python {
namespace {

py::tuple Simplify(py::handle vertices, py::handle faces, std::optional<int64_t> target_triangles,
                   std::optional<double> target_error, bool lock_boundary, py::object progress) {
  vhacd::SimplifyParameters p;
  if (target_triangles)
    p.target_triangles = CountArgument("simplify", "target_triangles", *target_triangles);
  if (target_error) p.target_error = *target_error;
  p.lock_boundary = lock_boundary;
  std::string why;
  if (vhacd::ValidateSimplifyParameters(p, &why) != vhacd::Status::kOk)
    throw py::value_error("simplify: invalid parameter: " + why);

  const MeshIn mesh = ReadMesh(vertices, faces);
  Watch watch(std::move(progress));
  WatchObserver observer(watch);
  vhacd::SimplifyResult result;
  watch.Run([&] { result = vhacd::Simplify(mesh.view, p, &observer); });
  if (!result.ok()) RaiseStatus("simplify", result.status, result.message);

  const size_t nv = result.points.size() / 3, nt = result.triangle_count();
  py::dict info;
  info["point_source"] = OwnedArray(std::move(result.point_source), nv, 0);
  info["triangle_source"] = OwnedArray(std::move(result.triangle_source), nt, 0);
  info["error"] = result.error;
  return py::make_tuple(OwnedArray(std::move(result.points), nv, 3),
                        OwnedArray(std::move(result.indices), nt, 3), info);
}

const char kDoc[] = R"(Simplify a triangle mesh by quadric-error edge collapses (Garland-Heckbert).

Collapses edges cheapest first until the mesh has at most `target_triangles` triangles or the
next collapse would exceed `target_error`, whichever comes first. Open borders and attribute
seams keep their shape; no collapse flips a triangle, makes the surface non-manifold or closes
a hole. Identical positions are welded first; degenerate and duplicate triangles are dropped.
Deterministic. This is the simplifier method="hacd" of hullpack.decompose runs first.

Parameters
----------
vertices : array_like, shape (n, 3)
    Point coordinates, float32 or float64 (read in place when C-ordered rows), or any
    numbers (converted once). Every value must be finite.
faces : array_like, shape (m, 3)
    Triangles as indices into `vertices`, any integer dtype. Any soup is accepted (open,
    non-manifold, several parts).
target_triangles : int, optional
    Stop once the mesh has at most this many triangles; None or 0 = no count target, below
    2**31.
target_error : float, optional
    Stop before a collapse whose error (root mean square distance to the planes of the
    collapsed region, as a fraction of the bounding-box diagonal) would exceed this; None or
    0 = no error limit, 0 to 1. At least one of target_triangles and target_error must be
    given.
lock_boundary : bool
    Never move a boundary vertex: open borders stay exactly as they are (default False).
progress : callable, optional
    Called as progress(percent, stage) from the calling thread about every 20 ms while the
    work runs; return False to stop (raises hullpack.Cancelled). An exception it raises
    stops the run and is re-raised.

Returns
-------
(vertices, faces, info)
    vertices float64 (k, 3) and faces uint32 (t, 3): the simplified mesh, triangles wound as
    the input triangles they come from. info: dict with "point_source" (uint32 (k,): the
    input vertex each output vertex comes from; index your normals, UVs or colours with it),
    "triangle_source" (uint32 (t,): the input triangle each output triangle descends from,
    e.g. for its material) and "error" (float: the largest collapse error made, fraction of
    the bounding-box diagonal).

Raises
------
ValueError
    A wrong shape or dtype, a non-finite coordinate, an index out of range, an empty mesh, or
    a parameter out of its range or neither target given; the message names it.
hullpack.Cancelled
    The progress callback returned False.
KeyboardInterrupt
    Ctrl-C.

The GIL is released while the simplification runs.)";

}  // namespace

void BindSimplify(py::module_& m) {
  m.def("simplify", &Simplify, kDoc, py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("target_triangles") = py::none(), py::arg("target_error") = py::none(),
        py::arg("lock_boundary") = false, py::arg("progress") = py::none());
}

}  // namespace hullpack::python
