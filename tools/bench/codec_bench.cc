// codec_bench: the project's SC3DMC coder and Draco side by side on every mesh of a folder, in one
// run, at the same quantization (default 14-bit positions, 10-bit normals, 12-bit UVs; Draco at -cl 7
// and -cl 10): bytes, bits per vertex, encode and decode time (median of repeats), maximum position
// error. Prints a table and writes CSV.
//
//   codec_bench FOLDER [--repeats 5] [--csv out.csv] [--qp 14] [--qn 10] [--qt 12]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/draco_bridge.h"
#include "common/file_util.h"
#include "io/scene_io.h"
#include "pipeline/mesh_codec.h"

namespace {

using hullpack::Mesh;

struct Settings {
  int repeats = 5, qp = 14, qn = 10, qt = 12;
  std::string csv;
};

// Every mesh of the file as one: the codecs compress one mesh at a time.
Mesh Merge(const hullpack::Scene& scene) {
  Mesh out;
  bool normals = true, uvs = true;
  for (const Mesh& m : scene.meshes) {
    normals = normals && !m.normals.empty();
    uvs = uvs && !m.uv_sets.empty();
  }
  if (uvs) out.uv_sets.emplace_back();
  for (const Mesh& m : scene.meshes) {
    const uint32_t base = static_cast<uint32_t>(out.vertex_count());
    out.positions.insert(out.positions.end(), m.positions.begin(), m.positions.end());
    if (normals) out.normals.insert(out.normals.end(), m.normals.begin(), m.normals.end());
    if (uvs) out.uv_sets[0].insert(out.uv_sets[0].end(), m.uv_sets[0].begin(), m.uv_sets[0].end());
    for (uint32_t i : m.indices) out.indices.push_back(base + i);
  }
  return out;
}

struct Row {
  std::string name;
  size_t triangles = 0, vertices = 0;
  size_t bytes[3] = {0, 0, 0};  // ours, draco cl7, draco cl10
  double encode_ms[3] = {0, 0, 0}, decode_ms[3] = {0, 0, 0}, error[3] = {0, 0, 0};
};

bool RunDraco(const Mesh& mesh, const Settings& s, int level, Row& row, int slot) {
  std::unique_ptr<draco::Mesh> d = hullpack::ToDracoMesh(mesh);
  if (!d) return false;
  std::vector<uint8_t> bytes;
  row.encode_ms[slot] = hullpack::MedianMs(s.repeats, [&] { bytes = hullpack::DracoEncode(*d, s.qp, s.qn, s.qt, level); });
  if (bytes.empty()) return false;
  row.bytes[slot] = bytes.size();
  Mesh decoded;
  row.decode_ms[slot] = hullpack::MedianMs(s.repeats, [&] { decoded = hullpack::DracoDecodePositions(bytes); });
  if (decoded.positions.empty()) return false;
  row.error[slot] = hullpack::MaxVertexDistance(mesh, decoded);
  return true;
}

bool RunOurs(const Mesh& mesh, const Settings& s, Row& row) {
  hullpack::MeshCodecSettings cs;
  cs.position_bits = s.qp;
  cs.normal_bits = s.qn;
  cs.uv_bits = s.qt;
  hullpack::Result<hullpack::EncodedMesh> encoded = hullpack::Status(hullpack::StatusCode::kInternal, "");
  row.encode_ms[0] = hullpack::MedianMs(s.repeats, [&] { encoded = hullpack::EncodeMesh(mesh, {}, cs); });
  if (!encoded.ok()) return false;
  row.bytes[0] = encoded->stream.size();
  hullpack::Result<Mesh> decoded = hullpack::Status(hullpack::StatusCode::kInternal, "");
  row.decode_ms[0] = hullpack::MedianMs(s.repeats, [&] {
    decoded = hullpack::DecodeMesh(encoded->stream.data(), encoded->stream.size(), nullptr, row.name);
  });
  if (!decoded.ok()) return false;
  row.error[0] = hullpack::MaxVertexDistance(mesh, decoded.value());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: codec_bench FOLDER [--repeats N] [--csv FILE] [--qp N] [--qn N] [--qt N]\n");
    return 64;
  }
  Settings s;
  const std::string folder = argv[1];
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--repeats") s.repeats = std::max(1, std::atoi(argv[i + 1]));
    else if (flag == "--csv") s.csv = argv[i + 1];
    else if (flag == "--qp") s.qp = std::atoi(argv[i + 1]);
    else if (flag == "--qn") s.qn = std::atoi(argv[i + 1]);
    else if (flag == "--qt") s.qt = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "codec_bench: unknown option %s\n", flag.c_str());
      return 64;
    }
  }
  std::vector<std::string> files;
  if (!hullpack::ListFiles(folder, {"obj"}, &files)) {
    std::fprintf(stderr, "codec_bench: %s: cannot open folder\n", folder.c_str());
    return 1;
  }
  std::vector<Row> rows;
  std::printf("%-18s %8s %8s | %8s %8s %8s | %6s %6s | %6s %6s %6s | %6s %6s %6s | %9s %9s\n", "mesh", "tris", "verts",
              "ours B", "cl7 B", "cl10 B", "/cl7", "/cl10", "enc", "cl7", "cl10", "dec", "cl7", "cl10", "err ours",
              "err cl10");
  for (const std::string& file : files) {
    hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(folder + "/" + file);
    if (!scene.ok()) {
      std::fprintf(stderr, "codec_bench: %s\n", scene.status().message().c_str());
      continue;
    }
    const Mesh mesh = Merge(scene.value());
    Row row;
    row.name = file.substr(0, file.size() - 4);
    row.triangles = mesh.triangle_count();
    row.vertices = mesh.vertex_count();
    if (!RunOurs(mesh, s, row) || !RunDraco(mesh, s, 7, row, 1) || !RunDraco(mesh, s, 10, row, 2)) {
      std::fprintf(stderr, "codec_bench: %s: a codec failed\n", file.c_str());
      continue;
    }
    std::printf("%-18s %8zu %8zu | %8zu %8zu %8zu | %6.3f %6.3f | %6.1f %6.1f %6.1f | %6.1f %6.1f %6.1f | %9.3g %9.3g\n",
                row.name.c_str(), row.triangles, row.vertices, row.bytes[0], row.bytes[1], row.bytes[2],
                double(row.bytes[0]) / row.bytes[1], double(row.bytes[0]) / row.bytes[2], row.encode_ms[0],
                row.encode_ms[1], row.encode_ms[2], row.decode_ms[0], row.decode_ms[1], row.decode_ms[2], row.error[0],
                row.error[2]);
    rows.push_back(row);
  }
  double log7 = 0, log10 = 0;
  for (const Row& r : rows) {
    log7 += std::log(double(r.bytes[0]) / r.bytes[1]);
    log10 += std::log(double(r.bytes[0]) / r.bytes[2]);
  }
  if (!rows.empty()) {
    std::printf("geometric mean of bytes: ours/cl7 %.3f, ours/cl10 %.3f over %zu meshes (median of %d runs per time)\n",
                std::exp(log7 / rows.size()), std::exp(log10 / rows.size()), rows.size(), s.repeats);
  }
  if (!s.csv.empty()) {
    std::string text =
        "mesh,triangles,vertices,ours_bytes,draco7_bytes,draco10_bytes,ours_encode_ms,draco7_encode_ms,draco10_encode_ms,"
        "ours_decode_ms,draco7_decode_ms,draco10_decode_ms,ours_max_error,draco7_max_error,draco10_max_error\n";
    for (const Row& r : rows) {
      char line[512];
      std::snprintf(line, sizeof(line), "%s,%zu,%zu,%zu,%zu,%zu,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.6g,%.6g,%.6g\n",
                    r.name.c_str(), r.triangles, r.vertices, r.bytes[0], r.bytes[1], r.bytes[2], r.encode_ms[0],
                    r.encode_ms[1], r.encode_ms[2], r.decode_ms[0], r.decode_ms[1], r.decode_ms[2], r.error[0], r.error[1],
                    r.error[2]);
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
