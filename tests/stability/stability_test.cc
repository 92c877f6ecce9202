// The stability suite (docs/stability.md): every generated case of stability_cases.h through
// decomposition (vhacd), the codec (o3dgc's public API and the pipeline's mesh codec) and packing
// (PackScene, then the packed-GLB reader). Each stage must give what the case expects: a valid
// result (finite; hulls closed and convex; round trip within the promised bound) or a clear error
// status. Crashes, hangs (ctest timeouts) and memory (peak RSS) are caught around it.
// Each case prints one Markdown row; tests/stability/make_table.sh collects them for the docs.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>

#include "convex_hull.h"  // vhacd/src: the reference hull for the dent depth of packed hulls
#include "o3dgc/o3dgc.h"
#include "packed/packed_glb_reader.h"
#include "pipeline/mesh_codec.h"
#include "pipeline/pack.h"
#include "stability_cases.h"
#include "vhacd/vhacd.h"

#ifndef HULLPACK_STABILITY_HEAVY
#define HULLPACK_STABILITY_HEAVY 0
#endif

#if defined(__SANITIZE_ADDRESS__)
#define HULLPACK_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HULLPACK_UNDER_ASAN 1
#endif
#endif

namespace hullpack::stability {
namespace {

constexpr int kPositionBits = 14;          // o3dgc stage
constexpr double kConvexTolerance = 1e-6;  // of the input's bounding-box diagonal
constexpr double kHullBoxMargin =
    0.1;  // hulls stay within the input's box grown by this x diagonal
constexpr const char* kMeshName = "stability_mesh";  // pack errors must name it

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

std::string Format(const char* fmt, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, a);
  return buf;
}

// Bounding box of the finite points (double).
struct Box {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool any = false;
  template <typename T>
  explicit Box(const std::vector<T>& p) {
    for (size_t i = 0; i + 2 < p.size(); i += 3) {
      if (!std::isfinite(double(p[i])) || !std::isfinite(double(p[i + 1])) ||
          !std::isfinite(double(p[i + 2])))
        continue;
      for (int k = 0; k < 3; ++k) {
        lo[k] = any ? std::min(lo[k], double(p[i + k])) : double(p[i + k]);
        hi[k] = any ? std::max(hi[k], double(p[i + k])) : double(p[i + k]);
      }
      any = true;
    }
  }
  double Extent() const { return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}); }
  double MaxAbs() const {
    double m = 0;
    for (int k = 0; k < 3; ++k) m = std::max({m, std::fabs(lo[k]), std::fabs(hi[k])});
    return m;
  }
  double Diagonal() const {
    return std::hypot(hi[0] - lo[0], std::hypot(hi[1] - lo[1], hi[2] - lo[2]));
  }
};

// One float ulp at the magnitude of x (the rounding every float output may add).
double FloatUlp(double x) {
  const float f =
      static_cast<float>(std::min(std::fabs(x), double(std::numeric_limits<float>::max())));
  return double(std::nextafter(f, std::numeric_limits<float>::infinity())) - double(f);
}

// "Is there a point of the set within `radius` of q?" on a hash grid of cells >= radius.
class PointSet {
 public:
  PointSet(const std::vector<float>& p, double radius) : p_(p) {
    Box box(p);
    cell_ = std::max({radius, box.Extent() * 1e-6, std::numeric_limits<double>::min()});
    for (int k = 0; k < 3; ++k) origin_[k] = box.lo[k];
    for (uint32_t i = 0; i < p.size() / 3; ++i) cells_[Key(Cell(&p[i * 3]))].push_back(i);
  }
  // Distance from q to the nearest point of the set, looking only at the 27 cells around q
  // (exact whenever that distance is below the cell size; +inf when no point is that near).
  double NearDistance(const float* q) const {
    const std::array<int64_t, 3> c = Cell(q);
    double best = std::numeric_limits<double>::infinity();
    for (int64_t dx = -1; dx <= 1; ++dx) {
      for (int64_t dy = -1; dy <= 1; ++dy) {
        for (int64_t dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(Key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells_.end()) continue;
          for (uint32_t i : it->second) {
            const double d =
                std::hypot(double(p_[i * 3]) - q[0],
                           std::hypot(double(p_[i * 3 + 1]) - q[1], double(p_[i * 3 + 2]) - q[2]));
            best = std::min(best, d);
          }
        }
      }
    }
    return best;
  }

