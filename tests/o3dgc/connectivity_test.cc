// Connectivity coder on its own: every triangle comes back with its winding.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <random>

#include "connectivity_decoder.h"
#include "connectivity_encoder.h"
#include "test_meshes.h"

namespace {

using namespace o3dgc;

std::vector<std::array<uint32_t, 3>> Canon(const std::vector<uint32_t>& t,
                                          const std::vector<uint32_t>* map) {
  std::vector<std::array<uint32_t, 3>> out;
  for (size_t i = 0; i < t.size() / 3; ++i) {
    std::array<uint32_t, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = map ? (*map)[t[3 * i + k]] : t[3 * i + k];
    const int best = int(std::min_element(c.begin(), c.end()) - c.begin());
    out.push_back({c[best], c[(best + 1) % 3], c[(best + 2) % 3]});
  }
  std::sort(out.begin(), out.end());
  return out;
}

void RoundTrip(const std::vector<uint32_t>& tris, uint32_t nv, size_t* bytes = nullptr) {
  std::vector<uint8_t> buf;
  ConnectivityEncoding enc_out;
  {
    ArithmeticEncoder enc(&buf);
    EncodeConnectivity(tris, nv, &enc, &enc_out);
    enc.Finish();
  }
  ASSERT_EQ(enc_out.old_of_new.size(), nv);
  ArithmeticDecoder dec(buf.data(), buf.size());
  std::vector<uint32_t> out;
  uint32_t dnv = 0;
  ASSERT_EQ(DecodeConnectivity(&dec, tris.size() / 3, nv, &out, &dnv), Status::kOk);
  EXPECT_EQ(dnv, nv);
  EXPECT_EQ(out, enc_out.triangles);
  EXPECT_EQ(Canon(out, &enc_out.old_of_new), Canon(tris, nullptr));
  if (bytes) *bytes = buf.size();
}

TEST(Connectivity, ManifoldMeshes) {
  RoundTrip(o3dgc_test::Grid(20, 13).indices, 21 * 14);
  const auto s = o3dgc_test::Sphere(40, 30);
  size_t bytes = 0;
  RoundTrip(s.indices, uint32_t(s.nv()), &bytes);
  EXPECT_LT(double(bytes) * 8 / s.nv(), 1.0);
  const auto t = o3dgc_test::Torus(30, 17);
  RoundTrip(t.indices, uint32_t(t.nv()));
}

TEST(Connectivity, NonManifoldFlippedDuplicatedDegenerate) {
  const auto a = o3dgc_test::Awkward();
  // Awkward() references all but vertices 9 and 10; renumber to drop them.
  std::vector<uint32_t> tris = a.indices;
  for (auto& v : tris) {
    if (v == 11) v = 9;
  }
  RoundTrip(tris, 10);
}

TEST(Connectivity, TwoSidedMesh) {
  // Every face twice with opposite winding (like a two-sided CAD export).
  auto g = o3dgc_test::Grid(15, 15);
  std::vector<uint32_t> tris = g.indices;
  for (size_t i = 0; i < g.indices.size(); i += 3) {
    tris.insert(tris.end(), {g.indices[i], g.indices[i + 2], g.indices[i + 1]});
  }
  size_t one = 0, two = 0;
  RoundTrip(g.indices, uint32_t(g.nv()), &one);
  RoundTrip(tris, uint32_t(g.nv()), &two);
  EXPECT_LT(two, one + one / 4 + 8);
}

TEST(Connectivity, RandomTriangleSoups) {
  std::mt19937 rng(1);
  for (int iter = 0; iter < 200; ++iter) {
    const uint32_t nv = 3 + rng() % 30;
    const size_t nt = 1 + rng() % 60;
    std::vector<uint32_t> tris;
    std::vector<uint8_t> used(nv, 0);
    for (size_t i = 0; i < 3 * nt; ++i) {
      tris.push_back(rng() % nv);
      used[tris.back()] = 1;
    }
    // Compact the ids to the referenced ones.
    std::vector<uint32_t> map(nv);
    uint32_t n = 0;
    for (uint32_t v = 0; v < nv; ++v) map[v] = used[v] ? n++ : 0;
    for (auto& v : tris) v = map[v];
    RoundTrip(tris, n);
  }
}

}  // namespace

namespace {

TEST(Connectivity, HighValenceVerticesStayFast) {
  // A fan of 20000 triangles around one apex, plus 20000 separate triangles that all share
  // vertex 0: neither may make coding quadratic.
  std::vector<uint32_t> tris;
  const uint32_t n = 20000;
  for (uint32_t i = 0; i < n; ++i) tris.insert(tris.end(), {0, 1 + i, 2 + i});
  const uint32_t base = n + 2;
  for (uint32_t i = 0; i < n; ++i) tris.insert(tris.end(), {0, base + 2 * i, base + 2 * i + 1});
  const auto t0 = std::chrono::steady_clock::now();
  RoundTrip(tris, base + 2 * n);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
}

}  // namespace
