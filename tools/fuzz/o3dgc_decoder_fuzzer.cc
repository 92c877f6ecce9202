// libFuzzer target: the o3dgc stream decoder takes any bytes. It must return a status or a mesh
// whose every index is in range and every float finite; never crash, hang or over-allocate.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "o3dgc/o3dgc.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  o3dgc::DecodeOptions options;
  options.verify_checksum = size > 0 && (data[0] & 1);  // half the runs reach past the checksum
  o3dgc::DecodedMesh mesh;
  if (o3dgc::Decode(data, size, options, &mesh) != o3dgc::Status::kOk) return 0;
  const size_t n = mesh.num_vertices();
  for (uint32_t i : mesh.indices) {
    if (i >= n) std::abort();
  }
  for (float f : mesh.positions) {
    if (!std::isfinite(f)) std::abort();
  }
  for (const auto& a : mesh.float_attributes) {
    for (float f : a.values) {
      if (!std::isfinite(f)) std::abort();
    }
  }
  return 0;
}
