// test_o3dgc: compress a mesh file to an o3dgc stream (.s3d) or decompress one to OBJ.
//
//   test_o3dgc -c -i bunny.obj [-st binary|ascii] [-qc 14] [-qn 10] [-qt 12] [-keep]
//       writes bunny.s3d next to the input
//   test_o3dgc -d -i bunny.s3d
//       writes bunny_dec.obj next to the input
// Material names (the stream keeps only per-triangle group ids) go to a side file bunny.mat, one
// name per line in id order, which -d reads back when it exists.
// Every mesh of the input is merged into one (material ids become triangle groups, written back
// as usemtl groups). Prints mesh info, timings, stream size and the size of each part.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/scene_io.h"
#include "o3dgc/o3dgc.h"
#include "scene/scene.h"

namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

int Usage() {
  std::fprintf(stderr,
               "usage: test_o3dgc -c -i <mesh> [-st binary|ascii] [-qc bits] [-qn bits] [-qt bits] "
               "[-keep]\n       test_o3dgc -d -i <stream.s3d>\n");
  return 2;
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

int Compress(const std::string& input, o3dgc::EncodeParams params, int uv_bits) {
  hullpack::Result<hullpack::Scene> scene = hullpack::ReadScene(input);
  if (!scene.ok()) {
    std::fprintf(stderr, "%s\n", scene.status().ToString().c_str());
    return 1;
  }
  // Merge every mesh into one; keep an attribute only if every mesh has it.
  hullpack::Mesh all;
  bool normals = true, uvs = true, colors = true, skin = true, materials = false;
  for (const hullpack::Mesh& m : scene->meshes) {
    normals = normals && !m.normals.empty();
    uvs = uvs && !m.uv_sets.empty();
    colors = colors && !m.colors.empty();
    skin = skin && m.has_skin();
    materials = materials || !m.material_ids.empty();
  }
  if (scene->meshes.empty()) normals = uvs = colors = skin = false;
  all.uv_sets.resize(uvs ? 1 : 0);
  for (const hullpack::Mesh& m : scene->meshes) {
    const uint32_t base = uint32_t(all.vertex_count());
    all.positions.insert(all.positions.end(), m.positions.begin(), m.positions.end());
    for (uint32_t i : m.indices) all.indices.push_back(base + i);
    if (normals) all.normals.insert(all.normals.end(), m.normals.begin(), m.normals.end());
    if (uvs) all.uv_sets[0].insert(all.uv_sets[0].end(), m.uv_sets[0].begin(), m.uv_sets[0].end());
    if (colors) all.colors.insert(all.colors.end(), m.colors.begin(), m.colors.end());
    if (skin) {
      all.joints.insert(all.joints.end(), m.joints.begin(), m.joints.end());
      all.weights.insert(all.weights.end(), m.weights.begin(), m.weights.end());
    }
    if (materials) {
      for (size_t t = 0; t < m.triangle_count(); ++t) {
        all.material_ids.push_back(m.material_ids.empty() ? 0 : m.material_ids[t]);
      }
    }
  }
  o3dgc::MeshView view;
  view.positions = all.positions.data();
  view.num_vertices = all.vertex_count();
  view.indices = all.indices.data();
  view.num_triangles = all.triangle_count();
  if (normals) view.normals = all.normals.data();
  if (uvs) {
    o3dgc::FloatAttributeView a;
    a.data = all.uv_sets[0].data();
    a.dimension = 2;
    a.semantic = o3dgc::Semantic::kTexCoord;
    a.bits = uv_bits;
    view.float_attributes.push_back(a);
  }
  if (colors) {
    o3dgc::FloatAttributeView a;
    a.data = all.colors.data();
    a.dimension = 4;
    a.semantic = o3dgc::Semantic::kColor;
    a.bits = 8;
    view.float_attributes.push_back(a);
  }
  std::vector<int32_t> joints(all.joints.begin(), all.joints.end());
  if (skin) {
    o3dgc::FloatAttributeView w;
    w.data = all.weights.data();
    w.dimension = 4;
    w.semantic = o3dgc::Semantic::kWeight;
    w.bits = 10;
    view.float_attributes.push_back(w);
    o3dgc::IntAttributeView j;
    j.data = joints.data();
    j.dimension = 4;
    j.semantic = o3dgc::Semantic::kJointId;
    view.int_attributes.push_back(j);
  }
  if (materials) view.triangle_groups = all.material_ids.data();

  std::printf("Mesh info\n  vertices %zu\n  triangles %zu\n  normals %s\n  uv %s\n  colors %s\n"
              "  skin %s\n  groups %s\n",
              view.num_vertices, view.num_triangles, normals ? "yes" : "no", uvs ? "yes" : "no",
              colors ? "yes" : "no", skin ? "yes" : "no", materials ? "yes" : "no");
  std::vector<uint8_t> stream;
  o3dgc::StreamInfo info;
  const auto t0 = Clock::now();
  const o3dgc::Status s = o3dgc::Encode(view, params, &stream, &info);
  const auto t1 = Clock::now();
  if (s != o3dgc::Status::kOk) {
    std::fprintf(stderr, "encode failed: %s\n", o3dgc::StatusName(s));
    return 1;
  }
  const std::string out = Stem(input) + ".s3d";
  std::ofstream f(out, std::ios::binary);
  f.write(reinterpret_cast<const char*>(stream.data()), std::streamsize(stream.size()));
  if (!f) {
    std::fprintf(stderr, "cannot write %s\n", out.c_str());
    return 1;
  }
  if (materials) {
    std::ofstream mat(Stem(input) + ".mat");
    for (const hullpack::Material& m : scene->materials) mat << m.name << "\n";
  }
  std::printf("Encode time %.2f ms\nStream %s (%s), %zu bytes\n", Ms(t0, t1), out.c_str(),
              params.stream_type == o3dgc::StreamType::kAscii ? "ascii" : "binary", stream.size());
  PrintParts(info, view.num_vertices);
  return 0;
}

int Decompress(const std::string& input) {
  std::ifstream f(input, std::ios::binary);
  if (!f) {
    std::fprintf(stderr, "cannot read %s\n", input.c_str());
    return 1;
  }
  const std::vector<uint8_t> stream((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  o3dgc::DecodedMesh mesh;
  o3dgc::StreamInfo info;
  const auto t0 = Clock::now();
  const o3dgc::Status s = o3dgc::Decode(stream.data(), stream.size(), o3dgc::DecodeOptions(), &mesh, &info);
  const auto t1 = Clock::now();
  if (s != o3dgc::Status::kOk) {
    std::fprintf(stderr, "decode failed: %s\n", o3dgc::StatusName(s));
    return 1;
  }
  hullpack::Scene scene;
  hullpack::Mesh m;
  m.name = "decoded";
  m.positions = mesh.positions;
  m.indices = mesh.indices;
  m.normals = mesh.normals;
  for (const auto& a : mesh.float_attributes) {
    if (a.semantic == o3dgc::Semantic::kTexCoord && a.dimension == 2) m.uv_sets.push_back(a.values);
    if (a.semantic == o3dgc::Semantic::kColor && a.dimension == 4) m.colors = a.values;
    if (a.semantic == o3dgc::Semantic::kWeight && a.dimension == 4) m.weights = a.values;
  }
  for (const auto& a : mesh.int_attributes) {
    if (a.semantic == o3dgc::Semantic::kJointId && a.dimension == 4) {
      m.joints.assign(a.values.begin(), a.values.end());
    }
  }
  if (!mesh.triangle_groups.empty()) {
    uint32_t max_id = 0;
    for (uint32_t g : mesh.triangle_groups) max_id = g > max_id ? g : max_id;
    if (max_id < 65536) {
      std::vector<std::string> names;
      std::ifstream mat(Stem(input) + ".mat");
      for (std::string line; std::getline(mat, line);) names.push_back(line);
      m.material_ids = mesh.triangle_groups;
      for (uint32_t g = 0; g <= max_id; ++g) {
        hullpack::Material material;
        material.name = g < names.size() && !names[g].empty() ? names[g] : "group_" + std::to_string(g);
        scene.materials.push_back(material);
      }
    }
  }
  scene.meshes.push_back(std::move(m));
  hullpack::AddRootNodeForAllMeshes(scene, "decoded");
  const std::string out = Stem(input) + "_dec.obj";
  const hullpack::Status w = hullpack::WriteScene(scene, out);
  if (!w.ok()) {
    std::fprintf(stderr, "%s\n", w.ToString().c_str());
    return 1;
  }
  std::printf("Mesh info\n  vertices %zu\n  triangles %zu\nDecode time %.2f ms\nWrote %s\n",
              mesh.num_vertices(), mesh.num_triangles(), Ms(t0, t1), out.c_str());
  PrintParts(info, mesh.num_vertices());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  bool compress = false, decompress = false;
  std::string input;
  o3dgc::EncodeParams params;
  int uv_bits = 12;
  params.position_bits = 14;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next_int = [&](int* v) {
      if (i + 1 >= argc) return false;
      *v = std::atoi(argv[++i]);
      return true;
    };
    if (a == "-c") {
      compress = true;
    } else if (a == "-d") {
      decompress = true;
    } else if (a == "-i" && i + 1 < argc) {
      input = argv[++i];
    } else if (a == "-st" && i + 1 < argc) {
      const std::string t = argv[++i];
      if (t == "ascii") {
        params.stream_type = o3dgc::StreamType::kAscii;
      } else if (t == "binary") {
        params.stream_type = o3dgc::StreamType::kBinary;
      } else {
        return Usage();
      }
    } else if (a == "-qc") {
      if (!next_int(&params.position_bits)) return Usage();
    } else if (a == "-qn") {
      if (!next_int(&params.normal_bits)) return Usage();
    } else if (a == "-qt") {
      if (!next_int(&uv_bits)) return Usage();
    } else if (a == "-keep") {
      params.keep_order = true;
    } else {
      return Usage();
    }
  }
  if (input.empty() || compress == decompress) return Usage();
  if (uv_bits < 1 || uv_bits > 30) return Usage();
  return compress ? Compress(input, params, uv_bits) : Decompress(input);
}
