// The first part of the arithmetic-coded payload: counts and attribute descriptors, plus the
// models of the small side tables (seams, order, groups) shared by encoder.cc and decoder.cc.
//
// Payload content, in order:
//   counts and descriptors (this file), quantization ranges as raw IEEE floats
//   connectivity (connectivity_encoder.h) over position-welded vertices
//   seams: per welded vertex its number of attribute vertices, per corner which one it uses
//   [keep_order] vertex permutation, triangle permutation and corner rotation
//   positions, normals, float attributes, int attributes (attribute_coder.h)
//   [groups] one id per triangle
#ifndef O3DGC_SRC_PAYLOAD_HEADER_H_
#define O3DGC_SRC_PAYLOAD_HEADER_H_

#include <cstdint>
#include <vector>

#include "arithmetic_coder.h"
#include "entropy.h"
#include "o3dgc/o3dgc.h"
#include "quantizer.h"

namespace o3dgc {

struct AttributeDesc {
  Semantic semantic = Semantic::kGeneric;
  uint32_t dimension = 0;
  int bits = 0;  // quantization bits (octahedral bits for surface-normal normals; 0 for ints)
  Prediction prediction = Prediction::kNone;
  RangeMode range = RangeMode::kPerAxis;
  Quantizer quant;  // unused for ints and surface-normal normals
};

struct PayloadHeader {
  uint64_t num_vertices = 0;
  uint64_t num_triangles = 0;
  bool has_normals = false;
  bool has_groups = false;
  AttributeDesc position;
  AttributeDesc normal;
  std::vector<AttributeDesc> floats;
  std::vector<AttributeDesc> ints;

  // Elements the payload must pay for: triangles + vertices * (1 + components).
  uint64_t Budget() const;
};

// The payload of a valid stream holds at least Budget() / 64 - 64 bytes (the encoder pads);
// the decoder rejects larger claims before allocating anything.
constexpr uint64_t kElementsPerByte = 64;
constexpr uint64_t kBudgetSlackBytes = 64;

void EncodePayloadHeader(ArithmeticEncoder* enc, const PayloadHeader& h);
Status DecodePayloadHeader(ArithmeticDecoder* dec, PayloadHeader* h);

// The bytes after the last coded part (the coder's final bytes) count for the groups when there
// are groups, else for the last part that was coded. Encoder and decoder report the same split.
void AddTailBytes(const PayloadHeader& h, size_t tail, StreamInfo* si);

struct SideModels {
  EGModel seam_count;
  BitModel seam_same;
  BitModel seam_new;
  EGModel perm_vertex;
  EGModel perm_triangle;
  BitModel rotation[2];
  BitModel group_same;
  EGModel group_value;
};

inline uint64_t ZigZag(int64_t v) {
  return v < 0 ? (uint64_t(-(v + 1)) << 1) | 1 : uint64_t(v) << 1;
}
inline int64_t UnZigZag(uint64_t u) { return (u & 1) ? -int64_t(u >> 1) - 1 : int64_t(u >> 1); }

}  // namespace o3dgc

#endif  // O3DGC_SRC_PAYLOAD_HEADER_H_
