// test_o3dgc: compress a mesh file to an o3dgc stream (.s3d) or decompress one to OBJ.
//
//   test_o3dgc -c -i bunny.obj [-st binary|ascii] [-qc 14] [-qn 10] [-qt 12] [-keep] [-fast]
//       writes bunny.s3d next to the input
//   test_o3dgc -d -i bunny.s3d
//       writes bunny_dec.obj next to the input; also reads streams of the original Open3DGC tool
//       (2013), written out in that tool's OBJ layout
// The single-dash options are the original tool's spellings; each has the long name the other
// programs use (--compress, --input, --qp, --keep-order, ...), see --help.
// Material names (the stream keeps only per-triangle group ids) go to a side file bunny.mat, one
// name per line in id order, which -d reads back when it exists.
// Every mesh of the input is merged into one (material ids become triangle groups, written back
// as usemtl groups). Prints mesh info, timings, stream size and the size of each part.
#include <chrono>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/cli_args.h"
#include "common/file_util.h"
#include "io/scene_io.h"
#include "mesh/flatten.h"
#include "o3dgc/o3dgc.h"
#include "pipeline/mesh_codec.h"
#include "scene/scene.h"

namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

std::string Stem(const std::string& path) {
  const size_t dot = path.rfind('.');
  const size_t slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
  return path.substr(0, dot);
}

void PrintParts(const o3dgc::StreamInfo& info, size_t nv) {
  auto line = [&](const char* name, size_t bytes) {
    std::printf("  %-14s %10zu bytes  %7.3f bits/vertex\n", name, bytes,
                nv ? double(bytes) * 8 / double(nv) : 0.0);
  };
  line("header", info.header);
  line("connectivity", info.connectivity);
  line("positions", info.positions);
  if (info.normals) line("normals", info.normals);
  for (size_t i = 0; i < info.float_attributes.size(); ++i) {
    const std::string n = "float attr " + std::to_string(i);
    line(n.c_str(), info.float_attributes[i]);
  }
  for (size_t i = 0; i < info.int_attributes.size(); ++i) {
    const std::string n = "int attr " + std::to_string(i);
    line(n.c_str(), info.int_attributes[i]);
  }
  if (info.groups) line("groups", info.groups);
  line("total", info.total);
}

int Compress(const std::string& input, const hullpack::MeshCodecSettings& settings) {
  hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(input);
  if (!scene.ok()) {
    std::fprintf(stderr, "%s\n", scene.status().ToString().c_str());
    return 1;
  }
  const hullpack::Mesh all = hullpack::FlattenScene(scene.value());
  std::printf(
      "Mesh info\n  vertices %zu\n  triangles %zu\n  normals %s\n  uv %s\n  colors %s\n"
      "  skin %s\n  groups %s\n",
      all.vertex_count(), all.triangle_count(), all.normals.empty() ? "no" : "yes",
      all.uv_sets.empty() ? "no" : "yes", all.colors.empty() ? "no" : "yes",
      all.has_skin() ? "yes" : "no", all.material_ids.empty() ? "no" : "yes");
  const auto t0 = Clock::now();
  hullpack::Result<hullpack::EncodedMesh> encoded =
      hullpack::EncodeMesh(all, all.material_ids, settings);
  const auto t1 = Clock::now();
  if (!encoded.ok()) {
    std::fprintf(stderr, "%s: %s\n", input.c_str(), encoded.status().message().c_str());
    return 1;
  }
  const std::string out = Stem(input) + ".s3d";
  hullpack::Status written = hullpack::WriteFileAtomically(out, encoded->stream);
  if (written.ok() && !all.material_ids.empty()) {  // material names, one per group id
    std::string names;
    for (const hullpack::Material& m : scene->materials) names += m.name + "\n";
    written = hullpack::WriteFileAtomically(Stem(input) + ".mat", names.data(), names.size());
  }
  if (!written.ok()) {
    std::fprintf(stderr, "%s\n", written.message().c_str());
    return 1;
  }
  std::printf("Encode time %.2f ms\nStream %s (%s), %zu bytes\n", Ms(t0, t1), out.c_str(),
              settings.stream_type == o3dgc::StreamType::kAscii ? "ascii" : "binary",
              encoded->stream.size());
  PrintParts(encoded->info, all.vertex_count());
  return 0;
}

