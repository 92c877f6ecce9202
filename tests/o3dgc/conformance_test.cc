// Conformance vectors of the o3dgc stream format (tests/o3dgc/conformance/<major>.<minor>/):
//  - every committed stream of every released version decodes to exactly its committed mesh
//    (NAME.s3d -> NAME.txt), so that a later decoder still reads every stream from 1.0 on;
//  - the encoder's output for the fixed inputs below is byte for byte the committed stream of the
//    version it writes (the lowest version with the stream's features: a stream without the
//    features of 1.2 is a 1.1 stream): a change of the encoder's output without a new version
//    fails here.
// A deliberate change of what the encoder codes (not of how a version's bytes read) keeps the old
// stream as a vector of its own, with the parameters that still write it, and rewrites the vector
// of the default (see docs/o3dgc-stream-format.md, "Versions and the promise").
// The inputs are built with exact arithmetic only (no sin/cos), so they are the same bits on every
// platform. To write the vectors of a new version (after raising kFormatMinor):
//   O3DGC_WRITE_CONFORMANCE=1 build/tests/o3dgc/o3dgc_tests --gtest_filter='Conformance.*'
// and add the new folder to conformance/VERSIONS. Each stream goes to the folder of its version.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "o3dgc/o3dgc.h"
#include "test_meshes.h"

namespace o3dgc {
namespace {

using o3dgc_test::TestMesh;

std::string Dir() { return std::string(HULLPACK_SOURCE_DIR) + "/tests/o3dgc/conformance/"; }

std::string CurrentVersion() {
  return std::to_string(kFormatMajor) + "." + std::to_string(kFormatMinor);
}

bool ReadFile(const std::string& path, std::string* out) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::ostringstream s;
  s << f.rdbuf();
  *out = s.str();
  return true;
}

void WriteFile(const std::string& path, const std::string& data) {
  std::ofstream f(path, std::ios::binary);
  f << data;
  ASSERT_TRUE(f.good()) << path;
}

// The decoded mesh as text: every float printed with 9 significant digits (exact for float).
std::string Dump(const DecodedMesh& m) {
  std::string s;
  char buf[64];
  auto floats = [&](const char* tag, const std::vector<float>& v, size_t dim) {
    for (size_t i = 0; i < v.size(); i += dim) {
      s += tag;
      for (size_t k = 0; k < dim; ++k) {
        std::snprintf(buf, sizeof(buf), " %.9g", double(v[i + k]));
        s += buf;
      }
      s += "\n";
    }
  };
  s += "vertices " + std::to_string(m.num_vertices()) + "\ntriangles " +
       std::to_string(m.num_triangles()) + "\n";
  floats("v", m.positions, 3);
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    s += "f " + std::to_string(m.indices[i]) + " " + std::to_string(m.indices[i + 1]) + " " +
         std::to_string(m.indices[i + 2]) + "\n";
  }
  floats("n", m.normals, 3);
  for (const DecodedFloatAttribute& a : m.float_attributes) {
    s += "float_attribute semantic " + std::to_string(int(a.semantic)) + " dimension " +
         std::to_string(a.dimension) + "\n";
    floats("a", a.values, a.dimension);
  }
  for (const DecodedIntAttribute& a : m.int_attributes) {
    s += "int_attribute semantic " + std::to_string(int(a.semantic)) + " dimension " +
         std::to_string(a.dimension) + "\n";
    for (size_t i = 0; i < a.values.size(); i += a.dimension) {
      s += "i";
      for (size_t k = 0; k < a.dimension; ++k) s += " " + std::to_string(a.values[i + k]);
      s += "\n";
    }
  }
  for (uint32_t g : m.triangle_groups) s += "g " + std::to_string(g) + "\n";
  return s;
}

