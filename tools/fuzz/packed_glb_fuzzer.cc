// libFuzzer target: the GLB reader with the packed-file decoder (what `hullpack unpack` and every
// GLB input go through). Any bytes give a Status or a consistent scene.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "packed/packed_glb_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hullpack::Result<hullpack::Scene> scene =
      hullpack::ReadPackedGltf(data, size, "fuzz.glb", "", nullptr);
  if (!scene.ok()) return 0;
  for (const hullpack::Mesh& mesh : scene.value().meshes) {
    for (uint32_t index : mesh.indices) {
      if (index >= mesh.vertex_count()) std::abort();
    }
  }
  return 0;
}
