#include "hullpack/batch_command.h"

#include <dirent.h>
#include <sched.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <set>
#include <thread>

#include "batch/asset_cache.h"
#include "batch/batch_plan.h"
#include "batch/batch_summary.h"
#include "batch/slurm_submit.h"
#include "common/cli_args.h"
#include "common/file_util.h"
#include "hullpack/cli_util.h"
#include "hullpack/pack_command.h"

namespace hullpack {
namespace {

const char kSummary[] =
    "Packs every input into OUTDIR/PATH.packed.glb, PATH being the input's path relative to the\n"
    "  folder all inputs share, with pack's options (hullpack pack --help). Unchanged inputs come\n"
    "  from the cache; a killed run, restarted, goes on where it stopped; Ctrl-C or SIGTERM stops\n"
    "  it gracefully (exit 130/143). Writes OUTDIR/summary.json and OUTDIR/summary.csv.";

constexpr char kWorkDir[] = ".hullpack-batch";

// SIGINT or SIGTERM (what Slurm sends at a time limit or scancel) stops the batch: assets being
// packed are cancelled, none is started, the summary is written. A second signal ends the process.
volatile sig_atomic_t g_stop_signal = 0;

extern "C" void OnStopSignal(int signal_number) {
  g_stop_signal = signal_number;
  std::signal(signal_number, SIG_DFL);
}

class StopOnSignal : public PackObserver {
 public:
  bool IsCancelled() override { return g_stop_signal != 0; }
};

// The cores this process may use: its CPU affinity, and no more than Slurm allocated to the task
// (SLURM_CPUS_PER_TASK) where the cluster does not bind tasks to cores.
size_t UsableCores() {
  size_t cores = std::max(1u, std::thread::hardware_concurrency());
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) cores = std::max(1, CPU_COUNT(&set));
  if (const char* slurm = std::getenv("SLURM_CPUS_PER_TASK")) {
    const long n = std::atol(slurm);
    if (n > 0) cores = std::min(cores, static_cast<size_t>(n));
  }
  return cores;
}

std::string SelfPath() {
  char buffer[4096];
  const ssize_t n = readlink("/proc/self/exe", buffer, sizeof(buffer) - 1);
  return n > 0 ? std::string(buffer, static_cast<size_t>(n)) : "hullpack";
}

bool SameBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0 || static_cast<size_t>(st.st_size) != bytes.size()) return false;
  Result<std::vector<uint8_t>> old = ReadFileBytes(path);
  return old.ok() && old.value() == bytes;
}

// A run killed between writing a temporary file and renaming it leaves "NAME.tmp-PID-N" behind;
// removes those of this run's outputs (never another shard's).
void RemoveStaleTemporaries(const std::string& out_dir, const std::vector<BatchAsset>& assets) {
  std::set<std::string> folders;
  std::set<std::string> outputs;
  for (const BatchAsset& a : assets) {
    const std::string path = out_dir + "/" + a.output;
    folders.insert(FolderOf(path));
    outputs.insert(path);
  }
  for (const std::string& folder : folders) {
    DIR* dir = opendir(folder.c_str());
    if (!dir) continue;
    while (dirent* e = readdir(dir)) {
      const std::string name = e->d_name;
      const size_t tmp = name.rfind(".tmp-");
      if (tmp != std::string::npos && outputs.count(folder + "/" + name.substr(0, tmp)))
        unlink((folder + "/" + name).c_str());
    }
    closedir(dir);
  }
}

std::string Duration(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buffer[32];
  if (s >= 3600) {
    std::snprintf(buffer, sizeof(buffer), "%ldh%02ldm", s / 3600, s / 60 % 60);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%ldm%02lds", s / 60, s % 60);
  }
  return buffer;
}

Status WriteSummary(const BatchSummary& summary, const std::string& stem) {
  const std::string json = SummaryToJson(summary).dump(2) + "\n";
  Status s = WriteFileAtomically(stem + ".json", json.data(), json.size());
  if (!s.ok()) return s;
  const std::string csv = SummaryToCsv(summary);
  return WriteFileAtomically(stem + ".csv", csv.data(), csv.size());
}

void PrintCounts(const BatchSummary& s, const std::string& where) {
  const size_t cancelled = s.Count("cancelled");
  std::printf(
      "%zu assets: %zu packed, %zu from the cache, %zu failed%s; summary %s.json and .csv\n",
      s.assets.size(), s.Count("packed"), s.Count("cached"), s.Count("failed"),
      cancelled ? (", " + std::to_string(cancelled) + " not done").c_str() : "", where.c_str());
}