// The original tool's material side file: "MaterialLib <lib>", "Materials <n>", then n lines
// "<id> <triangle count> <name>"; triangles come in runs, one run per line.
struct LegacyMaterials {
  std::string library;
  std::vector<uint32_t> ids, counts;
  std::vector<std::string> names;
};

bool ReadLegacyMaterials(const std::string& path, LegacyMaterials* m) {
  hullpack::Result<std::vector<uint8_t>> bytes = hullpack::ReadFileBytes(path);
  if (!bytes.ok()) return false;
  std::istringstream in(std::string(bytes->begin(), bytes->end()));
  std::string tag;
  size_t n = 0;
  if (!(in >> tag) || tag != "MaterialLib" || !(in >> m->library >> tag) || tag != "Materials" ||
      !(in >> n)) {
    return false;
  }
  for (size_t i = 0; i < n; ++i) {
    uint32_t id, count;
    std::string name;
    if (!(in >> id >> count >> name)) return false;
    m->ids.push_back(id);
    m->counts.push_back(count);
    m->names.push_back(name);
  }
  return true;
}

// Streams of the original Open3DGC tool decode to the OBJ layout that tool wrote (one index per
// corner for v, vt and vn; texture coordinates as stored, without this project's glTF v flip),
// with full float precision, and its material side file (<stem>.mat) when there is one.
int DecompressLegacy(const std::string& input, const std::vector<uint8_t>& stream) {
  o3dgc::DecodedMesh m;
  o3dgc::StreamInfo info;
  const auto t0 = Clock::now();
  const o3dgc::Status st =
      o3dgc::Decode(stream.data(), stream.size(), o3dgc::DecodeOptions(), &m, &info);
  const auto t1 = Clock::now();
  if (st != o3dgc::Status::kOk) {
    std::fprintf(stderr, "decode failed: %s: original Open3DGC stream: %s\n", input.c_str(),
                 o3dgc::StatusName(st));
    return 1;
  }
  const std::vector<float>* uv = nullptr;
  for (const o3dgc::DecodedFloatAttribute& a : m.float_attributes) {
    if (a.semantic == o3dgc::Semantic::kTexCoord && a.dimension == 2 && !uv) uv = &a.values;
  }
  LegacyMaterials mat;
  const bool materials = ReadLegacyMaterials(Stem(input) + ".mat", &mat);
  std::string obj =
      "# decoded by hullpack test_o3dgc from " + input + " (original Open3DGC stream)\n";
  char line[160];
  auto add = [&](const char* tag, const std::vector<float>& v, size_t dim) {
    for (size_t i = 0; i + dim <= v.size(); i += dim) {
      int n = std::snprintf(line, sizeof line, "%s", tag);
      for (size_t k = 0; k < dim; ++k)
        n += std::snprintf(line + n, sizeof line - size_t(n), " %.9g", double(v[i + k]));
      obj.append(line).push_back('\n');
    }
  };
  add("v", m.positions, 3);
  add("vn", m.normals, 3);
  if (uv) add("vt", *uv, 2);
  if (materials && !mat.library.empty()) obj += "mtllib " + mat.library + "\n";
  std::vector<uint32_t>
      material_of;  // per triangle, from the runs (the original's name lookup: by id)
  for (size_t i = 0; materials && i < mat.counts.size(); ++i) {
    for (uint32_t c = 0; c < mat.counts[i] && material_of.size() < m.num_triangles(); ++c)
      material_of.push_back(mat.ids[i]);
  }
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    if (t < material_of.size() && (t == 0 || material_of[t] != material_of[t - 1]) &&
        material_of[t] < mat.names.size()) {
      obj += "usemtl " + mat.names[material_of[t]] + "\n";
    }
    obj += "f";
    for (int k = 0; k < 3; ++k) {
      const unsigned i = m.indices[3 * t + size_t(k)] + 1;
      if (uv && !m.normals.empty()) {
        std::snprintf(line, sizeof line, " %u/%u/%u", i, i, i);
      } else if (!m.normals.empty()) {
        std::snprintf(line, sizeof line, " %u//%u", i, i);
      } else if (uv) {
        std::snprintf(line, sizeof line, " %u/%u", i, i);
      } else {
        std::snprintf(line, sizeof line, " %u", i);
      }
      obj += line;
    }
    obj += "\n";
  }
  const std::string out = Stem(input) + "_dec.obj";
  const hullpack::Status w = hullpack::WriteFileAtomically(out, obj.data(), obj.size());
  if (!w.ok()) {
    std::fprintf(stderr, "%s\n", w.message().c_str());
    return 1;
  }
  std::printf(
      "Original Open3DGC stream (%s)\nMesh info\n  vertices %zu\n  triangles %zu\n  normals %s\n  "
      "uv %s\n"
      "Decode time %.2f ms\nWrote %s\n",
      info.stream_type == o3dgc::StreamType::kAscii ? "ascii" : "binary", m.num_vertices(),
      m.num_triangles(), m.normals.empty() ? "no" : "yes", uv ? "yes" : "no", Ms(t0, t1),
      out.c_str());
  PrintParts(info, m.num_vertices());
  return 0;
}