 private:
  std::array<int64_t, 3> Cell(const float* q) const {
    std::array<int64_t, 3> c;
    for (int k = 0; k < 3; ++k)
      c[k] = static_cast<int64_t>(
          std::floor(std::clamp((double(q[k]) - origin_[k]) / cell_, -1e12, 1e12)));
    return c;
  }
  static uint64_t Key(const std::array<int64_t, 3>& c) {
    uint64_t h = 1469598103934665603ull;
    for (int64_t v : c) h = (h ^ static_cast<uint64_t>(v)) * 1099511628211ull;
    return h;
  }
  const std::vector<float>& p_;
  double cell_ = 1, origin_[3] = {0, 0, 0};
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

// What the checks of one convex hull found.
struct HullCheck {
  std::string problem;   // empty when the hull is finite, closed, outward and in the box
  double convexity = 0;  // largest distance of a vertex above a face plane, / diagonal
};

// A hull whose points have no convex hull of positive volume: at least one point, every point
// finite and inside the input's box grown by kHullBoxMargin.
HullCheck CheckFlatHull(const std::vector<float>& points, const Box& input) {
  HullCheck r;
  if (points.size() < 3) r.problem = "no points";
  for (size_t i = 0; i < points.size() && r.problem.empty(); ++i) {
    const double v = points[i];
    const double margin = kHullBoxMargin * input.Diagonal() + FloatUlp(v);
    if (!std::isfinite(v))
      r.problem = "non-finite vertex";
    else if (v < input.lo[i % 3] - margin || v > input.hi[i % 3] + margin)
      r.problem = "vertex outside the input's box";
  }
  return r;
}

// Finite, indices in range, every vertex used, closed (every directed edge once, with its
// reverse), outward (non-negative volume), inside the input's box grown by kHullBoxMargin; the
// convexity defect is measured, not judged here.
template <typename T>
HullCheck CheckHull(const std::vector<T>& points, const std::vector<uint32_t>& triangles,
                    const Box& input) {
  HullCheck r;
  const size_t n = points.size() / 3;
  const double diagonal = input.Diagonal();
  if (n < 4 || triangles.size() < 12) {
    r.problem = "fewer than 4 vertices or 4 triangles";
    return r;
  }
  for (size_t i = 0; i < points.size(); ++i) {
    const double v = double(points[i]);
    if (!std::isfinite(v)) {
      r.problem = "non-finite vertex";
      return r;
    }
    const double margin = kHullBoxMargin * diagonal + FloatUlp(v);
    if (v < input.lo[i % 3] - margin || v > input.hi[i % 3] + margin) {
      r.problem = "vertex outside the input's box";
      return r;
    }
  }
  std::vector<bool> used(n, false);
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = triangles[t + k], b = triangles[t + (k + 1) % 3];
      if (a >= n || b >= n) {
        r.problem = "index out of range";
        return r;
      }
      used[a] = true;
      ++edges[{a, b}];
    }
  }
  if (std::count(used.begin(), used.end(), false) > 0) r.problem = "unused vertex";
  for (const auto& [edge, count] : edges) {
    auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) r.problem = "not closed";
  }
  // Volume and planes relative to the first vertex, in double.
  const double o[3] = {double(points[0]), double(points[1]), double(points[2])};
  double volume = 0;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    double a[3], b[3], c[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = double(points[triangles[t] * 3 + k]) - o[k];
      b[k] = double(points[triangles[t + 1] * 3 + k]) - o[k];
      c[k] = double(points[triangles[t + 2] * 3 + k]) - o[k];
    }
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                 w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double nrm[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                           u[0] * w[1] - u[1] * w[0]};
    volume += (a[0] * nrm[0] + a[1] * nrm[1] + a[2] * nrm[2]) / 6;
    const double len = std::hypot(nrm[0], std::hypot(nrm[1], nrm[2]));
    if (!(len > 0)) continue;  // a zero-area face has no plane to violate
    for (size_t v = 0; v < n; ++v) {
      double d = 0;
      for (int k = 0; k < 3; ++k) d += (double(points[v * 3 + k]) - o[k] - a[k]) * (nrm[k] / len);
      if (diagonal > 0) r.convexity = std::max(r.convexity, d / diagonal);
    }
  }
  if (!(volume >= 0)) r.problem = "inward (negative volume)";
  return r;
}

