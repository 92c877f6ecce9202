// Round trips through Encode/Decode: connectivity, accuracy bounds, attributes, groups, modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "o3dgc/o3dgc.h"
#include "test_meshes.h"

namespace {

using namespace o3dgc;
using o3dgc_test::TestMesh;

std::vector<uint8_t> EncodeOk(const TestMesh& t, const EncodeParams& p, StreamInfo* info = nullptr,
                              int uv_bits = 12) {
  std::vector<uint8_t> s;
  EXPECT_EQ(Encode(t.View(uv_bits), p, &s, info), Status::kOk);
  return s;
}

DecodedMesh DecodeOk(const std::vector<uint8_t>& s) {
  DecodedMesh m;
  EXPECT_EQ(Decode(s.data(), s.size(), DecodeOptions(), &m), Status::kOk);
  return m;
}

// Per-corner integer key: quantized position (uniform range), quantized uv, joints, group.
struct Keyer {
  double min[3], step;
  explicit Keyer(const TestMesh& t, int bits) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (size_t i = 0; i < t.nv(); ++i) {
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], double(t.positions[3 * i + k]));
        hi[k] = std::max(hi[k], double(t.positions[3 * i + k]));
      }
    }
    double e = 0;
    for (int k = 0; k < 3; ++k) {
      min[k] = lo[k];
      e = std::max(e, hi[k] - lo[k]);
    }
    step = e / double((1u << bits) - 1);
  }
  int64_t Q(double x, int k) const {
    return step > 0 ? int64_t(std::floor((x - min[k]) / step + 0.5)) : 0;
  }
};

std::vector<std::vector<int64_t>> Triangles(const Keyer& key, const std::vector<float>& pos,
                                            const std::vector<uint32_t>& idx,
                                            const std::vector<int32_t>* joints,
                                            const std::vector<uint32_t>* groups) {
  std::vector<std::vector<int64_t>> out;
  for (size_t t = 0; t < idx.size() / 3; ++t) {
    std::vector<std::vector<int64_t>> c(3);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = idx[3 * t + k];
      for (int d = 0; d < 3; ++d) c[k].push_back(key.Q(pos[3 * size_t(v) + d], d));
      if (joints && !joints->empty()) {
        for (int d = 0; d < 4; ++d) c[k].push_back((*joints)[4 * size_t(v) + d]);
      }
    }
    int best = 0;
    for (int k = 1; k < 3; ++k) {
      if (c[k] < c[best]) best = k;
    }
    std::vector<int64_t> r;
    for (int k = 0; k < 3; ++k)
      r.insert(r.end(), c[(best + k) % 3].begin(), c[(best + k) % 3].end());
    if (groups && !groups->empty()) r.push_back((*groups)[t]);
    out.push_back(r);
  }
  std::sort(out.begin(), out.end());
  return out;
}

void CheckTriangleSet(const TestMesh& t, const DecodedMesh& m, int bits) {
  Keyer key(t, bits);
  const std::vector<int32_t>* dj = m.int_attributes.empty() ? nullptr : &m.int_attributes[0].values;
  EXPECT_EQ(Triangles(key, t.positions, t.indices, &t.joints, &t.groups),
            Triangles(key, m.positions, m.indices, dj, &m.triangle_groups));
}

double StepOf(const std::vector<float>& v, int dim, int k, int bits) {
  float lo = 1e30f, hi = -1e30f;
  for (size_t i = k; i < v.size(); i += dim) {
    lo = std::min(lo, v[i]);
    hi = std::max(hi, v[i]);
  }
  return (double(hi) - lo) / double((1u << bits) - 1);
}

// keep_order: everything must correspond index by index.
void CheckExact(const TestMesh& t, const DecodedMesh& m, int pbits, int nbits, int uvbits) {
  ASSERT_EQ(m.indices, t.indices);
  ASSERT_EQ(m.num_vertices(), t.nv());
  Keyer key(t, pbits);
  for (size_t i = 0; i < t.positions.size(); ++i) {
    EXPECT_LE(std::fabs(double(m.positions[i]) - t.positions[i]),
              key.step * 0.5 * (1 + 1e-6) + 1e-7)
        << "position component " << i;
  }
  if (!t.normals.empty()) {
    ASSERT_EQ(m.normals.size(), t.normals.size());
    const double bound = 2.5 / double(1u << nbits) * 3.14159;
    for (size_t v = 0; v < t.nv(); ++v) {
      double dot = 0, la = 0, lb = 0;
      for (int k = 0; k < 3; ++k) {
        dot += double(m.normals[3 * v + k]) * t.normals[3 * v + k];
        la += double(m.normals[3 * v + k]) * m.normals[3 * v + k];
        lb += double(t.normals[3 * v + k]) * t.normals[3 * v + k];
      }
      EXPECT_NEAR(la, 1.0, 1e-5);
      const double angle = std::acos(std::min(1.0, dot / std::sqrt(la * lb)));
      EXPECT_LE(angle, bound) << "normal " << v;
    }
  }
  size_t fa = 0;
  if (!t.uvs.empty()) {
    const auto& a = m.float_attributes[fa++];
    ASSERT_EQ(a.values.size(), t.uvs.size());
    for (size_t i = 0; i < t.uvs.size(); ++i) {
      const double step = StepOf(t.uvs, 2, int(i % 2), uvbits);
      EXPECT_LE(std::fabs(double(a.values[i]) - t.uvs[i]), step * 0.5 * (1 + 1e-6) + 1e-7);
    }
  }
  if (!t.colors.empty()) {
    const auto& a = m.float_attributes[fa++];
    ASSERT_EQ(a.values.size(), t.colors.size());
    for (size_t i = 0; i < t.colors.size(); ++i) {
      const double step = StepOf(t.colors, 4, int(i % 4), 10);
      EXPECT_LE(std::fabs(double(a.values[i]) - t.colors[i]), step * 0.5 * (1 + 1e-6) + 1e-7);
    }
  }
  if (!t.joints.empty()) {
    ASSERT_EQ(m.int_attributes.size(), 1u);
    EXPECT_EQ(m.int_attributes[0].values, t.joints);
  }
  if (!t.groups.empty()) {
    EXPECT_EQ(m.triangle_groups, t.groups);
  }
}

