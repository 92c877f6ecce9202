// Streams written by the original Open3DGC tool (tests/o3dgc/vectors) through the public Decode:
// triangles identical to the original decoder's OBJ and in its order; positions, normals and
// texture coordinates printing the same at its 6 significant digits; binary and ASCII streams
// decoding to the same mesh; hostile variants of them (truncations, byte flips, lying counts)
// never accepted wrongly, never crashing.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace {

using namespace o3dgc;

std::string VectorPath(const std::string& name) {
  return std::string(HULLPACK_SOURCE_DIR) + "/tests/o3dgc/vectors/" + name;
}

std::vector<uint8_t> ReadBytes(const std::string& name) {
  std::ifstream in(VectorPath(name), std::ios::binary);
  EXPECT_TRUE(in.good()) << name;
  return std::vector<uint8_t>((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
}

struct Obj {
  std::vector<std::string> v, vn, vt;
  std::vector<uint32_t> f;
};

Obj ReadObj(const std::string& name) {
  Obj o;
  std::ifstream in(VectorPath(name));
  EXPECT_TRUE(in.good()) << name;
  std::string line, tag, tok;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    if (!(s >> tag)) continue;
    std::vector<std::string>* dst = tag == "v"    ? &o.v
                                    : tag == "vn" ? &o.vn
                                    : tag == "vt" ? &o.vt
                                                  : nullptr;
    while (s >> tok) {
      if (dst) {
        dst->push_back(tok);
      } else if (tag == "f") {
        o.f.push_back(uint32_t(std::stoul(tok) - 1));  // f i/i/i: one index for v, vt, vn
      }
    }
  }
  return o;
}

// What std::ostream prints for a float by default (the original tool's OBJ writer).
std::vector<std::string> Printed(const std::vector<float>& values) {
  std::vector<std::string> out;
  for (float f : values) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(f));
    out.push_back(buf);
  }
  return out;
}

const std::vector<float>* TexCoords(const DecodedMesh& m) {
  for (const DecodedFloatAttribute& a : m.float_attributes) {
    if (a.semantic == Semantic::kTexCoord && a.dimension == 2) return &a.values;
  }
  return nullptr;
}

DecodedMesh DecodeVector(const std::string& name, StreamInfo* info = nullptr) {
  const std::vector<uint8_t> s = ReadBytes(name);
  DecodedMesh m;
  EXPECT_EQ(Decode(s.data(), s.size(), DecodeOptions(), &m, info), Status::kOk) << name;
  return m;
}

struct Case {
  const char* stream;
  const char* obj;
  size_t normals, texcoords;
};

const Case kCases[] = {
    {"cup.binary.s3d", "cup.binary_dec.obj", 0, 0},
    {"cup.ascii.s3d", "cup.binary_dec.obj", 0, 0},
    {"cup.binary_default.s3d", "cup.binary_default_dec.obj", 0, 0},
    {"cup.ascii_default.s3d", "cup.binary_default_dec.obj", 0, 0},
    {"fox.binary.s3d", "fox.binary_dec.obj", 0, 434},
    {"fox.ascii.s3d", "fox.binary_dec.obj", 0, 434},
    {"test_nm.binary.s3d", "test_nm.binary_dec.obj", 97, 0},
    {"test_nm.ascii.s3d", "test_nm.binary_dec.obj", 97, 0},
    {"vertex_color_test.binary.s3d", "vertex_color_test.binary_dec.obj", 72, 72},
    {"vertex_color_test.ascii.s3d", "vertex_color_test.binary_dec.obj", 72, 72},
    {"foxmat.binary.s3d", "foxmat.binary_dec.obj", 0, 434},  // coded triangle order
    {"foxmat.ascii.s3d", "foxmat.binary_dec.obj", 0, 434},
};

TEST(LegacyDecoder, MatchesTheOriginalDecoder) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.stream);
    StreamInfo info;
    const DecodedMesh m = DecodeVector(c.stream, &info);
    const Obj o = ReadObj(c.obj);
    ASSERT_FALSE(o.f.empty());
    EXPECT_EQ(m.indices, o.f);  // same triangles, same corners, same order
    EXPECT_EQ(Printed(m.positions), o.v);
    EXPECT_EQ(Printed(m.normals), o.vn);
    EXPECT_EQ(m.normals.size(), 3 * c.normals);
    const std::vector<float>* uv = TexCoords(m);
    EXPECT_EQ(uv ? uv->size() / 2 : 0, c.texcoords);
    EXPECT_EQ(uv ? Printed(*uv) : std::vector<std::string>(), o.vt);
    EXPECT_EQ(info.format, StreamFormat::kOpen3dgc2013);
    EXPECT_EQ(info.num_vertices, m.num_vertices());
    EXPECT_EQ(info.num_triangles, m.num_triangles());
    EXPECT_GT(info.connectivity, 0u);
    EXPECT_GT(info.positions, 0u);
    EXPECT_EQ(info.header + info.connectivity + info.positions + info.normals +
                  (info.float_attributes.empty() ? 0 : info.float_attributes[0]),
              info.total);
  }
}

