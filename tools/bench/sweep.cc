#include "bench/sweep.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstring>
#include <ctime>
#include <set>
#include <tuple>

#include "bench/bench_util.h"
#include "bench/child_process.h"
#include "bench/codec_error.h"
#include "common/file_util.h"
#include "io/scene_io.h"
#include "mesh/topology.h"
#include "mesh/validate.h"
#include "o3dgc/o3dgc.h"
#include "pipeline/mesh_codec.h"

namespace hullpack {
namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// CPU time of this process (every thread), in ms: unlike wall time it does not grow while other
// processes hold the cores.
double CpuMs() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Runs `run` `repeats` times; medians of its wall and CPU times.
template <typename F>
void TimeRuns(int repeats, F&& run, double* wall_ms, double* cpu_ms) {
  std::vector<double> wall, cpu;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    const auto t0 = Clock::now();
    const double c0 = CpuMs();
    const bool go_on = run();
    cpu.push_back(CpuMs() - c0);
    wall.push_back(Ms(t0));
    if (!go_on) break;
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  *wall_ms = wall[wall.size() / 2];
  *cpu_ms = cpu[cpu.size() / 2];
}

std::string Stem(const std::string& file) {
  const size_t dot = file.rfind('.');
  return dot == std::string::npos ? file : file.substr(0, dot);
}

bool Contains(const std::vector<uint32_t>& v, uint32_t x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}
bool Contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}
bool Contains(const std::vector<double>& v, double x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

std::string Join(const std::vector<std::string>& parts) {
  std::string s;
  for (const std::string& p : parts) s += (s.empty() ? "" : "+") + p;
  return s;
}

void Log(const SweepOptions& o, const char* format, ...) __attribute__((format(printf, 2, 3)));
void Log(const SweepOptions& o, const char* format, ...) {
  if (!o.log) return;
  va_list args;
  va_start(args, format);
  std::vfprintf(o.log, format, args);
  va_end(args);
  std::fflush(o.log);
}

// ---- decomposition ----

void WriteString(PayloadWriter& w, const std::string& s) {
  w.U64(s.size());
  w.Bytes(s.data(), s.size());
}

bool ReadString(PayloadReader& r, std::string* s) {
  uint64_t n = 0;
  if (!r.U64(&n) || n > (1u << 20)) return false;
  s->resize(n);
  return r.Bytes(&(*s)[0], n);
}

std::vector<uint8_t> DecomposeInChild(const Mesh& mesh, const vhacd::Parameters& params,
                                      int repeats) {
  const vhacd::MeshView view = vhacd::MeshView::FromFloat(
      mesh.positions.data(), mesh.vertex_count(), mesh.indices.data(), mesh.triangle_count());
  vhacd::Result result;
  double wall = 0, cpu = 0;
  TimeRuns(
      repeats,
      [&] {
        result = vhacd::Decompose(view, params);
        return result.ok();
      },
      &wall, &cpu);
  PayloadWriter w;
  w.U64(static_cast<uint64_t>(result.status));
  WriteString(w, result.message);
  w.Double(wall);
  w.Double(cpu);
  w.U64(result.hulls.size());
  for (const vhacd::ConvexHull& h : result.hulls) {
    w.U64(h.points.size());
    w.Bytes(h.points.data(), h.points.size() * sizeof(double));
    w.U64(h.triangles.size());
    w.Bytes(h.triangles.data(), h.triangles.size() * sizeof(uint32_t));
  }
  return w.Take();
}

bool ReadHulls(PayloadReader& r, std::vector<vhacd::ConvexHull>* hulls) {
  uint64_t count = 0;
  if (!r.U64(&count) || count > (1u << 24)) return false;
  hulls->resize(count);
  for (vhacd::ConvexHull& h : *hulls) {
    uint64_t n = 0;
    if (!r.U64(&n) || n > (1u << 28)) return false;
    h.points.resize(n);
    if (!r.Bytes(h.points.data(), n * sizeof(double)) || !r.U64(&n) || n > (1u << 28)) return false;
    h.triangles.resize(n);
    if (!r.Bytes(h.triangles.data(), n * sizeof(uint32_t))) return false;
  }
  return true;
}

// The hulls as `hullpack pack` stores them: one stream, one group per hull, positions quantized to
// `hull_error` of the mesh's diagonal. Returns the stream size, or -1.
double HullStreamBytes(const std::vector<vhacd::ConvexHull>& hulls, double diagonal,
                       double hull_error, size_t* vertex_count) {
  Mesh all;
  std::vector<uint32_t> groups;
  for (size_t h = 0; h < hulls.size(); ++h) {
    const uint32_t base = static_cast<uint32_t>(all.vertex_count());
    for (double v : hulls[h].points) all.positions.push_back(static_cast<float>(v));
    for (uint32_t i : hulls[h].triangles) all.indices.push_back(base + i);
    groups.insert(groups.end(), hulls[h].triangle_count(), static_cast<uint32_t>(h));
  }
  *vertex_count = all.vertex_count();
  if (all.indices.empty()) return 0;
  MeshCodecSettings s;
  s.position_bits = PositionBitsForMaxError(PositionRange(all), hull_error * diagonal);
  Result<EncodedMesh> encoded = EncodeMesh(all, groups, s);
  return encoded.ok() ? double(encoded->stream.size()) : -1;
}

// Runs the decomposition of one point in a child; the hulls are returned for measuring later.
void RunDecomposePoint(const Mesh& mesh, const SweepOptions& o, uint32_t resolution,
                       double concavity, uint32_t max_hulls, SweepRow& row,
                       std::vector<vhacd::ConvexHull>* hulls) {
  vhacd::Parameters params = o.base;
  params.resolution = resolution;
  params.concavity = concavity;
  params.max_convex_hulls = max_hulls;
  params.compute_report = false;  // the time is the decomposition's; the error is measured apart
  std::string why;
  if (vhacd::ValidateParameters(params, &why) != vhacd::Status::kOk) {
    row.status = "invalid parameters: " + why;
    return;
  }
  const ChildResult child = RunInChild(
      [&] { return DecomposeInChild(mesh, params, o.decompose_repeats); }, o.timeout_seconds);
  if (!child.ok) {
    row.status = "decomposition " + child.error;
    return;
  }
  PayloadReader r(child.payload);
  uint64_t status = 0;
  std::string message;
  double ms = 0, cpu_ms = 0;
  if (!r.U64(&status) || !ReadString(r, &message) || !r.Double(&ms) || !r.Double(&cpu_ms) ||
      !ReadHulls(r, hulls)) {
    row.status = "malformed result from the decomposition child";
    return;
  }
  row.time_ms = ms;
  row.cpu_ms = cpu_ms;
  row.peak_mb = child.peak_rss_mb;
  row.base_mb = child.base_rss_mb;
  if (status != 0) {
    row.status = std::string("vhacd: ") + vhacd::StatusName(static_cast<vhacd::Status>(status)) +
                 " " + message;
    return;
  }
  row.hull_count = double(hulls->size());
  row.status = "ok";
}

bench::Soup ToSoup(const std::vector<double>& points, const uint32_t* triangles,
                   size_t triangle_count) {
  bench::Soup soup;
  for (size_t i = 0; i + 2 < points.size(); i += 3)
    soup.points.push_back({points[i], points[i + 1], points[i + 2]});
  for (size_t t = 0; t < triangle_count; ++t) {
    soup.triangles.push_back({triangles[t * 3], triangles[t * 3 + 1], triangles[t * 3 + 2]});
  }
  return soup;
}

// Error and size of the hulls of a point that ran.
void MeasureDecomposePoint(const bench::MeshMeasure& measure, const SweepOptions& o,
                           const std::vector<vhacd::ConvexHull>& hulls, SweepRow& row) {
  std::vector<bench::Soup> shapes;
  for (const vhacd::ConvexHull& h : hulls)
    shapes.push_back(ToSoup(h.points, h.triangles.data(), h.triangle_count()));
  const bench::HullMetrics m = measure.Measure(shapes);
  row.hausdorff_mesh_to_hulls = m.mesh_to_hulls;
  row.hausdorff_hulls_to_mesh = m.hulls_to_mesh;
  row.iou = m.iou;
  row.coverage = m.coverage;
  row.hulls_to_mesh_in_solid = m.hulls_to_mesh >= 0 ? (m.worst_hull_point_in_solid ? 1 : 0) : -1;
  row.invalid_hulls = double(m.invalid_hulls);
  size_t hull_vertices = 0;
  row.bytes = HullStreamBytes(hulls, measure.diagonal(), o.hull_error, &hull_vertices);
  row.hull_vertices = double(hull_vertices);
}

// ---- codec ----

// The mesh's positions, normals and first UV set, as `hullpack pack` hands them to the coder.
o3dgc::MeshView CodecView(const Mesh& mesh, int uv_bits) {
  o3dgc::MeshView view;
  view.positions = mesh.positions.data();
  view.position_stride = 3 * sizeof(float);
  view.num_vertices = mesh.vertex_count();
  view.indices = mesh.indices.data();
  view.num_triangles = mesh.triangle_count();
  if (!mesh.normals.empty()) {
    view.normals = mesh.normals.data();
    view.normal_stride = 3 * sizeof(float);
  }
  if (!mesh.uv_sets.empty()) {
    o3dgc::FloatAttributeView uv;
    uv.data = mesh.uv_sets[0].data();
    uv.stride = 2 * sizeof(float);
    uv.dimension = 2;
    uv.semantic = o3dgc::Semantic::kTexCoord;
    uv.bits = uv_bits;
    view.float_attributes.push_back(uv);
  }
  return view;
}

o3dgc::EncodeParams CodecParams(int position_bits, int normal_bits, bool keep_order) {
  o3dgc::EncodeParams p;
  p.position_bits = position_bits;
  p.normal_bits = normal_bits;
  p.keep_order = keep_order;
  return p;
}

void RunCodecPoint(const Mesh& mesh, const SweepOptions& o, int qp, int qn, int qt, SweepRow& row) {
  const o3dgc::MeshView view = CodecView(mesh, qt);
  const o3dgc::EncodeParams params = CodecParams(qp, qn, false);
  std::vector<uint8_t> stream, ordered_stream;
  o3dgc::Status s = o3dgc::Encode(view, params, &stream);
  if (s != o3dgc::Status::kOk) {
    row.status = std::string("encode: ") + o3dgc::StatusName(s);
    return;
  }
  row.bytes = double(stream.size());
  row.bits_per_vertex =
      mesh.vertex_count() ? 8.0 * double(stream.size()) / double(mesh.vertex_count()) : -1;
  // Error: measured vertex by vertex on a keep-order stream, after checking that the stream the
  // user gets decodes to the same values.
  {
    o3dgc::DecodedMesh decoded, ordered;
    s = o3dgc::Decode(stream.data(), stream.size(), o3dgc::DecodeOptions(), &decoded);
    if (s != o3dgc::Status::kOk) {
      row.status = std::string("decode: ") + o3dgc::StatusName(s);
      return;
    }
    s = o3dgc::Encode(view, CodecParams(qp, qn, true), &ordered_stream);
    if (s == o3dgc::Status::kOk)
      s = o3dgc::Decode(ordered_stream.data(), ordered_stream.size(), o3dgc::DecodeOptions(),
                        &ordered);
    if (s != o3dgc::Status::kOk) {
      row.status = std::string("keep-order stream: ") + o3dgc::StatusName(s);
      return;
    }
    row.same_values = SameVertexRecords(decoded, ordered) ? 1 : 0;
    VertexArrays original;
    original.positions = &mesh.positions;
    original.normals = &mesh.normals;
    original.uvs = mesh.uv_sets.empty() ? nullptr : &mesh.uv_sets[0];
    CodecError e;
    std::string why;
    if (!MeasureCodecError(original, ordered, &e, &why)) {
      row.status = "error measure: " + why;
      return;
    }
    row.position_max_error = e.position_max;
    row.position_rms_error = e.position_rms;
    row.normal_max_deg = e.normal_max_deg;
    row.normal_mean_deg = e.normal_mean_deg;
    row.uv_max_error = e.uv_max;
  }
  const int repeats = std::max(1, o.repeats);
  const ChildResult enc = RunInChild(
      [&] {
        std::vector<uint8_t> out;
        double wall = 0, cpu = 0;
        TimeRuns(
            repeats,
            [&] {
              if (o3dgc::Encode(view, params, &out) != o3dgc::Status::kOk) out.clear();
              return true;
            },
            &wall, &cpu);
        PayloadWriter w;
        w.Double(wall);
        w.Double(cpu);
        w.U64(out.size());
        return w.Take();
      },
      o.timeout_seconds);
  const ChildResult dec = RunInChild(
      [&] {
        o3dgc::Status st = o3dgc::Status::kOk;
        double wall = 0, cpu = 0;
        TimeRuns(
            repeats,
            [&] {
              o3dgc::DecodedMesh out;
              st = o3dgc::Decode(stream.data(), stream.size(), o3dgc::DecodeOptions(), &out);
              return true;
            },
            &wall, &cpu);
        PayloadWriter w;
        w.Double(wall);
        w.Double(cpu);
        w.U64(static_cast<uint64_t>(st));
        return w.Take();
      },
      o.timeout_seconds);
  if (!enc.ok || !dec.ok) {
    row.status = !enc.ok ? "encoder " + enc.error : "decoder " + dec.error;
    return;
  }
  double enc_ms = 0, enc_cpu = 0, dec_ms = 0, dec_cpu = 0;
  uint64_t enc_size = 0, dec_status = 0;
  PayloadReader re(enc.payload), rd(dec.payload);
  if (!re.Double(&enc_ms) || !re.Double(&enc_cpu) || !re.U64(&enc_size) || !rd.Double(&dec_ms) ||
      !rd.Double(&dec_cpu) || !rd.U64(&dec_status)) {
    row.status = "malformed result from a codec child";
    return;
  }
  if (enc_size != stream.size() || dec_status != 0) {
    row.status = "codec not repeatable in the timing child";
    return;
  }
  row.time_ms = enc_ms;
  row.cpu_ms = enc_cpu;
  row.peak_mb = enc.peak_rss_mb;
  row.base_mb = enc.base_rss_mb;
  row.decode_ms = dec_ms;
  row.decode_cpu_ms = dec_cpu;
  row.decode_peak_mb = dec.peak_rss_mb;
  row.status = "ok";
}

std::string Fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}

}  // namespace