TestMesh WithGroups(TestMesh t) {
  t.groups.resize(t.nt());
  for (size_t i = 0; i < t.nt(); ++i) t.groups[i] = uint32_t(i * 4 / t.nt());
  return t;
}

std::vector<TestMesh> AllMeshes() {
  TestMesh single;
  single.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  single.indices = {0, 1, 2};
  return {o3dgc_test::Grid(12, 9),
          o3dgc_test::Sphere(16, 10),
          o3dgc_test::Torus(20, 12),
          o3dgc_test::Awkward(),
          single,
          WithGroups(o3dgc_test::Sphere(12, 7))};
}

// `t` without its degenerate triangles (two corners at equal positions) and their groups.
TestMesh WithoutDegenerateTriangles(TestMesh t) {
  auto same = [&](uint32_t a, uint32_t b) {
    const float* p = &t.positions[3 * a];
    const float* q = &t.positions[3 * b];
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  };
  std::vector<uint32_t> indices, groups;
  for (size_t k = 0; k < t.nt(); ++k) {
    const uint32_t* c = &t.indices[3 * k];
    if (same(c[0], c[1]) || same(c[1], c[2]) || same(c[0], c[2])) continue;
    indices.insert(indices.end(), c, c + 3);
    if (!t.groups.empty()) groups.push_back(t.groups[k]);
  }
  t.indices = indices;
  t.groups = groups;
  return t;
}

// Every triangle comes back but the degenerate ones (none of these meshes has a vertex that only
// degenerate triangles use).
TEST(RoundTrip, DefaultModeKeepsTriangleSet) {
  for (const TestMesh& t : AllMeshes()) {
    EncodeParams p;
    const auto s = EncodeOk(t, p);
    const DecodedMesh m = DecodeOk(s);
    const TestMesh kept = WithoutDegenerateTriangles(t);
    EXPECT_EQ(m.num_triangles(), kept.nt());
    EXPECT_EQ(m.num_vertices(), t.nv());
    CheckTriangleSet(kept, m, p.position_bits);
  }
}

TEST(RoundTrip, KeepDegenerateTrianglesKeepsEveryTriangle) {
  for (const TestMesh& t : AllMeshes()) {
    EncodeParams p;
    p.keep_degenerate_triangles = true;
    const DecodedMesh m = DecodeOk(EncodeOk(t, p));
    EXPECT_EQ(m.num_triangles(), t.nt());
    EXPECT_EQ(m.num_vertices(), t.nv());
    CheckTriangleSet(t, m, p.position_bits);
  }
}

