// What a batch run does: the assets of a manifest or a command line, each with its output path,
// and the deterministic slice (shard) of them one process runs.
#ifndef HULLPACK_TOOLS_BATCH_BATCH_PLAN_H_
#define HULLPACK_TOOLS_BATCH_BATCH_PLAN_H_

#include <cstddef>
#include <string>
#include <vector>

#include "common/status.h"

namespace hullpack {

struct BatchAsset {
  size_t index = 0;    // position in the whole batch (manifest order)
  std::string input;   // absolute path
  std::string output;  // relative to the output folder: "sub/dir/name.packed.glb"
};

// Reads a manifest: one input path per line, relative to the manifest's folder unless absolute;
// blank lines and lines starting with '#' are skipped. Paths are returned as absolute paths.
Result<std::vector<std::string>> ReadManifest(const std::string& path);

// `path` made absolute (against the working folder) and lexically normalized ("." and ".."
// segments and repeated slashes removed), without resolving symbolic links.
std::string AbsolutePath(const std::string& path);

// One asset per input, in order. Output names are each input's path relative to the deepest folder
// all inputs share, with the extension replaced by ".packed.glb", so they depend on the set of
// inputs only, never on the machine, the working folder or a shard. Errors: no inputs, one input
// twice, two inputs that would write one output (both named).
Result<std::vector<BatchAsset>> PlanBatch(const std::vector<std::string>& inputs);

struct Shard {
  size_t index = 0, count = 1;
};

// Parses "K/N" (0 <= K < N <= 100000).
bool ParseShard(const std::string& text, Shard* out);

// The assets of shard K of N: every N-th asset starting at the K-th (so slices stay balanced when
// the manifest is sorted by size or folder).
std::vector<BatchAsset> SelectShard(const std::vector<BatchAsset>& assets, const Shard& shard);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BATCH_BATCH_PLAN_H_