SweepOptions DefaultSweepOptions() {
  SweepOptions o;
  o.grid.resolutions = {20000, 50000, 100000, 200000, 400000, 1000000};
  o.grid.concavities = {0.01, 0.005, 0.0025, 0.001, 0.0005};
  o.grid.max_hulls = {4, 8, 16, 32, 0};
  for (int b = 8; b <= 20; ++b) o.grid.position_bits.push_back(b);
  for (int b = 6; b <= 12; ++b) o.grid.normal_bits.push_back(b);
  for (int b = 8; b <= 14; ++b) o.grid.uv_bits.push_back(b);
  o.metrics.mesh_samples = o.metrics.hull_samples = 20000;
  o.metrics.threads = 0;  // the measure is not timed: every core
  return o;
}

SweepOptions QuickSweepOptions() {
  SweepOptions o = DefaultSweepOptions();
  o.grid.resolutions = {50000, 100000, 400000};
  o.grid.concavities = {0.01, 0.0025, 0.0005};
  o.grid.max_hulls = {8, 0};
  o.grid.position_bits = {8, 10, 12, 14, 16, 18, 20};
  o.grid.normal_bits = {6, 8, 10, 12};
  o.grid.uv_bits = {8, 10, 12, 14};
  o.repeats = 1;
  o.metrics.mesh_samples = o.metrics.hull_samples = 10000;
  return o;
}

