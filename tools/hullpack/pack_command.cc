#include "hullpack/pack_command.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <thread>

#include "common/file_util.h"
#include "gltf/external_images.h"
#include "hullpack/cli_util.h"
#include "io/scene_io.h"
#include "pipeline/pack.h"

namespace hullpack {
namespace {

const char kUsage[] =
    "usage: hullpack pack INPUT... -o OUTPUT [options]\n"
    "  INPUT: .glb .gltf .fbx .obj .dae .ply .stl .off .wrl; OUTPUT: a .glb file (one input) or a "
    "folder\n"
    "  (several inputs, or a path ending in '/'), which gets NAME.packed.glb per input\n"
    "options:\n"
    "  --max-error F      largest position error, fraction of each mesh's bbox diagonal (0.0005)\n"
    "  --qp N --qn N --qt N   explicit position / normal / UV bits instead (positions 1-30)\n"
    "  --hull-error F     largest hull vertex error, fraction of the mesh's bbox diagonal (0.002)\n"
    "  --ascii            7-bit ASCII streams (serve gzip'd) instead of binary\n"
    "  --keep-order       keep vertex and triangle order exactly (larger)\n"
    "  --fast-decode      code values in vertex id order: faster decoding, 2-5% larger\n"
    "  --fallback         also write plain accessors (readers without the extension still work)\n"
    "  --hulls all|none|auto   which meshes get collision hulls (auto)\n"
    "  --hulls N          exactly N hulls per decomposed mesh (when it can give N)\n"
    "  --max-concavity D  hulls within D x the mesh's diagonal of its surface, as few as that "
    "allows\n"
    "  --skinned-hulls    with --hulls auto, decompose skinned meshes too\n"
    "  --physics omi|khr  OMI_physics_shape/body (default) or the KHR_physics_rigid_bodies draft\n"
    "  --quality default|high  decomposition preset (default: V-HACD 2.0's, hulls merged while "
    "they\n"
    "                     stick out by at most 3 % of the diagonal, at most 24 vertices per hull)\n"
    "  --resolution N --max-hulls N --max-vertices N --concavity F   decomposition parameters\n"
    "  --report FILE.json per mesh: bytes before/after, bits per vertex, error, hulls, times\n"
    "  --jobs N           inputs packed at once (default: every core)\n"
    "  --force            replace existing outputs\n"
    "  --quiet            no progress line\n";

struct Job {
  std::string input, output;
  bool ok = false;
  std::string error;
  nlohmann::json report;
};

std::string FolderOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

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
    if (!m.no_hulls_reason.empty()) j["no_hulls"] = m.no_hulls_reason;
    if (m.hull_count) {
      j["hull_error"] = {{"concavity", m.hull_concavity},
                         {"volume_iou", m.hull_iou},
                         {"quantization", m.hull_quantization_error}};
      j["hull_position_bits"] = m.hull_position_bits;
      j["hull_position_range"] = m.hull_position_range;
    }
    meshes.push_back(std::move(j));
  }
  return {{"meshes", meshes},
          {"left_out", r.left_out},
          {"not_kept", r.not_kept},
          {"output_bytes", r.output_bytes},
          {"seconds",
           {{"prune", r.seconds_prune}, {"meshes", r.seconds_meshes}, {"write", r.seconds_write}}}};
}

void PackOne(Job& job, const std::vector<std::string>& inputs, const PackOptions& options,
             bool force, ProgressLine& progress) {
  Result<Scene> scene = ReadScene(job.input);
  if (!scene.ok()) {
    job.error = scene.status().message();
    return;
  }
  Status writable = CheckOutputPath(job.output, inputs, force);
  if (!writable.ok()) {
    job.error = writable.message();
    return;
  }
  // One GLB for web delivery: textures beside the input go inside it.
  const EmbedReport images = EmbedExternalImages(scene.value(), FolderOf(job.input));
  ProgressForwarder observer(progress, FileStem(job.input));
  Result<PackResult> packed = PackScene(std::move(scene.value()), options, &observer);
  if (!packed.ok()) {
    job.error = job.input + ": " + packed.status().message();
    return;
  }
  Status written = WriteFileAtomically(job.output, packed->glb);
  if (!written.ok()) {
    job.error = written.message();
    return;
  }
  job.report = ReportJson(packed->report);
  job.report["images_embedded"] = images.embedded;
  job.report["images_kept_as_references"] = images.kept_as_references;
  job.report["input"] = job.input;
  job.report["output"] = job.output;
  job.ok = true;
}

}  // namespace