// A welded CAD export's slivers that collapse (two corners at one position, distinct vertices):
// left out with the vertices only they use, they cost nothing; only with keep_degenerate_triangles
// each is coded. Of a mesh of nothing but degenerate triangles only its unreferenced vertex stays.
TEST(RoundTrip, DegenerateTrianglesAreLeftOutByDefault) {
  TestMesh t = o3dgc_test::Sphere(24, 16);
  const size_t nt = t.nt(), sphere_vertices = t.nv();
  for (size_t k = 0; k < nt; k += 3) {
    const uint32_t a = t.indices[3 * k], b = t.indices[3 * k + 1];
    // A copy of vertex a (a range of a vector cannot be inserted into itself).
    auto copy_row = [a](std::vector<float>& v, size_t dim) {
      if (v.empty()) return;
      const std::vector<float> row(v.begin() + dim * a, v.begin() + dim * (a + 1));
      v.insert(v.end(), row.begin(), row.end());
    };
    copy_row(t.positions, 3);
    copy_row(t.normals, 3);
    copy_row(t.uvs, 2);
    t.indices.insert(t.indices.end(), {a, uint32_t(t.nv() - 1), b});
    t.indices.insert(t.indices.end(), {b, b, a});
  }
  EncodeParams p;
  StreamInfo dropped, kept;
  const DecodedMesh m = DecodeOk(EncodeOk(t, p, &dropped));
  EXPECT_EQ(m.num_triangles(), nt);
  EXPECT_EQ(dropped.num_triangles, nt);
  EXPECT_EQ(m.num_vertices(), sphere_vertices);
  CheckTriangleSet(WithoutDegenerateTriangles(t), m, p.position_bits);
  p.keep_degenerate_triangles = true;
  const DecodedMesh all = DecodeOk(EncodeOk(t, p, &kept));
  EXPECT_EQ(all.num_triangles(), t.nt());
  EXPECT_EQ(all.num_vertices(), t.nv());
  EXPECT_GT(kept.connectivity, dropped.connectivity + (t.nt() - nt) * 2);

  TestMesh points;
  points.positions = {1, 2, 3, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  points.indices = {0, 1, 2, 2, 2, 0};
  points.groups = {5, 6};
  const DecodedMesh p2 = DecodeOk(EncodeOk(points, EncodeParams()));
  EXPECT_EQ(p2.num_triangles(), 0u);
  EXPECT_EQ(p2.positions, std::vector<float>({7, 8, 9}));
  EXPECT_TRUE(p2.triangle_groups.empty());
}

// Format 1.2's modelled low bits: taken by a grid-built model (version 1.2, flag reported by
// ReadStreamInfo), left out where they do not pay (a smooth sphere stays a 1.1 stream).
TEST(RoundTrip, ModelledLowBitsOnlyWhereTheyPay) {
  for (const bool grid : {true, false}) {
    TestMesh t = grid ? o3dgc_test::GridBlocks(6, 5) : o3dgc_test::Sphere(24, 16);
    // A scan-like sphere: positions off any grid (a symmetric sphere's residuals recur).
    std::mt19937 rng(9);
    if (!grid) {
      for (float& x : t.positions) x += float(rng() % 1000) * 1e-5f;
    }
    EncodeParams p;
    std::vector<uint8_t> s;
    StreamInfo info;
    ASSERT_EQ(Encode(t.View(), p, &s, &info), Status::kOk);
    EXPECT_EQ(info.low_bits, grid);
    EXPECT_EQ(info.version_minor, grid ? 2u : 1u);
    StreamInfo read;
    ASSERT_EQ(ReadStreamInfo(s.data(), s.size(), &read), Status::kOk);
    EXPECT_EQ(read.low_bits, grid);
    EXPECT_EQ(read.version_minor, info.version_minor);
    const DecodedMesh m = DecodeOk(s);
    EXPECT_EQ(m.num_triangles(), t.nt());
    CheckTriangleSet(t, m, p.position_bits);
  }
}

TestMesh SeamedGrid(bool hard);  // below

// A GridEncoder's stream for a grid is Encode's with that grid, byte for byte, and its part sizes
// too: every grid of every mode, grids encoded in any order from one Prepare, with seams, normals,
// uvs, groups, the input order kept, ASCII streams, and on a mesh large enough for the positions'
// automatic vertex-id order.
TEST(RoundTrip, GridEncoderGivesEncodesStreams) {
  std::vector<TestMesh> meshes = AllMeshes();
  meshes.push_back(o3dgc_test::Torus(72, 60));  // 4320 vertices: auto_fast_decode runs
  meshes.push_back(SeamedGrid(false));
  meshes.push_back(SeamedGrid(true));
  for (const TestMesh& t : meshes) {
    for (int variant = 0; variant < 3; ++variant) {
      EncodeParams p;
      p.keep_order = variant == 1;
      p.stream_type = variant == 2 ? StreamType::kAscii : StreamType::kBinary;
      GridEncoder grids;
      ASSERT_EQ(grids.Prepare(t.View(), p), Status::kOk);
      for (RangeMode mode : {RangeMode::kDiagonal, RangeMode::kUniform, RangeMode::kPerAxis}) {
        for (int bits : {14, 3, 21}) {
          EncodeParams one = p;
          one.position_bits = bits;
          one.position_range = mode;
          StreamInfo want_info, got_info;
          const std::vector<uint8_t> want = EncodeOk(t, one, &want_info);
          std::vector<uint8_t> got;
          ASSERT_EQ(grids.Encode(bits, mode, &got, &got_info), Status::kOk);
          EXPECT_EQ(got, want) << t.nv() << " vertices, variant " << variant << ", " << bits
                               << " bits, mode " << int(mode);
          EXPECT_EQ(got_info.connectivity, want_info.connectivity);
          EXPECT_EQ(got_info.positions, want_info.positions);
          EXPECT_EQ(got_info.total, want_info.total);
        }
      }
      std::vector<uint8_t> s;
      EXPECT_EQ(grids.Encode(0, RangeMode::kUniform, &s), Status::kInvalidArgument);
    }
  }
  GridEncoder unprepared;
  std::vector<uint8_t> s;
  EXPECT_EQ(unprepared.Encode(14, RangeMode::kUniform, &s), Status::kInvalidArgument);
  TestMesh bad = o3dgc_test::Sphere(8, 5);
  bad.indices[4] = uint32_t(bad.nv());
  EXPECT_EQ(unprepared.Prepare(bad.View(), EncodeParams()), Status::kInvalidArgument);
}

TEST(RoundTrip, KeepOrderIsExact) {
  for (const TestMesh& t : AllMeshes()) {
    EncodeParams p;
    p.keep_order = true;
    const DecodedMesh m = DecodeOk(EncodeOk(t, p));
    CheckExact(t, m, p.position_bits, p.normal_bits, 12);
  }
}

// fast_decode changes only the order in which the parallelogram-predicted values are coded: the
// decoded mesh is the one the default stream gives, bit for bit, for every attribute that uses that
// order (positions, normals and generic values by parallelograms, uvs from the shape), on small
// meshes and on large ones (raw low bits, class shifts), in both vertex-order modes.
TEST(RoundTrip, FastDecodeGivesTheSameMeshFromAnotherStream) {
  TestMesh noisy = o3dgc_test::Grid(72, 60);  // 4453 vertices: raw low bits; the noise: shifts
  for (size_t i = 2; i < noisy.positions.size(); i += 3)
    noisy.positions[i] = float(std::sin(i * 0.7) * 0.01);
  std::vector<TestMesh> meshes = AllMeshes();
  meshes.push_back(o3dgc_test::Torus(72, 60));
  meshes.push_back(noisy);
  for (const TestMesh& t : meshes) {
    std::vector<float> generic(t.nv());
    for (size_t i = 0; i < generic.size(); ++i)
      generic[i] = t.positions[3 * i] * t.positions[3 * i + 1];
    MeshView v = t.View();
    FloatAttributeView g;
    g.data = generic.data();
    g.dimension = 1;
    g.semantic = Semantic::kGeneric;
    v.float_attributes.push_back(g);
    for (const bool keep : {false, true}) {
      for (const Prediction np : {Prediction::kSurfaceNormal, Prediction::kParallelogram}) {
        EncodeParams p;
        p.keep_order = keep;
        p.normal_prediction = np;
        p.auto_fast_decode = false;
        std::vector<uint8_t> slow, fast, automatic;
        StreamInfo si;
        ASSERT_EQ(Encode(v, p, &slow), Status::kOk);
        EXPECT_EQ(slow[6] & 3, keep ? 1 : 0);  // bit 2: modelled low bits (1.2)
        // The automatic choice writes one of the two streams, and says which in its flags.
        p.auto_fast_decode = true;
        StreamInfo ai;
        ASSERT_EQ(Encode(v, p, &automatic, &ai), Status::kOk);
        EXPECT_EQ((automatic[6] & 3) == (keep ? 3 : 2), ai.fast_decode);
        p.auto_fast_decode = false;
        p.fast_decode = true;
        ASSERT_EQ(Encode(v, p, &fast, &si), Status::kOk);
        EXPECT_TRUE(si.fast_decode);
        EXPECT_EQ(fast[6] & 3, keep ? 3 : 2);  // the flags byte
        if (t.nv() > 100) {
          EXPECT_NE(slow, fast);
        }
        const DecodedMesh a = DecodeOk(slow);
        DecodedMesh b;
        StreamInfo di;
        ASSERT_EQ(Decode(fast.data(), fast.size(), DecodeOptions(), &b, &di), Status::kOk);
        EXPECT_TRUE(di.fast_decode);
        EXPECT_EQ(a.indices, b.indices);
        EXPECT_EQ(a.positions, b.positions);
        EXPECT_EQ(a.normals, b.normals);
        ASSERT_EQ(a.float_attributes.size(), b.float_attributes.size());
        for (size_t i = 0; i < a.float_attributes.size(); ++i) {
          EXPECT_EQ(a.float_attributes[i].values, b.float_attributes[i].values)
              << "attribute " << i;
        }
        ASSERT_EQ(a.int_attributes.size(), b.int_attributes.size());
        for (size_t i = 0; i < a.int_attributes.size(); ++i) {
          EXPECT_EQ(a.int_attributes[i].values, b.int_attributes[i].values);
        }
        EXPECT_EQ(a.triangle_groups, b.triangle_groups);
        EXPECT_TRUE(automatic == (ai.fast_decode ? fast : slow));
      }
    }
  }
}

TEST(RoundTrip, EveryPredictionModeAndBitDepth) {
  const TestMesh t = o3dgc_test::Torus(24, 10);
  TestMesh s = o3dgc_test::Sphere(20, 12);
  for (Prediction pp : {Prediction::kNone, Prediction::kDifferential, Prediction::kParallelogram}) {
    for (Prediction np : {Prediction::kNone, Prediction::kDifferential, Prediction::kParallelogram,
                          Prediction::kSurfaceNormal}) {
      for (int bits : {1, 7, 14, 30}) {
        EncodeParams p;
        p.keep_order = true;
        p.position_prediction = pp;
        p.normal_prediction = np;
        p.position_bits = bits;
        p.normal_bits = bits < 4 ? 4 : (bits > 20 ? 20 : bits);
        const DecodedMesh m = DecodeOk(EncodeOk(s, p));
        if (np == Prediction::kSurfaceNormal) {
          CheckExact(s, m, bits, p.normal_bits, 12);
        } else {
          // Magnitude-preserving modes: half a step per component.
          TestMesh no_normals = s;
          no_normals.normals.clear();
          DecodedMesh m2 = m;
          m2.normals.clear();
          CheckExact(no_normals, m2, bits, 0, 12);
          for (size_t i = 0; i < s.normals.size(); ++i) {
            const double step = StepOf(s.normals, 3, int(i % 3), p.normal_bits);
            EXPECT_LE(std::fabs(double(m.normals[i]) - s.normals[i]),
                      step * 0.5 * (1 + 1e-6) + 1e-7);
          }
        }
        const DecodedMesh mt = DecodeOk(EncodeOk(t, p));
        CheckExact(t, mt, bits, 0, 12);
      }
    }
  }
}

TEST(RoundTrip, LargeMeshesCodeResidualLowBitsRaw) {
  // From 4096 vertices on (kRawLowBitsMesh) residuals take their sign and low bits from the raw
  // bit stream: every residual path on meshes past that size, down to 30-bit differential
  // residuals (wider than one 24-bit raw read).
  TestMesh torus = o3dgc_test::Torus(72, 60);  // colours (differential), joint ids
  TestMesh grid = o3dgc_test::Grid(72, 60);    // uvs (predicted from the shape)
  grid.normals.clear();
  ASSERT_GE(torus.nv(), 4096u);
  ASSERT_GE(grid.nv(), 4096u);
  for (Prediction pp : {Prediction::kDifferential, Prediction::kParallelogram}) {
    for (int bits : {14, 30}) {
      EncodeParams p;
      p.keep_order = true;
      p.position_prediction = pp;
      p.position_bits = bits;
      CheckExact(torus, DecodeOk(EncodeOk(torus, p)), bits, 0, 12);
      CheckExact(grid, DecodeOk(EncodeOk(grid, p)), bits, 0, 12);
    }
  }
}

TEST(RoundTrip, MaxCompressionCodesLargeSectionsAdaptivelyAsFormat13) {
  // A large noisy torus with colours and joint ids, and a large grid with uvs: with
  // max_compression every section codes its low bits adaptively; the decoded values are exactly
  // those of the default stream, which is larger.
  TestMesh torus = o3dgc_test::Torus(72, 60);
  TestMesh grid = o3dgc_test::Grid(72, 60);
  grid.normals.clear();
  for (size_t i = 0; i < torus.positions.size(); ++i)
    torus.positions[i] += float(((i * 2654435761u) % 1000) * 2e-5);
  for (const TestMesh* t : {&torus, &grid}) {
    ASSERT_GE(t->nv(), 4096u);
    for (int bits : {14, 30}) {
      EncodeParams p;
      p.keep_order = true;
      p.position_bits = bits;
      StreamInfo plain_info, max_info;
      const std::vector<uint8_t> plain = EncodeOk(*t, p, &plain_info);
      p.max_compression = true;
      const std::vector<uint8_t> max = EncodeOk(*t, p, &max_info);
      EXPECT_TRUE(max_info.all_adaptive);
      EXPECT_EQ(max_info.version_minor, 3u);
      EXPECT_FALSE(plain_info.all_adaptive);
      EXPECT_LE(plain_info.version_minor, 2u);
      EXPECT_LT(max.size(), plain.size()) << bits << " bits";
      StreamInfo read;
      ASSERT_EQ(ReadStreamInfo(max.data(), max.size(), &read), Status::kOk);
      EXPECT_TRUE(read.all_adaptive);
      EXPECT_EQ(read.version_minor, 3u);
      const DecodedMesh a = DecodeOk(plain), b = DecodeOk(max);
      EXPECT_EQ(a.positions, b.positions);
      EXPECT_EQ(a.indices, b.indices);
      ASSERT_EQ(a.float_attributes.size(), b.float_attributes.size());
      for (size_t k = 0; k < a.float_attributes.size(); ++k)
        EXPECT_EQ(a.float_attributes[k].values, b.float_attributes[k].values);
      CheckExact(*t, b, bits, 0, 12);
    }
  }
  // A small mesh has no raw section: the option changes nothing and the stream stays 1.2 or older.
  TestMesh small = o3dgc_test::Grid(10, 10);
  EncodeParams p;
  StreamInfo plain_info, max_info;
  const std::vector<uint8_t> plain = EncodeOk(small, p, &plain_info);
  p.max_compression = true;
  EXPECT_EQ(EncodeOk(small, p, &max_info), plain);
  EXPECT_FALSE(max_info.all_adaptive);
  // It cannot be combined with the vertex id order.
  p.fast_decode = true;
  std::vector<uint8_t> s;
  EXPECT_EQ(Encode(small.View(), p, &s), Status::kInvalidArgument);
}

TEST(RoundTrip, FloatAttributeModesDimensionsAndRanges) {
  TestMesh t = o3dgc_test::Grid(10, 10);
  t.normals.clear();
  std::vector<float> attr(t.nv() * 4);
  for (size_t i = 0; i < attr.size(); ++i) attr[i] = float(std::sin(double(i) * 0.37) * 100.0);
  for (uint32_t dim = 1; dim <= 4; ++dim) {
    for (Prediction pr :
         {Prediction::kNone, Prediction::kDifferential, Prediction::kParallelogram}) {
      for (RangeMode rm : {RangeMode::kUniform, RangeMode::kPerAxis, RangeMode::kDiagonal}) {
        MeshView v = t.View();
        v.float_attributes.clear();
        FloatAttributeView a;
        a.data = attr.data();
        a.stride = 16;  // strided access: dim of the 4 floats
        a.dimension = dim;
        a.bits = 11;
        a.prediction = pr;
        a.range = rm;
        a.semantic = Semantic::kWeight;
        v.float_attributes.push_back(a);
        EncodeParams p;
        p.keep_order = true;
        std::vector<uint8_t> s;
        ASSERT_EQ(Encode(v, p, &s), Status::kOk);
        DecodedMesh m = DecodeOk(s);
        ASSERT_EQ(m.float_attributes.size(), 1u);
        ASSERT_EQ(m.float_attributes[0].dimension, dim);
        EXPECT_EQ(m.float_attributes[0].semantic, Semantic::kWeight);
        double ext = 0, diag2 = 0;
        for (uint32_t k = 0; k < dim; ++k) {
          std::vector<float> c;
          for (size_t i = 0; i < t.nv(); ++i) c.push_back(attr[4 * i + k]);
          ext = std::max(ext, StepOf(c, 1, 0, 11));
          diag2 += StepOf(c, 1, 0, 11) * StepOf(c, 1, 0, 11);
        }
        for (size_t i = 0; i < t.nv(); ++i) {
          for (uint32_t k = 0; k < dim; ++k) {
            std::vector<float> c;
            for (size_t j = 0; j < t.nv(); ++j) c.push_back(attr[4 * j + k]);
            const double step =
                rm == RangeMode::kUniform
                    ? ext
                    : (rm == RangeMode::kDiagonal ? std::sqrt(diag2) : StepOf(c, 1, 0, 11));
            EXPECT_LE(
                std::fabs(double(m.float_attributes[0].values[i * dim + k]) - attr[4 * i + k]),
                step * 0.5 * (1 + 1e-6) + 1e-5);
          }
        }
      }
    }
  }
}

TEST(RoundTrip, IntAttributesExactIncludingExtremes) {
  TestMesh t = o3dgc_test::Torus(8, 6);
  t.joints[0] = INT32_MIN;
  t.joints[1] = INT32_MAX;
  t.joints[5] = INT32_MIN;
  for (Prediction pr : {Prediction::kNone, Prediction::kDifferential}) {
    MeshView v = t.View();
    v.int_attributes[0].prediction = pr;
    EncodeParams p;
    p.keep_order = true;
    std::vector<uint8_t> s;
    ASSERT_EQ(Encode(v, p, &s), Status::kOk);
    DecodedMesh m = DecodeOk(s);
    ASSERT_EQ(m.int_attributes.size(), 1u);
    EXPECT_EQ(m.int_attributes[0].values, t.joints);
  }
}

TEST(RoundTrip, AsciiStreamIsSevenBitAndDecodesIdentically) {
  for (const TestMesh& t : AllMeshes()) {
    EncodeParams p;
    const auto bin = EncodeOk(t, p);
    p.stream_type = StreamType::kAscii;
    StreamInfo info;
    const auto asc = EncodeOk(t, p, &info);
    EXPECT_EQ(info.stream_type, StreamType::kAscii);
    for (uint8_t c : asc) ASSERT_LT(c, 128);
    const DecodedMesh a = DecodeOk(bin), b = DecodeOk(asc);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.indices, b.indices);
  }
}

