#include "hullpack/pack_command.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "common/cli_args.h"
#include "common/file_util.h"
#include "hullpack/cli_util.h"
#include "io/scene_io.h"
#include "pipeline/pack.h"

namespace hullpack {
namespace {

struct Job {
  std::string input, output;
  bool ok = false;
  std::string error;
  nlohmann::json report;
};

class ProgressForwarder : public PackObserver {
 public:
  ProgressForwarder(ProgressLine& line, std::string name) : line_(line), name_(std::move(name)) {}
  void OnProgress(double fraction, const std::string& stage) override {
    char percent[16];
    std::snprintf(percent, sizeof(percent), "%3d%%", static_cast<int>(fraction * 100));
    line_.Update(std::string("pack ") + percent + " " + name_ + ": " + stage);
  }

 private:
  ProgressLine& line_;
  std::string name_;
};

nlohmann::json ReportJson(const PackReport& r) {
  nlohmann::json meshes = nlohmann::json::array();
  for (const MeshPackReport& m : r.meshes) {
    nlohmann::json j = {{"name", m.name},
                        {"triangles", m.triangles},
                        {"vertices", m.vertices},
                        {"bytes_before", m.bytes_before},
                        {"bytes_after", m.bytes_after},
                        {"bits_per_vertex", m.bits_per_vertex},
                        {"position_bits", m.position_bits},
                        {"position_range", m.position_range},
                        {"max_error", m.max_error},
                        {"max_error_fraction", m.max_error_fraction},
                        {"hull_count", m.hull_count},
                        {"hull_vertices", m.hull_vertices},
                        {"hull_bytes", m.hull_bytes},
                        {"seconds",
                         {{"encode", m.seconds_encode},
                          {"decode", m.seconds_decode},
                          {"decompose", m.seconds_decompose},
                          {"hull_encode", m.seconds_hull_encode}}}};
    if (m.parts > 1) j["parts"] = m.parts;
    if (!m.no_hulls_reason.empty()) j["no_hulls"] = m.no_hulls_reason;
    if (m.hull_count) {
      j["hull_error"] = {{"concavity", m.hull_concavity},
                         {"volume_iou", m.hull_iou},
                         {"quantization", m.hull_quantization_error},
                         {"target_reached", m.hull_target_reached}};
      if (!m.hull_target_reached) j["hull_error"]["target_note"] = m.hull_target_note;
      j["hull_position_bits"] = m.hull_position_bits;
      j["hull_position_range"] = m.hull_position_range;
    }
    meshes.push_back(std::move(j));
  }
  return {{"meshes", meshes},
          {"left_out", r.left_out},
          {"not_kept", r.not_kept},
          {"output_bytes", r.output_bytes},
          {"key_frame_bytes_before", r.key_frame_bytes_before},
          {"key_frame_bytes_after", r.key_frame_bytes_after},
          {"images_embedded", r.images_embedded},
          {"images_kept_as_references", r.images_kept_outside},
          {"seconds",
           {{"load", r.seconds_load},
            {"repair", r.seconds_repair},
            {"prune", r.seconds_prune},
            {"meshes", r.seconds_meshes},
            {"assemble", r.seconds_assemble},
            {"write", r.seconds_write},
            {"total", r.seconds_total}}}};
}

// The write stage is this command's (the temp file written, flushed and renamed), after the
// report was made: its seconds go in here, and into the total. A cached report's write is this
// run's too.
void SetWriteSeconds(double seconds, nlohmann::json& report) {
  nlohmann::json* s =
      report.is_object() && report.contains("seconds") ? &report["seconds"] : nullptr;
  if (!s || !s->is_object()) return;
  const double before = s->value("write", 0.0);
  (*s)["write"] = seconds;
  if (s->contains("total") && (*s)["total"].is_number())
    (*s)["total"] = (*s)["total"].get<double>() - before + seconds;
}

void PackOne(Job& job, const std::vector<std::string>& inputs, const PackOptions& options,
             bool force, const AssetCache* cache, ProgressLine& progress) {
  Status writable = CheckOutputPath(job.output, inputs, force);
  if (!writable.ok()) {
    job.error = writable.message();
    return;
  }
  ProgressForwarder observer(progress, FileStem(job.input));
  Result<CachedPack> packed = PackFileCached(job.input, options, cache, &observer);
  if (!packed.ok()) {
    job.error = packed.status().message();
    return;
  }
  const auto write_start = std::chrono::steady_clock::now();
  Status written = WriteFileAtomically(job.output, packed->glb);
  if (!written.ok()) {
    job.error = written.message();
    return;
  }
  job.report = std::move(packed->report);
  SetWriteSeconds(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count(),
      job.report);
  if (cache) job.report["cache_hit"] = packed->cache_hit;
  job.report["input"] = job.input;
  job.report["output"] = job.output;
  job.ok = true;
}

// What the command line asks for.
struct PackCommandLine {
  std::vector<std::string> inputs;
  std::string output, report_path;
  PackOptions options;
  std::string cache_dir;
  bool force = false, quiet = false;
  size_t jobs = 0;                       // 0: every core
  size_t threads = 0;                    // per input; 0: every core (one input at a time) or 1
  std::vector<std::string> output_args;  // what can change an output's bytes: the cache key
};

// Parses the command line into `cmd`; returns an exit code when the command should stop.
std::optional<int> ParsePackCommandLine(const std::vector<std::string>& args,
                                        PackCommandLine* cmd) {
  PackOptions& o = cmd->options;
  CliArgs cli("hullpack pack", "INPUT... -o OUTPUT [options]",
              "Compressed meshes and convex collision hulls in one GLB per input.\n"
              "  INPUT: .glb .gltf .fbx .obj .dae .ply .stl .off .wrl; OUTPUT: a .glb file (one "
              "input) or a\n"
              "  folder (several inputs, or a path ending in '/'), which gets NAME.packed.glb per "
              "input");
  cli.VersionDetail(FormatVersionText());
  cli.Positional("INPUT", &cmd->inputs, 1);
  cli.String("-o, --output", "OUTPUT", &cmd->output, "a .glb file or a folder").Required();
  AddPackOptions(cli, &o);
  cli.String("--report", "FILE.json", &cmd->report_path,
             "per mesh: bytes before/after, bits per vertex, error, hulls, times");
  cli.String("--cache", "DIR", &cmd->cache_dir,
             "reuse the outputs of unchanged inputs (a content-addressed cache)");
  cli.Int("--jobs", "N", 1, 256, &cmd->jobs, "inputs packed at once (default: every core)");
  cli.Int("--threads", "N", 1, 256, &cmd->threads,
          "threads for each input's stages (default: every core, 1 with several\n"
          "inputs at once); the output bytes are the same for any N");
  cli.Flag("--force", &cmd->force, "replace existing outputs");
  cli.Flag("--quiet", &cmd->quiet, "no progress line");
  if (std::optional<int> exit_code = cli.Parse(args)) return exit_code;
  const std::string why = ApplyMethodOptions(cli, &o);
  if (!why.empty()) return cli.UsageError(why);
  if (o.fast_decode && o.max_compression)
    return cli.UsageError("--fast-decode and --max-compression exclude each other");
  cmd->output_args = OutputArgs(args, cmd->inputs);
  return std::nullopt;
}

// One job per input, with its output path; an exit code when the outputs cannot be planned.
std::optional<int> PlanJobs(const PackCommandLine& cmd, std::vector<Job>* work) {
  const std::string& output = cmd.output;
  // One input and a file name: that file. Otherwise a folder of NAME.packed.glb.
  const bool to_folder = cmd.inputs.size() > 1 || output.back() == '/' || IsDirectory(output);
  if (!to_folder && FormatFromExtension(output) != FileFormat::kGlb) {
    std::fprintf(stderr, "hullpack pack: %s: the output must be a .glb file or a folder\n",
                 output.c_str());
    return kExitUsage;
  }
  if (to_folder && !IsDirectory(output)) {
    std::fprintf(stderr, "hullpack pack: %s: no such folder\n", output.c_str());
    return kExitUsage;
  }
  work->resize(cmd.inputs.size());
  for (size_t i = 0; i < cmd.inputs.size(); ++i) {
    (*work)[i].input = cmd.inputs[i];
    (*work)[i].output = to_folder ? (output.back() == '/' ? output : output + "/") +
                                        FileStem(cmd.inputs[i]) + ".packed.glb"
                                  : output;
  }
  for (size_t i = 0; i < work->size();
       ++i) {  // two inputs with one stem would write one file twice
    for (size_t j = 0; j < i; ++j) {
      if ((*work)[i].output == (*work)[j].output) {
        std::fprintf(stderr, "hullpack pack: %s and %s would both write %s\n",
                     (*work)[j].input.c_str(), (*work)[i].input.c_str(), (*work)[i].output.c_str());
        return kExitUsage;
      }
    }
  }
  return std::nullopt;
}

void RunJobs(PackCommandLine& cmd, std::vector<Job>& work, const AssetCache* cache) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const size_t threads = std::min<size_t>(work.size(), cmd.jobs > 0 ? cmd.jobs : cores);
  // Several files at once: each one's stages on one thread (their results do not depend on it).
  PackOptions& o = cmd.options;
  if (cmd.threads > 0) {
    o.threads = static_cast<int>(cmd.threads);
    o.collision.parameters.num_threads = static_cast<uint32_t>(cmd.threads);
  } else if (threads > 1) {
    o.threads = 1;
    o.collision.parameters.num_threads = 1;
  }
  ProgressLine progress(!cmd.quiet);
  std::atomic<size_t> next{0};
  auto worker = [&]() {
    for (size_t i; (i = next.fetch_add(1)) < work.size();)
      PackOne(work[i], cmd.inputs, cmd.options, cmd.force, cache, progress);
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  progress.Clear();
}

// One summary line per input on stdout, errors on stderr, the JSON report; returns the exit code.
int ReportJobs(const PackCommandLine& cmd, const std::vector<Job>& work) {
  int failed = 0;
  nlohmann::json reports = nlohmann::json::array();
  for (const Job& job : work) {
    if (!job.ok) {
      ++failed;
      std::fprintf(stderr, "hullpack pack: %s\n", job.error.c_str());
      reports.push_back({{"input", job.input}, {"error", job.error}});
      continue;
    }
    reports.push_back(job.report);
    size_t hulls = 0, before = 0, after = 0;
    for (const auto& m : job.report["meshes"]) {
      hulls += m["hull_count"].get<size_t>();
      before += m["bytes_before"].get<size_t>();
      after += m["bytes_after"].get<size_t>() + m["hull_bytes"].get<size_t>();
    }
    std::printf("%s -> %s: %zu bytes (geometry %zu -> %zu bytes), %zu meshes, %zu hulls\n",
                job.input.c_str(), job.output.c_str(), job.report["output_bytes"].get<size_t>(),
                before, after, job.report["meshes"].size(), hulls);
    if (const size_t keys = job.report["key_frame_bytes_before"].get<size_t>()) {
      std::printf("  animation key frames %zu -> %zu bytes\n", keys,
                  job.report["key_frame_bytes_after"].get<size_t>());
    }
    for (const auto& line : job.report["left_out"])
      std::printf("  left out: %s\n", line.get<std::string>().c_str());
    if (job.report["images_embedded"].get<size_t>()) {
      std::printf("  embedded %zu external images\n", job.report["images_embedded"].get<size_t>());
    }
    for (const auto& line : job.report["images_kept_as_references"])
      std::printf("  %s\n", line.get<std::string>().c_str());
  }
  if (!cmd.report_path.empty()) {
    const nlohmann::json doc = work.size() == 1 ? reports[0] : nlohmann::json{{"files", reports}};
    const std::string text = doc.dump(2) + "\n";
    Status s = WriteFileAtomically(cmd.report_path, text.data(), text.size());
    if (!s.ok()) {
      std::fprintf(stderr, "hullpack pack: %s\n", s.message().c_str());
      if (failed == 0) failed = 1;
    }
  }
  return std::min(failed, 63);
}

}  // namespace

void AddPackOptions(CliArgs& cli, PackOptions* options) {
  PackOptions& o = *options;
  vhacd::Parameters& p = o.collision.parameters;
  cli.Double("--max-error", "F", 1e-9, 0.5, &o.max_error,
             "largest position error, fraction of each mesh's bbox diagonal (0.0005)");
  cli.Int("--qp", "N", 1, 30, &o.position_bits, "explicit position bits instead of --max-error");
  cli.Int("--qn", "N", 1, 30, &o.normal_bits, "explicit normal bits");
  cli.Int("--qt", "N", 1, 30, &o.uv_bits, "explicit texture coordinate bits");
  cli.Double("--hull-error", "F", 1e-9, 0.5, &o.hull_error,
             "largest hull vertex error, fraction of the mesh's bbox diagonal (0.002)");
  cli.Action("--ascii", "7-bit ASCII streams (serve gzip'd) instead of binary",
             [&o]() { o.stream_type = o3dgc::StreamType::kAscii; });
  cli.Flag("--keep-order", &o.keep_order, "keep vertex and triangle order exactly (larger)");
  cli.Flag("--fast-decode", &o.fast_decode,
           "code values in vertex id order: faster decoding, 2-5% larger");
  cli.Flag("--max-compression", &o.max_compression,
           "the smallest streams (format 1.3): large meshes 2-5% smaller, decoding\n"
           "about 1.2-1.5x slower (not with --fast-decode)");
  cli.Int("--part-triangles", "N", 0, 1000000000, &o.part_triangles,
          "code a larger render mesh in parts of at most N triangles, one stream\n"
          "and glTF mesh each, on one grid: less memory (600000; 0: never)");
  cli.Flag("--fallback", &o.glb.fallback,
           "also write plain accessors (readers without the extension still work)");
  cli.Flag("--quantized-hulls", &o.glb.quantized_hulls,
           "hull points as bytes/shorts with KHR_mesh_quantization, which the file then\n"
           "requires (smaller; default: floats, no extension needed because of hulls)");
  cli.Action("--plain-animations",
             "animation key frames as plain accessors (default: EXT_meshopt_compression,\n"
             "which the file then requires; fallback files are always plain)",
             [&o]() { o.glb.compress_animations = false; });
  cli.Value("--hulls", "all|none|auto|N",
            "which meshes get collision hulls (auto); a number N: exactly N hulls per mesh",
            [&o](const std::string& v) {
              if (v == "all") {
                o.collision.policy = HullPolicy::kAll;
              } else if (v == "none") {
                o.collision.policy = HullPolicy::kNone;
              } else if (v == "auto") {
                o.collision.policy = HullPolicy::kAuto;
              } else if (!v.empty() && v.size() <= 6 &&
                         v.find_first_not_of("0123456789") == std::string::npos &&
                         std::stol(v) >= 1 && std::stol(v) <= 100000) {
                o.collision.parameters.hull_count = static_cast<uint32_t>(std::stol(v));
              } else {
                return "takes all, none, auto or a count 1-100000, not '" + v + "'";
              }
              return std::string();
            });
  cli.Flag("--skinned-hulls", &o.collision.skinned_meshes,
           "with --hulls auto, decompose skinned meshes too");
  cli.Value("--physics", "omi|khr",
            "OMI_physics_shape/body (default) or the KHR_physics_rigid_bodies draft",
            [&o](const std::string& v) {
              if (v != "omi" && v != "khr") return "takes omi or khr, not '" + v + "'";
              o.glb.physics = v == "omi" ? PhysicsForm::kOmi : PhysicsForm::kKhr;
              return std::string();
            });
  cli.Value("--method", "vhacd|hacd",
            "decomposer: V-HACD 2.0 (voxels, default) or HACD (surface clustering,\n"
            "testHACD's recommended line 2 100 0 1 1 30 2000; open and thin shapes)",
            [&o](const std::string& v) {
              if (v != "vhacd" && v != "hacd") return "takes vhacd or hacd, not '" + v + "'";
              o.collision.method =
                  v == "hacd" ? DecompositionMethod::kHacd : DecompositionMethod::kVhacd;
              return std::string();
            });
  cli.Value("--quality", "default|high",
            "decomposition preset (default: --max-concavity 0.08, at most 24 vertices\n"
            "per hull; high: V-HACD 2.0's volume criteria, finer, up to 128 vertices);\n"
            "the decomposition options below refine it",
            [&p](const std::string& v) {
              if (v != "default" && v != "high") return "takes default or high, not '" + v + "'";
              if (v == "high") p = vhacd::Parameters::High();
              return std::string();
            })
      .First();
  cli.Int("--resolution", "N", 10000, 64000000, &p.resolution,
          "decomposition voxel count (V-HACD only)");
  cli.Int("--max-hulls", "N", 0, 100000, &p.max_convex_hulls,
          "most hulls per mesh (0: no limit); hacd: merge on past --concavity down to N");
  cli.Value("--max-vertices", "N", "most vertices per hull (4-1024)", [&o](const std::string& v) {
    char* end = nullptr;
    const long n = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || n < 4 || n > 1024)
      return "takes a whole number in 4-1024, not '" + v + "'";
    o.collision.parameters.max_vertices_per_hull = static_cast<uint32_t>(n);
    o.collision.hacd_parameters.max_vertices_per_hull = static_cast<uint32_t>(n);
    return std::string();
  });
  cli.Double("--concavity", "F", 0, 1, &p.concavity,
             "largest concavity of a part, fraction of the diagonal (V-HACD 2.0's\n"
             "volume criterion: applies with --max-concavity 0; hacd: of a merge)");
  cli.Double("--max-concavity", "D", 0, 1, &p.max_concavity,
             "hulls within D x the mesh's diagonal of its surface, as few as that allows\n"
             "(0.08; 0: V-HACD 2.0's volume criteria)");
  cli.Action("--oriented-cuts",
             "V-HACD on a closed mesh: always also cut along the parts' own axes (by\n"
             "default both ways are tried and the closer kept; see vhacd/README.md)",
             [&p] { p.oriented_cuts = vhacd::OrientedCuts::kAlways; });
  cli.Action("--no-oriented-cuts", "V-HACD: voxel slices only (by default both ways are tried)",
             [&p] { p.oriented_cuts = vhacd::OrientedCuts::kOff; });
}