// How far the hull's vertices lie inside the convex hull of its own points, / diagonal: 0 for a
// convex hull. A convex hull whose vertices then moved by at most e has a dent depth of at most
// 2e (the vertex stays within e of its supporting plane, which moves by at most e).
template <typename T>
double DentDepth(const std::vector<T>& points, double diagonal) {
  std::vector<vhacd::internal::Vec3> p;
  for (size_t i = 0; i + 2 < points.size(); i += 3)
    p.emplace_back(double(points[i]), double(points[i + 1]), double(points[i + 2]));
  vhacd::internal::HullMesh reference;
  if (vhacd::internal::ComputeConvexHull(p, -1, &reference) != vhacd::internal::HullStatus::kOk ||
      !(diagonal > 0))
    return 0;
  const vhacd::internal::HullPlanes planes(reference);
  double depth = 0;
  for (const vhacd::internal::Vec3& v : p) depth = std::max(depth, -planes.SignedDistanceBound(v));
  return depth / diagonal;
}

// The outcome of one stage: ok or not, a clear error or not, and the table cell.
struct Outcome {
  bool ok = false;
  bool clear_error = true;
  std::string cell;
  std::string message;  // the error's message, printed under the row
};

const char* ExpectName(Expect e) {
  return e == Expect::kOk ? "ok" : e == Expect::kError ? "error" : "ok or error";
}

void Judge(const char* stage, Expect expect, const Outcome& o) {
  if (expect == Expect::kOk) {
    EXPECT_TRUE(o.ok) << stage << " must succeed: " << o.cell;
  }
  if (expect == Expect::kError) {
    EXPECT_FALSE(o.ok) << stage << " must fail with a clear error: " << o.cell;
  }
  if (!o.ok) {
    EXPECT_TRUE(o.clear_error) << stage << " failed without a clear error: " << o.cell;
  }
}

// --- decompose: vhacd::Decompose on the double points ---
Outcome Decompose(const Case& c, const Box& box) {
  Outcome o;
  vhacd::Parameters params;
  params.resolution = 20000;
  const vhacd::MeshView view = vhacd::MeshView::FromDouble(c.points.data(), c.points.size() / 3,
                                                           c.indices.data(), c.indices.size() / 3);
  const auto t0 = Clock::now();
  const vhacd::Result r = vhacd::Decompose(view, params);
  const double seconds = Seconds(t0);
  if (!r.ok()) {
    o.clear_error = r.status != vhacd::Status::kInternalError && !r.message.empty();
    o.cell = std::string("error: ") + vhacd::StatusName(r.status);
    o.message = r.message;
    return o;
  }
  double convexity = 0;
  std::string problem = r.hulls.empty() ? "no hulls" : "";
  for (size_t h = 0; h < r.hulls.size() && problem.empty(); ++h) {
    const vhacd::ConvexHull& hull = r.hulls[h];
    HullCheck check = CheckHull(hull.points, hull.triangles, box);
    if (!check.problem.empty()) problem = "hull " + std::to_string(h) + ": " + check.problem;
    if (!std::isfinite(hull.volume) || hull.volume < 0)
      problem = "hull " + std::to_string(h) + ": bad volume";
    for (double x : hull.center) {
      if (!std::isfinite(x)) problem = "hull " + std::to_string(h) + ": non-finite centre";
    }
    convexity = std::max(convexity, check.convexity);
  }
  for (double x : {r.report.volume_iou, r.report.solid_coverage, r.report.concavity}) {
    if (!std::isfinite(x)) problem = "non-finite report";
  }
  EXPECT_EQ(problem, "") << "decompose";
  EXPECT_LE(convexity, kConvexTolerance)
      << "decompose: hull not convex within 1e-6 of the diagonal";
  o.ok = true;
  o.cell = "ok, " + std::to_string(r.hulls.size()) + (r.hulls.size() == 1 ? " hull" : " hulls") +
           ", convex to " + Format("%.0e", convexity) +
           (problem.empty() ? "" : " **" + problem + "**") + Format(" (%.2f s)", seconds);
  return o;
}

