#include "io/ply_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io/ply_writer.h"

namespace hullpack {
namespace {

Result<Scene> Parse(const std::string& text, const std::string& name = "t.ply") {
  return ParsePly(reinterpret_cast<const uint8_t*>(text.data()), text.size(), name);
}

bool Mentions(const Scene& s, const std::string& what) {
  return std::any_of(s.dropped.begin(), s.dropped.end(),
                     [&](const std::string& line) { return line.find(what) != std::string::npos; });
}

// Two quads sharing an edge, with normals, uchar colours and per-vertex texture coordinates.
const char kQuadsAscii[] =
    "ply\n"
    "format ascii 1.0\n"
    "comment two quads\n"
    "element vertex 6\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property float s\nproperty float t\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    "property float quality\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 0 0 0 1 0 0 255 0 0 1\n"
    "1 0 0 0 0 1 0.5 0 0 255 0 1\n"
    "2 0 0 0 0 1 1 0 0 0 255 1\n"
    "0 1 0 0 0 1 0 1 255 255 0 1\n"
    "1 1 0 0 0 1 0.5 1 0 255 255 1\n"
    "2 1 0 0 0 1 1 1 51 102 153 1\n"
    "4 0 1 4 3\n"
    "4 1 2 5 4\n";

TEST(PlyReader, AsciiQuadsWithNormalsColoursAndTextureCoordinates) {
  Result<Scene> s = Parse(kQuadsAscii);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->meshes.size(), 1u);
  const Mesh& m = s->meshes[0];
  EXPECT_EQ(m.vertex_count(), 6u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4}));
  EXPECT_EQ(m.positions[3 * 5], 2.0f);
  EXPECT_EQ(m.positions[3 * 5 + 1], 1.0f);
  ASSERT_EQ(m.normals.size(), 18u);
  EXPECT_EQ(m.normals[2], 1.0f);
  ASSERT_EQ(m.uv_sets.size(), 1u);
  EXPECT_EQ(m.uv_sets[0][2 * 1], 0.5f);
  EXPECT_EQ(m.uv_sets[0][2 * 3 + 1], 0.0f);  // t = 1 is v = 0
  EXPECT_EQ(m.uv_sets[0][2 * 0 + 1], 1.0f);
  ASSERT_EQ(m.colors.size(), 24u);
  EXPECT_FLOAT_EQ(m.colors[4 * 5], 0.2f);
  EXPECT_FLOAT_EQ(m.colors[4 * 5 + 2], 0.6f);
  EXPECT_EQ(m.colors[4 * 5 + 3], 1.0f);  // no alpha: opaque
  EXPECT_TRUE(Mentions(s.value(), "vertex properties not kept: quality"));
  EXPECT_EQ(s->source_vertex_records, 6u);
}

// The bytes of `values` as `T`, in either byte order.
template <typename T>
void Put(std::string* out, T value, bool big_endian) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big_endian) std::reverse(b, b + sizeof(T));
  out->append(b, sizeof(T));
}

// A tetrahedron in binary: double positions, ushort colours with alpha, uint indices with an
// int32 count, and an `edge` element the reader skips.
std::string BinaryTetra(bool big_endian) {
  std::string s = std::string("ply\nformat ") +
                  (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\n"
                  "element vertex 4\n"
                  "property double x\nproperty double y\nproperty double z\n"
                  "property ushort red\nproperty ushort green\nproperty ushort blue\n"
                  "property ushort alpha\n"
                  "element face 4\n"
                  "property list int uint vertex_index\n"
                  "element edge 1\n"
                  "property int vertex1\nproperty int vertex2\n"
                  "end_header\n";
  const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int v = 0; v < 4; ++v) {
    for (int k = 0; k < 3; ++k) Put(&s, p[v][k], big_endian);
    for (int k = 0; k < 4; ++k) Put<uint16_t>(&s, k == v ? 65535 : 0, big_endian);
  }
  const uint32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& face : f) {
    Put<int32_t>(&s, 3, big_endian);
    for (uint32_t i : face) Put(&s, i, big_endian);
  }
  Put<int32_t>(&s, 0, big_endian);
  Put<int32_t>(&s, 1, big_endian);
  return s;
}