// A sphere made of a cube's faces (n x n quads each), projected with sqrt only; normals are the
// unit positions. With `uv_charts`, every cube face has its own UV chart (seams on the cube's
// edges).
TestMesh CubeSphere(int n, bool uv_charts) {
  TestMesh t;
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 2, 0}, {1, 0, 2}, {2, 0, 1}, {2, 1, 0}};
  for (int f = 0; f < 6; ++f) {
    const double side = f % 2 ? -1.0 : 1.0;
    const uint32_t base = uint32_t(t.nv());
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        double p[3];
        p[axes[f][0]] = side * (2.0 * i / n - 1);
        p[axes[f][1]] = 2.0 * j / n - 1;
        p[axes[f][2]] = side;
        const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (double& c : p) c /= len;
        t.positions.insert(t.positions.end(), {float(p[0]), float(p[1]), float(p[2])});
        t.normals.insert(t.normals.end(), {float(p[0]), float(p[1]), float(p[2])});
        t.uvs.insert(t.uvs.end(),
                     {float((f % 3) + double(i) / n) / 3, float((f / 3) + double(j) / n) / 2});
      }
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const uint32_t a = base + uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1),
                       d = c + 1;
        t.indices.insert(t.indices.end(), {a, b, d, a, d, c});
      }
    }
  }
  if (!uv_charts) t.uvs.clear();
  return t;
}

// A torus from the rational parametrisation of the circle, with colours and joint ids.
TestMesh RationalTorus(int n, int m) {
  TestMesh t;
  auto circle = [](int i, int count, double* c, double* s) {
    const double u = 4.0 * i / count - 2;  // t in [-2, 2): most of the circle, evenly enough
    *c = (1 - u * u) / (1 + u * u);
    *s = 2 * u / (1 + u * u);
  };
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) {
      double cu, su, cv, sv;
      circle(i, n, &cu, &su);
      circle(j, m, &cv, &sv);
      t.positions.insert(t.positions.end(),
                         {float((2 + 0.5 * cv) * cu), float((2 + 0.5 * cv) * su), float(0.5 * sv)});
      t.colors.insert(t.colors.end(), {float(i) / n, float(j) / m, 0.5f, 1.0f});
      t.joints.insert(t.joints.end(), {i % 3, j % 5, 1000 + i, -7});
    }
  }
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * n + i), b = uint32_t(j * n + (i + 1) % n),
                     c = uint32_t(((j + 1) % m) * n + i),
                     d = uint32_t(((j + 1) % m) * n + (i + 1) % n);
      t.indices.insert(t.indices.end(), {a, b, d, a, d, c});
    }
  }
  return t;
}

struct Vector {
  std::string name;
  std::function<TestMesh()> mesh;
  std::function<void(EncodeParams*)> params;
  bool uvs_as_generic = false;  // the 2-component attribute coded as kGeneric (parallelogram)
};

