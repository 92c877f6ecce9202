// What the vhacd-library bindings (decompose, simplify) share: a MeshView over numpy arrays, an
// Observer that reports to a Watch, and a library Status raised as the matching Python exception.
#ifndef HULLPACK_PYTHON_SRC_VHACD_UTIL_H_
#define HULLPACK_PYTHON_SRC_VHACD_UTIL_H_

#include <cstdint>
#include <string>

#include "py_util.h"
#include "vhacd/vhacd.h"

namespace hullpack::python {

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

// The arrays `vertices` (n, 3) and `faces` (m, 3) checked and read (ValueError naming the
// problem); `view` points into `points` / `triangles`, which keep the arrays alive.
struct MeshIn {
  PointsIn points;
  IndicesIn triangles;
  vhacd::MeshView view;
};
MeshIn ReadMesh(py::handle vertices, py::handle faces);

// An integer keyword as the library's uint32_t; ValueError naming it when negative or too large
// (pybind11 itself would raise an unhelpful TypeError for a negative value of an unsigned type).
uint32_t CountArgument(const char* function, const char* name, int64_t value);

// Raises `what: <status>: <message>` as ValueError (bad input or parameter), hullpack.Cancelled,
// MemoryError or RuntimeError.
[[noreturn]] void RaiseStatus(const char* what, vhacd::Status status, const std::string& message);

}  // namespace hullpack::python

#endif  // HULLPACK_PYTHON_SRC_VHACD_UTIL_H_
