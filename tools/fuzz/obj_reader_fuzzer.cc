// libFuzzer target: the project's own OBJ parser must survive any bytes (no crash, no hang, no
// sanitizer report) and whatever it accepts must be a consistent mesh.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "io/scene_io.h"
#include "mesh/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hullpack::Result<hullpack::Scene> scene =
      hullpack::ReadSceneFromMemory(data, size, hullpack::FileFormat::kObj, "fuzz.obj");
  if (!scene.ok()) return 0;
  for (const hullpack::Mesh& mesh : scene.value().meshes) {
    // Indices must be in range; non-finite coordinates are the validator's to report, not a bug.
    for (uint32_t index : mesh.indices) {
      if (index >= mesh.vertex_count()) std::abort();
    }
    (void)hullpack::ValidateMesh(mesh);
  }
  return 0;
}
