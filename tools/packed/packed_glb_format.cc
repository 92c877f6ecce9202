#include "packed/packed_glb_format.h"

#include "gltf/skin_weights.h"

namespace hullpack {

o3dgc::Status DecodePackedStream(const uint8_t* data, size_t size, o3dgc::DecodedMesh* mesh,
                                 o3dgc::StreamInfo* info) {
  const o3dgc::Status st = o3dgc::Decode(data, size, o3dgc::DecodeOptions(), mesh, info);
  if (st != o3dgc::Status::kOk) return st;
  for (o3dgc::DecodedFloatAttribute& a : mesh->float_attributes) {
    if (a.semantic == o3dgc::Semantic::kWeight && a.dimension == 4)
      NormalizeSkinWeights(a.values.data(), a.values.size() / 4);
  }
  return st;
}

std::vector<float> DequantizeHull(const HullGrid& grid) {
  std::vector<float> out(grid.local.size());
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<float>(grid.translation[i % 3] + grid.scale * double(grid.local[i]));
  return out;
}

}  // namespace hullpack