TEST(RoundTrip, EmptyMeshAndIsolatedVertices) {
  TestMesh empty;
  DecodedMesh m = DecodeOk(EncodeOk(empty, EncodeParams()));
  EXPECT_EQ(m.num_vertices(), 0u);
  EXPECT_EQ(m.num_triangles(), 0u);
  TestMesh points;
  points.positions = {1, 2, 3, -1, 0, 5, 1, 2, 3, 7, 7, 7};
  EncodeParams p;
  p.keep_order = true;
  m = DecodeOk(EncodeOk(points, p));
  CheckExact(points, m, 14, 10, 12);
}

TEST(RoundTrip, DeterministicAndStreamInfoAddsUp) {
  const TestMesh t = o3dgc_test::Sphere(30, 20);
  StreamInfo info;
  const auto a = EncodeOk(t, EncodeParams(), &info);
  const auto b = EncodeOk(t, EncodeParams());
  EXPECT_EQ(a, b);
  EXPECT_EQ(info.total, a.size());
  EXPECT_GT(info.connectivity, 0u);
  EXPECT_GT(info.positions, 0u);
  EXPECT_GT(info.normals, 0u);
  ASSERT_EQ(info.float_attributes.size(), 0u);
  EXPECT_EQ(info.groups, 0u);  // no groups in this mesh
  const size_t sum = info.header + info.connectivity + info.positions + info.normals + info.groups;
  EXPECT_LE(sum, a.size() + 8);
  EXPECT_GE(sum + 8, a.size());
  StreamInfo read;
  ASSERT_EQ(ReadStreamInfo(a.data(), a.size(), &read), Status::kOk);
  EXPECT_EQ(read.num_vertices, t.nv());
  EXPECT_EQ(read.num_triangles, t.nt());
  EXPECT_EQ(read.version_major, kFormatMajor);
  // The lowest version with the stream's features (1.1, or 1.2 with modelled low bits).
  EXPECT_EQ(read.version_minor, info.version_minor);
  EXPECT_EQ(info.version_minor, info.low_bits ? 2u : 1u);
  EXPECT_EQ(info.version_major, 1u);
  EXPECT_STREQ(FormatVersionString(), "1.3");
}

