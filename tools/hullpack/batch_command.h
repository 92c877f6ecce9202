// `hullpack batch INPUT... | --manifest FILE -o OUTDIR`: many assets through the cache, resumable,
// with summaries; `--shard K/N` runs one slice, `--slurm` submits every slice as a Slurm job array
// (docs/guide-batch.md).
#ifndef HULLPACK_TOOLS_HULLPACK_BATCH_COMMAND_H_
#define HULLPACK_TOOLS_HULLPACK_BATCH_COMMAND_H_

#include <string>
#include <vector>

namespace hullpack {

// Exit code: 0 when every asset was packed (or found in the cache), 1 when any failed or the
// summary could not be written, kExitUsage for a command-line mistake.
int RunBatchCommand(const std::vector<std::string>& args);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_BATCH_COMMAND_H_
