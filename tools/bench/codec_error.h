// Error measures of a decoded mesh against the mesh that was encoded, vertex by vertex: position
// error (max and RMS, as fractions of the bounding-box diagonal), normal angle error (max and mean,
// degrees) and texture-coordinate error (max, UV units).
//
// The codec may reorder vertices for size; measure a stream encoded with keep_order (vertex i of
// the output is vertex i of the input) and use SameVertexRecords to show that the reordered stream
// decodes to the same vertex values, so the measures hold for it too.
#ifndef HULLPACK_TOOLS_BENCH_CODEC_ERROR_H_
#define HULLPACK_TOOLS_BENCH_CODEC_ERROR_H_

#include <cstddef>
#include <string>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace hullpack {

// The attributes that were encoded, as plain arrays (normals and uvs may be empty).
struct VertexArrays {
  const std::vector<float>* positions = nullptr;  // 3 per vertex
  const std::vector<float>* normals = nullptr;    // 3 per vertex, or null / empty
  const std::vector<float>* uvs = nullptr;        // 2 per vertex, or null / empty
};

struct CodecError {
  size_t vertices = 0;
  double diagonal = 0;      // of the original positions' bounding box (the unit of the two below)
  double position_max = 0;  // largest |decoded - original| / diagonal
  double position_rms = 0;  // sqrt(mean |decoded - original|^2) / diagonal
  // Angle between the original normal and the decoded one, in degrees; -1 when there are no
  // normals. Original normals of zero length have no direction and are not counted.
  double normal_max_deg = -1;
  double normal_mean_deg = -1;
  size_t normals_counted = 0;
  double uv_max = -1;  // largest Euclidean distance in UV space; -1 without UVs
};

// Measures `decoded` against `original`, vertex i against vertex i. The UVs are the decoded mesh's
// first 2-component kTexCoord attribute. Returns false (and says why) when the vertex counts or the
// attributes present differ.
bool MeasureCodecError(const VertexArrays& original, const o3dgc::DecodedMesh& decoded,
                       CodecError* out, std::string* why);

// True when `a` and `b` hold the same vertex records (position, normal, float and int attribute
// values, bit for bit) with the same multiplicities, in any order.
bool SameVertexRecords(const o3dgc::DecodedMesh& a, const o3dgc::DecodedMesh& b);

// Angle between two directions in degrees (atan2 of |a x b| and a . b: accurate for small angles);
// -1 when either has zero length.
double AngleDegrees(const double a[3], const double b[3]);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_CODEC_ERROR_H_
