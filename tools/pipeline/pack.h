// The packaging pipeline, one stage per file, called in this order:
//   load (load.h: read the file, embed external images)
//   -> checks and repairs (check_and_repair.h)
//   -> leave out what is unused (prune.h)
//   -> per mesh: decompose and encode (pack_mesh.h)
//   -> write (assemble.h: the packed GLB; then the file, atomically).
// PackInput runs load and the stages after it, as `hullpack pack` does (the command then writes the
// GLB atomically); PackScene runs the stages after load, for a scene already in memory.
// docs/architecture.md shows where each arrow is.
#ifndef HULLPACK_TOOLS_PIPELINE_PACK_H_
#define HULLPACK_TOOLS_PIPELINE_PACK_H_

#include <cstdint>
#include <string>
#include <vector>

#include "common/status.h"
#include "pipeline/pack_options.h"
#include "scene/scene.h"

namespace hullpack {

struct PackResult {
  std::vector<uint8_t> glb;
  PackReport report;
};

// Packs `scene` (consumed; LoadScene gives one with its external images embedded). Errors name the
// mesh and the problem.
Result<PackResult> PackScene(Scene scene, const PackOptions& options,
                             PackObserver* observer = nullptr);

// Loads `input` (LoadScene: external images embedded) and packs it. Errors start with the path.
// The report's stage seconds include loading (write is the caller's: 0 here).
Result<PackResult> PackInput(const std::string& input, const PackOptions& options,
                             PackObserver* observer = nullptr);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_PACK_H_
