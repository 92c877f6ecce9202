#include "oriented_cuts.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace vhacd {
namespace internal {

namespace {
// A direction this close to a grid axis (cosine) is what the axis-aligned planes already try.
constexpr double kAxisAligned = 0.99;
// Two candidate directions this close (cosine) are one.
constexpr double kSameDirection = 0.99;

int DominantAxis(const Vec3& n) {
  int a = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(n[i]) > std::fabs(n[a])) a = i;
  return a;
}
}  // namespace

std::vector<CutDirection> OrientedCutDirections(const Part& part) {
  std::vector<CutDirection> out;
  if (part.voxels.size() < 2) return out;
  const Eigen::Matrix3d cov = VoxelCovariance(part);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  if (es.info() != Eigen::Success) return out;
  const Eigen::Matrix3d e = es.eigenvectors();
  std::vector<Vec3> dirs = {e.col(2), e.col(1), e.col(0)};  // largest spread first
  const double s = std::sqrt(0.5);
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      dirs.push_back(s * (e.col(2 - i) + e.col(2 - j)));
      dirs.push_back(s * (e.col(2 - i) - e.col(2 - j)));
    }
  for (Vec3 n : dirs) {
    if (!n.allFinite() || n.norm() < 0.5) continue;
    n.normalize();
    const int a = DominantAxis(n);
    if (std::fabs(n[a]) > kAxisAligned) continue;
    if (n[a] < 0) n = -n;
    bool seen = false;
    for (const CutDirection& c : out) seen = seen || std::fabs(c.n.dot(n)) > kSameDirection;
    if (seen) continue;
    CutDirection cd;
    cd.n = n;
    cd.axis = a;
    cd.lo = std::numeric_limits<double>::infinity();
    cd.hi = -cd.lo;
    for (const Voxel& v : part.voxels) {
      const double p = n.dot(Vec3(v.c[0] + 0.5, v.c[1] + 0.5, v.c[2] + 0.5));
      cd.lo = std::min(cd.lo, p);
      cd.hi = std::max(cd.hi, p);
    }
    out.push_back(cd);
  }
  return out;
}

std::vector<double> OrientedCandidateOffsets(const CutDirection& dir, double step) {
  std::vector<double> out;
  const double span = dir.hi - dir.lo;
  if (!(span > 0)) return out;
  const int n = std::max(1, static_cast<int>(span / std::max(step, 1e-9)));
  for (int k = 0; k < n; ++k) out.push_back(dir.lo + (k + 0.5) * span / n);
  return out;
}

int OrientedSplit(const CutDirection& dir, double d, int u, int v) {
  const int a = dir.axis, ua = (a + 1) % 3, va = (a + 2) % 3;
  // Left when n.centre < d, i.e. when the coordinate along the axis is below t.
  const double t = (d - dir.n[ua] * (u + 0.5) - dir.n[va] * (v + 0.5)) / dir.n[a] - 0.5;
  return static_cast<int>(std::ceil(std::clamp(t, -1.0, 65536.0)));
}