int RunPackCommand(const std::vector<std::string>& args) {
  std::vector<std::string> inputs;
  std::string output, report_path;
  PackOptions options;
  bool force = false, quiet = false;
  long jobs = 0;
  bool high_quality = false;
  long resolution = 0, max_hulls = -1, max_vertices = 0;
  double concavity = -1, max_concavity = -1;
  long hull_count = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* out) {
      if (i + 1 >= args.size()) {
        std::fprintf(stderr, "hullpack pack: %s needs a value\n", a.c_str());
        return false;
      }
      *out = args[++i];
      return true;
    };
    std::string v;
    long n = 0;
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "-o" || a == "--output") {
      if (!value(&output)) return kExitUsage;
    } else if (a == "--report") {
      if (!value(&report_path)) return kExitUsage;
    } else if (a == "--max-error") {
      if (!value(&v) || !ParseDouble(a, v, 1e-9, 0.5, &options.max_error)) return kExitUsage;
    } else if (a == "--hull-error") {
      if (!value(&v) || !ParseDouble(a, v, 1e-9, 0.5, &options.hull_error)) return kExitUsage;
    } else if (a == "--qp" || a == "--qn" || a == "--qt") {
      if (!value(&v) || !ParseInt(a, v, 1, 30, &n)) return kExitUsage;
      (a == "--qp"   ? options.position_bits
       : a == "--qn" ? options.normal_bits
                     : options.uv_bits) = static_cast<int>(n);
    } else if (a == "--ascii") {
      options.stream_type = o3dgc::StreamType::kAscii;
    } else if (a == "--keep-order") {
      options.keep_order = true;
    } else if (a == "--fast-decode") {
      options.fast_decode = true;
    } else if (a == "--fallback") {
      options.glb.fallback = true;
    } else if (a == "--skinned-hulls") {
      options.collision.skinned_meshes = true;
    } else if (a == "--hulls") {
      if (!value(&v)) return kExitUsage;
      if (v == "all") {
        options.collision.policy = HullPolicy::kAll;
      } else if (v == "none") {
        options.collision.policy = HullPolicy::kNone;
      } else if (v == "auto") {
        options.collision.policy = HullPolicy::kAuto;
      } else if (!v.empty() && v.find_first_not_of("0123456789") == std::string::npos) {
        if (!ParseInt(a, v, 1, 100000, &hull_count)) return kExitUsage;
      } else {
        std::fprintf(stderr, "hullpack pack: --hulls takes all, none, auto or a count, not '%s'\n",
                     v.c_str());
        return kExitUsage;
      }
    } else if (a == "--physics") {
      if (!value(&v) || (v != "omi" && v != "khr")) {
        std::fprintf(stderr, "hullpack pack: --physics takes omi or khr\n");
        return kExitUsage;
      }
      options.glb.physics = v == "omi" ? PhysicsForm::kOmi : PhysicsForm::kKhr;
    } else if (a == "--quality") {
      if (!value(&v) || (v != "default" && v != "high")) {
        std::fprintf(stderr, "hullpack pack: --quality takes default or high\n");
        return kExitUsage;
      }
      high_quality = v == "high";
    } else if (a == "--resolution") {
      if (!value(&v) || !ParseInt(a, v, 10000, 64000000, &resolution)) return kExitUsage;
    } else if (a == "--max-hulls") {
      if (!value(&v) || !ParseInt(a, v, 0, 100000, &max_hulls)) return kExitUsage;
    } else if (a == "--max-vertices") {
      if (!value(&v) || !ParseInt(a, v, 4, 1024, &max_vertices)) return kExitUsage;
    } else if (a == "--concavity") {
      if (!value(&v) || !ParseDouble(a, v, 0, 1, &concavity)) return kExitUsage;
    } else if (a == "--max-concavity") {
      if (!value(&v) || !ParseDouble(a, v, 1e-6, 1, &max_concavity)) return kExitUsage;
    } else if (a == "--jobs") {
      if (!value(&v) || !ParseInt(a, v, 1, 256, &jobs)) return kExitUsage;
    } else if (a == "--force") {
      force = true;
    } else if (a == "--quiet") {
      quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "hullpack pack: unknown option '%s'\n%s", a.c_str(), kUsage);
      return kExitUsage;
    } else {
      inputs.push_back(a);
    }
  }
  if (inputs.empty() || output.empty()) {
    std::fputs(kUsage, stderr);
    return kExitUsage;
  }
  vhacd::Parameters& p = options.collision.parameters;
  if (high_quality) p = vhacd::Parameters::High();
  if (resolution) p.resolution = static_cast<uint32_t>(resolution);
  if (max_hulls >= 0) p.max_convex_hulls = static_cast<uint32_t>(max_hulls);
  if (max_vertices) p.max_vertices_per_hull = static_cast<uint32_t>(max_vertices);
  if (concavity >= 0) p.concavity = concavity;
  if (max_concavity > 0) p.max_concavity = max_concavity;
  if (hull_count > 0) p.hull_count = static_cast<uint32_t>(hull_count);

  // One input and a file name: that file. Otherwise a folder of NAME.packed.glb.
  const bool to_folder = inputs.size() > 1 || output.back() == '/' || IsDirectory(output);
  if (!to_folder && FormatFromExtension(output) != FileFormat::kGlb) {
    std::fprintf(stderr, "hullpack pack: %s: the output must be a .glb file or a folder\n",
                 output.c_str());
    return kExitUsage;
  }
  if (to_folder && !IsDirectory(output)) {
    std::fprintf(stderr, "hullpack pack: %s: no such folder\n", output.c_str());
    return kExitUsage;
  }
  std::vector<Job> work(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) {
    work[i].input = inputs[i];
    work[i].output = to_folder ? (output.back() == '/' ? output : output + "/") +
                                     FileStem(inputs[i]) + ".packed.glb"
                               : output;
  }
  for (size_t i = 0; i < work.size(); ++i) {  // two inputs with one stem would write one file twice
    for (size_t j = 0; j < i; ++j) {
      if (work[i].output == work[j].output) {
        std::fprintf(stderr, "hullpack pack: %s and %s would both write %s\n",
                     work[j].input.c_str(), work[i].input.c_str(), work[i].output.c_str());
        return kExitUsage;
      }
    }
  }
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const size_t threads =
      std::min<size_t>(work.size(), jobs > 0 ? static_cast<size_t>(jobs) : cores);
  // Several files at once: each decomposition on one thread (its result does not depend on it).
  if (threads > 1) p.num_threads = 1;
  ProgressLine progress(!quiet);
  std::atomic<size_t> next{0};
  auto worker = [&]() {
    for (size_t i; (i = next.fetch_add(1)) < work.size();)
      PackOne(work[i], inputs, options, force, progress);
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  progress.Clear();

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
    for (const auto& line : job.report["left_out"])
      std::printf("  left out: %s\n", line.get<std::string>().c_str());
    if (job.report["images_embedded"].get<size_t>()) {
      std::printf("  embedded %zu external images\n", job.report["images_embedded"].get<size_t>());
    }
    for (const auto& line : job.report["images_kept_as_references"])
      std::printf("  %s\n", line.get<std::string>().c_str());
  }
  if (!report_path.empty()) {
    const nlohmann::json doc = work.size() == 1 ? reports[0] : nlohmann::json{{"files", reports}};
    const std::string text = doc.dump(2) + "\n";
    Status s = WriteFileAtomically(report_path, text.data(), text.size());
    if (!s.ok()) {
      std::fprintf(stderr, "hullpack pack: %s\n", s.message().c_str());
      if (failed == 0) failed = 1;
    }
  }
  return std::min(failed, 63);
}

}  // namespace hullpack
