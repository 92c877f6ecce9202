#include "scene/transform.h"

#include <cmath>

namespace hullpack {

Matrix4 TrsMatrix(const Trs& trs) {
  const double x = trs.rotation[0], y = trs.rotation[1], z = trs.rotation[2], w = trs.rotation[3];
  // Column-major: column c of the rotation is r[3c .. 3c+2].
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                       2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                       2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
  Matrix4 m = kIdentity;
  for (size_t c = 0; c < 3; ++c) {
    for (size_t row = 0; row < 3; ++row) m[4 * c + row] = r[3 * c + row] * trs.scale[c];
  }
  for (size_t k = 0; k < 3; ++k) m[12 + k] = trs.translation[k];
  return m;
}

bool DecomposeMatrix(const Matrix4& m, Trs* out) {
  if (m[3] != 0 || m[7] != 0 || m[11] != 0 || m[15] != 1) return false;
  double axis[3][3];
  double scale[3];
  for (size_t c = 0; c < 3; ++c) {
    scale[c] =
        std::sqrt(m[4 * c] * m[4 * c] + m[4 * c + 1] * m[4 * c + 1] + m[4 * c + 2] * m[4 * c + 2]);
    if (!(scale[c] > 0) || !std::isfinite(scale[c])) return false;
    for (size_t row = 0; row < 3; ++row) axis[c][row] = m[4 * c + row] / scale[c];
  }
  const double det = axis[0][0] * (axis[1][1] * axis[2][2] - axis[1][2] * axis[2][1]) -
                     axis[1][0] * (axis[0][1] * axis[2][2] - axis[0][2] * axis[2][1]) +
                     axis[2][0] * (axis[0][1] * axis[1][2] - axis[0][2] * axis[1][1]);
  if (det < 0) {
    scale[0] = -scale[0];
    for (double& v : axis[0]) v = -v;
  }
  // The axes must be orthonormal for the matrix to be a rotation times a scale.
  constexpr double kTolerance = 1e-5;
  for (size_t a = 0; a < 3; ++a) {
    for (size_t b = a + 1; b < 3; ++b) {
      const double dot =
          axis[a][0] * axis[b][0] + axis[a][1] * axis[b][1] + axis[a][2] * axis[b][2];
      if (std::fabs(dot) > kTolerance) return false;
    }
  }
  // Rotation matrix to quaternion (Shepperd's method: the largest diagonal term keeps it stable).
  // axis[c][row] is the rotation's element (row, c).
  const double m00 = axis[0][0], m11 = axis[1][1], m22 = axis[2][2];
  const double trace = m00 + m11 + m22;
  double q[4];
  if (trace > 0) {
    const double s = 2 * std::sqrt(trace + 1);
    q[3] = s / 4;
    q[0] = (axis[1][2] - axis[2][1]) / s;
    q[1] = (axis[2][0] - axis[0][2]) / s;
    q[2] = (axis[0][1] - axis[1][0]) / s;
  } else if (m00 > m11 && m00 > m22) {
    const double s = 2 * std::sqrt(1 + m00 - m11 - m22);
    q[3] = (axis[1][2] - axis[2][1]) / s;
    q[0] = s / 4;
    q[1] = (axis[1][0] + axis[0][1]) / s;
    q[2] = (axis[2][0] + axis[0][2]) / s;
  } else if (m11 > m22) {
    const double s = 2 * std::sqrt(1 + m11 - m00 - m22);
    q[3] = (axis[2][0] - axis[0][2]) / s;
    q[0] = (axis[1][0] + axis[0][1]) / s;
    q[1] = s / 4;
    q[2] = (axis[2][1] + axis[1][2]) / s;
  } else {
    const double s = 2 * std::sqrt(1 + m22 - m00 - m11);
    q[3] = (axis[0][1] - axis[1][0]) / s;
    q[0] = (axis[2][0] + axis[0][2]) / s;
    q[1] = (axis[2][1] + axis[1][2]) / s;
    q[2] = s / 4;
  }
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  Trs trs;
  for (size_t k = 0; k < 4; ++k) trs.rotation[k] = q[k] / norm;
  for (size_t k = 0; k < 3; ++k) {
    trs.scale[k] = scale[k];
    trs.translation[k] = m[12 + k];
  }
  *out = trs;
  return true;
}

}  // namespace hullpack
