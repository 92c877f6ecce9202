// Per-vertex arrays of original Open3DGC streams: positions, normals, float and int attributes.
//
// Each array is one section: [u32 section bytes][mask: prediction mode in bits 0-2, coding in
// bits 4-6] then the residuals. Values are predicted from the vertices before them in id order
// over the decoded triangles:
//  - parallelogram (mode 5): a + b - c for each triangle (v, a, b) with a, b < v and each triangle
//    (a, b, c) with c < v; plus, as in the modes below, every earlier neighbour w itself;
//  - differential (mode 1): the earlier neighbours themselves;
//  - surface normal (mode 6, normals only): an orientation (cube face) per vertex relative to the
//    face of the summed triangle normals of the quantized positions, then two components in
//    that face, each predicted from the earlier neighbours' components;
// of all candidates the two smallest (parallelograms before neighbours, see .cc) are kept and a
// coded symbol picks one; with fewer than two candidates the previous vertex (v - 1) predicts,
// and vertex 0 is coded as it is. Binary sections code residuals with an adaptive data model of
// M + 2 symbols, the value M escaping to an Exp-Golomb code; ASCII sections write them as
// variable-length numbers and the predictor choices as bytes in a second section.
// Dequantization is min + q * (max - min) / (2^bits - 1) in float arithmetic, as the original.
#ifndef O3DGC_SRC_LEGACY_ATTRIBUTE_DECODER_H_
#define O3DGC_SRC_LEGACY_ATTRIBUTE_DECODER_H_

#include <cstdint>
#include <vector>

#include "legacy_stream_reader.h"
#include "o3dgc/o3dgc.h"

namespace o3dgc {

class LegacyAttributeDecoder {
 public:
  // `triangles`: the decoded triangles over `num_coords` vertices, in decoding order.
  LegacyAttributeDecoder(LegacyReader* reader, const std::vector<uint32_t>& triangles,
                         uint32_t num_coords);

  // Decodes the positions; they must come first (normal prediction uses them).
  Status DecodePositions(const LegacyArrayDesc& d, std::vector<float>* out);
  Status DecodeNormals(const LegacyArrayDesc& d, std::vector<float>* out);
  Status DecodeFloats(const LegacyArrayDesc& d, std::vector<float>* out);
  // Int values outside the int32 range are kCorrupt.
  Status DecodeInts(const LegacyArrayDesc& d, std::vector<int32_t>* out);

 private:
  enum class Kind { kPositions, kNormals, kFloats, kInts };
  Status DecodeArray(const LegacyArrayDesc& d, Kind kind, std::vector<int64_t>* q, uint32_t* dim,
                     uint8_t* mode);

  LegacyReader* r_;
  const std::vector<uint32_t>& triangles_;
  uint32_t num_coords_;
  std::vector<uint32_t> offsets_, incident_;  // vertex -> triangles (CSR)
  std::vector<int64_t> coords_;               // quantized positions, 3 per vertex
  std::vector<int8_t> orientation_;           // surface-normal mode: cube face per vertex
  std::vector<float> normal_prediction_;      // surface-normal mode: 2 per vertex
  uint64_t work_ = 0;                         // parallelogram search steps (bounded)
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_LEGACY_ATTRIBUTE_DECODER_H_
