#include "batch/slurm_submit.h"

#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>

#include "common/file_util.h"

namespace hullpack {
namespace {

std::string Join(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + ShellQuote(w);
  return out;
}

Status WriteScript(const std::string& path, const std::string& text) {
  Status s = WriteFileAtomically(path, text.data(), text.size());
  if (s.ok() && chmod(path.c_str(), 0755) != 0)
    return Status(StatusCode::kIoError, path + ": cannot make it executable");
  return s;
}

// Runs sbatch --parsable with `options` and `script`; its output is "ID" or "ID;CLUSTER".
Result<std::string> Sbatch(const std::string& sbatch, const std::vector<std::string>& options,
                           const std::string& script) {
  std::vector<std::string> argv = {sbatch, "--parsable"};
  argv.insert(argv.end(), options.begin(), options.end());
  argv.push_back(script);
  const std::string command = Join(argv);
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return Status(StatusCode::kIoError, "cannot run " + sbatch);
  std::string out;
  char buffer[256];
  while (std::fgets(buffer, sizeof(buffer), pipe)) out += buffer;
  const int status = pclose(pipe);
  if (status != 0) {
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return Status(StatusCode::kIoError, command + ": failed (exit " + std::to_string(code) +
                                            (code == 127 ? ", sbatch not found" : "") + ")");
  }
  const size_t end = out.find_first_of(";\n");
  const std::string id = out.substr(0, end);
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    return Status(StatusCode::kIoError, command + ": unexpected output '" + out + "'");
  return id;
}

}  // namespace

std::string ShellQuote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

Result<SlurmJobIds> SubmitSlurmBatch(const SlurmBatchJob& job) {
  Status s = MakeDirectories(job.work_dir);
  if (!s.ok()) return s;
  const std::string shard_script = job.work_dir + "/shard.sh";
  const std::string merge_script = job.work_dir + "/merge.sh";
  s = WriteScript(shard_script, "#!/bin/sh\n# hullpack batch: shard SLURM_ARRAY_TASK_ID of " +
                                    std::to_string(job.shards) + "\nexec " +
                                    Join(job.shard_command) + " --shard \"$SLURM_ARRAY_TASK_ID/" +
                                    std::to_string(job.shards) + "\"\n");
  if (s.ok())
    s = WriteScript(merge_script, "#!/bin/sh\n# hullpack batch: merge the shard summaries\nexec " +
                                      Join(job.merge_command) + "\n");
  if (!s.ok()) return s;

  std::vector<std::string> array_options = {"--array=0-" + std::to_string(job.shards - 1),
                                            "--job-name=hullpack-batch",
                                            "--output=" + job.work_dir + "/shard-%a.log"};
  array_options.insert(array_options.end(), job.sbatch_options.begin(), job.sbatch_options.end());
  Result<std::string> array = Sbatch(job.sbatch, array_options, shard_script);
  if (!array.ok()) return array.status();

  std::vector<std::string> merge_options = {"--dependency=afterany:" + array.value(),
                                            "--job-name=hullpack-merge",
                                            "--output=" + job.work_dir + "/merge.log"};
  merge_options.insert(merge_options.end(), job.sbatch_options.begin(), job.sbatch_options.end());
  Result<std::string> merge = Sbatch(job.sbatch, merge_options, merge_script);
  if (!merge.ok()) return merge.status();
  return SlurmJobIds{array.value(), merge.value()};
}

}  // namespace hullpack