std::vector<Vector> Vectors() {
  auto none = [](EncodeParams*) {};
  return {
      {"empty", [] { return TestMesh(); }, none},
      {"points_only",
       [] {
         TestMesh t = CubeSphere(2, false);
         t.indices.clear();
         t.normals.clear();
         return t;
       },
       none},
      {"positions",
       [] {
         TestMesh t = CubeSphere(4, false);
         t.normals.clear();
         return t;
       },
       none},
      {"positions_differential_per_axis",
       [] {
         TestMesh t = CubeSphere(3, false);
         t.normals.clear();
         return t;
       },
       [](EncodeParams* p) {
         p->position_prediction = Prediction::kDifferential;
         p->position_range = RangeMode::kPerAxis;
         p->position_bits = 11;
       }},
      {"positions_none_diagonal",
       [] {
         TestMesh t = CubeSphere(3, false);
         t.normals.clear();
         return t;
       },
       [](EncodeParams* p) {
         p->position_prediction = Prediction::kNone;
         p->position_range = RangeMode::kDiagonal;
       }},
      {"normals_surface", [] { return CubeSphere(4, false); }, none},
      {"normals_parallelogram", [] { return CubeSphere(3, false); },
       [](EncodeParams* p) {
         p->normal_prediction = Prediction::kParallelogram;
         p->normal_bits = 8;
       }},
      {"texcoord_seams", [] { return CubeSphere(4, true); }, none},
      {"generic_float_attribute", [] { return CubeSphere(3, true); }, none, true},
      {"colors_joints", [] { return RationalTorus(12, 8); }, none},
      {"awkward_groups", [] { return o3dgc_test::Awkward(); }, none},
      // Every triangle, the degenerate one too (EncodeParams::keep_degenerate_triangles): the
      // stream "awkward_groups" was before the encoder left degenerate triangles out by default.
      {"awkward_groups_all_triangles", [] { return o3dgc_test::Awkward(); },
       [](EncodeParams* p) { p->keep_degenerate_triangles = true; }},
      // From 1.1: an STL-style CAD part (fans, slivers, holes and pockets) whose connectivity
      // uses walks along the front.
      {"cad_pocket_plate", [] { return o3dgc_test::PocketPlate(3, 2); }, none},
      {"keep_order", [] { return o3dgc_test::Awkward(); },
       [](EncodeParams* p) { p->keep_order = true; }},
      {"keep_order_torus", [] { return RationalTorus(9, 6); },
       [](EncodeParams* p) { p->keep_order = true; }},
      {"fast_decode", [] { return CubeSphere(4, true); },
       [](EncodeParams* p) { p->fast_decode = true; }},
      {"ascii", [] { return CubeSphere(3, true); },
       [](EncodeParams* p) { p->stream_type = StreamType::kAscii; }},
      // Above the vertex count from which residual low bits are coded raw (kRawLowBitsMesh):
      // 4706 position vertices once the cube's edges are welded (parallelogram selection on), and
      // a smooth torus of 4800 (selection off).
      {"large_raw_bits",
       [] {
         TestMesh t = CubeSphere(28, false);
         t.normals.clear();
         return t;
       },
       none},
      {"large_raw_bits_smooth",
       [] {
         TestMesh t = RationalTorus(80, 60);
         t.colors.clear();
         t.joints.clear();
         return t;
       },
       [](EncodeParams* p) { p->auto_fast_decode = false; }},
      // From 1.2: a model built on a design grid, whose positions and texture coordinates take
      // modelled low bits, and the same as ASCII.
      {"grid_blocks", [] { return o3dgc_test::GridBlocks(5, 4); }, none},
      {"grid_blocks_ascii", [] { return o3dgc_test::GridBlocks(4, 3); },
       [](EncodeParams* p) { p->stream_type = StreamType::kAscii; }},
      // From 1.3: max_compression, whose large sections code their low bits adaptively: the
      // positions of the large cube-sphere, then the same with its normals and texture charts,
      // and a smooth torus with colours.
      {"max_compression",
       [] {
         TestMesh t = CubeSphere(28, false);
         t.normals.clear();
         return t;
       },
       [](EncodeParams* p) { p->max_compression = true; }},
      {"max_compression_attributes", [] { return CubeSphere(28, true); },
       [](EncodeParams* p) { p->max_compression = true; }},
      {"max_compression_colors",
       [] {
         TestMesh t = RationalTorus(80, 60);
         t.joints.clear();
         return t;
       },
       [](EncodeParams* p) { p->max_compression = true; }},
  };
}

MeshView ViewOf(const TestMesh& t, const Vector& v) {
  MeshView view = t.View();
  if (v.uvs_as_generic) {
    for (FloatAttributeView& a : view.float_attributes) {
      if (a.semantic == Semantic::kTexCoord) a.semantic = Semantic::kGeneric;
    }
  }
  return view;
}

std::vector<std::string> Versions() {
  std::string text;
  EXPECT_TRUE(ReadFile(Dir() + "VERSIONS", &text));
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') out.push_back(line);
  }
  return out;
}