TEST(RoundTrip, RejectsInvalidInput) {
  TestMesh t = o3dgc_test::Grid(3, 3);
  std::vector<uint8_t> s;
  MeshView v = t.View();
  t.indices[4] = 1000;
  EXPECT_EQ(Encode(t.View(), EncodeParams(), &s), Status::kInvalidArgument);
  t = o3dgc_test::Grid(3, 3);
  t.positions[5] = std::nanf("");
  EXPECT_EQ(Encode(t.View(), EncodeParams(), &s), Status::kInvalidArgument);
  t = o3dgc_test::Grid(3, 3);
  EncodeParams p;
  p.position_bits = 31;
  EXPECT_EQ(Encode(t.View(), p, &s), Status::kInvalidArgument);
  EXPECT_EQ(Encode(t.View(), EncodeParams(), nullptr), Status::kInvalidArgument);
  (void)v;
}

TEST(RoundTrip, PartsCodedInTheWholeBoxDecodeSharedVerticesAlike) {
  // A sphere cut in two halves, each coded alone: with the whole sphere's box they share a grid,
  // so the vertices of the cut decode to the same positions in both streams.
  const TestMesh whole = o3dgc_test::Sphere(24, 16);
  std::array<float, 6> box = {whole.positions[0], whole.positions[1], whole.positions[2],
                              whole.positions[0], whole.positions[1], whole.positions[2]};
  for (size_t i = 0; i < whole.positions.size(); ++i) {
    box[i % 3] = std::min(box[i % 3], whole.positions[i]);
    box[3 + i % 3] = std::max(box[3 + i % 3], whole.positions[i]);
  }
  TestMesh half[2];
  for (size_t t = 0; t < whole.nt(); ++t) {
    float z = 0;
    for (int k = 0; k < 3; ++k) z += whole.positions[3 * whole.indices[3 * t + k] + 2];
    TestMesh& h = half[z > 0 ? 1 : 0];
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = whole.indices[3 * t + k];
      h.indices.push_back(uint32_t(h.nv()));
      h.positions.insert(h.positions.end(), whole.positions.begin() + 3 * v,
                         whole.positions.begin() + 3 * v + 3);
    }
  }
  ASSERT_GT(half[0].nt(), 0u);
  ASSERT_GT(half[1].nt(), 0u);
  for (RangeMode mode : {RangeMode::kUniform, RangeMode::kPerAxis, RangeMode::kDiagonal}) {
    EncodeParams p;
    p.position_bits = 9;
    p.position_range = mode;
    p.position_box = box;
    std::map<std::array<float, 3>, std::array<float, 3>> decoded_of;  // input -> decoded
    int shared = 0;
    for (const TestMesh& h : half) {
      const DecodedMesh d = DecodeOk(EncodeOk(h, p));
      ASSERT_EQ(d.num_triangles(), h.nt());
      // Triangles keep their corners' input positions through the quantization: match each
      // input corner with its decoded corner through the set of decoded positions nearest.
      const double step = 4.0 / double((1 << 9) - 1);
      for (size_t v = 0; v < h.nv(); ++v) {
        const std::array<float, 3> in = {h.positions[3 * v], h.positions[3 * v + 1],
                                         h.positions[3 * v + 2]};
        size_t best = 0;
        double best_d = 1e30;
        for (size_t u = 0; u < d.num_vertices(); ++u) {
          double e = 0;
          for (int k = 0; k < 3; ++k) e += std::pow(double(d.positions[3 * u + k]) - in[k], 2);
          if (e < best_d) {
            best_d = e;
            best = u;
          }
        }
        ASSERT_LT(std::sqrt(best_d), step);
        const std::array<float, 3> out = {d.positions[3 * best], d.positions[3 * best + 1],
                                          d.positions[3 * best + 2]};
        auto it = decoded_of.find(in);
        if (it == decoded_of.end()) {
          decoded_of[in] = out;
        } else if (&h == &half[1]) {
          ++shared;
          EXPECT_EQ(it->second, out);
        }
      }
    }
    EXPECT_GT(shared, 0);
  }
  // The box of the mesh itself gives the stream without a box; a box that misses a position is
  // refused.
  EncodeParams p;
  EXPECT_EQ(EncodeOk(whole, p), [&] {
    p.position_box = box;
    return EncodeOk(whole, p);
  }());
  std::array<float, 6> small = box;
  small[4] *= 0.5f;
  p.position_box = small;
  std::vector<uint8_t> s;
  EXPECT_EQ(Encode(whole.View(), p, &s), Status::kInvalidArgument);
}