// The original decoder's dump of its arrays: "* <name>\t<index>\t<type>\t<count>\t<dim>", then
// one line "[i]\tv0\tv1..." per element.
std::vector<std::string> DumpedArray(const std::string& file, const std::string& name) {
  std::ifstream in(VectorPath(file));
  EXPECT_TRUE(in.good()) << file;
  std::vector<std::string> values;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line[0] == '*') {
      inside = line.compare(0, name.size() + 2, "* " + name) == 0 && line[name.size() + 2] == '\t';
      continue;
    }
    if (!inside) continue;
    std::istringstream s(line);
    std::string tok;
    s >> tok;  // [i]
    while (s >> tok) values.push_back(tok);
  }
  return values;
}

TEST(LegacyDecoder, WeightsAndJointIds) {
  const std::string dump = "test_nm_weights.binary_dec_ifs.txt";
  for (const char* name : {"test_nm_weights.binary.s3d", "test_nm_weights.ascii.s3d"}) {
    SCOPED_TRACE(name);
    const DecodedMesh m = DecodeVector(name);
    ASSERT_EQ(m.float_attributes.size(), 1u);
    ASSERT_EQ(m.int_attributes.size(), 1u);
    EXPECT_EQ(m.float_attributes[0].semantic, Semantic::kWeight);
    EXPECT_EQ(m.float_attributes[0].dimension, 4u);
    EXPECT_EQ(m.int_attributes[0].semantic, Semantic::kJointId);
    EXPECT_EQ(m.int_attributes[0].dimension, 4u);
    EXPECT_EQ(Printed(m.float_attributes[0].values), DumpedArray(dump, "FloatAttribute"));
    std::vector<std::string> joints;
    for (int32_t j : m.int_attributes[0].values) joints.push_back(std::to_string(j));
    EXPECT_EQ(joints, DumpedArray(dump, "IntAttribute"));
    EXPECT_EQ(Printed(m.positions), DumpedArray(dump, "Coord"));
    EXPECT_EQ(Printed(m.normals), DumpedArray(dump, "Normal"));
    ASSERT_EQ(m.float_attributes[0].values.size(), 4 * m.num_vertices());
  }
}

TEST(LegacyDecoder, BinaryAndAsciiDecodeAlike) {
  for (const char* name : {"knot", "fox", "vertex_color_test"}) {
    SCOPED_TRACE(name);
    StreamInfo bi, ai;
    const DecodedMesh b = DecodeVector(std::string(name) + ".binary.s3d", &bi);
    const DecodedMesh a = DecodeVector(std::string(name) + ".ascii.s3d", &ai);
    EXPECT_EQ(bi.stream_type, StreamType::kBinary);
    EXPECT_EQ(ai.stream_type, StreamType::kAscii);
    EXPECT_EQ(b.indices, a.indices);
    EXPECT_EQ(b.positions, a.positions);
    EXPECT_EQ(b.normals, a.normals);
    ASSERT_EQ(b.float_attributes.size(), a.float_attributes.size());
    for (size_t i = 0; i < b.float_attributes.size(); ++i) {
      EXPECT_EQ(b.float_attributes[i].values, a.float_attributes[i].values);
    }
  }
  // The knot's normals (surface-normal prediction) are unit length to the quantization.
  const DecodedMesh k = DecodeVector("knot.binary.s3d");
  ASSERT_EQ(k.normals.size(), k.positions.size());
  for (size_t i = 0; i < k.normals.size(); i += 3) {
    const double n = std::sqrt(double(k.normals[i]) * k.normals[i] +
                               double(k.normals[i + 1]) * k.normals[i + 1] +
                               double(k.normals[i + 2]) * k.normals[i + 2]);
    EXPECT_NEAR(n, 1.0, 0.01) << i / 3;
  }
}

