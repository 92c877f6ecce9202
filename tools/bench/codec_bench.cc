// codec_bench: the project's SC3DMC coder and Draco side by side on every mesh of a folder (one
// file per name: .obj first, then .glb, then the other formats the scene reader takes; skins
// kept), in one run, at the same
// quantization (default 14-bit positions, 10-bit normals, 12-bit UVs; Draco at -cl
// 7 and -cl 10): bytes, bits per vertex, encode and decode time (median of repeats), maximum
// position error; and the ASCII stream's bytes once gzip'd, against the binary stream's. Prints a
// table and writes CSV.
//
//   codec_bench FOLDER [--repeats 5] [--csv out.csv] [--qp 14] [--qn 10] [--qt 12] [--only a,b]
//               [--clock wall|cpu] [--ours-only] [--fast-decode] [--parts]   (see --help)
//
// The repeats are interleaved (one encode and one decode of each codec per round, the codecs'
// order rotating from round to round, so that none always runs after the same one), so that a load
// change during the run affects the three codecs alike; the ratios to Draco -cl 7 (enc/cl7,
// dec/cl7) are the medians of the per-round ratios, which a load change during the run moves less
// than a ratio of medians. --clock cpu times the process's CPU time
// instead of wall time: steadier on a loaded machine (the time spent waiting for a core is left
// out), the same on a quiet one. --ours-only skips Draco (profiling runs, size checks).
// --fast-decode encodes ours with EncodeParams::fast_decode (values in vertex id order),
// --max-compression with EncodeParams::max_compression.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/draco_bridge.h"
#include "bench/gzip_size.h"
#include "common/cli_args.h"
#include "common/file_util.h"
#include "io/scene_io.h"
#include "o3dgc/o3dgc.h"
#include "pipeline/mesh_codec.h"

