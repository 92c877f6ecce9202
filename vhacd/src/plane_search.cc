#include "plane_search.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace vhacd {
namespace internal {

RevolutionHint ComputeRevolutionHint(const Part& part) {
  RevolutionHint hint;
  if (part.voxels.size() < 2) return hint;
  const Eigen::Matrix3d cov = VoxelCovariance(part);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  if (es.info() != Eigen::Success) return hint;
  const Vec3 ev = es.eigenvalues();  // ascending
  auto rel = [](double a, double b) {
    const double m = std::max(std::fabs(a), std::fabs(b));
    return m > 0 ? std::fabs(a - b) / m : 0.0;
  };
  const double d01 = rel(ev[0], ev[1]), d12 = rel(ev[1], ev[2]);
  if (d01 < d12) {  // the two smallest are alike: the axis is the largest one's
    hint.axis = es.eigenvectors().col(2);
    hint.weight = 1.0 - d01;
  } else {
    hint.axis = es.eigenvectors().col(0);
    hint.weight = 1.0 - d12;
  }
  hint.weight = std::clamp(hint.weight, 0.0, 1.0);
  return hint;
}

double CutCost(const Part& part, const AxisLines& lines, int c, int hull_downsample,
               const CutWeights& w, const RevolutionHint& hint, double part_concavity,
               const TetraAxis* tetra) {
  const int a = lines.axis;
  const double symmetry = w.beta * hint.weight * std::fabs(hint.axis[a]) * part_concavity;
  if (tetra != nullptr && hull_downsample <= 1) {
    std::vector<Vec3> pts;
    double vol[2] = {0.0, 0.0}, concavity = 0.0;
    HullMesh h;
    for (int side = 0; side < 2; ++side) {
      TetraSideHullPoints(part, *tetra, c, side == 0, &pts, &vol[side]);
      if (PrimitiveHull(part, pts, &h)) {
        concavity += std::max(0.0, h.Volume() - vol[side]);
      } else {
        // Flat cells (a thin sheet): that side is measured on its voxels, as in mode 0.
        double voxels = 0.0;
        SideHullPoints(lines, c, side == 0, 1, &pts, &voxels);
        concavity += std::max(0.0, ExactHullVolume(pts) - voxels);
      }
    }
    return concavity / w.volume0 + w.alpha * std::fabs(vol[0] - vol[1]) / w.volume0 + symmetry;
  }
  double vl = 0.0;
  for (int s = part.bmin[a]; s < c; ++s) vl += lines.slice_count[s - part.bmin[a]];
  const double vr = static_cast<double>(part.voxels.size()) - vl;  // voxel count in both modes
  std::vector<Vec3> pts;
  double cvl = 0.0, cvr = 0.0;  // volumes of the (possibly coarse) shapes the hulls describe
  SideHullPoints(lines, c, true, hull_downsample, &pts, &cvl);
  const double hl = ExactHullVolume(pts);
  SideHullPoints(lines, c, false, hull_downsample, &pts, &cvr);
  const double hr = ExactHullVolume(pts);
  const double concavity = (std::max(0.0, hl - cvl) + std::max(0.0, hr - cvr)) / w.volume0;
  const double balance = w.alpha * std::fabs(vl - vr) / w.volume0;
  return concavity + balance + symmetry;
}

std::vector<int> CandidatePlanes(const Part& part, int axis, int step) {
  std::vector<int> out;
  const int lo = part.bmin[axis] + 1, hi = part.bmax[axis];
  if (hi < lo) return out;
  step = std::max(1, step);
  // Centre the coarse samples in the range.
  const int span = hi - lo;
  const int first = lo + (span % step) / 2;
  for (int c = first; c <= hi; c += step) out.push_back(c);
  return out;
}

}  // namespace internal
}  // namespace vhacd