TEST(PlyReader, BinaryInEitherByteOrder) {
  for (bool big : {false, true}) {
    Result<Scene> s = Parse(BinaryTetra(big));
    ASSERT_TRUE(s.ok()) << s.status().ToString();
    const Mesh& m = s->meshes[0];
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3})) << big;
    EXPECT_EQ(m.positions, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1})) << big;
    ASSERT_EQ(m.colors.size(), 16u);
    EXPECT_EQ(m.colors[4 * 2 + 2], 1.0f);
    EXPECT_EQ(m.colors[4 * 2 + 0], 0.0f);
    EXPECT_EQ(m.colors[4 * 3 + 3], 1.0f);  // vertex 3's alpha
    EXPECT_EQ(m.colors[4 * 0 + 3], 0.0f);
    EXPECT_TRUE(Mentions(s.value(), "1 'edge' records not kept"));
  }
}

TEST(PlyReader, ReadsWhatThePlyWriterWrites) {
  Scene scene;
  Mesh mesh;
  mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5f};
  mesh.indices = {0, 1, 2, 2, 1, 3};
  mesh.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  mesh.uv_sets = {{0, 0.25f, 1, 0.25f, 0, 0.75f, 1, 1}};
  mesh.colors = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1};
  scene.meshes.push_back(mesh);
  const std::vector<uint8_t> bytes = EncodePly(scene);
  Result<Scene> back = ParsePly(bytes.data(), bytes.size(), "w.ply");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  const Mesh& m = back->meshes[0];
  EXPECT_EQ(m.positions, mesh.positions);
  EXPECT_EQ(m.indices, mesh.indices);
  EXPECT_EQ(m.normals, mesh.normals);
  ASSERT_EQ(m.uv_sets.size(), 1u);
  for (size_t i = 0; i < mesh.uv_sets[0].size(); ++i)
    EXPECT_NEAR(m.uv_sets[0][i], mesh.uv_sets[0][i], 1e-6) << i;
  EXPECT_EQ(m.colors, mesh.colors);
  EXPECT_TRUE(back->dropped.empty());
}