std::string ShardStem(const std::string& out_dir, size_t k, size_t n) {
  return out_dir + "/" + kWorkDir + "/summary-" + std::to_string(k) + "-of-" + std::to_string(n);
}

int Merge(const std::string& out_dir, size_t shards) {
  std::vector<BatchSummary> parts;
  for (size_t k = 0; k < shards; ++k) {
    const std::string path = ShardStem(out_dir, k, shards) + ".json";
    Result<std::vector<uint8_t>> bytes = ReadFileBytes(path);
    Result<BatchSummary> part =
        bytes.ok() ? SummaryFromJson(std::string(bytes->begin(), bytes->end()), path)
                   : Result<BatchSummary>(bytes.status());
    if (!part.ok()) {
      std::fprintf(stderr, "hullpack batch: shard %zu of %zu did not finish: %s\n", k, shards,
                   part.status().message().c_str());
      return 1;
    }
    parts.push_back(std::move(part.value()));
  }
  Result<BatchSummary> merged = MergeSummaries(parts);
  if (!merged.ok()) {
    std::fprintf(stderr, "hullpack batch: %s\n", merged.status().message().c_str());
    return 1;
  }
  Status s = WriteSummary(merged.value(), out_dir + "/summary");
  if (!s.ok()) {
    std::fprintf(stderr, "hullpack batch: %s\n", s.message().c_str());
    return 1;
  }
  PrintCounts(merged.value(), out_dir + "/summary");
  return merged->Count("failed") + merged->Count("cancelled") ? 1 : 0;
}

struct BatchRun {
  std::string out_dir;
  const PackOptions* options = nullptr;
  const AssetCache* cache = nullptr;
  std::set<std::pair<dev_t, ino_t>> input_files;  // outputs never replace one of these
};

AssetOutcome RunOne(const BatchRun& run, const BatchAsset& asset) {
  const auto start = std::chrono::steady_clock::now();
  AssetOutcome o;
  o.index = asset.index;
  o.input = asset.input;
  o.output = asset.output;
  o.status = "failed";
  struct stat st;
  if (stat(asset.input.c_str(), &st) == 0) o.input_bytes = static_cast<uint64_t>(st.st_size);
  const std::string path = run.out_dir + "/" + asset.output;
  Status s = MakeDirectories(FolderOf(path));
  if (s.ok() && stat(path.c_str(), &st) == 0 && run.input_files.count({st.st_dev, st.st_ino}))
    s = Status(StatusCode::kInvalidArgument, path + ": is an input file; refusing to overwrite it");
  StopOnSignal stop;
  Result<CachedPack> packed =
      s.ok() ? PackFileCached(asset.input, *run.options, run.cache, &stop) : Result<CachedPack>(s);
  if (packed.ok() && !SameBytes(path, packed->glb)) s = WriteFileAtomically(path, packed->glb);
  if (!packed.ok()) s = packed.status();
  if (s.code() == StatusCode::kCancelled || (!s.ok() && g_stop_signal)) {
    o.status = "cancelled";
    o.error = asset.input + ": cancelled (the batch was stopped)";
  } else if (s.ok()) {
    o.status = packed->cache_hit ? "cached" : "packed";
    o.cache_hit = packed->cache_hit;
    FillFromReport(packed->report, &o);
  } else {
    o.error = s.message();
  }
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return o;
}

struct BatchCommandLine {
  std::vector<std::string> inputs;
  std::string output, manifest, cache_dir;
  PackOptions options;
  size_t jobs = 0;  // 0: every core this process may use
  bool quiet = false;
  Shard shard;
  bool sharded = false;
  long merge = 0, shards = 0;
  bool slurm = false;
  std::vector<std::string> sbatch_options;
  std::vector<std::string> output_args;  // the cache key's share of the command line
};

}  // namespace

