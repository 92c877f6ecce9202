// The `hullpack._hullpack` extension module; python/hullpack/__init__.py re-exports it.
#include "o3dgc/o3dgc.h"
#include "py_util.h"
#include "vhacd/vhacd.h"

PYBIND11_MODULE(_hullpack, m) {
  namespace py = pybind11;
  m.doc() =
      "Convex decomposition (V-HACD 2.0), mesh compression (o3dgc) and packaging for "
      "simulators and the web.";
  m.attr("VHACD_VERSION") = VHACD_VERSION;
  m.attr("STREAM_VERSION") = o3dgc::kStreamVersion;
  hullpack::python::RegisterExceptions(m);
  hullpack::python::BindDecompose(m);
  hullpack::python::BindCodec(m);
  hullpack::python::BindFiles(m);
  hullpack::python::BindBench(m);
}
