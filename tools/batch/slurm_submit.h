// Submitting a sharded batch to Slurm: one job array (task K runs shard K of N) and a final job,
// started after every task has ended, that merges the shard summaries.
#ifndef HULLPACK_TOOLS_BATCH_SLURM_SUBMIT_H_
#define HULLPACK_TOOLS_BATCH_SLURM_SUBMIT_H_

#include <cstddef>
#include <string>
#include <vector>

#include "common/status.h"

namespace hullpack {

struct SlurmBatchJob {
  std::string work_dir;  // job scripts and logs; on a file system every node sees
  // One shard's command; "--shard $SLURM_ARRAY_TASK_ID/N" is appended.
  std::vector<std::string> shard_command;
  std::vector<std::string> merge_command;
  size_t shards = 1;
  std::vector<std::string> sbatch_options;  // the user's, given to both submissions
  std::string sbatch = "sbatch";
};

struct SlurmJobIds {
  std::string array_job, merge_job;
};

// Writes WORK/shard.sh and WORK/merge.sh and submits them: the array with --array=0-(N-1), the
// merge job with --dependency=afterany:ARRAY. Errors carry sbatch's message.
Result<SlurmJobIds> SubmitSlurmBatch(const SlurmBatchJob& job);

// `text` in single quotes for /bin/sh.
std::string ShellQuote(const std::string& text);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BATCH_SLURM_SUBMIT_H_
