#include "vhacd_util.h"

#include <new>
#include <stdexcept>

namespace hullpack::python {

MeshIn ReadMesh(py::handle vertices, py::handle faces) {
  MeshIn in;
  in.points = ReadPoints(vertices, "vertices", 3, false);
  in.triangles = ReadIndices(faces, "faces", in.points.count);
  const PointsIn& p = in.points;
  const IndicesIn& t = in.triangles;
  in.view = p.f ? vhacd::MeshView::FromFloat(p.f, p.count, t.data, t.count)
                : vhacd::MeshView::FromDouble(p.d, p.count, t.data, t.count);
  in.view.point_stride = p.stride;
  return in;
}

uint32_t CountArgument(const char* function, const char* name, int64_t value) {
  if (value < 0 || value > int64_t{UINT32_MAX}) {
    throw py::value_error(std::string(function) + ": invalid parameter: " + name +
                          " must be a non-negative integer below 2^32, not " +
                          std::to_string(value));
  }
  return static_cast<uint32_t>(value);
}

void RaiseStatus(const char* what, vhacd::Status status, const std::string& message) {
  const std::string text = std::string(what) + ": " + vhacd::StatusName(status) +
                           (message.empty() ? "" : ": " + message);
  switch (status) {
    case vhacd::Status::kInvalidParameter:
    case vhacd::Status::kEmptyMesh:
    case vhacd::Status::kInvalidMesh:
    case vhacd::Status::kIndexOutOfRange:
      throw py::value_error(text);
    case vhacd::Status::kCancelled:
      ThrowCancelled(text);
    case vhacd::Status::kOutOfMemory:
      throw std::bad_alloc();
    default:
      throw std::runtime_error(text);
  }
}

}  // namespace hullpack::python