std::string ApplyMethodOptions(const CliArgs& cli, PackOptions* options) {
  if (options->collision.method != DecompositionMethod::kHacd) return "";
  for (const char* name : {"--resolution", "--quality"})
    if (cli.Seen(name))
      return std::string(name) +
             " is a V-HACD option (voxels); --method hacd clusters the surface and has none";
  const vhacd::Parameters& p = options->collision.parameters;
  vhacd::HacdParameters& h = options->collision.hacd_parameters;
  if (cli.Seen("--max-hulls")) h.max_clusters = p.max_convex_hulls;
  // HACD's concavity limit is a distance in units of a diagonal of 2 * scale_factor.
  if (cli.Seen("--concavity")) h.concavity = p.concavity * 2.0 * h.scale_factor;
  if (cli.Seen("--max-concavity")) h.max_concavity = p.max_concavity;
  h.hull_count = p.hull_count;
  return "";
}

std::vector<std::string> OutputArgs(const std::vector<std::string>& args,
                                    const std::vector<std::string>& operands) {
  // Options that only steer the run (where to write, how many threads, which slice), never the
  // bytes of an output; the first group takes a value.
  static const char* const kWithValue[] = {"-o",       "--output",  "--report",   "--jobs",
                                           "--cache",  "--threads", "--manifest", "--shard",
                                           "--shards", "--merge"};
  static const char* const kFlags[] = {"--force", "--quiet", "--"};
  std::vector<std::string> out;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    bool skip = std::find(operands.begin(), operands.end(), a) != operands.end();
    for (const char* f : kFlags) skip = skip || a == f;
    for (const char* name : kWithValue) {
      const std::string n = name;
      if (a == n) {
        skip = true;
        ++i;
      } else if (a.compare(0, n.size() + 1, n + "=") == 0) {
        skip = true;
      }
    }
    if (!skip) out.push_back(a);
  }
  return out;
}