namespace {

using hullpack::Mesh;

struct Settings {
  int repeats = 5, qp = 14, qn = 10, qt = 12;
  bool cpu_clock = false;
  bool ours_only = false;
  bool fast_decode = false;
  bool max_compression = false;
  bool parts = false;
  std::string csv;
  std::vector<std::string> only;  // mesh names (file names without extension); empty: all
};

double NowMs(bool cpu) {
  timespec t;
  clock_gettime(cpu ? CLOCK_PROCESS_CPUTIME_ID : CLOCK_MONOTONIC, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

template <typename F>
double TimeMs(bool cpu, F&& run) {
  const double t0 = NowMs(cpu);
  run();
  return NowMs(cpu) - t0;
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Row {
  std::string name;
  size_t triangles = 0, vertices = 0;
  size_t bytes[3] = {0, 0, 0};  // ours, draco cl7, draco cl10
  size_t ascii_gzip_bytes = 0;  // ours, the 7-bit ASCII stream gzip'd as a server sends it
  double encode_ms[3] = {0, 0, 0}, decode_ms[3] = {0, 0, 0}, error[3] = {0, 0, 0};
  double encode_ratio7 = 0, decode_ratio7 = 0;  // ours / Draco -cl 7, medians of per-round ratios
  o3dgc::StreamInfo info;                       // ours: the bytes of each part of the stream
};

// "header 36, connectivity 567, ...": where the bytes of our stream go (--parts).
std::string PartBytes(const o3dgc::StreamInfo& i) {
  std::string out = "header " + std::to_string(i.header) + ", connectivity " +
                    std::to_string(i.connectivity) + ", positions " + std::to_string(i.positions);
  if (i.normals) out += ", normals " + std::to_string(i.normals);
  for (size_t k = 0; k < i.float_attributes.size(); ++k)
    out += ", float " + std::to_string(k) + " " + std::to_string(i.float_attributes[k]);
  for (size_t k = 0; k < i.int_attributes.size(); ++k)
    out += ", int " + std::to_string(k) + " " + std::to_string(i.int_attributes[k]);
  if (i.groups) out += ", groups " + std::to_string(i.groups);
  return out;
}

// Draco at one level: the mesh converted once (not timed), then encoded and decoded per round.
struct DracoRun {
  int level = 7;
  std::unique_ptr<draco::Mesh> mesh;
  std::vector<uint8_t> bytes;
  Mesh decoded;
};

// Every codec encodes and decodes once per round; times are medians over the rounds.
bool RunAll(const Mesh& mesh, const Settings& s, Row& row) {
  hullpack::MeshCodecSettings cs;
  cs.position_bits = s.qp;
  cs.normal_bits = s.qn;
  cs.uv_bits = s.qt;
  cs.fast_decode = s.fast_decode;
  cs.max_compression = s.max_compression;
  DracoRun draco[2];
  draco[0].level = 7;
  draco[1].level = 10;
  const int num_draco = s.ours_only ? 0 : 2;
  for (int i = 0; i < num_draco; ++i) {
    DracoRun& d = draco[i];
    d.mesh = hullpack::ToDracoMesh(mesh);
    if (!d.mesh) return false;
  }
  std::vector<double> enc[3], dec[3];
  hullpack::Result<hullpack::EncodedMesh> encoded =
      hullpack::Status(hullpack::StatusCode::kInternal, "");
  hullpack::Result<Mesh> decoded = hullpack::Status(hullpack::StatusCode::kInternal, "");
  // One timed encode / decode of codec i (0: ours, 1..: Draco at its level); false on failure.
  auto encode = [&](int i) {
    if (i == 0) {
      enc[0].push_back(TimeMs(s.cpu_clock, [&] { encoded = hullpack::EncodeMesh(mesh, {}, cs); }));
      return encoded.ok();
    }
    DracoRun& d = draco[i - 1];
    enc[i].push_back(TimeMs(
        s.cpu_clock, [&] { d.bytes = hullpack::DracoEncode(*d.mesh, s.qp, s.qn, s.qt, d.level); }));
    return !d.bytes.empty();
  };
  auto decode = [&](int i) {
    if (i == 0) {
      dec[0].push_back(TimeMs(s.cpu_clock, [&] {
        decoded =
            hullpack::DecodeMesh(encoded->stream.data(), encoded->stream.size(), nullptr, row.name);
      }));
      return decoded.ok();
    }
    DracoRun& d = draco[i - 1];
    dec[i].push_back(
        TimeMs(s.cpu_clock, [&] { d.decoded = hullpack::DracoDecodePositions(d.bytes); }));
    return !d.decoded.positions.empty();
  };
  // Round r runs the codecs from the (r mod n)-th on: each one follows each other one as often.
  const int n = 1 + num_draco;
  for (int round = 0; round < s.repeats; ++round) {
    for (int j = 0; j < n; ++j) {
      if (!encode((round + j) % n)) return false;
    }
    for (int j = 0; j < n; ++j) {
      if (!decode((round + j) % n)) return false;
    }
  }
  row.bytes[0] = encoded->stream.size();
  row.info = encoded->info;
  hullpack::MeshCodecSettings ascii = cs;
  ascii.stream_type = o3dgc::StreamType::kAscii;
  hullpack::Result<hullpack::EncodedMesh> ascii_stream = hullpack::EncodeMesh(mesh, {}, ascii);
  if (!ascii_stream.ok()) return false;
  row.ascii_gzip_bytes =
      hullpack::GzipSize(ascii_stream->stream.data(), ascii_stream->stream.size());
  row.error[0] = hullpack::MaxVertexDistance(mesh, decoded.value());
  for (int i = 0; i < num_draco; ++i) {
    row.bytes[i + 1] = draco[i].bytes.size();
    row.error[i + 1] = hullpack::MaxVertexDistance(mesh, draco[i].decoded);
  }
  for (int i = 0; i < 3; ++i) {
    row.encode_ms[i] = Median(enc[i]);
    row.decode_ms[i] = Median(dec[i]);
  }
  if (num_draco > 0) {
    std::vector<double> enc_ratio, dec_ratio;
    for (int r = 0; r < s.repeats; ++r) {
      enc_ratio.push_back(enc[0][r] / enc[1][r]);
      dec_ratio.push_back(dec[0][r] / dec[1][r]);
    }
    row.encode_ratio7 = Median(enc_ratio);
    row.decode_ratio7 = Median(dec_ratio);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Settings s;
  std::vector<std::string> folders;
  hullpack::CliArgs cli(
      "codec_bench", "FOLDER [options]",
      "The o3dgc coder and Draco (-cl 7 and -cl 10) side by side on every mesh file of FOLDER\n"
      "(one per name: .obj, else .glb, else .gltf .dae .stl .ply .off .fbx .wrl; joints and\n"
      "weights kept), at the same\n"
      "quantization: bytes, encode and decode time (median of interleaved repeats), largest\n"
      "position error, gzip'd ASCII stream bytes. Prints a table; --csv writes it.");
  cli.VersionDetail(std::string("o3dgc stream format ") + o3dgc::FormatVersionString());
  cli.Positional("FOLDER", &folders, 1, 1);
  cli.Int("--repeats", "N", 1, 1000, &s.repeats, "interleaved runs per codec, median time (5)");
  cli.String("--csv", "FILE", &s.csv, "also write the table as CSV");
  cli.Int("--qp", "N", 1, 30, &s.qp, "position bits (14)");
  cli.Int("--qn", "N", 1, 30, &s.qn, "normal bits (10)");
  cli.Int("--qt", "N", 1, 30, &s.qt, "texture coordinate bits (12)");
  cli.Value("--only", "A,B", "only these meshes (file names without extension)",
            [&s](const std::string& list) {
              for (size_t p = 0; p <= list.size();) {
                const size_t q = std::min(list.find(',', p), list.size());
                if (q > p) s.only.push_back(list.substr(p, q - p));
                p = q + 1;
              }
              return std::string();
            });
  cli.Value("--clock", "wall|cpu", "time wall clock (default) or the process's CPU time",
            [&s](const std::string& v) {
              if (v != "wall" && v != "cpu") return "takes wall or cpu, not '" + v + "'";
              s.cpu_clock = v == "cpu";
              return std::string();
            });
  cli.Flag("--ours-only", &s.ours_only, "skip Draco (profiling runs, size checks)");
  cli.Flag("--fast-decode", &s.fast_decode, "encode ours with EncodeParams::fast_decode");
  cli.Flag("--max-compression", &s.max_compression,
           "encode ours with EncodeParams::max_compression");
  cli.Flag("--parts", &s.parts, "also print the bytes of each part of our stream");
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  const std::string& folder = folders[0];
  // One file per name, the first of kFormats: the corpus holds some meshes both as .obj and .glb
  // (the .obj is the benchmarked one); other formats (robot parts as .dae and .stl) are read as
  // every program reads them.
  static const std::vector<std::string> kFormats = {"obj", "glb", "gltf", "dae", "stl",
                                                    "ply", "off", "fbx",  "wrl"};
  auto stem = [](const std::string& f) { return f.substr(0, f.rfind('.')); };
  std::vector<std::string> files;
  {
    std::vector<std::string> listed;
    if (!hullpack::ListFiles(folder, kFormats, &listed)) {
      std::fprintf(stderr, "codec_bench: %s: cannot open folder\n", folder.c_str());
      return 1;
    }
    for (const std::string& f : listed) {
      const size_t rank = std::find(kFormats.begin(), kFormats.end(), hullpack::LowerExtension(f)) -
                          kFormats.begin();
      const bool shadowed = std::any_of(listed.begin(), listed.end(), [&](const std::string& g) {
        return g != f && stem(g) == stem(f) &&
               size_t(std::find(kFormats.begin(), kFormats.end(), hullpack::LowerExtension(g)) -
                      kFormats.begin()) < rank;
      });
      if (!shadowed) files.push_back(f);
    }
  }
  if (!s.only.empty()) {
    std::vector<std::string> kept;
    for (const std::string& f : files) {
      if (std::find(s.only.begin(), s.only.end(), stem(f)) != s.only.end()) kept.push_back(f);
    }
    files = kept;
  }
  std::vector<Row> rows;
  std::printf(
      "%-18s %8s %8s | %8s %8s %8s | %6s %6s | %6s %6s %6s | %6s %6s %6s | %7s %7s | %9s %9s | %8s "
      "%6s\n",
      "mesh", "tris", "verts", "ours B", "cl7 B", "cl10 B", "/cl7", "/cl10", "enc", "cl7", "cl10",
      "dec", "cl7", "cl10", "enc/cl7", "dec/cl7", "err ours", "err cl10", "ascii.gz", "/bin");
  for (const std::string& file : files) {
    hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(folder + "/" + file);
    if (!scene.ok()) {
      std::fprintf(stderr, "codec_bench: %s\n", scene.status().message().c_str());
      continue;
    }
    const Mesh mesh = hullpack::MergeGeometry(scene.value(), true);
    Row row;
    row.name = stem(file);
    row.triangles = mesh.triangle_count();
    row.vertices = mesh.vertex_count();
    if (!RunAll(mesh, s, row)) {
      std::fprintf(stderr, "codec_bench: %s: a codec failed\n", file.c_str());
      continue;
    }
    std::printf(
        "%-18s %8zu %8zu | %8zu %8zu %8zu | %6.3f %6.3f | %6.2f %6.2f %6.2f | %6.2f %6.2f %6.2f | "
        "%7.2f %7.2f | %9.3g %9.3g | "
        "%8zu %6.3f\n",
        row.name.c_str(), row.triangles, row.vertices, row.bytes[0], row.bytes[1], row.bytes[2],
        double(row.bytes[0]) / row.bytes[1], double(row.bytes[0]) / row.bytes[2], row.encode_ms[0],
        row.encode_ms[1], row.encode_ms[2], row.decode_ms[0], row.decode_ms[1], row.decode_ms[2],
        row.encode_ratio7, row.decode_ratio7, row.error[0], row.error[2], row.ascii_gzip_bytes,
        double(row.ascii_gzip_bytes) / row.bytes[0]);
    if (s.parts) std::printf("  %s\n", PartBytes(row.info).c_str());
    rows.push_back(row);
  }
  double log7 = 0, log10 = 0, worst_ascii = 0;
  for (const Row& r : rows) {
    worst_ascii = std::max(worst_ascii, double(r.ascii_gzip_bytes) / r.bytes[0]);
    log7 += std::log(double(r.bytes[0]) / r.bytes[1]);
    log10 += std::log(double(r.bytes[0]) / r.bytes[2]);
  }
  if (!rows.empty() && !s.ours_only) {
    std::printf(
        "geometric mean of bytes: ours/cl7 %.3f, ours/cl10 %.3f over %zu meshes (median of %d "
        "interleaved runs per %s time)\n",
        std::exp(log7 / rows.size()), std::exp(log10 / rows.size()), rows.size(), s.repeats,
        s.cpu_clock ? "CPU" : "wall");
  }
  if (!rows.empty()) std::printf("largest gzip'd ASCII / binary: %.3f\n", worst_ascii);
  if (!s.csv.empty()) {
    std::string text =
        "mesh,triangles,vertices,ours_bytes,draco7_bytes,draco10_bytes,ours_encode_ms,draco7_"
        "encode_ms,draco10_encode_ms,"
        "ours_decode_ms,draco7_decode_ms,draco10_decode_ms,ours_max_error,draco7_max_error,draco10_"
        "max_error,"
        "ours_ascii_gzip_bytes,ours_over_draco7_encode,ours_over_draco7_decode\n";
    for (const Row& r : rows) {
      char line[512];
      std::snprintf(
          line, sizeof(line),
          "%s,%zu,%zu,%zu,%zu,%zu,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.6g,%.6g,%.6g,%zu,%.4f,%.4f\n",
          r.name.c_str(), r.triangles, r.vertices, r.bytes[0], r.bytes[1], r.bytes[2],
          r.encode_ms[0], r.encode_ms[1], r.encode_ms[2], r.decode_ms[0], r.decode_ms[1],
          r.decode_ms[2], r.error[0], r.error[1], r.error[2], r.ascii_gzip_bytes, r.encode_ratio7,
          r.decode_ratio7);
      text += line;
    }
    hullpack::Status st = hullpack::WriteFileAtomically(s.csv, text.data(), text.size());
    if (!st.ok()) {
      std::fprintf(stderr, "codec_bench: %s\n", st.message().c_str());
      return 1;
    }
  }
  return rows.size() == files.size() ? 0 : 1;
}
