// The points of a decomposition's mesh in grid units: either owned, or mapped from the caller's
// points on every read (Parameters::points_in_place: a large clean input is then not copied; in
// double precision its points would be the decomposition's largest array). Both forms give the
// same values.
#ifndef VHACD_SRC_GRID_POINTS_H_
#define VHACD_SRC_GRID_POINTS_H_

#include <cstddef>
#include <utility>
#include <vector>

#include "working_frame.h"

namespace vhacd {
namespace internal {

// The caller's points (a MeshView's), read in double.
struct PointSource {
  const float* f = nullptr;
  const double* d = nullptr;
  size_t stride = 3;
  size_t count = 0;

  size_t size() const { return count; }
  bool empty() const { return count == 0; }
  Vec3 operator[](size_t i) const {
    const size_t at = i * stride;
    if (d != nullptr) return Vec3(d[at], d[at + 1], d[at + 2]);
    return Vec3(static_cast<double>(f[at]), static_cast<double>(f[at + 1]),
                static_cast<double>(f[at + 2]));
  }
};

// Where the grid sits in a decomposer's unit box: grid = (unit - origin) / h.
struct GridFrame {
  UnitFrame unit;
  Vec3 origin = Vec3::Zero();
  double h = 1.0;

  Vec3 FromUnit(const Vec3& unit_point) const { return (unit_point - origin) / h; }
  Vec3 ToGrid(const Vec3& input_point) const { return FromUnit(unit.Unit(input_point)); }
};

class GridPoints {
 public:
  GridPoints() = default;
  // Points already in grid units.
  explicit GridPoints(std::vector<Vec3> owned) : owned_(std::move(owned)), count_(owned_.size()) {}
  // The caller's points through `frame`, on every read (the source must outlive this).
  GridPoints(const PointSource& source, const GridFrame& frame)
      : source_(source), frame_(frame), count_(source.size()), mapped_(true) {}

  size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  // Whether the points are mapped on every read (not held).
  bool mapped() const { return mapped_; }
  Vec3 operator[](size_t i) const { return mapped_ ? frame_.ToGrid(source_[i]) : owned_[i]; }

 private:
  std::vector<Vec3> owned_;
  PointSource source_;
  GridFrame frame_;
  size_t count_ = 0;
  bool mapped_ = false;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_GRID_POINTS_H_