TEST(PlyReader, PerCornerTextureCoordinatesAndTheTextureFile) {
  // MeshLab's layout: the texture named in a comment, texture coordinates per face corner.
  const std::string text =
      "ply\nformat ascii 1.0\ncomment TextureFile wood grain.png\n"
      "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
      "end_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
      "3 0 1 2 6 0 0 1 0 1 1\n"
      "3 0 2 3 6 0.5 0 0.5 1 0 1\n";
  Result<Scene> s = Parse(text);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  const Mesh& m = s->meshes[0];
  // A vertex per corner: vertex 0 has two texture coordinates.
  ASSERT_EQ(m.vertex_count(), 6u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(m.positions[3 * 3], 0.0f);  // corner 3 is vertex 0 again
  ASSERT_EQ(m.uv_sets.size(), 1u);
  EXPECT_EQ(m.uv_sets[0][2 * 3], 0.5f);
  EXPECT_EQ(m.uv_sets[0][2 * 3 + 1], 1.0f);  // t = 0 is v = 1
  EXPECT_EQ(m.uv_sets[0][2 * 2 + 1], 0.0f);
  ASSERT_EQ(s->images.size(), 1u);
  EXPECT_EQ(s->images[0].uri, "wood grain.png");
  ASSERT_EQ(s->materials.size(), 1u);
  EXPECT_EQ(s->materials[0].base_color_texture.image, 0);
  EXPECT_EQ(m.material_ids, (std::vector<uint32_t>{0, 0}));
}

TEST(PlyReader, LenientWhereExportersDiffer) {
  // A bare header line (old Blender), CRLF line ends, a face of two corners, "3.0" as a count.
  const std::string text =
      "ply\r\nformat ascii 1.0\r\nCreated by Blender3D 247\r\nelement vertex 3\r\n"
      "property float x\r\nproperty float y\r\nproperty float z\r\n"
      "element face 2\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
      "0 0 0\r\n1 0 0\r\n0 1 0\r\n3.0 0 1 2\r\n2 0 1\r\n";
  Result<Scene> s = Parse(text);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->meshes[0].indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_TRUE(Mentions(s.value(), "1 header lines of no PLY keyword"));
  EXPECT_TRUE(Mentions(s.value(), "1 faces with fewer than 3 corners"));
}

TEST(PlyReader, MalformedFilesAreErrorsNamingTheFileAndTheProblem) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"plx\n", "does not start with 'ply'"},
      {"ply\nformat ascii 1.0\nelement vertex 3\n", "no end_header"},
      {"ply\nformat ascii 2.0\nend_header\n", "format"},
      {"ply\nformat ascii 1.0\nproperty float x\nend_header\n", "before any element"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\nend_header\n", "cannot read"},
      {"ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", "not a number"},
      {"ply\nelement vertex 3\nend_header\n", "no format line"},
      {head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "refers to vertex 3 of 3"},
      {head + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "truncated"},
      {head + "0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n", "malformed or missing"},
      {head + "0 0 0\n1 0 0\n", "do not fit"},
      {"ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n",
       "do not fit"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "end_header\n0 0\n",
       "no x, y and z"},
      {"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
       "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
       "3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n",
       "before element 'vertex'"},
  };
  for (const auto& [text, why] : cases) {
    Result<Scene> s = Parse(text, "bad.ply");
    ASSERT_FALSE(s.ok()) << why;
    EXPECT_EQ(s.status().code(), StatusCode::kParseError) << why;
    EXPECT_NE(s.status().message().find("bad.ply"), std::string::npos) << s.status().message();
    EXPECT_NE(s.status().message().find(why), std::string::npos) << s.status().message();
  }
}

// Found by ply_reader_fuzzer: values beyond every integer and float type, converted without
// undefined behaviour (UBSan checks it in the sanitized test run).
TEST(PlyReader, ValuesBeyondTheirTypesAreErrorsOrInfinities) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  Result<Scene> index = Parse(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 1e54\n", "big.ply");
  ASSERT_FALSE(index.ok());
  EXPECT_NE(index.status().message().find("refers to vertex 1e+54 of 3"), std::string::npos)
      << index.status().message();
  Result<Scene> position = Parse(head + "1e300 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  ASSERT_TRUE(position.ok()) << position.status().ToString();
  EXPECT_EQ(position->meshes[0].positions[0], std::numeric_limits<float>::infinity());
}

TEST(PlyReader, EveryTruncationOrCorruptionIsAnErrorOrAMeshInRange) {
  // Not a fuzzer (tools/fuzz/ has one), but every prefix and every single-byte change of a binary
  // file must neither crash nor give an index out of range.
  const std::string whole = BinaryTetra(false);
  auto check = [](const std::string& bytes) {
    Result<Scene> s = Parse(bytes);
    if (!s.ok()) return;
    for (const Mesh& m : s->meshes)
      for (uint32_t i : m.indices) ASSERT_LT(i, m.vertex_count());
  };
  for (size_t n = 0; n < whole.size(); ++n) check(whole.substr(0, n));
  for (size_t i = 0; i < whole.size(); ++i) {
    std::string changed = whole;
    changed[i] = static_cast<char>(changed[i] ^ 0x5a);
    check(changed);
  }
}

TEST(PlyReader, ElementsWithoutPropertiesAreNotLoopedOver) {
  // 2^64 - 1 records of nothing: read past at once, not one by one.
  const std::string text =
      "ply\nformat binary_little_endian 1.0\nelement nothing 18446744073709551615\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar uchar vertex_indices\nend_header\n" +
      std::string(36, '\0') + std::string("\x03\x00\x01\x02", 4);
  Result<Scene> s = Parse(text);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->meshes[0].triangle_count(), 1u);
}

}  // namespace
}  // namespace hullpack