TEST(RoundTrip, ExtremeCoordinates) {
  TestMesh t;
  t.positions = {-3e38f, 0, 1, 3e38f, 0, 1, 0, 1e-30f, 1};
  t.indices = {0, 1, 2};
  std::vector<uint8_t> s;
  // The range end overflows a float: refused, not a stream the decoder would reject.
  EXPECT_EQ(Encode(t.View(), EncodeParams(), &s), Status::kUnsupported);
  t.positions = {-1e37f, 5e36f, 1, 1e37f, 0, -1e37f, 1e-30f, 1e-30f, 1e-30f};
  EncodeParams p;
  p.keep_order = true;
  p.position_bits = 30;
  ASSERT_EQ(Encode(t.View(), p, &s), Status::kOk);
  DecodedMesh m = DecodeOk(s);
  CheckExact(t, m, 30, 10, 12);
}

TEST(RoundTrip, CancelFromProgress) {
  const TestMesh t = o3dgc_test::Sphere(10, 6);
  EncodeParams p;
  p.progress = [](float f) { return f < 0.5f; };
  std::vector<uint8_t> s;
  EXPECT_EQ(Encode(t.View(), p, &s), Status::kCancelled);
}

TEST(RoundTrip, TwoSidedMeshCostsLittleMore) {
  // Every face twice with opposite winding, as in two-sided CAD exports.
  TestMesh one = o3dgc_test::Sphere(24, 16);
  one.normals.clear();
  TestMesh two = one;
  for (size_t i = 0; i < one.indices.size(); i += 3) {
    two.indices.insert(two.indices.end(), {one.indices[i], one.indices[i + 2], one.indices[i + 1]});
  }
  const auto a = EncodeOk(one, EncodeParams());
  const auto b = EncodeOk(two, EncodeParams());
  EXPECT_LT(b.size(), a.size() + a.size() / 20 + 16);
  CheckTriangleSet(two, DecodeOk(b), 14);
  EncodeParams keep;
  keep.keep_order = true;
  CheckExact(two, DecodeOk(EncodeOk(two, keep)), 14, 10, 12);
}