std::string DecomposeSweeps(const SweepOptions& o, uint32_t resolution, double concavity,
                            uint32_t max_hulls) {
  const bool base_r = resolution == o.base.resolution, base_c = concavity == o.base.concavity,
             base_h = max_hulls == o.base.max_convex_hulls;
  std::vector<std::string> on;
  if (base_c && base_h && (base_r || Contains(o.grid.resolutions, resolution)))
    on.push_back("resolution");
  if (base_r && base_h && (base_c || Contains(o.grid.concavities, concavity)))
    on.push_back("concavity");
  if (base_r && base_c && (base_h || Contains(o.grid.max_hulls, max_hulls)))
    on.push_back("max_hulls");
  return Join(on);
}

std::string CodecSweeps(const SweepOptions& o, int qp, int qn, int qt) {
  const bool base_p = qp == o.base_position_bits, base_n = qn == o.base_normal_bits,
             base_t = qt == o.base_uv_bits;
  std::vector<std::string> on;
  if (base_n && base_t && (base_p || Contains(o.grid.position_bits, qp)))
    on.push_back("position_bits");
  if (base_p && base_t && (base_n || Contains(o.grid.normal_bits, qn))) on.push_back("normal_bits");
  if (base_p && base_n && (base_t || Contains(o.grid.uv_bits, qt))) on.push_back("uv_bits");
  return Join(on);
}