// --- codec: o3dgc::Encode (keep_order, 14 bits) then o3dgc::Decode; again with fast_decode ---
Outcome Codec(const Case& c, const std::vector<float>& positions) {
  Outcome o;
  o3dgc::MeshView view;
  view.positions = positions.data();
  view.num_vertices = positions.size() / 3;
  view.indices = c.indices.data();
  view.num_triangles = c.indices.size() / 3;
  o3dgc::EncodeParams params;
  params.keep_order = true;
  params.position_bits = kPositionBits;
  std::vector<uint8_t> stream;
  const auto t0 = Clock::now();
  const o3dgc::Status s = o3dgc::Encode(view, params, &stream);
  if (s != o3dgc::Status::kOk) {
    o.cell = std::string("error: ") + o3dgc::StatusName(s);
    return o;
  }
  o3dgc::DecodedMesh out;
  const o3dgc::Status d = o3dgc::Decode(stream.data(), stream.size(), o3dgc::DecodeOptions(), &out);
  const double seconds = Seconds(t0);
  EXPECT_EQ(d, o3dgc::Status::kOk) << "an encoded stream must decode";
  if (d != o3dgc::Status::kOk) {
    o.clear_error = false;
    o.cell = std::string("**encoded stream does not decode: ") + o3dgc::StatusName(d) + "**";
    return o;
  }
  o.ok = true;
  EXPECT_EQ(out.positions.size(), positions.size());
  EXPECT_TRUE(out.indices == c.indices) << "keep_order: the decoded triangles are the input's";
  // Promise: every coordinate within half a quantization step of the input (uniform cube of side
  // = the largest extent, 2^14 - 1 steps), plus the float rounding of the result.
  const double step = Box(positions).Extent() / double((1 << kPositionBits) - 1);
  double worst = 0;  // in steps (or absolute when the step is 0)
  size_t over = 0;
  for (size_t i = 0; i < std::min(positions.size(), out.positions.size()); ++i) {
    const double x = positions[i], y = out.positions[i];
    const double err = std::fabs(y - x);
    if (!std::isfinite(y) ||
        err > 0.5 * step * (1 + 1e-6) + FloatUlp(std::max(std::fabs(x), std::fabs(y))))
      ++over;
    worst = std::max(worst, step > 0 ? err / step : err);
  }
  EXPECT_EQ(over, 0u) << "coordinates beyond half a step (" << step << ")";
  // fast_decode changes only the coding order: the same decoded mesh from another stream.
  params.fast_decode = true;
  std::vector<uint8_t> fast;
  o3dgc::DecodedMesh out_fast;
  EXPECT_EQ(o3dgc::Encode(view, params, &fast), o3dgc::Status::kOk) << "fast_decode";
  EXPECT_EQ(o3dgc::Decode(fast.data(), fast.size(), o3dgc::DecodeOptions(), &out_fast),
            o3dgc::Status::kOk)
      << "fast_decode: an encoded stream must decode";
  const bool same = out_fast.positions == out.positions && out_fast.indices == out.indices;
  EXPECT_TRUE(same) << "fast_decode decodes to another mesh";
  o.cell = "ok, " + Format(step > 0 ? "%.2f step" : "%.0e abs", worst) + (over ? " **over**" : "") +
           (same ? "" : " **fast_decode differs**") + Format(" (%.2f s)", seconds);
  return o;
}