TEST(LegacyDecoder, StreamInfoAndOptions) {
  const std::vector<uint8_t> s = ReadBytes("fox.ascii.s3d");
  StreamInfo info;
  ASSERT_EQ(ReadStreamInfo(s.data(), s.size(), &info), Status::kOk);
  EXPECT_EQ(info.format, StreamFormat::kOpen3dgc2013);
  EXPECT_EQ(info.stream_type, StreamType::kAscii);
  EXPECT_EQ(info.num_vertices, 434u);
  EXPECT_EQ(info.num_triangles, 576u);
  EXPECT_EQ(info.total, s.size());
  DecodedMesh m;
  DecodeOptions o;
  o.max_vertices = 433;
  EXPECT_EQ(Decode(s.data(), s.size(), o, &m), Status::kLimitExceeded);
  o = DecodeOptions();
  o.max_triangles = 575;
  EXPECT_EQ(Decode(s.data(), s.size(), o, &m), Status::kLimitExceeded);
  o = DecodeOptions();
  o.progress = [](float f) { return f < 0.5f; };
  EXPECT_EQ(Decode(s.data(), s.size(), o, &m), Status::kCancelled);
}

void ExpectSane(const DecodedMesh& m) {
  for (float f : m.positions) ASSERT_TRUE(std::isfinite(f));
  for (float f : m.normals) ASSERT_TRUE(std::isfinite(f));
  for (const DecodedFloatAttribute& a : m.float_attributes) {
    for (float f : a.values) ASSERT_TRUE(std::isfinite(f));
  }
  for (uint32_t i : m.indices) ASSERT_LT(i, m.num_vertices());
}

TEST(LegacyDecoder, EveryTruncationIsRejected) {
  for (const char* name :
       {"vertex_color_test.binary.s3d", "vertex_color_test.ascii.s3d", "cup.binary.s3d"}) {
    const std::vector<uint8_t> s = ReadBytes(name);
    const bool binary = s[0] == 0xF1;
    for (size_t n = 0; n < s.size(); ++n) {
      DecodedMesh m;
      EXPECT_NE(Decode(s.data(), n, DecodeOptions(), &m), Status::kOk) << name << " " << n;
      // The same with the header's stream size fixed up to the cut: the sections still tell.
      if (!binary || n < 8) continue;
      std::vector<uint8_t> cut(s.begin(), s.begin() + long(n));
      for (int i = 0; i < 4; ++i) cut[4 + size_t(i)] = uint8_t(n >> (8 * i));
      EXPECT_NE(Decode(cut.data(), cut.size(), DecodeOptions(), &m), Status::kOk)
          << name << " " << n;
    }
  }
}

TEST(LegacyDecoder, RandomDamageNeverCrashes) {
  std::mt19937 rng(11);
  const auto start = std::chrono::steady_clock::now();
  for (const char* name :
       {"test_nm.binary.s3d", "test_nm.ascii.s3d", "fox.binary.s3d", "fox.ascii.s3d"}) {
    const std::vector<uint8_t> good = ReadBytes(name);
    for (int trial = 0; trial < 300; ++trial) {
      std::vector<uint8_t> s = good;
      const int flips = 1 + int(rng() % 4);
      for (int k = 0; k < flips; ++k) {
        const size_t at = rng() % s.size();
        s[at] = trial % 2 ? uint8_t(rng()) : uint8_t(s[at] ^ (1u << (rng() % 8)));
      }
      DecodedMesh m;
      if (Decode(s.data(), s.size(), DecodeOptions(), &m) == Status::kOk) ExpectSane(m);
    }
  }
  // Hostile input must not be slow either.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
}

TEST(LegacyDecoder, LyingCountsAreRejectedBeforeAllocating) {
  // Header counts of the binary cup: coords at byte 14, triangles at byte 30 (little endian).
  const std::vector<uint8_t> good = ReadBytes("cup.binary.s3d");
  for (size_t field : {size_t(14), size_t(30)}) {
    for (uint32_t v : {0x7FFFFFFFu, 0xFFFFFFFFu, 1000000u}) {
      std::vector<uint8_t> s = good;
      for (int i = 0; i < 4; ++i) s[field + size_t(i)] = uint8_t(v >> (8 * i));
      DecodedMesh m;
      EXPECT_EQ(Decode(s.data(), s.size(), DecodeOptions(), &m), Status::kLimitExceeded)
          << field << " " << v;
    }
  }
  // A stream size beyond the data: truncated.
  std::vector<uint8_t> s = good;
  s[4] = 0xFF;
  s[5] = 0xFF;
  DecodedMesh m;
  EXPECT_EQ(Decode(s.data(), s.size(), DecodeOptions(), &m), Status::kTruncated);
}

}  // namespace