bool Writing() { return std::getenv("O3DGC_WRITE_CONFORMANCE") != nullptr; }

TEST(Conformance, EncoderOutputIsFrozenForTheCurrentVersion) {
  for (const Vector& v : Vectors()) {
    SCOPED_TRACE(v.name);
    const TestMesh t = v.mesh();
    EncodeParams p;
    v.params(&p);
    std::vector<uint8_t> stream;
    ASSERT_EQ(Encode(ViewOf(t, v), p, &stream), Status::kOk);
    const std::string bytes(stream.begin(), stream.end());
    StreamInfo written;
    ASSERT_EQ(ReadStreamInfo(stream.data(), stream.size(), &written), Status::kOk);
    ASSERT_EQ(written.version_major, kFormatMajor);
    ASSERT_LE(written.version_minor, kFormatMinor);
    const std::string dir = Dir() + std::to_string(written.version_major) + "." +
                            std::to_string(written.version_minor) + "/";
    if (Writing()) {
      WriteFile(dir + v.name + ".s3d", bytes);
      DecodedMesh m;
      ASSERT_EQ(Decode(stream.data(), stream.size(), DecodeOptions(), &m), Status::kOk);
      WriteFile(dir + v.name + ".txt", Dump(m));
      continue;
    }
    std::string expected;
    ASSERT_TRUE(ReadFile(dir + v.name + ".s3d", &expected)) << dir << v.name << ".s3d";
    EXPECT_TRUE(bytes == expected)
        << "the encoder's output for this fixed input changed without a format version change: "
           "restore it, or raise kFormatMinor and write the vectors of the new version (see the "
           "top of this file)";
  }
}

TEST(Conformance, EveryVectorOfEveryVersionDecodesToItsMesh) {
  const std::vector<std::string> versions = Versions();
  ASSERT_FALSE(versions.empty());
  EXPECT_EQ(versions.back(), CurrentVersion());
  size_t checked = 0;
  for (const std::string& version : versions) {
    for (const Vector& v : Vectors()) {
      SCOPED_TRACE(version + "/" + v.name);
      std::string stream, expected;
      if (!ReadFile(Dir() + version + "/" + v.name + ".s3d", &stream)) continue;
      ASSERT_TRUE(ReadFile(Dir() + version + "/" + v.name + ".txt", &expected));
      const uint8_t* data = reinterpret_cast<const uint8_t*>(stream.data());
      DecodedMesh m;
      StreamInfo info;
      ASSERT_EQ(Decode(data, stream.size(), DecodeOptions(), &m, &info), Status::kOk);
      EXPECT_TRUE(Dump(m) == expected) << "decoded mesh differs from " << v.name << ".txt";
      StreamInfo read;
      ASSERT_EQ(ReadStreamInfo(data, stream.size(), &read), Status::kOk);
      EXPECT_EQ(std::to_string(read.version_major) + "." + std::to_string(read.version_minor),
                version);
      EXPECT_EQ(read.num_vertices, m.num_vertices());
      EXPECT_EQ(read.num_triangles, m.num_triangles());
      ++checked;
    }
  }
  EXPECT_GE(checked, Vectors().size());
}

// Every byte matters: a stream with any single bit flipped is rejected or decodes to a different
// mesh, never to the committed one silently (the CRC covers the payload).
TEST(Conformance, FlippedBitsAreDetected) {
  std::string stream;
  ASSERT_TRUE(ReadFile(Dir() + "1.2/grid_blocks.s3d", &stream));  // small: one decode per bit
  for (size_t i = 0; i < stream.size(); ++i) {
    std::vector<uint8_t> c(stream.begin(), stream.end());
    c[i] ^= uint8_t(1u << (i % 8));
    DecodedMesh m;
    EXPECT_NE(Decode(c.data(), c.size(), DecodeOptions(), &m), Status::kOk) << "byte " << i;
  }
}

}  // namespace
}  // namespace o3dgc