// Triangles with two corners at equal float positions, which the codec leaves out by default
// (o3dgc::EncodeParams::keep_degenerate_triangles).
size_t DegenerateTriangles(const std::vector<float>& positions,
                           const std::vector<uint32_t>& indices) {
  auto same = [&](uint32_t a, uint32_t b) {
    const float* p = &positions[3 * size_t(a)];
    const float* q = &positions[3 * size_t(b)];
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  };
  size_t n = 0;
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    n += same(a, b) || same(b, c) || same(a, c);
  }
  return n;
}

// --- mesh codec: the pipeline's EncodeMesh / DecodeMesh with its defaults (reordering) ---
Outcome MeshCodec(const Case& c, const std::vector<float>& positions) {
  Outcome o;
  Mesh mesh;
  mesh.name = c.name;
  mesh.positions = positions;
  mesh.indices = c.indices;
  const MeshCodecSettings settings;
  const auto t0 = Clock::now();
  Result<EncodedMesh> encoded = EncodeMesh(mesh, {}, settings);
  if (!encoded.ok()) {
    o.clear_error =
        encoded.status().code() != StatusCode::kInternal && !encoded.status().message().empty();
    o.cell = std::string("error: ") + StatusCodeName(encoded.status().code());
    o.message = encoded.status().message();
    return o;
  }
  std::vector<uint32_t> groups;
  Result<Mesh> decoded =
      DecodeMesh(encoded->stream.data(), encoded->stream.size(), &groups, c.name);
  const double seconds = Seconds(t0);
  EXPECT_TRUE(decoded.ok()) << decoded.status().ToString();
  if (!decoded.ok()) {
    o.clear_error = false;
    o.cell = "**encoded stream does not decode**";
    return o;
  }
  o.ok = true;
  const Mesh& out = decoded.value();
  EXPECT_EQ(out.triangle_count(),
            mesh.triangle_count() - DegenerateTriangles(mesh.positions, mesh.indices));
  EXPECT_EQ(std::count_if(out.indices.begin(), out.indices.end(),
                          [&](uint32_t i) { return i >= out.vertex_count(); }),
            0);
  // Promise: every decoded vertex within half a cell diagonal (sqrt(3)/2 step) of an input vertex,
  // and every input vertex a non-degenerate triangle uses within that of a decoded vertex.
  const double step = Box(positions).Extent() / double((1 << settings.position_bits) - 1);
  const double bound =
      std::sqrt(3.0) / 2 * step * (1 + 1e-6) + 2 * FloatUlp(Box(positions).MaxAbs());
  PointSet in(positions, bound), back(out.positions, bound);
  double worst = 0;
  for (size_t v = 0; v < out.vertex_count(); ++v)
    worst = std::max(worst, in.NearDistance(&out.positions[v * 3]));
  std::vector<bool> referenced(mesh.vertex_count(), false);
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    const uint32_t* c = &mesh.indices[t];
    if (DegenerateTriangles(mesh.positions, {c[0], c[1], c[2]}) == 0)
      referenced[c[0]] = referenced[c[1]] = referenced[c[2]] = true;
  }
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (referenced[v]) worst = std::max(worst, back.NearDistance(&positions[v * 3]));
  }
  EXPECT_LE(worst, bound) << "vertex distance beyond sqrt(3)/2 step";
  o.cell = "ok, " + Format(step > 0 ? "%.2f step" : "%.0e abs", step > 0 ? worst / step : worst) +
           Format(" (%.2f s)", seconds);
  return o;
}