Result<SweepResult> RunSweep(const std::string& folder, const SweepOptions& o) {
  std::string why;
  if (vhacd::ValidateParameters(o.base, &why) != vhacd::Status::kOk) {
    return Status(StatusCode::kInvalidArgument, "base decomposition parameters: " + why);
  }
  std::vector<std::string> files;
  if (!ListFiles(folder, o.extensions, &files)) {
    return Status(StatusCode::kIoError, folder + ": cannot list the folder");
  }
  const auto t_start = Clock::now();
  SweepResult result;
  // One file per stem, the first in order of extension preference.
  std::vector<std::string> chosen;
  for (const std::string& ext : o.extensions) {
    for (const std::string& f : files) {
      if (LowerExtension(f) != ext) continue;
      const std::string stem = Stem(f);
      if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), stem) == o.only.end())
        continue;
      bool taken = false;
      for (const std::string& c : chosen) taken = taken || Stem(c) == stem;
      if (taken) {
        result.skipped.push_back(f + ": same mesh name as a file measured already");
        continue;
      }
      chosen.push_back(f);
    }
  }
  std::sort(chosen.begin(), chosen.end());

  // The points, one parameter at a time around the base point, each once.
  std::set<std::tuple<uint32_t, double, uint32_t>> decompose_points;
  for (uint32_t r : o.grid.resolutions)
    decompose_points.insert({r, o.base.concavity, o.base.max_convex_hulls});
  for (double c : o.grid.concavities)
    decompose_points.insert({o.base.resolution, c, o.base.max_convex_hulls});
  for (uint32_t h : o.grid.max_hulls)
    decompose_points.insert({o.base.resolution, o.base.concavity, h});
  decompose_points.insert({o.base.resolution, o.base.concavity, o.base.max_convex_hulls});
  std::set<std::tuple<int, int, int>> codec_points;
  for (int b : o.grid.position_bits) codec_points.insert({b, o.base_normal_bits, o.base_uv_bits});
  for (int b : o.grid.normal_bits) codec_points.insert({o.base_position_bits, b, o.base_uv_bits});
  for (int b : o.grid.uv_bits) codec_points.insert({o.base_position_bits, o.base_normal_bits, b});
  codec_points.insert({o.base_position_bits, o.base_normal_bits, o.base_uv_bits});

  for (size_t f = 0; f < chosen.size(); ++f) {
    const std::string& file = chosen[f];
    // Give the previous mesh's freed memory back to the system: the children start at this
    // process's resident size, which is in their peak.
    malloc_trim(0);
    Mesh mesh;
    {
      Result<Scene> scene = ReadScene(folder + "/" + file);
      if (!scene.ok()) {
        result.skipped.push_back(file + ": " + scene.status().message());
        continue;
      }
      mesh = MergeGeometry(scene.value());
    }
    mesh.name = Stem(file);
    const Status valid = ValidateMesh(mesh);
    if (!valid.ok() || mesh.triangle_count() == 0) {
      result.skipped.push_back(file + ": " +
                               (valid.ok() ? std::string("no triangles") : valid.message()));
      continue;
    }
    SweepMesh info;
    info.name = mesh.name;
    info.file = file;
    info.triangles = mesh.triangle_count();
    info.vertices = mesh.vertex_count();
    info.closed = AnalyzeTopology(mesh).closed;
    info.normals = !mesh.normals.empty();
    info.uvs = !mesh.uv_sets.empty();
    result.meshes.push_back(info);
    auto new_row = [&](const char* stage) {
      SweepRow row;
      row.mesh = info.name;
      row.stage = stage;
      row.triangles = info.triangles;
      row.vertices = info.vertices;
      row.closed = info.closed;
      row.status = "not run";
      return row;
    };
    Log(o, "[%zu/%zu] %s: %zu triangles, %zu vertices, %s%s%s\n", f + 1, chosen.size(),
        info.name.c_str(), info.triangles, info.vertices, info.closed ? "closed" : "open",
        info.normals ? ", normals" : "", info.uvs ? ", uvs" : "");
    if (o.codec) {
      for (const auto& [qp, qn, qt] : codec_points) {
        // A sweep of an attribute the mesh does not have measures nothing new.
        if (qn != o.base_normal_bits && !info.normals) continue;
        if (qt != o.base_uv_bits && !info.uvs) continue;
        SweepRow row = new_row("codec");
        row.sweep = CodecSweeps(o, qp, qn, qt);
        row.position_bits = qp;
        row.normal_bits = qn;
        row.uv_bits = qt;
        RunCodecPoint(mesh, o, qp, qn, qt, row);
        Log(o,
            "  codec %d/%d/%d bits: %s, %.0f bytes (%.2f bits/vertex), position max %s rms %s, "
            "normal %s deg, "
            "uv %s, encode %.2f ms, decode %.2f ms\n",
            qp, qn, qt, row.status.c_str(), row.bytes, row.bits_per_vertex,
            Fmt(row.position_max_error).c_str(), Fmt(row.position_rms_error).c_str(),
            Fmt(row.normal_max_deg).c_str(), Fmt(row.uv_max_error).c_str(), row.time_ms,
            row.decode_ms);
        result.rows.push_back(row);
      }
    }
    if (o.decompose) {
      // The children run first, while this process holds only the mesh; the measure (its samples,
      // tree and lattice) is built afterwards.
      std::vector<SweepRow> rows;
      std::vector<std::vector<vhacd::ConvexHull>> hull_sets;
      for (const auto& [res, conc, max_hulls] : decompose_points) {
        SweepRow row = new_row("decompose");
        row.sweep = DecomposeSweeps(o, res, conc, max_hulls);
        row.resolution = res;
        row.concavity = conc;
        row.max_hulls = max_hulls;
        hull_sets.emplace_back();
        RunDecomposePoint(mesh, o, res, conc, max_hulls, row, &hull_sets.back());
        Log(o,
            "  decompose resolution %u concavity %g max hulls %u: %s, %.0f hulls, %.3f s (cpu %.3f "
            "s), %.1f MB\n",
            res, conc, max_hulls, row.status.c_str(), row.hull_count, row.time_ms / 1000,
            row.cpu_ms / 1000, row.peak_mb);
        rows.push_back(row);
      }
      malloc_trim(0);
      const bench::MeshMeasure measure(
          ToSoup(std::vector<double>(mesh.positions.begin(), mesh.positions.end()),
                 mesh.indices.data(), mesh.triangle_count()),
          o.metrics);
      for (size_t i = 0; i < rows.size(); ++i) {
        SweepRow& row = rows[i];
        if (row.status == "ok") MeasureDecomposePoint(measure, o, hull_sets[i], row);
        Log(o,
            "  measured resolution %.0f concavity %g max hulls %.0f: H mesh>hulls %s hulls>mesh "
            "%s%s, IoU %s, "
            "%.0f hull bytes\n",
            row.resolution, row.concavity, row.max_hulls, Fmt(row.hausdorff_mesh_to_hulls).c_str(),
            Fmt(row.hausdorff_hulls_to_mesh).c_str(),
            row.hulls_to_mesh_in_solid == 1 ? " (inside the solid)" : "", Fmt(row.iou).c_str(),
            row.bytes);
        result.rows.push_back(row);
      }
    }
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - t_start).count();
  return result;
}

}  // namespace hullpack