int RunBatchCommand(const std::vector<std::string>& all_args) {
  BatchCommandLine parsed;
  // Everything after --slurm is sbatch's.
  std::vector<std::string> args = all_args;
  const auto slurm_at = std::find(args.begin(), args.end(), "--slurm");
  if (slurm_at != args.end()) {
    parsed.slurm = true;
    parsed.sbatch_options.assign(slurm_at + 1, args.end());
    args.erase(slurm_at + 1, args.end());
  }
  CliArgs cli("hullpack batch", "INPUT... | --manifest FILE  -o OUTDIR [options] [pack options]",
              kSummary);
  cli.VersionDetail(FormatVersionText());
  cli.Positional("INPUT", &parsed.inputs, 0);
  cli.String("-o, --output", "OUTDIR", &parsed.output, "output folder (created if missing)")
      .Required();
  cli.String("--manifest", "FILE", &parsed.manifest,
             "inputs, one path per line (relative to FILE's folder; '#' comments)");
  cli.String("--cache", "DIR", &parsed.cache_dir,
             "the content-addressed cache (default OUTDIR/.hullpack-cache); may be\n"
             "shared by many batches, machines and `hullpack pack --cache`");
  cli.Int("--jobs", "N", 1, 256, &parsed.jobs,
          "assets packed at once (default: every core this process may use)");
  cli.Value("--shard", "K/N",
            "run only the K-th of N slices (every N-th asset from the K-th); its\n"
            "summary goes to OUTDIR/.hullpack-batch/summary-K-of-N.json",
            [&parsed](const std::string& v) {
              if (!ParseShard(v, &parsed.shard))
                return "takes K/N with 0 <= K < N, not '" + v + "'";
              parsed.sharded = true;
              return std::string();
            });
  cli.Int("--merge", "N", 1, 100000, &parsed.merge,
          "merge the N shard summaries into OUTDIR/summary.json and .csv");
  cli.Int("--shards", "N", 1, 100000, &parsed.shards, "with --slurm: how many array tasks");
  cli.Action("--slurm",
             "submit the shards as a Slurm job array plus a merge job; every\n"
             "argument after --slurm goes to sbatch",
             []() {});
  cli.Flag("--quiet", &parsed.quiet, "no progress line");
  AddPackOptions(cli, &parsed.options);
  if (std::optional<int> exit_code = cli.Parse(args)) return *exit_code;
  const std::string method_error = ApplyMethodOptions(cli, &parsed.options);
  if (!method_error.empty()) return cli.UsageError(method_error);
  parsed.output_args = OutputArgs(args, parsed.inputs);
  if (parsed.slurm) parsed.output_args.pop_back();  // "--slurm"
  const long merge = parsed.merge, shards = parsed.shards;
  const bool slurm = parsed.slurm, sharded = parsed.sharded;
  const Shard shard = parsed.shard;
  const std::vector<std::string>& sbatch_options = parsed.sbatch_options;
  const std::string& manifest = parsed.manifest;
  const std::string out_dir = AbsolutePath(parsed.output);
  if (merge > 0) return Merge(out_dir, static_cast<size_t>(merge));
  if (slurm != (shards > 0) || (slurm && sharded))
    return cli.UsageError("--slurm needs --shards N (and no --shard)");

  std::vector<std::string> inputs = parsed.inputs;
  if (!manifest.empty()) {
    Result<std::vector<std::string>> listed = ReadManifest(manifest);
    if (!listed.ok()) return cli.UsageError(listed.status().message());
    inputs.insert(inputs.end(), listed->begin(), listed->end());
  }
  Result<std::vector<BatchAsset>> plan = PlanBatch(inputs);
  if (!plan.ok()) {
    return cli.UsageError(plan.status().message() +
                          (inputs.empty() ? " (give INPUT... or --manifest FILE)" : ""));
  }
  const std::string cache_dir =
      AbsolutePath(parsed.cache_dir.empty() ? out_dir + "/.hullpack-cache" : parsed.cache_dir);
  for (const std::string& dir : {out_dir, out_dir + "/" + kWorkDir}) {
    Status made = MakeDirectories(dir);
    if (!made.ok()) {
      std::fprintf(stderr, "hullpack batch: %s\n", made.message().c_str());
      return 1;
    }
  }

  if (slurm) {
    // The shards read one manifest of absolute paths, so that every node sees the same batch.
    const std::string work = out_dir + "/" + kWorkDir;
    std::string list;
    for (const BatchAsset& a : plan.value()) list += a.input + "\n";
    Status s = WriteFileAtomically(work + "/manifest.txt", list.data(), list.size());
    SlurmBatchJob job;
    job.work_dir = work;
    job.shards = static_cast<size_t>(shards);
    job.sbatch_options = sbatch_options;
    job.shard_command = {SelfPath(), "batch", "--manifest", work + "/manifest.txt",
                         "-o",       out_dir, "--cache",    cache_dir};
    job.shard_command.insert(job.shard_command.end(), parsed.output_args.begin(),
                             parsed.output_args.end());
    if (parsed.jobs > 0) {
      job.shard_command.push_back("--jobs");
      job.shard_command.push_back(std::to_string(parsed.jobs));
    }
    job.merge_command = {SelfPath(), "batch", "--merge", std::to_string(shards), "-o", out_dir};
    Result<SlurmJobIds> ids = s.ok() ? SubmitSlurmBatch(job) : Result<SlurmJobIds>(s);
    if (!ids.ok()) {
      std::fprintf(stderr, "hullpack batch: %s\n", ids.status().message().c_str());
      return 1;
    }
    std::printf("array job %s: %ld tasks, shard.sh in %s\n", ids->array_job.c_str(), shards,
                work.c_str());
    std::printf("merge job %s: after the array, writes %s/summary.json and .csv\n",
                ids->merge_job.c_str(), out_dir.c_str());
    return 0;
  }

  const std::vector<BatchAsset> assets = SelectShard(plan.value(), shard);
  AssetCache cache(cache_dir, CacheSalt(parsed.output_args));
  Status ready = cache.Prepare();
  if (!ready.ok()) {
    std::fprintf(stderr, "hullpack batch: %s\n", ready.message().c_str());
    return 1;
  }
  RemoveStaleTemporaries(out_dir, assets);
  PackOptions options = parsed.options;
  BatchRun run;
  run.out_dir = out_dir;
  run.options = &options;
  run.cache = &cache;
  for (const BatchAsset& a : plan.value()) {
    struct stat st;
    if (stat(a.input.c_str(), &st) == 0) run.input_files.insert({st.st_dev, st.st_ino});
  }
  const size_t threads = std::max<size_t>(
      1,
      std::min(assets.size(), parsed.jobs > 0 ? static_cast<size_t>(parsed.jobs) : UsableCores()));
  // Several assets at once: each decomposition on one thread (its result does not depend on it).
  if (threads > 1) options.collision.parameters.num_threads = 1;

  BatchSummary summary;
  summary.total_assets = plan->size();
  summary.shard_index = shard.index;
  summary.shard_count = shard.count;
  summary.assets.resize(assets.size());
  for (size_t i = 0; i < assets.size(); ++i) {  // what a stopped run never reaches
    AssetOutcome& o = summary.assets[i];
    o.index = assets[i].index;
    o.input = assets[i].input;
    o.output = assets[i].output;
    o.status = "cancelled";
    o.error = assets[i].input + ": not started (the batch was stopped)";
  }
  std::signal(SIGINT, OnStopSignal);
  std::signal(SIGTERM, OnStopSignal);
  ProgressLine progress(!parsed.quiet);
  const auto start = std::chrono::steady_clock::now();
  std::atomic<size_t> next{0}, done{0}, cached{0}, failed{0};
  auto worker = [&]() {
    for (size_t i; !g_stop_signal && (i = next.fetch_add(1)) < assets.size();) {
      summary.assets[i] = RunOne(run, assets[i]);
      if (summary.assets[i].cache_hit) ++cached;
      if (summary.assets[i].status == "failed") ++failed;
      const size_t finished = ++done;
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double rate = finished / std::max(elapsed, 1e-6);
      char line[256];
      std::snprintf(line, sizeof(line),
                    "batch %zu/%zu: %zu from the cache, %zu failed; %.1f assets/s, ETA %s",
                    finished, assets.size(), cached.load(), failed.load(), rate,
                    Duration((assets.size() - finished) / rate).c_str());
      progress.Update(line);
    }
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  progress.Clear();
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  for (const AssetOutcome& o : summary.assets)
    if (o.status == "failed") std::fprintf(stderr, "hullpack batch: %s\n", o.error.c_str());
  const int stopped_by = g_stop_signal;
  if (stopped_by) {
    std::fprintf(stderr,
                 "hullpack batch: stopped by signal %d; %zu assets not done (run the same command "
                 "again to go on)\n",
                 stopped_by, summary.Count("cancelled"));
  }
  const std::string stem =
      sharded ? ShardStem(out_dir, shard.index, shard.count) : out_dir + "/summary";
  Status written = WriteSummary(summary, stem);
  if (!written.ok()) {
    std::fprintf(stderr, "hullpack batch: %s\n", written.message().c_str());
    return 1;
  }
  PrintCounts(summary, stem);
  if (stopped_by) return 128 + stopped_by;
  return summary.Count("failed") ? 1 : 0;
}

}  // namespace hullpack