Result<PackedFile> PackFile(const std::string& input, const PackOptions& options,
                            PackObserver* observer) {
  Result<PackResult> packed = PackInput(input, options, observer);
  if (!packed.ok()) return packed.status();
  PackedFile out;
  out.glb = std::move(packed->glb);
  out.report = ReportJson(packed->report);
  out.image_uris = std::move(packed->report.image_uris);
  return out;
}

Result<CachedPack> PackFileCached(const std::string& input, const PackOptions& options,
                                  const AssetCache* cache, PackObserver* observer) {
  CachedPack out;
  std::string input_key;
  if (cache) {
    Result<CacheProbe> probe = cache->Lookup(input);
    if (!probe.ok()) return probe.status();
    if (probe->hit) {
      nlohmann::json meta = nlohmann::json::parse(probe->meta, nullptr, false);
      if (!meta.is_discarded() && meta.is_object()) {
        out.glb = std::move(probe->glb);
        out.report = std::move(meta);
        out.cache_hit = true;
        return out;
      }
    }
    input_key = probe->input_key;
  }
  Result<PackedFile> packed = PackFile(input, options, observer);
  if (!packed.ok()) return packed.status();
  out.glb = std::move(packed->glb);
  out.report = std::move(packed->report);
  if (cache) {
    const std::string meta = out.report.dump();
    Status stored =
        cache->Store(input, input_key, ReferencedFiles(input, packed->image_uris), out.glb, meta);
    if (!stored.ok()) return stored;
  }
  return out;
}

int RunPackCommand(const std::vector<std::string>& args) {
  PackCommandLine cmd;
  if (std::optional<int> exit_code = ParsePackCommandLine(args, &cmd)) return *exit_code;
  std::vector<Job> work;
  if (std::optional<int> exit_code = PlanJobs(cmd, &work)) return *exit_code;
  std::unique_ptr<AssetCache> cache;
  if (!cmd.cache_dir.empty()) {
    cache = std::make_unique<AssetCache>(cmd.cache_dir, CacheSalt(cmd.output_args));
    Status ready = cache->Prepare();
    if (!ready.ok()) {
      std::fprintf(stderr, "hullpack pack: %s\n", ready.message().c_str());
      return 1;
    }
  }
  RunJobs(cmd, work, cache.get());
  return ReportJobs(cmd, work);
}

}  // namespace hullpack