// A grid with a varied normal field and joint ids whose right half uses its own copies of the
// middle column (a UV seam). `hard`: the copies in rows 8 and up get another normal (a hard edge
// along half the seam).
TestMesh SeamedGrid(bool hard) {
  const uint32_t n = 16;
  TestMesh g = o3dgc_test::Grid(n, n);
  for (size_t v = 0; v < g.nv(); ++v) {
    const double x = g.positions[3 * v] - 0.5, y = g.positions[3 * v + 1] - 0.5;
    const double l = std::sqrt(x * x + y * y + 1);
    g.normals[3 * v] = float(x / l);
    g.normals[3 * v + 1] = float(y / l);
    g.normals[3 * v + 2] = float(1 / l);
    g.joints.insert(g.joints.end(), {int32_t(v % 7), int32_t(v / 40), 0, 3});
  }
  TestMesh s = g;
  std::vector<uint32_t> copy_of(g.nv(), 0xFFFFFFFFu);
  for (uint32_t j = 0; j <= n; ++j) {
    const uint32_t v = j * (n + 1) + n / 2;
    copy_of[v] = uint32_t(s.nv());
    s.positions.insert(s.positions.end(), &g.positions[3 * v], &g.positions[3 * v] + 3);
    s.normals.insert(s.normals.end(),
                     {g.normals[3 * v], g.normals[3 * v + 1],
                      hard && j >= 8 ? -g.normals[3 * v + 2] : g.normals[3 * v + 2]});
    s.joints.insert(s.joints.end(), &g.joints[4 * v], &g.joints[4 * v] + 4);
    s.uvs.insert(s.uvs.end(), {g.uvs[2 * v] + 0.5f, g.uvs[2 * v + 1]});
  }
  for (size_t t = 0; t < s.nt(); ++t) {
    bool right = false;
    for (int k = 0; k < 3; ++k) right |= (s.indices[3 * t + k] % (n + 1)) > n / 2;
    if (!right) continue;
    for (int k = 0; k < 3; ++k) {
      uint32_t& v = s.indices[3 * t + k];
      if (copy_of[v] != 0xFFFFFFFFu) v = copy_of[v];
    }
  }
  return s;
}

