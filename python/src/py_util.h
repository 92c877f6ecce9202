// What every binding shares: numpy arrays in and out, the exceptions, and running C++ work with
// the GIL released while Ctrl-C and the progress callback stay live.
#ifndef HULLPACK_PYTHON_SRC_PY_UTIL_H_
#define HULLPACK_PYTHON_SRC_PY_UTIL_H_

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hullpack::python {

namespace py = pybind11;

// hullpack.Cancelled: the progress callback returned False.
PyObject* CancelledError();
void RegisterExceptions(py::module_& m);
[[noreturn]] void ThrowCancelled(const std::string& what);

// An (n, 3) array of points, read in place when it is float32 or float64 with a usable layout,
// else converted once. `keep` holds the array that the pointers point into.
struct PointsIn {
  const float* f = nullptr;
  const double* d = nullptr;
  size_t count = 0;
  size_t stride = 3;  // in elements
  py::array keep;
};
// Raises ValueError naming `what` for a wrong shape, a non-numeric dtype or a non-finite value.
// `width` is the number of columns (3 for points, 2 for UVs, ...); with `float_only`, float64
// input is converted to float32 (the codec stores floats).
PointsIn ReadPoints(py::handle obj, const char* what, size_t width, bool float_only);

// An (m, 3) array of vertex indices as uint32, read in place when it already is uint32 and
// C-contiguous, else checked and converted. Raises ValueError for a wrong shape, a non-integer
// dtype, or an index outside [0, vertex_count) (naming the first one).
struct IndicesIn {
  const uint32_t* data = nullptr;
  size_t count = 0;  // triangles
  py::array keep;
  std::vector<uint32_t> converted;
};
IndicesIn ReadIndices(py::handle obj, const char* what, size_t vertex_count);

// A numpy array that takes over `values` without a copy (freed with the array).
template <typename T>
py::array_t<T> OwnedArray(std::vector<T>&& values, size_t rows, size_t cols) {
  auto* owner = new std::vector<T>(std::move(values));
  py::capsule free_when_done(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  const auto r = static_cast<py::ssize_t>(rows), c = static_cast<py::ssize_t>(cols);
  if (cols == 0) return py::array_t<T>({r}, owner->data(), free_when_done);
  return py::array_t<T>({r, c}, owner->data(), free_when_done);
}

// Runs `work` on a worker thread while the calling thread, the GIL released, wakes every 20 ms to
// run Python's signal handlers (Ctrl-C raises KeyboardInterrupt in the main thread only, so they
// cannot be checked from the library's threads) and to pass the latest progress to `progress`.
// A pending KeyboardInterrupt, an exception raised by the callback, or the callback returning
// False sets cancelled(), which the work polls; Run then re-raises the Python exception, if any.
class Watch {
 public:
  explicit Watch(py::object progress) : progress_(std::move(progress)) {}
  // From any thread: the latest progress (percent in [0, 100]) and what runs.
  void Report(double percent, const char* stage);
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  // True when the callback returned False (as opposed to an exception being pending).
  bool cancelled_by_callback() const { return by_callback_; }
  void Run(const std::function<void()>& work);

 private:
  void Poll();  // with the GIL held

  py::object progress_;
  std::atomic<bool> cancelled_{false};
  bool by_callback_ = false;
  std::unique_ptr<py::error_already_set> error_;
  std::mutex mutex_;
  double percent_ = -1;
  std::string stage_;
  bool fresh_ = false;
};

void BindDecompose(py::module_& m);
void BindCodec(py::module_& m);
void BindFiles(py::module_& m);
void BindBench(py::module_& m);

}  // namespace hullpack::python

#endif  // HULLPACK_PYTHON_SRC_PY_UTIL_H_
