// vhacd::Simplify: reads the MeshView, finds attribute seams, runs the quadric collapser.
#include "vhacd/simplify.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <tuple>

#include "context.h"
#include "input_mesh.h"
#include "simplify_qem.h"

namespace vhacd {

Status ValidateSimplifyParameters(const SimplifyParameters& p, std::string* why) {
  auto bad = [&](const char* msg) {
    if (why != nullptr) *why = msg;
    return Status::kInvalidParameter;
  };
  if (!std::isfinite(p.target_error) || p.target_error < 0 || p.target_error > 1)
    return bad("target_error must be in [0, 1]");
  if (p.target_triangles >= (uint32_t{1} << 31)) return bad("target_triangles must be below 2^31");
  if (p.target_triangles == 0 && p.target_error == 0)
    return bad("set target_triangles or target_error (both are 0)");
  if (why != nullptr) why->clear();
  return Status::kOk;
}

namespace {

SimplifyResult Fail(Status s, std::string message) {
  SimplifyResult r;
  r.status = s;
  r.message = std::move(message);
  return r;
}

// Welded edges whose two triangles use different input points at an end (split attributes).
std::vector<uint64_t> FindSeams(const MeshView& m, const internal::InputMesh& in) {
  struct Use {
    uint64_t key;
    uint32_t a, b;  // input point indices at the welded ends min, max
  };
  std::vector<Use> uses;
  uses.reserve(in.triangles.size() * 3);
  for (size_t t = 0; t < in.triangles.size(); ++t) {
    const size_t src = in.triangle_source[t];
    for (int k = 0; k < 3; ++k) {
      uint32_t wa = in.triangles[t][k], wb = in.triangles[t][(k + 1) % 3];
      uint32_t ia = m.indices[src * m.triangle_stride + k],
               ib = m.indices[src * m.triangle_stride + (k + 1) % 3];
      if (wa > wb) {
        std::swap(wa, wb);
        std::swap(ia, ib);
      }
      uses.push_back({(uint64_t{wa} << 32) | wb, ia, ib});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return std::tie(x.key, x.a, x.b) < std::tie(y.key, y.a, y.b);
  });
  std::vector<uint64_t> seams;
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    bool split = false;
    while (j < uses.size() && uses[j].key == uses[i].key) {
      split = split || uses[j].a != uses[i].a || uses[j].b != uses[i].b;
      ++j;
    }
    if (split && j - i == 2) seams.push_back(uses[i].key);
    i = j;
  }
  return seams;
}

SimplifyResult SimplifyImpl(const MeshView& view, const SimplifyParameters& params,
                            Observer* observer) {
  std::string why;
  Status st = ValidateSimplifyParameters(params, &why);
  if (st != Status::kOk) return Fail(st, why);
  internal::Context ctx(observer, 1);
  internal::InputMesh input;
  st = internal::ReadMesh(view, &ctx, &input, &why);
  if (st != Status::kOk) return Fail(st, why);
  ctx.BeginStage("Simplification", 0, 100);
  internal::QemMesh mesh, out;
  mesh.points = input.points;
  mesh.triangles = input.triangles.ToArrays();
  internal::Vec3 lo = input.points[0], hi = input.points[0];
  for (const auto& p : input.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diag = (hi - lo).norm();
  if (!std::isfinite(diag))
    return Fail(Status::kInvalidMesh, "the mesh has an overflowing bounding box");
  internal::QemOptions opt;
  opt.target_triangles = params.target_triangles;
  opt.max_error = params.target_error * diag;
  opt.lock_boundary = params.lock_boundary;
  if (!internal::SimplifyQem(mesh, FindSeams(view, input), opt, &ctx, &out))
    return Fail(Status::kCancelled, "cancelled");
  SimplifyResult r;
  r.points.reserve(out.points.size() * 3);
  for (size_t i = 0; i < out.points.size(); ++i) {
    if (!out.points[i].allFinite())
      return Fail(Status::kInternalError, "a simplified point is not finite");
    r.points.insert(r.points.end(), {out.points[i][0], out.points[i][1], out.points[i][2]});
    r.point_source.push_back(input.point_source[out.source[i]]);
  }
  for (const auto& t : out.triangles) r.indices.insert(r.indices.end(), {t[0], t[1], t[2]});
  for (uint32_t t : out.triangle_source) r.triangle_source.push_back(input.triangle_source[t]);
  r.error = diag > 0 ? std::min(1.0, out.error / diag) : 0.0;
  ctx.Progress(100, "done");
  return r;
}

}  // namespace

SimplifyResult Simplify(const MeshView& mesh, const SimplifyParameters& params,
                        Observer* observer) {
  try {
    return SimplifyImpl(mesh, params, observer);
  } catch (const std::bad_alloc&) {
    return Fail(Status::kOutOfMemory, "out of memory");
  } catch (...) {
    return Fail(Status::kInternalError, "unexpected exception");
  }
}

}  // namespace vhacd
