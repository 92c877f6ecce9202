// Private timing hooks for python/bench/binding_overhead.py: the same library calls as the
// public functions, timed in C++ on the same arrays, so the script can compare the Python call
// (conversion, threads, result arrays) with the bare C++ call in one process.
#include <time.h>

#include <functional>

#include "o3dgc/o3dgc.h"
#include "py_util.h"
#include "vhacd/vhacd.h"

namespace hullpack::python {
namespace {

// Process CPU time (every thread): steadier than wall time on a shared machine.
double Seconds(const std::function<void()>& f) {
  timespec start, end;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &start);
  f();
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &end);
  return double(end.tv_sec - start.tv_sec) + 1e-9 * double(end.tv_nsec - start.tv_nsec);
}

// A C++ caller that wants progress and cancellation passes an observer too.
class PollingObserver : public vhacd::Observer {
 public:
  void OnProgress(double overall, double, double, const char*, const char*) override {
    last_ = overall;
  }
  bool IsCancelled() override { return false; }

 private:
  double last_ = 0;
};

double DecomposeSeconds(py::handle vertices, py::handle faces, uint32_t resolution,
                        uint32_t num_threads, bool observer) {
  const PointsIn points = ReadPoints(vertices, "vertices", 3, false);
  const IndicesIn triangles = ReadIndices(faces, "faces", points.count);
  vhacd::MeshView view =
      points.f
          ? vhacd::MeshView::FromFloat(points.f, points.count, triangles.data, triangles.count)
          : vhacd::MeshView::FromDouble(points.d, points.count, triangles.data, triangles.count);
  view.point_stride = points.stride;
  vhacd::Parameters p;
  p.resolution = resolution;
  p.num_threads = num_threads;
  py::gil_scoped_release release;
  PollingObserver polling;
  return Seconds([&] { vhacd::Decompose(view, p, observer ? &polling : nullptr); });
}

py::tuple CodecSeconds(py::handle vertices, py::handle faces) {
  const PointsIn points = ReadPoints(vertices, "vertices", 3, true);
  const IndicesIn triangles = ReadIndices(faces, "faces", points.count);
  o3dgc::MeshView mesh;
  mesh.positions = points.f;
  mesh.position_stride = points.stride * sizeof(float);
  mesh.num_vertices = points.count;
  mesh.indices = triangles.data;
  mesh.num_triangles = triangles.count;
  double encode = 0, decode = 0;
  {
    py::gil_scoped_release release;
    std::vector<uint8_t> stream;
    encode = Seconds([&] { o3dgc::Encode(mesh, o3dgc::EncodeParams(), &stream); });
    o3dgc::DecodedMesh out;
    decode =
        Seconds([&] { o3dgc::Decode(stream.data(), stream.size(), o3dgc::DecodeOptions(), &out); });
  }
  return py::make_tuple(encode, decode);
}

}  // namespace

void BindBench(py::module_& m) {
  m.def("_decompose_seconds", &DecomposeSeconds, py::arg("vertices"), py::arg("faces"),
        py::arg("resolution"), py::arg("num_threads"), py::arg("observer"));
  m.def("_codec_seconds", &CodecSeconds, py::arg("vertices"), py::arg("faces"));
}

}  // namespace hullpack::python