// Format 1.1: the copies a UV seam makes merge back where their normals and joints equal the
// original's (they decode to the same values and cost no more than without the seam); along a hard
// edge (normals that differ) the copies keep their own normals.
TEST(RoundTrip, AttributesContinuousAcrossSeamsAreCodedOnce) {
  for (bool hard : {false, true}) {
    SCOPED_TRACE(hard ? "hard edge" : "smooth");
    const TestMesh s = SeamedGrid(hard);
    EncodeParams keep;
    keep.keep_order = true;
    StreamInfo info;
    const DecodedMesh m = DecodeOk(EncodeOk(s, keep, &info));
    CheckExact(s, m, 14, 10, 12);
    ASSERT_EQ(m.int_attributes.size(), 1u);
    EXPECT_EQ(m.int_attributes[0].values, s.joints);
    // The copies (the last 17 vertices) against their originals.
    const size_t first_copy = s.nv() - 17;
    for (uint32_t j = 0; j <= 16; ++j) {
      const size_t v = j * 17 + 8, c = first_copy + j;
      const bool same = std::equal(&m.normals[3 * v], &m.normals[3 * v] + 3, &m.normals[3 * c]);
      EXPECT_EQ(same, !hard || j < 8) << "row " << j;
    }
    // Without the seam (the copies welded back): the normals' and joints' bytes barely differ.
    TestMesh welded = s;
    welded.uvs.clear();
    for (size_t i = 0; i < welded.indices.size(); ++i) {
      if (welded.indices[i] >= first_copy)
        welded.indices[i] = uint32_t((welded.indices[i] - first_copy) * 17 + 8);
    }
    welded.positions.resize(3 * first_copy);
    welded.normals.resize(3 * first_copy);
    welded.joints.resize(4 * first_copy);
    StreamInfo seamed_info, welded_info;
    EncodeOk(s, EncodeParams(), &seamed_info);
    EncodeOk(welded, EncodeParams(), &welded_info);
    if (!hard) {
      EXPECT_LE(seamed_info.normals, welded_info.normals + 2);
      EXPECT_LE(seamed_info.int_attributes[0], welded_info.int_attributes[0] + 2);
    } else {
      EXPECT_GT(seamed_info.normals, welded_info.normals + 8);
    }
  }
}

// Split vertices with joint ids only (no normal, no UV): the joints merge, nothing else needs the
// attribute mesh.
TEST(RoundTrip, JointsOnlyAcrossSeams) {
  TestMesh s = SeamedGrid(false);
  s.normals.clear();
  s.uvs.clear();
  for (bool keep : {false, true}) {
    EncodeParams p;
    p.keep_order = keep;
    const DecodedMesh m = DecodeOk(EncodeOk(s, p));
    ASSERT_EQ(m.int_attributes.size(), 1u);
    if (keep) {
      EXPECT_EQ(m.int_attributes[0].values, s.joints);
    } else {
      CheckTriangleSet(s, m, 14);
    }
  }
}

TEST(RoundTrip, SeamsShareWeldedPositions) {
  // A grid whose right half uses its own copies of the middle column (a UV seam): the copies share
  // positions, so the stream must barely grow, and the round trip keeps both sides.
  TestMesh g = o3dgc_test::Grid(16, 16);
  g.normals.clear();
  StreamInfo base_info, seamed_info;
  const auto base = EncodeOk(g, EncodeParams(), &base_info);
  TestMesh s = g;
  const uint32_t n = 16;
  std::vector<uint32_t> copy_of(g.nv(), 0xFFFFFFFFu);
  for (uint32_t j = 0; j <= n; ++j) {
    const uint32_t v = j * (n + 1) + n / 2;
    copy_of[v] = uint32_t(s.nv());
    s.positions.insert(s.positions.end(),
                       {g.positions[3 * v], g.positions[3 * v + 1], g.positions[3 * v + 2]});
    s.uvs.insert(s.uvs.end(), {g.uvs[2 * v] + 0.5f, g.uvs[2 * v + 1]});
  }
  for (size_t t = 0; t < s.nt(); ++t) {
    bool right = false;
    for (int k = 0; k < 3; ++k) right |= (s.indices[3 * t + k] % (n + 1)) > n / 2;
    if (!right) continue;
    for (int k = 0; k < 3; ++k) {
      uint32_t& v = s.indices[3 * t + k];
      if (copy_of[v] != 0xFFFFFFFFu) v = copy_of[v];
    }
  }
  const auto seamed = EncodeOk(s, EncodeParams(), &seamed_info);
  // Positions are coded once per welded vertex: the 17 copies add (almost) nothing there.
  EXPECT_LE(seamed_info.positions, base_info.positions + 4);
  EXPECT_GT(seamed.size(), base.size());
  EncodeParams keep;
  keep.keep_order = true;
  CheckExact(s, DecodeOk(EncodeOk(s, keep)), 14, 10, 12);
  CheckTriangleSet(s, DecodeOk(seamed), 14);
}

TEST(RoundTrip, CompressesARegularSphereWell) {
  // 14-bit positions + 10-bit normals of a smooth closed mesh: well under 4 bytes per vertex.
  const TestMesh t = o3dgc_test::Sphere(64, 48);
  StreamInfo info;
  const auto s = EncodeOk(t, EncodeParams(), &info);
  EXPECT_LT(double(s.size()) / t.nv(), 4.0);
  EXPECT_LT(double(info.connectivity) * 8 / t.nv(), 1.0);  // regular valence-6 mesh
}

}  // namespace
