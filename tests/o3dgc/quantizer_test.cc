// Quantizer and octahedral mapping.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "predictors.h"
#include "quantizer.h"

namespace {

using namespace o3dgc;

TEST(Quantizer, DequantizeAllMatchesDequantizeForEveryDimension) {
  // Whole arrays, direct and through an index, with one component of zero range: bit for bit what
  // Dequantize gives per value.
  std::mt19937 rng(5);
  for (uint32_t dim = 1; dim <= 4; ++dim) {
    Quantizer q;
    q.dimension = dim;
    q.bits = 14;
    for (uint32_t c = 0; c < dim; ++c) {
      q.min[c] = -3.25f + float(c);
      q.range[c] = c == 1 ? 0.0f : 7.5f * float(c + 1);
    }
    const size_t n = 257;
    std::vector<int32_t> values(n * dim);
    for (int32_t& v : values) v = int32_t(rng() % (q.max_q() + 1));
    std::vector<uint32_t> index(n);
    for (size_t i = 0; i < n; ++i) index[i] = uint32_t((i * 7 + 3) % n);
    std::vector<float> direct(n * dim), indexed(n * dim);
    q.DequantizeAll(values.data(), nullptr, n, direct.data());
    q.DequantizeAll(values.data(), index.data(), n, indexed.data());
    for (size_t i = 0; i < n; ++i) {
      for (uint32_t c = 0; c < dim; ++c) {
        ASSERT_EQ(direct[i * dim + c], q.Dequantize(values[i * dim + c], c)) << dim << " " << i;
        ASSERT_EQ(indexed[i * dim + c], q.Dequantize(values[index[i] * dim + c], c))
            << dim << " " << i;
      }
    }
  }
}

TEST(Quantizer, HalfStepBoundAllBitDepths) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1000.f, 3000.f);
  std::vector<float> v(3 * 500);
  for (auto& x : v) x = u(rng);
  for (int bits = 1; bits <= 30; ++bits) {
    for (RangeMode mode : {RangeMode::kUniform, RangeMode::kPerAxis, RangeMode::kDiagonal}) {
      Quantizer q;
      q.dimension = 3;
      q.bits = bits;
      q.mode = mode;
      q.Fit(v.data(), 12, 500);
      ASSERT_TRUE(q.Valid());
      if (mode != RangeMode::kPerAxis) {
        EXPECT_EQ(q.range[0], q.range[1]);
        EXPECT_EQ(q.range[1], q.range[2]);
      }
      for (size_t i = 0; i < v.size(); ++i) {
        const uint32_t c = uint32_t(i % 3);
        const int32_t k = q.Quantize(v[i], c);
        ASSERT_GE(k, 0);
        ASSERT_LE(uint32_t(k), q.max_q());
        const double step = double(q.range[c]) / q.max_q();
        EXPECT_LE(std::fabs(double(q.Dequantize(k, c)) - v[i]), step / 2 + std::fabs(v[i]) * 1e-7);
      }
    }
  }
}

TEST(Quantizer, ConstantDataAndValidity) {
  std::vector<float> v(6, 2.5f);
  Quantizer q;
  q.dimension = 3;
  q.bits = 12;
  q.Fit(v.data(), 12, 2);
  EXPECT_EQ(q.Quantize(2.5f, 0), 0);
  EXPECT_EQ(q.Dequantize(0, 1), 2.5f);
  q.range[0] = INFINITY;
  EXPECT_FALSE(q.Valid());
  q.range[0] = 1;
  q.min[2] = 3e38f;
  q.range[2] = 3e38f;
  EXPECT_FALSE(q.Valid());
}

TEST(Octahedral, RoundTripsDirections) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  for (int i = 0; i < 10000; ++i) {
    double n[3] = {g(rng), g(rng), g(rng)};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x /= l;
    double u, v, r[3];
    OctEncode(n, &u, &v);
    ASSERT_LE(std::fabs(u), 1.0);
    ASSERT_LE(std::fabs(v), 1.0);
    OctDecode(u, v, r);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(r[k], n[k], 1e-9);
  }
}

}  // namespace

namespace position_error {

// PositionQuantizationError against the positions a real stream decodes to (keep_order, so vertex
// i of the decoded mesh is vertex i of the input), for every range mode and a spread of bits.
TEST(PositionQuantizationError, EqualsTheErrorOfTheDecodedStream) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> positions;
  std::vector<uint32_t> indices;
  for (uint32_t t = 0; t < 200; ++t) {
    for (int k = 0; k < 3; ++k) {
      positions.push_back(3.0f * u(rng) + 10.0f);
      positions.push_back(0.5f * u(rng));
      positions.push_back(1.5f * u(rng) - 2.0f);
      indices.push_back(3 * t + uint32_t(k));
    }
  }
  o3dgc::MeshView view;
  view.positions = positions.data();
  view.num_vertices = positions.size() / 3;
  view.indices = indices.data();
  view.num_triangles = indices.size() / 3;
  for (RangeMode mode : {RangeMode::kUniform, RangeMode::kPerAxis, RangeMode::kDiagonal}) {
    for (int bits : {1, 4, 9, 14, 22}) {
      EncodeParams params;
      params.keep_order = true;
      params.position_bits = bits;
      params.position_range = mode;
      std::vector<uint8_t> stream;
      ASSERT_EQ(Encode(view, params, &stream), Status::kOk);
      DecodedMesh decoded;
      ASSERT_EQ(Decode(stream.data(), stream.size(), DecodeOptions(), &decoded), Status::kOk);
      ASSERT_EQ(decoded.positions.size(), positions.size());
      double worst = 0;
      for (size_t i = 0; i < positions.size(); i += 3) {
        double d2 = 0;
        for (int c = 0; c < 3; ++c) {
          const double d = double(decoded.positions[i + c]) - double(positions[i + c]);
          d2 += d * d;
        }
        worst = std::max(worst, std::sqrt(d2));
      }
      EXPECT_EQ(PositionQuantizationError(positions.data(), 3 * sizeof(float), positions.size() / 3,
                                          bits, mode),
                worst)
          << int(mode) << " " << bits;
    }
  }
}

TEST(PositionQuantizationError, RejectsWhatEncodeRejects) {
  const float p[6] = {0, 0, 0, 1, NAN, 0};
  EXPECT_EQ(PositionQuantizationError(p, 12, 2, 10, RangeMode::kUniform), -1);
  EXPECT_EQ(PositionQuantizationError(p, 12, 1, 0, RangeMode::kUniform), -1);
  EXPECT_EQ(PositionQuantizationError(p, 12, 1, 31, RangeMode::kUniform), -1);
  EXPECT_EQ(PositionQuantizationError(nullptr, 12, 1, 10, RangeMode::kUniform), -1);
  EXPECT_EQ(PositionQuantizationError(p, 12, 1, 10, RangeMode::kUniform), 0);  // one point
}

}  // namespace position_error