int Decompress(const std::string& input) {
  hullpack::Result<std::vector<uint8_t>> stream = hullpack::ReadFileBytes(input);
  if (!stream.ok()) {
    std::fprintf(stderr, "%s\n", stream.status().message().c_str());
    return 1;
  }
  o3dgc::StreamInfo probe;
  if (o3dgc::ReadStreamInfo(stream->data(), stream->size(), &probe) == o3dgc::Status::kOk &&
      probe.format == o3dgc::StreamFormat::kOpen3dgc2013) {
    return DecompressLegacy(input, stream.value());
  }
  o3dgc::StreamInfo info;
  std::vector<uint32_t> groups;
  const auto t0 = Clock::now();
  hullpack::Result<hullpack::Mesh> mesh =
      hullpack::DecodeMesh(stream.value().data(), stream.value().size(), &groups, input, &info);
  const auto t1 = Clock::now();
  if (!mesh.ok()) {
    std::fprintf(stderr, "decode failed: %s\n", mesh.status().message().c_str());
    return 1;
  }
  hullpack::Scene scene;
  hullpack::Mesh& m = mesh.value();
  m.name = "decoded";
  if (!groups.empty()) {
    uint32_t max_id = 0;
    for (uint32_t g : groups) max_id = g > max_id ? g : max_id;
    if (max_id < 65536) {
      std::vector<std::string> names;
      hullpack::Result<std::vector<uint8_t>> mat = hullpack::ReadFileBytes(Stem(input) + ".mat");
      if (mat.ok()) {
        std::string line;
        for (uint8_t c : mat.value()) {
          if (c == '\n') {
            names.push_back(line);
            line.clear();
          } else {
            line.push_back(static_cast<char>(c));
          }
        }
      }
      m.material_ids = groups;
      for (uint32_t g = 0; g <= max_id; ++g) {
        hullpack::Material material;
        material.name =
            g < names.size() && !names[g].empty() ? names[g] : "group_" + std::to_string(g);
        scene.materials.push_back(material);
      }
    }
  }
  const size_t vertices = m.vertex_count(), triangles = m.triangle_count();
  scene.meshes.push_back(std::move(m));
  hullpack::AddRootNodeForAllMeshes(scene, "decoded");
  const std::string out = Stem(input) + "_dec.obj";
  const hullpack::Status w = hullpack::WriteScene(scene, out);
  if (!w.ok()) {
    std::fprintf(stderr, "%s\n", w.ToString().c_str());
    return 1;
  }
  std::printf("Mesh info\n  vertices %zu\n  triangles %zu\nDecode time %.2f ms\nWrote %s\n",
              vertices, triangles, Ms(t0, t1), out.c_str());
  PrintParts(info, vertices);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  bool compress = false, decompress = false;
  std::string input;
  std::vector<std::string> operands;
  hullpack::MeshCodecSettings settings;
  settings.color_bits = 8;
  hullpack::CliArgs cli(
      "test_o3dgc", "-c|-d -i INPUT [options]",
      "Compresses a mesh file (.obj .off .wrl .ply .stl .glb .gltf .fbx .dae) to an o3dgc stream\n"
      "NAME.s3d, or decompresses a stream (this project's or the original Open3DGC tool's) to\n"
      "NAME_dec.obj, both next to INPUT, where NAME is INPUT without its extension. The\n"
      "single-dash spellings are the original tool's.");
  cli.VersionDetail(std::string("writes o3dgc stream format ") +
                    std::to_string(o3dgc::kFormatMajor) + ".1, or " + o3dgc::FormatVersionString() +
                    " where modelled low bits pay; reads formats " +
                    std::to_string(o3dgc::kFormatMajor) + ".0 to " + o3dgc::FormatVersionString() +
                    " and original Open3DGC (2013) streams");
  cli.Flag("-c, --compress", &compress, "compress INPUT to NAME.s3d");
  cli.Flag("-d, --decompress", &decompress, "decompress the stream INPUT to NAME_dec.obj");
  cli.String("-i, --input", "INPUT", &input, "the file to read (or give it as the operand)");
  cli.Positional("INPUT", &operands, 0, 1);
  cli.Value("-st, --stream-type", "binary|ascii", "binary (default) or 7-bit ASCII stream",
            [&settings](const std::string& v) {
              if (v != "binary" && v != "ascii") return "takes binary or ascii, not '" + v + "'";
              settings.stream_type =
                  v == "ascii" ? o3dgc::StreamType::kAscii : o3dgc::StreamType::kBinary;
              return std::string();
            });
  cli.Action("--ascii", "the same as -st ascii",
             [&settings]() { settings.stream_type = o3dgc::StreamType::kAscii; });
  cli.Int("-qc, --qp", "BITS", 1, 30, &settings.position_bits, "position bits (14)");
  cli.Int("-qn, --qn", "BITS", 1, 30, &settings.normal_bits, "normal bits (10)");
  cli.Int("-qt, --qt", "BITS", 1, 30, &settings.uv_bits, "texture coordinate bits (12)");
  cli.Flag("-keep, --keep-order", &settings.keep_order,
           "keep vertex and triangle order exactly (larger)");
  cli.Flag("--keep-degenerate", &settings.keep_degenerate_triangles,
           "code triangles with two corners at one position too (left out by default)");
  cli.Flag("-fast, --fast-decode", &settings.fast_decode,
           "code values in vertex id order: faster decoding, a few % larger");
  cli.Flag("-max, --max-compression", &settings.max_compression,
           "the smallest stream (format 1.3): slower decoding");
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  if (settings.fast_decode && settings.max_compression)
    return cli.UsageError("-fast and -max exclude each other");
  if (compress == decompress) return cli.UsageError("give one of -c and -d");
  if (!operands.empty()) {
    if (!input.empty()) return cli.UsageError("give INPUT once (-i or operand)");
    input = operands[0];
  }
  if (input.empty()) return cli.UsageError("missing -i INPUT");
  return compress ? Compress(input, settings) : Decompress(input);
}
