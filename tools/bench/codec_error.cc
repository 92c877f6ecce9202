#include "bench/codec_error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace hullpack {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

size_t Size(const std::vector<float>* v) { return v ? v->size() : 0; }

const o3dgc::DecodedFloatAttribute* DecodedUvs(const o3dgc::DecodedMesh& mesh) {
  for (const o3dgc::DecodedFloatAttribute& a : mesh.float_attributes) {
    if (a.semantic == o3dgc::Semantic::kTexCoord && a.dimension == 2) return &a;
  }
  return nullptr;
}

// The bytes of vertex v's record: position, normal, then every attribute in stream order.
std::string Record(const o3dgc::DecodedMesh& m, size_t v) {
  std::string r;
  auto add = [&](const void* p, size_t bytes) { r.append(static_cast<const char*>(p), bytes); };
  add(&m.positions[v * 3], 3 * sizeof(float));
  if (!m.normals.empty()) add(&m.normals[v * 3], 3 * sizeof(float));
  for (const o3dgc::DecodedFloatAttribute& a : m.float_attributes)
    add(&a.values[v * a.dimension], a.dimension * sizeof(float));
  for (const o3dgc::DecodedIntAttribute& a : m.int_attributes)
    add(&a.values[v * a.dimension], a.dimension * sizeof(int32_t));
  return r;
}

bool Consistent(const o3dgc::DecodedMesh& m) {
  const size_t n = m.num_vertices();
  if (m.positions.size() != n * 3 || (!m.normals.empty() && m.normals.size() != n * 3))
    return false;
  for (const o3dgc::DecodedFloatAttribute& a : m.float_attributes) {
    if (a.values.size() != n * a.dimension) return false;
  }
  for (const o3dgc::DecodedIntAttribute& a : m.int_attributes) {
    if (a.values.size() != n * a.dimension) return false;
  }
  return true;
}

}  // namespace

double AngleDegrees(const double a[3], const double b[3]) {
  const double cross[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                           a[0] * b[1] - a[1] * b[0]};
  const double sin_part =
      std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
  const double cos_part = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double la = a[0] * a[0] + a[1] * a[1] + a[2] * a[2],
               lb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
  if (!(la > 0) || !(lb > 0)) return -1;
  return std::atan2(sin_part, cos_part) * kDegrees;
}

bool MeasureCodecError(const VertexArrays& original, const o3dgc::DecodedMesh& decoded,
                       CodecError* out, std::string* why) {
  auto fail = [&](const std::string& text) {
    if (why) *why = text;
    return false;
  };
  if (!original.positions || original.positions->size() % 3 != 0)
    return fail("no original positions");
  const size_t n = original.positions->size() / 3;
  if (decoded.num_vertices() != n || decoded.positions.size() != n * 3) {
    return fail("decoded " + std::to_string(decoded.num_vertices()) + " vertices, encoded " +
                std::to_string(n));
  }
  const bool has_normals = Size(original.normals) > 0, has_uvs = Size(original.uvs) > 0;
  if (has_normals && (Size(original.normals) != n * 3 || decoded.normals.size() != n * 3))
    return fail("normal counts differ");
  const o3dgc::DecodedFloatAttribute* uvs = DecodedUvs(decoded);
  if (has_uvs && (Size(original.uvs) != n * 2 || !uvs || uvs->values.size() != n * 2))
    return fail("uv counts differ");

  CodecError e;
  e.vertices = n;
  const std::vector<float>& p = *original.positions;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (size_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double x = p[v * 3 + k];
      lo[k] = v == 0 ? x : std::min(lo[k], x);
      hi[k] = v == 0 ? x : std::max(hi[k], x);
    }
  }
  e.diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                         (hi[2] - lo[2]) * (hi[2] - lo[2]));
  // A mesh without extent (one point) gets absolute errors rather than a division by zero.
  const double unit = e.diagonal > 0 ? e.diagonal : 1.0;
  double max2 = 0, sum2 = 0;
  for (size_t v = 0; v < n; ++v) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = double(decoded.positions[v * 3 + k]) - double(p[v * 3 + k]);
      d2 += d * d;
    }
    max2 = std::max(max2, d2);
    sum2 += d2;
  }
  e.position_max = n ? std::sqrt(max2) / unit : 0;
  e.position_rms = n ? std::sqrt(sum2 / double(n)) / unit : 0;

  if (has_normals) {
    double max_deg = 0, sum_deg = 0;
    size_t counted = 0;
    for (size_t v = 0; v < n; ++v) {
      const double a[3] = {(*original.normals)[v * 3], (*original.normals)[v * 3 + 1],
                           (*original.normals)[v * 3 + 2]};
      const double b[3] = {decoded.normals[v * 3], decoded.normals[v * 3 + 1],
                           decoded.normals[v * 3 + 2]};
      const double deg = AngleDegrees(a, b);
      if (deg < 0) {
        // An original without direction is not counted; a decoded normal without direction for
        // an original that had one is as wrong as it can be.
        if (a[0] == 0 && a[1] == 0 && a[2] == 0) continue;
        max_deg = 180;
        sum_deg += 180;
        ++counted;
        continue;
      }
      max_deg = std::max(max_deg, deg);
      sum_deg += deg;
      ++counted;
    }
    e.normals_counted = counted;
    e.normal_max_deg = max_deg;
    e.normal_mean_deg = counted ? sum_deg / double(counted) : 0;
  }
  if (has_uvs) {
    double max2_uv = 0;
    for (size_t v = 0; v < n; ++v) {
      const double du = double(uvs->values[v * 2]) - double((*original.uvs)[v * 2]);
      const double dv = double(uvs->values[v * 2 + 1]) - double((*original.uvs)[v * 2 + 1]);
      max2_uv = std::max(max2_uv, du * du + dv * dv);
    }
    e.uv_max = std::sqrt(max2_uv);
  }
  *out = e;
  return true;
}

bool SameVertexRecords(const o3dgc::DecodedMesh& a, const o3dgc::DecodedMesh& b) {
  if (a.num_vertices() != b.num_vertices() || a.normals.empty() != b.normals.empty() ||
      a.float_attributes.size() != b.float_attributes.size() ||
      a.int_attributes.size() != b.int_attributes.size()) {
    return false;
  }
  for (size_t i = 0; i < a.float_attributes.size(); ++i) {
    if (a.float_attributes[i].dimension != b.float_attributes[i].dimension) return false;
  }
  for (size_t i = 0; i < a.int_attributes.size(); ++i) {
    if (a.int_attributes[i].dimension != b.int_attributes[i].dimension) return false;
  }
  if (!Consistent(a) || !Consistent(b)) return false;
  std::vector<std::string> ra, rb;
  ra.reserve(a.num_vertices());
  rb.reserve(b.num_vertices());
  for (size_t v = 0; v < a.num_vertices(); ++v) {
    ra.push_back(Record(a, v));
    rb.push_back(Record(b, v));
  }
  std::sort(ra.begin(), ra.end());
  std::sort(rb.begin(), rb.end());
  return ra == rb;
}

}  // namespace hullpack
