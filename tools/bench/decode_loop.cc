// decode_loop: one codec decodes one mesh's stream N times, exactly as codec_bench times it
// (ours: hullpack::DecodeMesh; Draco: DracoDecodePositions), so that a profiler or an instruction
// counter sees the decoder alone:
//
//   decode_loop MESH [--codec ours|cl7|cl10] [--runs N] [--qp 14] [--qn 10] [--qt 12]
//               [--write STREAM]
//   valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*DecodeRuns*'
//       decode_loop MESH --codec cl7 --runs 3      (one command: instructions of 3 decodes)
//
// The stream is encoded once, untimed, with codec_bench's settings. Prints the stream's bytes and
// the median CPU time of one decode.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/draco_bridge.h"
#include "common/cli_args.h"
#include "common/file_util.h"
#include "io/scene_io.h"
#include "o3dgc/o3dgc.h"
#include "pipeline/mesh_codec.h"

namespace {

double CpuMs() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// The decodes, out of line so that callgrind can count this function alone; false on a failure.
__attribute__((noinline)) bool DecodeRuns(int level, const std::vector<uint8_t>& stream, int runs,
                                          std::vector<double>* ms) {
  for (int i = 0; i < runs; ++i) {
    const double t0 = CpuMs();
    bool ok;
    if (level == 0) {
      ok = hullpack::DecodeMesh(stream.data(), stream.size(), nullptr, "mesh").ok();
    } else {
      ok = !hullpack::DracoDecodePositions(stream).positions.empty();
    }
    ms->push_back(CpuMs() - t0);
    if (!ok) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths;
  std::string codec = "ours", write;
  int runs = 5, qp = 14, qn = 10, qt = 12;
  hullpack::CliArgs cli("decode_loop", "MESH [options]",
                        "Encodes MESH once with one codec (codec_bench's settings), then decodes "
                        "the stream\nN times; prints its bytes and the median CPU time of a "
                        "decode. For profilers and\ninstruction counts of one decoder.");
  cli.VersionDetail(std::string("o3dgc stream format ") + o3dgc::FormatVersionString());
  cli.Positional("MESH", &paths, 1, 1);
  cli.Value("--codec", "ours|cl7|cl10", "the codec (ours)", [&codec](const std::string& v) {
    if (v != "ours" && v != "cl7" && v != "cl10") return "takes ours, cl7 or cl10, not '" + v + "'";
    codec = v;
    return std::string();
  });
  cli.Int("--runs", "N", 1, 100000, &runs, "decodes (5)");
  cli.Int("--qp", "N", 1, 30, &qp, "position bits (14)");
  cli.Int("--qn", "N", 1, 30, &qn, "normal bits (10)");
  cli.Int("--qt", "N", 1, 30, &qt, "texture coordinate bits (12)");
  cli.String("--write", "STREAM", &write, "also write the stream to STREAM (e.g. for decoder_ab)");
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(paths[0]);
  if (!scene.ok()) {
    std::fprintf(stderr, "decode_loop: %s\n", scene.status().message().c_str());
    return 1;
  }
  const hullpack::Mesh mesh = hullpack::MergeGeometry(scene.value());
  const int level = codec == "ours" ? 0 : codec == "cl7" ? 7 : 10;
  std::vector<uint8_t> stream;
  if (level == 0) {
    hullpack::MeshCodecSettings cs;
    cs.position_bits = qp;
    cs.normal_bits = qn;
    cs.uv_bits = qt;
    hullpack::Result<hullpack::EncodedMesh> encoded = hullpack::EncodeMesh(mesh, {}, cs);
    if (encoded.ok()) stream = std::move(encoded->stream);
  } else {
    const std::unique_ptr<draco::Mesh> d = hullpack::ToDracoMesh(mesh);
    if (d) stream = hullpack::DracoEncode(*d, qp, qn, qt, level);
  }
  if (stream.empty()) {
    std::fprintf(stderr, "decode_loop: %s: %s cannot encode it\n", paths[0].c_str(), codec.c_str());
    return 1;
  }
  if (!write.empty()) {
    const hullpack::Status st = hullpack::WriteFileAtomically(write, stream);
    if (!st.ok()) {
      std::fprintf(stderr, "decode_loop: %s\n", st.message().c_str());
      return 1;
    }
  }
  std::vector<double> ms;
  if (!DecodeRuns(level, stream, runs, &ms)) {
    std::fprintf(stderr, "decode_loop: %s: %s cannot decode its stream\n", paths[0].c_str(),
                 codec.c_str());
    return 1;
  }
  std::sort(ms.begin(), ms.end());
  std::printf("%s %s: %zu bytes, %d decodes, median %.3f ms CPU\n", paths[0].c_str(), codec.c_str(),
              stream.size(), runs, ms[ms.size() / 2]);
  return 0;
}