// --- pack: PackScene (hulls for every mesh) then ReadPackedGltf ---
Outcome Pack(const Case& c, const std::vector<float>& positions) {
  Outcome o;
  Scene scene;
  scene.meshes.resize(1);
  scene.meshes[0].name = kMeshName;
  scene.meshes[0].positions = positions;
  scene.meshes[0].indices = c.indices;
  AddRootNodeForAllMeshes(scene, "root");
  PackOptions options;
  options.collision.policy = HullPolicy::kAll;
  options.collision.parameters.resolution = 20000;
  const auto t0 = Clock::now();
  Result<PackResult> packed = PackScene(scene, options);
  if (!packed.ok()) {
    // Errors name the mesh and the problem (pack.h).
    o.clear_error = packed.status().code() != StatusCode::kInternal &&
                    packed.status().message().find(kMeshName) != std::string::npos;
    o.cell = std::string("error: ") + StatusCodeName(packed.status().code());
    o.message = packed.status().message();
    return o;
  }
  GltfDocument doc;
  Result<Scene> read =
      ReadPackedGltf(packed->glb.data(), packed->glb.size(), "packed.glb", "", &doc);
  Result<std::vector<CollisionHull>> collision_hulls =
      read.ok() ? ReadCollisionHulls(doc, "packed.glb")
                : Result<std::vector<CollisionHull>>(read.status());
  const double seconds = Seconds(t0);
  EXPECT_TRUE(read.ok()) << read.status().ToString();
  if (!read.ok()) {
    o.clear_error = false;
    o.cell = "**packed GLB does not read back**";
    return o;
  }
  o.ok = true;
  const PackReport& report = packed->report;
  const std::vector<Mesh>& meshes = read->meshes;
  EXPECT_EQ(report.meshes.size(), 1u);
  const size_t hulls = report.meshes.empty() ? 0 : report.meshes[0].hull_count;
  // A mesh above PackOptions::part_triangles reads back as one mesh per part.
  const size_t parts = report.meshes.empty() ? 1 : report.meshes[0].parts;
  EXPECT_EQ(meshes.size(), parts + hulls);
  if (meshes.size() < parts) return o;
  // Render mesh: every vertex within max_error x diagonal of an input vertex (pruning may drop
  // vertices and triangles, so only this direction is promised).
  const double budget = options.max_error * Box(positions).Diagonal();
  const double bound = budget * (1 + 1e-6) + 2 * FloatUlp(Box(positions).MaxAbs());
  PointSet in(positions, bound);
  double worst = 0;
  for (size_t p = 0; p < parts; ++p) {
    const Mesh& render = meshes[p];
    EXPECT_EQ(std::count_if(render.indices.begin(), render.indices.end(),
                            [&](uint32_t i) { return i >= render.vertex_count(); }),
              0);
    for (size_t v = 0; v < render.vertex_count(); ++v)
      worst = std::max(worst, in.NearDistance(&render.positions[v * 3]));
  }
  EXPECT_LE(worst, bound) << "render vertex beyond max_error x diagonal";
  // Hulls as an engine builds them (ReadCollisionHulls: the quantized points dequantized by their
  // collider nodes): the convex hull of each hull's points must be finite, closed, outward and in
  // the box, and no point may lie deeper than 2 x hull quantization error inside the hull of the
  // points (DentDepth). The face measure (the 1e-6 criterion of decompose) is reported.
  const Box float_box(positions);
  const double diagonal = float_box.Diagonal();
  double convexity = 0, dent = 0;
  std::string problem;
  EXPECT_TRUE(collision_hulls.ok()) << collision_hulls.status().ToString();
  if (collision_hulls.ok()) {
    EXPECT_EQ(collision_hulls->size(), hulls);
    for (size_t h = 0; h < collision_hulls->size(); ++h) {
      const std::vector<float>& points = collision_hulls.value()[h].hull.positions;
      std::vector<vhacd::internal::Vec3> p;
      for (size_t i = 0; i + 2 < points.size(); i += 3)
        p.emplace_back(double(points[i]), double(points[i + 1]), double(points[i + 2]));
      vhacd::internal::HullMesh built;
      std::vector<double> corners;
      std::vector<uint32_t> triangles;
      if (vhacd::internal::ComputeConvexHull(p, -1, &built) == vhacd::internal::HullStatus::kOk) {
        for (const vhacd::internal::Vec3& v : built.vertices)
          corners.insert(corners.end(), {v.x(), v.y(), v.z()});
        for (const auto& t : built.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
      }
      // A hull thinner than its quantization step may come out flat (a flat input's hulls do):
      // within the budget, and then only its points can be checked.
      HullCheck check = triangles.empty() ? CheckFlatHull(points, float_box)
                                          : CheckHull(corners, triangles, float_box);
      if (!check.problem.empty() && problem.empty())
        problem = "hull " + std::to_string(h) + ": " + check.problem;
      convexity = std::max(convexity, check.convexity);
      dent = std::max(dent, DentDepth(points, diagonal));
    }
  }
  EXPECT_EQ(problem, "") << "packed hulls";
  const double quantization = report.meshes.empty() ? 0 : report.meshes[0].hull_quantization_error;
  EXPECT_LE(quantization, options.hull_error * (1 + 1e-6)) << "hull vertices beyond their budget";
  EXPECT_LE(dent, 2 * quantization * (1 + 1e-6) +
                      4 * FloatUlp(float_box.MaxAbs()) / std::max(diagonal, 1e-300))
      << "packed hull dented deeper than twice its quantization";
  o.cell =
      "ok, " +
      Format(budget > 0 ? "%.2f budget" : "%.0e abs", budget > 0 ? worst / budget : worst) + ", " +
      std::to_string(hulls) + (hulls == 1 ? " hull" : " hulls") +
      (hulls ? ", faces " + Format("%.0e", convexity) + ", dent " + Format("%.0e", dent) : "") +
      (problem.empty() ? "" : " **" + problem + "**") + Format(" (%.2f s)", seconds);
  return o;
}

double PeakRssMegabytes() {
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

class Stability : public ::testing::TestWithParam<std::string> {};

TEST_P(Stability, EveryStageGivesAValidResultOrAClearError) {
  const Case c = MakeCase(GetParam());
  ASSERT_EQ(c.name, GetParam()) << "unknown case";
  std::vector<float> positions(c.points.begin(), c.points.end());
  const Box box(c.points);

  const Outcome decompose = Decompose(c, box);
  Judge("decompose", c.decompose, decompose);
  const Outcome codec = Codec(c, positions);
  Judge("o3dgc codec", c.codec, codec);
  const Outcome mesh_codec = MeshCodec(c, positions);
  Judge("mesh codec", c.codec, mesh_codec);
  const Outcome pack = Pack(c, positions);
  Judge("pack", c.pack, pack);

  const double rss = PeakRssMegabytes();
#if !defined(HULLPACK_UNDER_ASAN)
  EXPECT_LT(rss, HULLPACK_STABILITY_HEAVY ? 4096 : 1024) << "peak memory (MB)";
#endif
  // The promise in model units: half a 14-bit step per axis (codec), max_error x diagonal (pack).
  const Box float_box(positions);
  const std::string promised =
      float_box.any ? Format("%.1e", 0.5 * float_box.Extent() / double((1 << kPositionBits) - 1)) +
                          " / " + Format("%.1e", PackOptions().max_error * float_box.Diagonal())
                    : "-";
  std::cout << "| " << c.name << " | " << c.description << " | " << ExpectName(c.decompose) << " / "
            << ExpectName(c.codec) << " / " << ExpectName(c.pack) << " | " << promised << " | "
            << decompose.cell << " | " << codec.cell << " | " << mesh_codec.cell << " | "
            << pack.cell << " | " << Format("%.0f", rss) << " |\n";
  for (const Outcome* o : {&decompose, &codec, &mesh_codec, &pack}) {
    if (!o->message.empty()) std::cout << "message: " << o->message << "\n";
  }
}

std::string TestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string s = info.param;
  for (char& ch : s) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return s;
}

INSTANTIATE_TEST_SUITE_P(Cases, Stability, ::testing::ValuesIn(CaseNames(HULLPACK_STABILITY_HEAVY)),
                         TestName);

}  // namespace
}  // namespace hullpack::stability
