#include "py_util.h"

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <thread>

namespace hullpack::python {
namespace {

PyObject* g_cancelled = nullptr;

std::string ShapeText(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

py::array AsArray(py::handle obj, const char* what) {
  if (obj.is_none()) throw py::value_error(std::string(what) + " is None");
  py::array a = py::array::ensure(obj);
  if (!a) {
    PyErr_Clear();
    throw py::value_error(std::string(what) + " must be an array-like of numbers");
  }
  return a;
}

// True when a row-major (n, width) view with element stride 1 can be read in place.
bool InPlace(const py::array& a, size_t item, size_t width) {
  if (a.shape(0) == 0) return false;
  if (a.strides(1) != static_cast<py::ssize_t>(item)) return false;
  return a.strides(0) >= static_cast<py::ssize_t>(width * item) &&
         a.strides(0) % static_cast<py::ssize_t>(item) == 0;
}

}  // namespace

PyObject* CancelledError() { return g_cancelled; }

void RegisterExceptions(py::module_& m) {
  static py::exception<std::runtime_error> cancelled(m, "Cancelled", PyExc_RuntimeError);
  cancelled.doc() = "Raised when a progress callback returns False: the run stopped early.";
  g_cancelled = cancelled.ptr();
}

void ThrowCancelled(const std::string& what) {
  PyErr_SetString(g_cancelled, what.c_str());
  throw py::error_already_set();
}

PointsIn ReadPoints(py::handle obj, const char* what, size_t width, bool float_only) {
  py::array a = AsArray(obj, what);
  if (a.ndim() != 2 || a.shape(1) != static_cast<py::ssize_t>(width)) {
    throw py::value_error(std::string(what) + " must have shape (n, " + std::to_string(width) +
                          "), not " + ShapeText(a));
  }
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::value_error(std::string(what) + " must hold numbers, not dtype " +
                          std::string(py::str(a.dtype())));
  }
  PointsIn in;
  in.count = static_cast<size_t>(a.shape(0));
  if (a.dtype().is(py::dtype::of<float>()) && InPlace(a, 4, width)) {
    in.keep = a;
  } else if (!float_only && a.dtype().is(py::dtype::of<double>()) && InPlace(a, 8, width)) {
    in.keep = a;
  } else if (float_only || a.dtype().is(py::dtype::of<float>())) {
    in.keep = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(a);
  } else {
    in.keep = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  }
  if (!in.keep) throw py::error_already_set();
  const bool is_float = in.keep.dtype().is(py::dtype::of<float>());
  const size_t item = is_float ? 4 : 8;
  in.stride = in.count ? static_cast<size_t>(in.keep.strides(0)) / item : width;
  if (is_float) {
    in.f = static_cast<const float*>(in.keep.data());
  } else {
    in.d = static_cast<const double*>(in.keep.data());
  }
  for (size_t i = 0; i < in.count; ++i) {
    for (size_t k = 0; k < width; ++k) {
      const double v = is_float ? in.f[i * in.stride + k] : in.d[i * in.stride + k];
      if (!std::isfinite(v)) {
        throw py::value_error(std::string(what) + "[" + std::to_string(i) + "] is not finite");
      }
    }
  }
  return in;
}

IndicesIn ReadIndices(py::handle obj, const char* what, size_t vertex_count) {
  py::array a = AsArray(obj, what);
  if (a.ndim() != 2 || a.shape(1) != 3) {
    throw py::value_error(std::string(what) + " must have shape (m, 3), not " + ShapeText(a));
  }
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw py::value_error(std::string(what) + " must hold integers, not dtype " +
                          std::string(py::str(a.dtype())));
  }
  IndicesIn in;
  in.count = static_cast<size_t>(a.shape(0));
  auto bad = [&](size_t i, long long v) {
    return py::value_error(std::string(what) + "[" + std::to_string(i / 3) + "] refers to vertex " +
                           std::to_string(v) + ", but there are " + std::to_string(vertex_count) +
                           " vertices");
  };
  if (a.dtype().is(py::dtype::of<uint32_t>()) && (a.flags() & py::array::c_style)) {
    in.keep = a;
    in.data = static_cast<const uint32_t*>(a.data());
    for (size_t i = 0; i < in.count * 3; ++i)
      if (in.data[i] >= vertex_count) throw bad(i, in.data[i]);
    return in;
  }
  auto wide = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  if (kind == 'u' && a.dtype().itemsize() == 8) {
    // uint64 values above 2^63 would wrap in int64: check them as unsigned.
    auto u = py::array_t<uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    const uint64_t* p = u.data();
    for (size_t i = 0; i < in.count * 3; ++i)
      if (p[i] >= vertex_count) throw bad(i, static_cast<long long>(p[i] > INT64_MAX ? -1 : p[i]));
  }
  const int64_t* p = wide.data();
  in.converted.resize(in.count * 3);
  for (size_t i = 0; i < in.count * 3; ++i) {
    if (p[i] < 0 || static_cast<uint64_t>(p[i]) >= vertex_count) throw bad(i, p[i]);
    in.converted[i] = static_cast<uint32_t>(p[i]);
  }
  in.data = in.converted.data();
  return in;
}

void Watch::Report(double percent, const char* stage) {
  std::lock_guard<std::mutex> lock(mutex_);
  percent_ = percent;
  stage_ = stage ? stage : "";
  fresh_ = true;
}

void Watch::Poll() {
  if (error_) return;
  if (PyErr_CheckSignals() != 0) {
    error_ = std::make_unique<py::error_already_set>();
    cancelled_ = true;
    return;
  }
  if (progress_.is_none()) return;
  double percent;
  std::string stage;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!fresh_) return;
    percent = percent_;
    stage = stage_;
    fresh_ = false;
  }
  try {
    py::object answer = progress_(percent, stage);
    if (answer.ptr() == Py_False) {
      by_callback_ = true;
      cancelled_ = true;
    }
  } catch (py::error_already_set& e) {
    error_ = std::make_unique<py::error_already_set>(std::move(e));
    cancelled_ = true;
  }
}

void Watch::Run(const std::function<void()>& work) {
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    std::mutex done_mutex;
    std::condition_variable done_cv;
    bool done = false;
    std::thread worker([&] {
      try {
        work();
      } catch (...) {
        failure = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(done_mutex);
      done = true;
      done_cv.notify_all();
    });
    std::unique_lock<std::mutex> lock(done_mutex);
    while (!done) {
      done_cv.wait_for(lock, std::chrono::milliseconds(20));
      if (done) break;
      lock.unlock();
      {
        py::gil_scoped_acquire acquire;
        Poll();
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  Poll();  // the last progress report, and a Ctrl-C that came during the last interval
  if (error_) {
    py::error_already_set e = *error_;
    error_.reset();
    throw e;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace hullpack::python
