// First-hit ray casting against a triangle soup through a bounding-volume hierarchy (HACD's extra
// distance points for bowl-like shapes).
#ifndef VHACD_SRC_HACD_RAYCAST_H_
#define VHACD_SRC_HACD_RAYCAST_H_

#include <array>
#include <cstdint>
#include <vector>

#include "convex_hull.h"

namespace vhacd {
namespace internal {

class RayCaster {
 public:
  // `points` and `triangles` must outlive the caster.
  RayCaster(const std::vector<Vec3>& points, const std::vector<std::array<uint32_t, 3>>& triangles);

  // Nearest triangle hit by origin + t * dir with t > min_t, ignoring triangle `skip`. Returns
  // false when nothing is hit; otherwise fills *triangle and *t.
  bool Cast(const Vec3& origin, const Vec3& dir, double min_t, uint32_t skip, uint32_t* triangle,
            double* t) const;

  // Whether p is inside the surface: along at least two of three fixed, slightly skewed rays the
  // crossings leaving the surface (along its normals) outnumber or undercut those entering it, i.e.
  // the winding number is not zero (exact for consistently oriented closed surfaces, also where
  // closed pieces overlap; a vote for open ones).
  bool Inside(const Vec3& p) const;

 private:
  struct Node {
    Vec3 lo, hi;
    uint32_t first = 0, count = 0;  // leaf: order_[first, first + count)
    uint32_t left = 0, right = 0;
  };
  // Möller-Trumbore: *t is the ray parameter of the hit; false when the ray misses the triangle.
  bool HitTriangle(uint32_t tri, const Vec3& origin, const Vec3& dir, double* t) const;
  // Crossings of origin + t * dir (t > 0) leaving the surface minus those entering it.
  int CountHits(const Vec3& origin, const Vec3& dir) const;
  uint32_t Build(uint32_t first, uint32_t count, const std::vector<Vec3>& centroids);
  const std::vector<Vec3>& points_;
  const std::vector<std::array<uint32_t, 3>>& triangles_;
  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_HACD_RAYCAST_H_