double OrientedCutCost(const Part& part, const AxisLines& lines, const CutDirection& dir, double d,
                       int hull_downsample, const CutWeights& w, const RevolutionHint& hint,
                       double part_concavity, const TetraAxis* tetra) {
  const double symmetry = w.beta * hint.weight * std::fabs(hint.axis.dot(dir.n)) * part_concavity;
  std::vector<Vec3> pts;
  if (tetra != nullptr && hull_downsample <= 1) {
    const AxisLines& interior = tetra->interior;
    std::vector<int> split(interior.line_count());
    for (size_t l = 0; l < split.size(); ++l)
      split[l] = OrientedSplit(dir, d, interior.lu[l], interior.lv[l]);
    std::vector<int> voxel_split(lines.line_count());
    for (size_t l = 0; l < voxel_split.size(); ++l)
      voxel_split[l] = OrientedSplit(dir, d, lines.lu[l], lines.lv[l]);
    double vol[2] = {0.0, 0.0}, concavity = 0.0;
    HullMesh h;
    for (int side = 0; side < 2; ++side) {
      const bool left = side == 0;
      double count = 0.0;
      SideHullPointsPerLine(interior, split, left, 1, &pts, nullptr, &count);
      vol[side] = count;
      for (const SurfaceCell& cell : part.cells) {
        if (OrientedLeft(dir, d, cell.c) != left) continue;
        vol[side] += cell.volume;
        for (int i = 0; i < cell.point_count; ++i)
          pts.emplace_back(cell.p[i][0], cell.p[i][1], cell.p[i][2]);
      }
      if (PrimitiveHull(part, pts, &h)) {
        concavity += std::max(0.0, h.Volume() - vol[side]);
      } else {
        // Flat cells (a thin sheet): that side is measured on its voxels, as in mode 0.
        double voxels = 0.0;
        SideHullPointsPerLine(lines, voxel_split, left, 1, &pts, &voxels);
        concavity += std::max(0.0, ExactHullVolume(pts) - voxels);
      }
    }
    return concavity / w.volume0 + w.alpha * std::fabs(vol[0] - vol[1]) / w.volume0 + symmetry;
  }
  std::vector<int> split(lines.line_count());
  for (size_t l = 0; l < split.size(); ++l)
    split[l] = OrientedSplit(dir, d, lines.lu[l], lines.lv[l]);
  double cvl = 0.0, cvr = 0.0, vl = 0.0, vr = 0.0;
  SideHullPointsPerLine(lines, split, true, hull_downsample, &pts, &cvl, &vl);
  const double hl = ExactHullVolume(pts);
  SideHullPointsPerLine(lines, split, false, hull_downsample, &pts, &cvr, &vr);
  const double hr = ExactHullVolume(pts);
  const double concavity = (std::max(0.0, hl - cvl) + std::max(0.0, hr - cvr)) / w.volume0;
  const double balance = w.alpha * std::fabs(vl - vr) / w.volume0;
  return concavity + balance + symmetry;
}

void ClipPolygonToCuts(const std::vector<Vec3>& poly, const std::vector<CutPlane>& cuts,
                       std::vector<Vec3>* out) {
  std::vector<Vec3> cur = poly, next;
  for (const CutPlane& cut : cuts) {
    next.clear();
    const size_t n = cur.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec3& p = cur[i];
      const Vec3& q = cur[(i + 1) % n];
      const double sp = cut.n.dot(p) - cut.d, sq = cut.n.dot(q) - cut.d;
      if (sp <= 0) next.push_back(p);
      if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) next.push_back(p + (sp / (sp - sq)) * (q - p));
    }
    cur.swap(next);
    if (cur.empty()) return;
  }
  out->insert(out->end(), cur.begin(), cur.end());
}

HullMesh ClipHullToCuts(const HullMesh& hull, const std::vector<CutPlane>& cuts) {
  // The clipped polytope's vertices: the hull's vertices inside every half-space, and where its
  // edges cross a plane (kept when inside the others).
  std::vector<Vec3> pts;
  auto inside_all = [&](const Vec3& p) {
    for (const CutPlane& c : cuts)
      if (c.n.dot(p) > c.d + 1e-9) return false;
    return true;
  };
  for (const Vec3& v : hull.vertices)
    if (inside_all(v)) pts.push_back(v);
  for (const auto& t : hull.triangles)
    for (int e = 0; e < 3; ++e) {
      const Vec3& p = hull.vertices[t[e]];
      const Vec3& q = hull.vertices[t[(e + 1) % 3]];
      for (const CutPlane& c : cuts) {
        const double sp = c.n.dot(p) - c.d, sq = c.n.dot(q) - c.d;
        if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
          const Vec3 x = p + (sp / (sp - sq)) * (q - p);
          if (inside_all(x)) pts.push_back(x);
        }
      }
    }
  HullMesh out;
  if (ComputeConvexHull(pts, -1.0, &out) != HullStatus::kOk) return HullMesh();
  return out;
}

bool HasOrientedCut(const std::vector<Part>& parts) {
  for (const Part& part : parts)
    if (!part.cuts.empty()) return true;
  return false;
}

}  // namespace internal
}  // namespace vhacd
