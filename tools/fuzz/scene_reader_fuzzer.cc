// libFuzzer target for the project's own scene parsers, built once per format
// (HULLPACK_FUZZ_FORMAT = kObj, kOff, kWrl, kPly or kThreeMf): any bytes must give a Status or a
// mesh whose indices are in range; never a crash, hang or sanitizer report.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "io/scene_io.h"
#include "mesh/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hullpack::Result<hullpack::Scene> scene =
      hullpack::ReadSceneFromMemory(data, size, hullpack::FileFormat::HULLPACK_FUZZ_FORMAT, "fuzz");
  if (!scene.ok()) return 0;
  for (const hullpack::Mesh& mesh : scene.value().meshes) {
    for (uint32_t index : mesh.indices) {
      if (index >= mesh.vertex_count()) std::abort();
    }
    // Non-finite coordinates are the validator's to report, not a parser bug.
    (void)hullpack::ValidateMesh(mesh);
  }
  return 0;
}
