// vhacd::Decompose: validation, normalization and the pipeline stages (see include/vhacd/vhacd.h).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <thread>

#include "clipping.h"
#include "context.h"
#include "convex_hull.h"
#include "convex_input.h"
#include "distance_field.h"
#include "error_metrics.h"
#include "hull_simplify.h"
#include "input_mesh.h"
#include "merge.h"
#include "oriented_cuts.h"
#include "part_hull.h"
#include "primitive_set.h"
#include "solid_corners.h"
#include "stick_out.h"
#include "thread_pool.h"
#include "vhacd/vhacd.h"
#include "voxel_islands.h"
#include "voxelizer.h"
#include "working_frame.h"

namespace vhacd {

const char* StatusName(Status status) {
  switch (status) {
    case Status::kOk:
      return "ok";
    case Status::kInvalidParameter:
      return "invalid parameter";
    case Status::kEmptyMesh:
      return "empty mesh";
    case Status::kInvalidMesh:
      return "invalid mesh";
    case Status::kIndexOutOfRange:
      return "index out of range";
    case Status::kUnsupported:
      return "unsupported";
    case Status::kCancelled:
      return "cancelled";
    case Status::kOutOfMemory:
      return "out of memory";
    case Status::kInternalError:
      return "internal error";
  }
  return "unknown";
}

Parameters Parameters::High() {
  Parameters p;
  p.resolution = 400000;
  p.concavity = 0.001;
  p.plane_downsampling = 2;
  p.convexhull_downsampling = 2;
  p.gamma = 0.0005;
  p.max_vertices_per_hull = 128;
  p.min_volume_per_hull = 0.00001;
  p.max_distance = 0.018;
  return p;
}

Status ValidateParameters(const Parameters& p, std::string* why) {
  auto bad = [&](const char* msg) {
    if (why != nullptr) *why = msg;
    return Status::kInvalidParameter;
  };
  auto in01 = [](double v, double hi) { return std::isfinite(v) && v >= 0.0 && v <= hi; };
  if (p.resolution < 10000 || p.resolution > 64000000)
    return bad("resolution must be in [10000, 64000000]");
  if (p.depth < 1 || p.depth > 32) return bad("depth must be in [1, 32]");
  if (!in01(p.concavity, 1.0)) return bad("concavity must be in [0, 1]");
  if (p.plane_downsampling < 1 || p.plane_downsampling > 16)
    return bad("plane_downsampling must be in [1, 16]");
  if (p.convexhull_downsampling < 1 || p.convexhull_downsampling > 16)
    return bad("convexhull_downsampling must be in [1, 16]");
  if (!in01(p.alpha, 1.0)) return bad("alpha must be in [0, 1]");
  if (!in01(p.beta, 1.0)) return bad("beta must be in [0, 1]");
  if (!in01(p.gamma, 1.0)) return bad("gamma must be in [0, 1]");
  if (p.mode != Mode::kVoxel && p.mode != Mode::kTetrahedron) return bad("mode must be 0 or 1");
  if (p.max_vertices_per_hull < 4 || p.max_vertices_per_hull > 1024)
    return bad("max_vertices_per_hull must be in [4, 1024]");
  if (!in01(p.min_volume_per_hull, 0.01)) return bad("min_volume_per_hull must be in [0, 0.01]");
  if (!in01(p.max_distance, 1.0)) return bad("max_distance must be in [0, 1]");
  if (p.max_convex_hulls > 100000) return bad("max_convex_hulls must be in [0, 100000]");
  if (!in01(p.max_concavity, 1.0)) return bad("max_concavity must be in [0, 1]");
  if (p.hull_count > 100000) return bad("hull_count must be in [0, 100000]");
  if (!in01(p.min_opening, 1.0)) return bad("min_opening must be in [0, 1]");
  if (p.oriented_cuts != OrientedCuts::kOff && p.oriented_cuts != OrientedCuts::kAuto &&
      p.oriented_cuts != OrientedCuts::kAlways)
    return bad("oriented_cuts must be off, auto or always");
  if (p.num_threads > 256) return bad("num_threads must be in [0, 256]");
  if (why != nullptr) why->clear();
  return Status::kOk;
}

namespace {

using internal::Vec3;

// max_concavity keeps another attempt's result only when it reaches D or is this much closer: the
// report's measure and an independent one differ by a few percent.
constexpr double kMinGain = 0.95;

Result Fail(Status s, std::string message) {
  Result r;
  r.status = s;
  r.message = std::move(message);
  return r;
}

// run()'s answer when a run with oriented cuts kept none (outside Status's public values).
constexpr Status kUnoriented = static_cast<Status>(-1);

// kAuto keeps the oriented result only when the report says it is better: for hull_count exactly N
// hulls, then closer; for max_concavity reaching D, then closer with no more hulls.
bool OrientedIsBetter(const Report& oriented, size_t oriented_hulls, const Report& slices,
                      size_t slice_hulls, const Parameters& params) {
  if (params.hull_count > 0) {
    const bool oriented_exact = oriented_hulls == params.hull_count;
    if (oriented_exact != (slice_hulls == params.hull_count)) return oriented_exact;
    return oriented.concavity < slices.concavity;
  }
  if (oriented.target_reached != slices.target_reached) return oriented.target_reached;
  if (!oriented.target_reached) return oriented.concavity < slices.concavity;
  // Both reach D: closer with no more hulls. Fewer hulls alone is not enough: at an equal or
  // farther report an independent measure often found them farther (igea: 15 hulls at 0.0175
  // against 16 at 0.0167, fox), which moved the corpus median up.
  return oriented_hulls <= slice_hulls && oriented.concavity < slices.concavity;
}

// The run at the requested resolution that a refined grid is compared with. Under kAuto it cuts
// by voxel slices only: the refined grid has compared both already, and this run is there for the
// voxel solid (a narrow opening), which the cut planes do not change.
Parameters CoarseComparison(const Parameters& params) {
  Parameters coarse = params;
  coarse.compute_report = true;
  if (coarse.oriented_cuts == OrientedCuts::kAuto) coarse.oriented_cuts = OrientedCuts::kOff;
  return coarse;
}

// refine_grid: max_concavity and hull_count may refine the grid (off for the comparison run at
// the requested resolution, see the end).
Result DecomposeImpl(const MeshView& view, const Parameters& params, Observer* observer,
                     bool refine_grid = true) {
  std::string why;
  Status st = ValidateParameters(params, &why);
  if (st != Status::kOk) return Fail(st, why);
  internal::Context ctx(observer, internal::ThreadCount(params.num_threads));
  internal::InputMesh input;
  internal::ReadOptions read;
  read.keep_sources = false;
  read.may_borrow = true;  // the decomposition does not depend on the point order
  read.points_in_place = params.points_in_place;
  st = internal::ReadMesh(view, &ctx, &input, &why, read);
  if (st != Status::kOk) return Fail(st, why);
  Result result;
  Report& rep = result.report;
  rep.closed_input = input.closed;
  internal::Clock clock, total;

  // Normalization. With points_in_place a clean input is read in place (input.view_points), with
  // no copy in double; otherwise its welded copy is mapped in place. Both give the same grid
  // points.
  internal::GridFrame frame;
  const bool in_place = !input.view_points.empty();
  const size_t np = input.point_count();
  std::vector<Vec3> pn = std::move(input.points);
  auto given = [&](size_t i) { return in_place ? input.view_points[i] : pn[i]; };
  if (!internal::FitUnitBox(np, given, &frame.unit))
    return Fail(Status::kInvalidMesh, "the mesh has a degenerate or overflowing bounding box");
  if (!in_place)
    for (Vec3& p : pn) p = frame.unit.Unit(p);
  // Point i in the unit box (turned onto the principal axes once frame.unit.rotate is set).
  auto unit = [&](size_t i) { return in_place ? frame.unit.Unit(input.view_points[i]) : pn[i]; };
  const Vec3 center = frame.unit.center;
  const double scale = frame.unit.scale;
  if (input.closed && params.hull_count <= 1 && np <= internal::kMaxConvexInputPoints) {
    // Tolerance in the unit box: far above the hull's rounding, far below any dent that matters.
    constexpr double kOnHull = 1e-9;
    std::vector<Vec3> few;  // the points in the unit box, when read in place
    if (in_place)
      for (size_t i = 0; i < np; ++i) few.push_back(unit(i));
    internal::HullMesh hull;
    if (internal::ConvexInputHull(in_place ? few : pn, input.triangles,
                                  params.max_vertices_per_hull, kOnHull, &hull)) {
      ConvexHull out;
      if (!internal::ToOutputHull(
              hull, [&](const Vec3& p) -> Vec3 { return center + scale * p; }, scale* scale* scale,
              &out))
        return Fail(Status::kInternalError, "a hull has a non-finite coordinate");
      rep.parts_before_merge = 1;
      rep.attempts = 1;
      HullReport h;
      h.vertex_count = static_cast<uint32_t>(hull.vertices.size());
      h.volume = out.volume;
      if (params.compute_report) {
        h.distance = 0.0;
        rep.volume_iou = rep.solid_coverage = 1.0;
        rep.hausdorff_mesh_to_hulls = rep.hausdorff_hulls_to_mesh = rep.concavity = 0.0;
      }
      rep.hulls.push_back(h);
      result.hulls.push_back(std::move(out));
      rep.seconds_total = total.Lap();
      ctx.Progress(100, "done");
      ctx.Log("the input is convex: its hull is the decomposition");
      return result;
    }
  }
  Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
  if (params.pca) {
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    Vec3 mean = Vec3::Zero();
    double area = 0.0;
    for (const auto& t : input.triangles) {
      const Vec3 p0 = unit(t[0]), p1 = unit(t[1]), p2 = unit(t[2]);
      const double a = 0.5 * (p1 - p0).cross(p2 - p0).norm();
      mean += a * (p0 + p1 + p2) / 3.0;
      area += a;
    }
    if (area > 0) {
      mean /= area;
      for (const auto& t : input.triangles) {
        const Vec3 p0 = unit(t[0]), p1 = unit(t[1]), p2 = unit(t[2]);
        const double a = 0.5 * (p1 - p0).cross(p2 - p0).norm();
        for (int k = 0; k < 3; ++k) {
          const Vec3 d = unit(t[k]) - mean;
          cov += (a / 3.0) * d * d.transpose();
        }
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
      if (es.info() == Eigen::Success) {
        Eigen::Matrix3d ev = es.eigenvectors();
        for (int c = 0; c < 3; ++c) {  // deterministic sign: largest component positive
          int arg = 0;
          for (int r = 1; r < 3; ++r)
            if (std::fabs(ev(r, c)) > std::fabs(ev(arg, c))) arg = r;
          if (ev(arg, c) < 0) ev.col(c) = -ev.col(c);
        }
        if (ev.determinant() < 0) ev.col(0) = -ev.col(0);
        rot = ev.transpose();  // rows are the principal axes
        for (Vec3& p : pn) p = rot * p;
        frame.unit.rotate = true;
        frame.unit.rotation = rot;
      }
    }
  }
  Vec3 nlo = unit(0), nhi = nlo;
  for (size_t i = 1; i < np; ++i) {
    const Vec3 p = unit(i);
    nlo = nlo.cwiseMin(p);
    nhi = nhi.cwiseMax(p);
  }
  const bool exact_count = params.hull_count > 0;
  const bool target = !exact_count && params.max_concavity > 0;
  internal::GridPlacement place = internal::ChooseGrid(nlo, nhi, params.resolution);
  bool refined = false;
  if (exact_count && refine_grid) {
    // The error N hulls can reach falls with N, but no cut or hull is finer than a voxel: give
    // each hull a share of voxels, so that the grid stops bounding the error as N grows.
    constexpr double kVoxelsPerHull = 6250.0, kMaxCountResolution = 1e6;
    const double wanted = std::min(kVoxelsPerHull * params.hull_count, kMaxCountResolution);
    if (wanted > params.resolution) {
      place = internal::ChooseGrid(nlo, nhi, static_cast<uint32_t>(wanted));
      refined = true;
    }
  }
  if (target && refine_grid) {
    // The split and merge limits are measured on the grid: let max_concavity span a few voxels.
    constexpr double kVoxelsPerTarget = 3.0, kMaxTargetResolution = 1e6;
    const double spans = params.max_concavity * (nhi - nlo).norm() / place.h;
    if (spans < kVoxelsPerTarget && params.resolution < kMaxTargetResolution) {
      const double wanted = params.resolution * std::pow(kVoxelsPerTarget / spans, 3.0);
      place = internal::ChooseGrid(nlo, nhi,
                                   static_cast<uint32_t>(std::min(wanted, kMaxTargetResolution)));
      refined = true;
    }
  }
  internal::GridMesh gmesh;
  gmesh.triangles = std::move(input.triangles);
  gmesh.vertex_samples = std::move(input.vertex_samples);
  frame.origin = place.origin;
  frame.h = place.h;
  if (in_place) {
    gmesh.points = internal::GridPoints(input.view_points, frame);
  } else {
    for (Vec3& p : pn) p = frame.FromUnit(p);  // pn holds the unit points
    gmesh.points = internal::GridPoints(std::move(pn));
  }
  // grid -> world: center + scale * rot^T * (origin + h * g)
  auto to_world = [&](const Vec3& g) -> Vec3 {
    return center + scale * (rot.transpose() * (place.origin + place.h * g));
  };
  const double diag_grid = (nhi - nlo).norm() / place.h;

  // Voxelization.
  ctx.BeginStage("Voxelization", 0, 15);
  internal::VoxelGrid grid;
  if (!internal::Voxelize(gmesh, place.dims, &ctx, &grid, &rep.seconds_fill, params.min_opening))
    return Fail(Status::kCancelled, "cancelled");
  rep.seconds_voxelize = clock.Lap() - rep.seconds_fill;
  internal::Part root;
  for (int z = 0; z < grid.dims[2]; ++z)
    for (int y = 0; y < grid.dims[1]; ++y)
      for (int x = 0; x < grid.dims[0]; ++x) {
        const uint8_t c = grid.cell[grid.Index(x, y, z)];
        if (c == internal::kCellOutside) continue;
        internal::Voxel v;
        v.c[0] = static_cast<uint16_t>(x);
        v.c[1] = static_cast<uint16_t>(y);
        v.c[2] = static_cast<uint16_t>(z);
        v.surface = c == internal::kCellSurface;
        rep.surface_voxel_count += v.surface;
        root.voxels.push_back(v);
      }
  rep.voxel_count = root.voxels.size();
  clock.Lap();
  if (params.mode == Mode::kTetrahedron) {
    // Mode 1: the surface voxels become trimmed tetrahedra (see tetrahedron_set.h).
    if (!internal::BuildSurfaceCells(gmesh, grid, &ctx, &root.cells))
      return Fail(Status::kCancelled, "cancelled");
    if (root.cells.size() != rep.surface_voxel_count)
      return Fail(Status::kInternalError, "surface cells do not match the surface voxels");
    root.tetra = true;
    // A surface voxel trimmed to nothing (the surface lies on its face) holds no solid: drop it, or
    // its face would be counted on the wrong side of a cut there.
    internal::Part kept;
    kept.tetra = true;
    size_t k = 0;
    for (const internal::Voxel& v : root.voxels) {
      if (!v.surface) {
        kept.voxels.push_back(v);
        continue;
      }
      const internal::SurfaceCell& c = root.cells[k++];
      if (c.volume > 1e-6f) {
        kept.voxels.push_back(v);
        kept.cells.push_back(c);
      }
    }
    if (!kept.voxels.empty()) root = std::move(kept);
    rep.tetrahedron_count = 5 * (root.voxels.size() - root.cells.size());
    uint64_t trimmed = 0;
    for (const internal::SurfaceCell& c : root.cells) {
      rep.tetrahedron_count += c.tetrahedra;
      trimmed += c.volume < 1.0f;
    }
    ctx.Log(std::to_string(rep.tetrahedron_count) + " tetrahedra, " + std::to_string(trimmed) +
            " of " + std::to_string(root.cells.size()) +
            " surface voxels trimmed to the surface, " +
            std::to_string(rep.surface_voxel_count - root.cells.size()) + " left empty");
  }
  rep.seconds_tetrahedra = clock.Lap();
  ctx.Log("grid " + std::to_string(grid.dims[0]) + "x" + std::to_string(grid.dims[1]) + "x" +
          std::to_string(grid.dims[2]) + ", " + std::to_string(rep.voxel_count) + " voxels (" +
          std::to_string(rep.surface_voxel_count) + " on the surface)");
  if (root.voxels.empty()) return Fail(Status::kInternalError, "voxelization produced no voxel");
  internal::DistanceField field;
  if (!field.Build(grid, &ctx)) return Fail(Status::kCancelled, "cancelled");
  // A hull surface point is at most ~half a voxel farther from the input than the deepest outside
  // voxel centre the hull contains: compare depths with that margin taken off.
  const double max_depth =
      params.max_distance > 0 ? std::max(0.25, params.max_distance * diag_grid - 0.5) : 0.0;
  rep.seconds_distance = clock.Lap();

  // Clipping, hulls, merge, simplification and report, with the split and merge limits of one
  // attempt. max_concavity: the volume criteria are off, parts are split while their hull sticks
  // out more than the limit and merged while the merged hull does not.
  struct Limits {
    double concavity, gamma, max_depth;
    double max_stick;  // grid units, exact surface (targets only; 0: off)
    // max_concavity on an open surface: split by the exact measure too (else it only ranks).
    bool split_open = false;
  };
  // The targets decide splits and merges on the exact surface (stick_out.h).
  const bool exact_measure = exact_count || target;
  const internal::TriangleIndex index(gmesh, grid.dims, 8);
  std::unique_ptr<internal::StickOutMeter> meter;
  if (exact_measure) meter.reset(new internal::StickOutMeter(gmesh, grid, input.closed, &field));
  // hull_count cuts parts finely: their hulls must reach the cuts inside surface voxels too. Only
  // on a closed surface: an open one has no side to tell inside corners by (teapot: farther).
  internal::SolidCorners corners;
  if (exact_count && input.closed && !corners.Build(gmesh, grid, meter->locator(), &ctx))
    return Fail(Status::kCancelled, "cancelled");
  rep.seconds_distance += clock.Lap();
  // Oriented cuts are compared on the exact surface, whose side is known only on a closed one (on
  // open shells they made the hulls farther). kAuto runs with and without them on these voxels.
  const bool can_orient = exact_measure && input.closed;
  const bool compare_orientations = can_orient && params.oriented_cuts == OrientedCuts::kAuto;
  bool oriented = can_orient && params.oriented_cuts == OrientedCuts::kAlways;
  const internal::SolidCorners* hull_corners = exact_count && input.closed ? &corners : nullptr;
  internal::PartHulls part_hulls(root, index, hull_corners);
  // Under a distance target, separate pieces of a closed mesh's solid start apart and keep their
  // own hulls (voxel_islands.h), unless their hulls hold more than kIslandShare of the whole's
  // (clusters: a hull each is no closer than one), there are more than kMaxIslands (a hull each
  // would outweigh the mesh, and merging them down to a budget compares every pair), or the surface
  // is open (its voxels are a shell whose pieces may be one sheet's). See vhacd/README.md.
  constexpr uint32_t kMaxIslands = 256;
  constexpr double kIslandShare = 0.6;
  std::unique_ptr<internal::VoxelIslands> islands;
  if (target && input.closed) {
    islands.reset(new internal::VoxelIslands(root, grid.dims));
    const uint32_t count = islands->count();
    std::string why;
    if (count > kMaxIslands) {
      why = "too many, decomposed as one";
    } else if (count > 1) {
      root.ComputeBounds();
      const double share = islands->HullShare(root, kIslandShare);
      if (share > kIslandShare) why = "their hulls overlap, decomposed as one";
      ctx.Log("the islands' hulls hold " + std::to_string(share) + " of the whole's");
    }
    if (count > 1)
      ctx.Log(std::to_string(count) + " separate pieces of solid (voxel islands): " +
              (why.empty() ? "decomposed apart" : why));
    if (count <= 1 || !why.empty()) islands.reset();
  }
  std::vector<internal::HullMesh> hulls;
  int clip_levels = 0;
  // A run with oriented cuts whose clipping kept none made the slices' parts: it stops there and
  // the slices' result of the same attempt is used (kUnoriented), which saves its merge and report.
  bool reuse_slices = false;
  std::vector<std::pair<Report, std::vector<internal::HullMesh>>> slice_attempts;
  const size_t kOverSplit = static_cast<size_t>(2);
  auto run = [&](const Limits& lim, Report* rep_out) -> Status {
    Report& r = *rep_out;
    clock.Lap();
    ctx.BeginStage("Clipping", 15, 60);
    internal::ClipParams cp;
    cp.depth = static_cast<int>(params.depth);
    cp.concavity = lim.concavity;
    cp.plane_downsampling = static_cast<int>(params.plane_downsampling);
    cp.convexhull_downsampling = static_cast<int>(params.convexhull_downsampling);
    cp.alpha = params.alpha;
    cp.beta = params.beta;
    cp.field = &field;
    cp.max_depth = lim.max_depth;
    cp.meter = meter.get();
    cp.index = &index;
    cp.corners = hull_corners;
    cp.part_hulls = &part_hulls;
    cp.oriented_cuts = oriented;
    cp.islands = islands.get();
    // On an open surface the side is only known per voxel: for max_concavity the exact measure
    // splits only from the second attempt on, kept when it gets closer (on scans with filled
    // holes it multiplied hulls without getting closer); hull_count merges down to N anyway.
    cp.max_stick = input.closed || exact_count || lim.split_open ? lim.max_stick : 0.0;
    internal::ClipOutput clip;
    // Only the last run on these voxels may take them.
    const bool keep_root = target || (compare_orientations && !oriented);
    const bool ok = keep_root ? internal::ClipRecursively(root, cp, &ctx, &clip)
                              : internal::ClipRecursively(std::move(root), cp, &ctx, &clip);
    if (!ok) return Status::kCancelled;
    // hull_count: N more cuts of the parts sticking out farthest (at least kOverSplit x N parts),
    // N / kCutRounds per round so that a half still sticking out is cut again. The clip's own
    // limit is fixed, so without them every N had the same worst part and the error stopped
    // falling with N; the merge down to N then has finer parts to choose from.
    if (exact_count) {
      const size_t n = params.hull_count;
      constexpr size_t kCutRounds = 8;
      const size_t want = std::max(n * kOverSplit, clip.parts.size()) + n;
      if (!internal::SplitToCount(want, cp, &ctx, &clip, std::max<size_t>(1, n / kCutRounds)))
        return Status::kCancelled;
    }
    clip_levels = clip.levels;
    if (oriented && reuse_slices && !internal::HasOrientedCut(clip.parts)) return kUnoriented;
    r.parts_before_merge = static_cast<uint32_t>(clip.parts.size());
    r.seconds_clip = clock.Lap();

    // One hull per part.
    ctx.BeginStage("Hull generation", 60, 75);
    hulls.assign(clip.parts.size(), internal::HullMesh());
    if (!internal::ParallelFor(&ctx, clip.parts.size(),
                               [&](size_t i) { hulls[i] = part_hulls.Of(clip.parts[i]); }))
      return Status::kCancelled;
    std::vector<uint32_t> hull_islands;  // the island of each hull's part
    {
      size_t kept = 0;
      for (size_t i = 0; i < hulls.size(); ++i) {
        if (hulls[i].empty()) continue;
        if (islands) hull_islands.push_back(islands->Of(clip.parts[i].voxels[0]));
        if (kept != i) hulls[kept] = std::move(hulls[i]);
        ++kept;
      }
      hulls.resize(kept);
    }
    std::vector<internal::Part>().swap(clip.parts);
    r.seconds_hulls = clock.Lap();

    // Simplify before merging (cheaper merges; the merged hulls are simplified again below).
    // Adaptive sampling: a vertex adding less than min_volume_per_hull of the whole hull's volume
    // is dropped, but never one adding more than kMaxRelativeLoss of its own hull (small hulls
    // would shrink away from their neighbours and open gaps).
    const double min_volume = params.min_volume_per_hull * clip.volume0;
    constexpr double kMaxRelativeLoss = 0.002;
    // ... and never one farther than kKeepDistance of the diagonal from the hull of the others
    // (a thin part's corner adds little volume but sticks out far, and shrinking it opens cracks
    // between neighbours).
    constexpr double kKeepDistance = 0.001;
    const double keep_distance = kKeepDistance * diag_grid;
    auto simplify = [&]() {
      return internal::ParallelFor(&ctx, hulls.size(), [&](size_t i) {
        hulls[i] = internal::SimplifyHull(
            hulls[i], params.max_vertices_per_hull,
            std::min(min_volume, kMaxRelativeLoss * hulls[i].Volume()), keep_distance);
      });
    };
    if (!simplify()) return Status::kCancelled;

    // Merge.
    ctx.BeginStage("Merging", 75, 85);
    internal::MergeParams mp;
    // hull_count merges by the merged hull's stick-out alone: merges in volume order under gamma
    // took every pair up to the split limit first, which then was the error at any N.
    mp.gamma = exact_count ? 0.0 : lim.gamma;
    mp.max_hulls = exact_count ? params.hull_count : params.max_convex_hulls;
    mp.min_hulls = exact_count ? params.hull_count : 0;
    mp.volume0 = clip.volume0;
    mp.adjacency = 1.0;
    mp.field = &field;
    mp.max_depth = lim.max_depth;
    mp.meter = meter.get();
    mp.max_stick = lim.max_stick;
    if (islands) mp.groups = &hull_islands;
    if (!internal::MergeHulls(&hulls, mp, &ctx)) return Status::kCancelled;
    r.seconds_merge = clock.Lap();

    // Simplification.
    ctx.BeginStage("Simplification", 85, 90);
    if (!simplify()) return Status::kCancelled;
    r.seconds_simplify = clock.Lap();

    // Report.
    ctx.BeginStage("Error report", 90, 100);
    if (params.compute_report || target || refined || compare_orientations) {
      internal::MetricsInput mi;
      mi.mesh = &gmesh;
      mi.grid = &grid;
      mi.hulls = &hulls;
      mi.diagonal = diag_grid;
      mi.volume0 = clip.volume0;
      mi.closed = input.closed;
      // The stick-out measure's locator serves the report too: one build per decomposition
      // instead of one per run, and one mesh-sized index less at once.
      if (meter) mi.locator = &meter->locator();
      if (!internal::ComputeErrorReport(mi, &ctx, &r)) return Status::kCancelled;
    }
    r.seconds_report = clock.Lap();
    return Status::kOk;
  };

  // One decomposition on these voxels (max_concavity: its attempts), into `hulls` and *res.
  auto decompose = [&](Report* out) -> Status {
    Report& res = *out;
    if (!target) {
      res.attempts = 1;
      // hull_count: parts split by how far their hull sticks out only (0.6 x the max_distance
      // limit, at least a voxel), which the merge down to N then trades best.
      constexpr double kExactSplit = 0.6;
      const Limits lim = exact_count && max_depth > 0
                             ? Limits{1.0, params.gamma, std::max(1.0, kExactSplit * max_depth),
                                      kExactSplit * params.max_distance * diag_grid}
                             : Limits{params.concavity, params.gamma, max_depth, 0.0};
      reuse_slices = compare_orientations;
      const Status outcome = run(lim, &res);
      if (outcome == kUnoriented) return outcome;
      if (outcome != Status::kOk) return Status::kCancelled;
      if (exact_count && hulls.size() != params.hull_count) {
        res.target_reached = false;
        res.target_note = "the voxel set could be cut into only " + std::to_string(hulls.size()) +
                          " parts (raise resolution for more)";
      }
    } else {
      // Each attempt splits with a tighter limit until the measured concavity reaches the target;
      // the first that does is kept, else the closest.
      const double d = params.max_concavity;
      constexpr int kAttempts = 3;
      constexpr double kTighten = 0.6;
      // Below one voxel no outside voxel centre may lie in a hull at all: parts then split into
      // slivers along every curved surface without getting closer to it.
      constexpr double kMinLimit = 1.0;
      // Cuts are voxel-aligned: a tighter exact limit only multiplies slivers.
      constexpr double kMinStick = 0.5;
      double limit = std::max(kMinLimit, d * diag_grid - 0.5);
      // The exact measure samples the faces half a voxel apart and the report samples them its own
      // way: split and merge a margin below D, or a mesh at D by one measure was just over by the
      // other (spot, chair: 0.0200 and 0.0222 at D = 0.02 without it).
      constexpr double kStickMargin = 0.85;
      double stick = std::max(kMinStick, kStickMargin * d * diag_grid);
      bool split_open = false;
      // On an open surface the report's measure is the more lenient (it cannot tell sides inside
      // surface voxels either): stop there only a margin below D.
      const double stop = input.closed ? d : kStickMargin * d;
      std::vector<internal::HullMesh> best_hulls;
      Report best;
      bool have = false;
      for (int attempt = 0; attempt < kAttempts; ++attempt) {
        Report r = res;
        reuse_slices = static_cast<size_t>(attempt) < slice_attempts.size();
        const Status outcome = run(Limits{1.0, 1.0, limit, stick, split_open}, &r);
        if (outcome == kUnoriented) {
          r = slice_attempts[attempt].first;
          hulls = slice_attempts[attempt].second;
        } else if (outcome != Status::kOk) {
          return Status::kCancelled;
        } else if (compare_orientations && !oriented) {
          slice_attempts.emplace_back(r, hulls);
        }
        ctx.Log("max_concavity attempt " + std::to_string(attempt + 1) + ": split limit " +
                std::to_string(limit) + " voxels, " + std::to_string(hulls.size()) +
                " hulls, concavity " + std::to_string(r.concavity));
        r.attempts = static_cast<uint32_t>(attempt + 1);
        // A tighter attempt costs hulls: keep it only when it reaches D or is clearly closer.
        if (!have || (r.concavity <= stop && best.concavity > stop) ||
            r.concavity < kMinGain * best.concavity) {
          best = r;
          best_hulls = hulls;
          have = true;
        }
        if (r.concavity <= stop) break;
        // Every hull over D lies within the filled voxel solid (a hole the fill rule closed): its
        // cover is farther than D from any surface whatever the split limits, and tighter attempts
        // only cut the filled cavity into hundreds of parts.
        bool over = false, only_in_solid = true;
        for (size_t i = 0; i < r.hulls.size() && i < hulls.size() && only_in_solid; ++i)
          if (r.hulls[i].distance > d) {
            over = true;
            only_in_solid = field.HullDepth(hulls[i]) <= 1.0;
          }
        if (over && only_in_solid) break;
        if (!input.closed && !split_open) {  // the same limits, split by the exact measure too
          split_open = true;
          continue;
        }
        if (limit <= kMinLimit) break;
        limit = std::max(kMinLimit, limit * kTighten);
        stick = std::max(kMinStick, stick * kTighten);
      }
      hulls = std::move(best_hulls);
      const uint32_t attempts = best.attempts;
      res = best;
      res.attempts = attempts;
      res.target_reached = res.concavity <= d;
      if (!res.target_reached) {
        std::string over;
        size_t n_over = 0;
        for (size_t i = 0; i < res.hulls.size(); ++i)
          if (res.hulls[i].distance > d) {
            if (n_over++ < 8) over += (over.empty() ? "" : ", ") + std::to_string(i);
          }
        std::string cause;
        if (res.hausdorff_mesh_to_hulls > d)
          cause = "parts of the surface lie outside every hull by " +
                  std::to_string(res.hausdorff_mesh_to_hulls) +
                  " (features thinner than a voxel, or vertices dropped by max_vertices_per_hull)";
        if (n_over > 0) {
          if (!cause.empty()) cause += "; ";
          size_t in_solid = 0;
          for (size_t i = 0; i < res.hulls.size(); ++i)
            if (res.hulls[i].distance > d && field.HullDepth(hulls[i]) <= 1.0) ++in_solid;
          cause += std::to_string(n_over) + " hull(s) stick out by more than max_concavity (" +
                   over + (n_over > 8 ? ", ..." : "") + "): " +
                   (in_solid == n_over
                        ? "they lie within the filled voxel solid, which is farther than "
                          "max_concavity from the surface there (a hole or an open side closed by "
                          "the fill rule, see min_opening)"
                    : clip_levels >= static_cast<int>(params.depth)
                        ? "the clipping depth limit was reached"
                        : "a voxel-aligned cut could not separate them at this resolution");
        }
        res.target_note = "max_concavity " + std::to_string(d) + " not reached (" +
                          std::to_string(res.concavity) + "): " + cause;
      }
    }
    return Status::kOk;
  };

  Report slice_rep = rep;
  if (decompose(&slice_rep) != Status::kOk) return Fail(Status::kCancelled, "cancelled");
  if (compare_orientations) {
    std::vector<internal::HullMesh> slice_hulls = std::move(hulls);
    oriented = true;
    Report oriented_rep = rep;
    const Status outcome = decompose(&oriented_rep);
    if (outcome != Status::kOk && outcome != kUnoriented)
      return Fail(Status::kCancelled, "cancelled");
    const bool keep =
        outcome == Status::kOk &&
        OrientedIsBetter(oriented_rep, hulls.size(), slice_rep, slice_hulls.size(), params);
    if (outcome == kUnoriented)
      ctx.Log("oriented cuts: none kept by the clipping, the slices' result stands");
    else
      ctx.Log("oriented cuts: " + std::to_string(hulls.size()) + " hulls, concavity " +
              std::to_string(oriented_rep.concavity) + " against slices " +
              std::to_string(slice_hulls.size()) + ", " + std::to_string(slice_rep.concavity) +
              (keep ? ": kept" : ": slices kept"));
    if (keep) {
      rep = oriented_rep;
    } else {
      rep = slice_rep;
      hulls = std::move(slice_hulls);
    }
  } else {
    rep = slice_rep;
  }
  const bool missed = target && !rep.target_reached;
  const double reached = rep.concavity;
  if (!params.compute_report) {
    // The caller did not ask for the measures (a max_concavity run needed them internally).
    internal::ClearMeasures(&rep);
  }

  // Output in input coordinates.
  const double vol_scale = std::pow(scale * place.h, 3);
  if (rep.hulls.size() != hulls.size()) rep.hulls.assign(hulls.size(), HullReport());
  for (size_t i = 0; i < hulls.size(); ++i) {
    ConvexHull out;
    if (!internal::ToOutputHull(hulls[i], to_world, vol_scale, &out))
      return Fail(Status::kInternalError, "a hull has a non-finite coordinate");
    rep.hulls[i].vertex_count = static_cast<uint32_t>(hulls[i].vertices.size());
    rep.hulls[i].volume = out.volume;
    result.hulls.push_back(std::move(out));
  }
  if (exact_count && refined) {
    // A finer grid's voxel solid can differ from the requested grid's at a narrow opening (the
    // teapot's spout): the requested grid is run too and the closer of the two kept.
    Parameters coarse = CoarseComparison(params);
    Result other = DecomposeImpl(view, coarse, observer, false);
    if (other.status != Status::kOk) return other;
    const bool both_exact = other.hulls.size() == result.hulls.size();
    if ((both_exact && other.report.concavity < reached) ||
        (!both_exact && other.hulls.size() == params.hull_count)) {
      ctx.Log("hull_count: kept the requested resolution's result (" +
              std::to_string(other.report.concavity) + " against " + std::to_string(reached) + ")");
      if (!params.compute_report) internal::ClearMeasures(&other.report);
      other.report.seconds_total = total.Lap();
      return other;
    }
  }
  if (missed && refined) {
    // The refined grid's voxel solid can differ from the requested grid's (the fill decision at a
    // narrow opening, a gap between hulls): when the target was missed, the requested grid is
    // tried too and the closer result kept, so refining never returns a result farther than the
    // requested resolution would have given (by the same rule as the attempts).
    ctx.Log("max_concavity missed on the refined grid (" + std::to_string(reached) +
            "): trying the requested resolution");
    Parameters coarse = CoarseComparison(params);
    Result other = DecomposeImpl(view, coarse, observer, false);
    if (other.status != Status::kOk) return other;
    if (other.report.target_reached || other.report.concavity < kMinGain * reached) {
      ctx.Log("kept the requested resolution's result (" + std::to_string(other.report.concavity) +
              ")");
      if (!params.compute_report) internal::ClearMeasures(&other.report);
      other.report.seconds_total = total.Lap();
      return other;
    }
  }
  rep.seconds_total = total.Lap();
  ctx.Progress(100, "done");
  ctx.Log("done: " + std::to_string(result.hulls.size()) + " hulls from " +
          std::to_string(rep.parts_before_merge) + " parts");
  return result;
}

}  // namespace

Result Decompose(const MeshView& mesh, const Parameters& params, Observer* observer) {
  try {
    return DecomposeImpl(mesh, params, observer);
  } catch (const std::bad_alloc&) {
    return Fail(Status::kOutOfMemory, "out of memory");
  } catch (...) {
    return Fail(Status::kInternalError, "unexpected exception");
  }
}

}  // namespace vhacd
