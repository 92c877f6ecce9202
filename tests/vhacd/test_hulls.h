// Convex hulls built in code for the vhacd tests of internal stages.
#ifndef HULLPACK_TESTS_VHACD_TEST_HULLS_H_
#define HULLPACK_TESTS_VHACD_TEST_HULLS_H_

#include <gtest/gtest.h>

#include <vector>

#include "convex_hull.h"

namespace vhacd {
namespace internal {

// The axis-aligned box [x0, x1] x [y0, y1] x [z0, z1] as a hull.
inline HullMesh BoxHull(double x0, double y0, double z0, double x1, double y1, double z1) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
  HullMesh h;
  EXPECT_EQ(ComputeConvexHull(pts, -1.0, &h), HullStatus::kOk);
  return h;
}

}  // namespace internal
}  // namespace vhacd

#endif  // HULLPACK_TESTS_VHACD_TEST_HULLS_H_
