// Connectivity coder on its own: every triangle comes back with its winding.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <random>
#include <set>

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

// Triangles with the same vertex set are coded as one primary (the first in the input) followed
// by its copies in input order: check that order in the encoder's output (degenerate triangles,
// coded apart, left out).
void ExpectCopiesFollowTheirPrimary(const std::vector<uint32_t>& tris,
                                    const std::vector<uint32_t>& source) {
  auto vertex_set = [&](uint32_t t) {
    std::array<uint32_t, 3> k = {tris[3 * t], tris[3 * t + 1], tris[3 * t + 2]};
    std::sort(k.begin(), k.end());
    return k;
  };
  std::map<std::array<uint32_t, 3>, uint32_t> first;  // vertex set -> first input triangle
  for (uint32_t t = 0; t < tris.size() / 3; ++t) first.emplace(vertex_set(t), t);
  std::set<std::array<uint32_t, 3>> coded;
  std::array<uint32_t, 3> previous = {0, 0, 0};
  uint32_t previous_t = 0;
  for (const uint32_t t : source) {
    const std::array<uint32_t, 3> k = vertex_set(t);
    if (k[0] == k[1] || k[1] == k[2]) continue;
    if (!coded.empty() && k == previous) {
      EXPECT_LT(previous_t, t) << "copies in input order";
    } else {
      EXPECT_EQ(t, first[k]) << "triangle " << t << " coded as a primary, but " << first[k]
                             << " has its vertices";
      EXPECT_TRUE(coded.insert(k).second) << "a vertex set coded in two places";
    }
    previous = k;
    previous_t = t;
  }
}

// Round trip in every format minor version (0: 1.0, 1: 1.1); `bytes` gets the current one's size.
void RoundTrip(const std::vector<uint32_t>& tris, uint32_t nv, size_t* bytes = nullptr) {
  for (uint32_t minor = 0; minor <= kFormatMinor; ++minor) {
    SCOPED_TRACE("format 1." + std::to_string(minor));
    std::vector<uint8_t> buf;
    ConnectivityEncoding enc_out;
    {
      ArithmeticEncoder enc(&buf);
      EncodeConnectivity(tris, nv, &enc, &enc_out, true, minor);
      enc.Finish();
    }
    ASSERT_EQ(enc_out.old_of_new.size(), nv);
    ExpectCopiesFollowTheirPrimary(tris, enc_out.source);
    ArithmeticDecoder dec(buf.data(), buf.size());
    std::vector<uint32_t> out, opposite, opposite_vertices, component_ends;
    uint32_t dnv = 0;
    ASSERT_EQ(DecodeConnectivity(&dec, tris.size() / 3, nv, &out, &dnv, &opposite,
                                 &opposite_vertices, nullptr, minor, false, &component_ends),
              Status::kOk);
    EXPECT_EQ(component_ends, enc_out.component_ends);  // the encoder keeps the same ranges
    {
      // With the front's gates compacted between steps: the same triangles and neighbours.
      ArithmeticDecoder again(buf.data(), buf.size());
      std::vector<uint32_t> c_out, c_opposite, c_opposite_vertices;
      uint32_t c_nv = 0;
      ASSERT_EQ(DecodeConnectivity(&again, tris.size() / 3, nv, &c_out, &c_nv, &c_opposite,
                                   &c_opposite_vertices, nullptr, minor, /*compact_front=*/true),
                Status::kOk);
      EXPECT_EQ(c_out, out);
      EXPECT_EQ(c_nv, dnv);
      EXPECT_EQ(c_opposite, opposite);
      EXPECT_EQ(c_opposite_vertices, opposite_vertices);
    }
    EXPECT_EQ(dnv, nv);
    EXPECT_EQ(out, enc_out.triangles);
    EXPECT_EQ(opposite, enc_out.opposite);
    EXPECT_EQ(opposite_vertices, enc_out.opposite_vertices);
    EXPECT_EQ(Canon(out, &enc_out.old_of_new), Canon(tris, nullptr));
    if (bytes) *bytes = buf.size();
  }
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

// Size of the connectivity of `tris` in format 1.minor.
size_t ConnectivityBytes(const std::vector<uint32_t>& tris, uint32_t nv, uint32_t minor) {
  std::vector<uint8_t> buf;
  ConnectivityEncoding out;
  ArithmeticEncoder enc(&buf);
  EncodeConnectivity(tris, nv, &enc, &out, false, minor);
  enc.Finish();
  return buf.size();
}

// Format 1.1's gate contexts and walks along the front, on an STL-style part (fans, slivers, a
// hole per cell): the round trip holds in both versions and 1.1 takes clearly fewer bytes.
TEST(Connectivity, CadTessellationSmallerInFormat11) {
  const o3dgc_test::TestMesh t = o3dgc_test::PocketPlate(6, 5);
  RoundTrip(t.indices, uint32_t(t.nv()));
  const size_t v10 = ConnectivityBytes(t.indices, uint32_t(t.nv()), 0);
  const size_t v11 = ConnectivityBytes(t.indices, uint32_t(t.nv()), 1);
  EXPECT_LT(double(v11), 0.9 * double(v10)) << v10 << " -> " << v11;
}

// A hostile format 1.1 stream cannot make a walk run long: the steps are capped.
TEST(Connectivity, WalkStepsAreBounded) {
  const o3dgc_test::TestMesh t = o3dgc_test::PocketPlate(2, 2);
  std::vector<uint8_t> buf;
  ConnectivityEncoding enc_out;
  ArithmeticEncoder enc(&buf);
  EncodeConnectivity(t.indices, uint32_t(t.nv()), &enc, &enc_out, false, 1);
  enc.Finish();
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    std::vector<uint8_t> c = buf;
    c[rng() % c.size()] ^= uint8_t(1u << (rng() % 8));
    ArithmeticDecoder dec(c.data(), c.size());
    std::vector<uint32_t> out;
    uint32_t nv = 0;
    const Status s =
        DecodeConnectivity(&dec, t.nt(), t.nv(), &out, &nv, nullptr, nullptr, nullptr, 1);
    if (s == Status::kOk) {
      ASSERT_EQ(out.size(), 3 * t.nt());
      for (uint32_t v : out) ASSERT_LT(v, nv);
    }
  }
}

// The vertex ranges of the parts, as the decoder numbers them: one past each part's last id,
// when no triangle joins two parts, else none.
std::vector<uint32_t> DecodedComponentEnds(const std::vector<uint32_t>& tris, uint32_t nv,
                                           std::vector<uint32_t>* decoded) {
  std::vector<uint8_t> buf;
  ConnectivityEncoding enc_out;
  ArithmeticEncoder enc(&buf);
  EncodeConnectivity(tris, nv, &enc, &enc_out, false, kFormatMinor);
  enc.Finish();
  ArithmeticDecoder dec(buf.data(), buf.size());
  std::vector<uint32_t> ends;
  uint32_t dnv = 0;
  EXPECT_EQ(DecodeConnectivity(&dec, tris.size() / 3, nv, decoded, &dnv, nullptr, nullptr, nullptr,
                               kFormatMinor, false, &ends),
            Status::kOk);
  EXPECT_EQ(dnv, nv);
  return ends;
}

// Ascending ends, and no triangle with corners in two of the ranges they bound.
void ExpectTrianglesWithinRanges(const std::vector<uint32_t>& tris,
                                 const std::vector<uint32_t>& ends) {
  EXPECT_TRUE(std::is_sorted(ends.begin(), ends.end()));
  const auto range = [&](uint32_t v) {
    return std::upper_bound(ends.begin(), ends.end(), v) - ends.begin();
  };
  for (size_t i = 0; i < tris.size() / 3; ++i) {
    EXPECT_EQ(range(tris[3 * i]), range(tris[3 * i + 1])) << "triangle " << i;
    EXPECT_EQ(range(tris[3 * i]), range(tris[3 * i + 2])) << "triangle " << i;
  }
}

TEST(Connectivity, DisjointPartsGiveTheirVertexRanges) {
  const o3dgc_test::TestMesh t = o3dgc_test::Concatenated(
      {o3dgc_test::Torus(12, 8), o3dgc_test::Grid(6, 5), o3dgc_test::Sphere(10, 7)});
  RoundTrip(t.indices, uint32_t(t.nv()));  // the encoder's ranges are the decoder's
  std::vector<uint32_t> decoded;
  const std::vector<uint32_t> ends = DecodedComponentEnds(t.indices, uint32_t(t.nv()), &decoded);
  ASSERT_EQ(ends.size(), 3u);
  EXPECT_EQ(ends.back(), t.nv());
  ExpectTrianglesWithinRanges(decoded, ends);
}

TEST(Connectivity, PartsJoinedAtAVertexGiveNoRanges) {
  // Two grids sharing one corner vertex: the second part's triangles reuse a vertex of the first.
  o3dgc_test::TestMesh t =
      o3dgc_test::Concatenated({o3dgc_test::Grid(4, 4), o3dgc_test::Grid(4, 4)});
  const uint32_t second = 25;  // the first vertex of the second grid
  for (size_t i = 3 * 32; i < t.indices.size(); ++i) {
    if (t.indices[i] == second) t.indices[i] = 0;
  }
  std::vector<uint32_t> tris;
  for (const uint32_t v : t.indices) tris.push_back(v > second ? v - 1 : v);
  std::vector<uint32_t> decoded;
  EXPECT_TRUE(DecodedComponentEnds(tris, uint32_t(t.nv() - 1), &decoded).empty());
  // A non-manifold mesh with a separate component and duplicated triangles.
  std::vector<uint32_t> awkward = o3dgc_test::Awkward().indices;
  for (auto& v : awkward) {
    if (v == 11) v = 9;
  }
  ExpectTrianglesWithinRanges(decoded, DecodedComponentEnds(awkward, 10, &decoded));
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

TEST(Connectivity, TwoSidedFanAroundOneApex) {
  // Every triangle holds vertex 0, the smallest id, so the copies are found among the 2 x 60
  // triangles bucketed at that vertex (the sorted path, not the small-bucket one); the copies are
  // interleaved with the primaries and alternate in winding.
  std::vector<uint32_t> fan;
  const uint32_t n = 60;
  for (uint32_t i = 0; i < n; ++i) fan.insert(fan.end(), {0, 1 + i, 1 + (i + 1) % n});
  std::vector<uint32_t> two;
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t* t = &fan[3 * i];
    two.insert(two.end(), t, t + 3);
    if (i >= 2) {  // a copy of an earlier triangle, every other one flipped
      const uint32_t* e = &fan[3 * (i - 2)];
      if (i % 2) {
        two.insert(two.end(), {e[0], e[2], e[1]});
      } else {
        two.insert(two.end(), e, e + 3);
      }
    }
  }
  two.insert(two.end(), {fan[3 * (n - 2)], fan[3 * (n - 2) + 2], fan[3 * (n - 2) + 1]});
  two.insert(two.end(), fan.begin() + 3 * (n - 1), fan.end());
  RoundTrip(fan, n + 1);
  RoundTrip(two, n + 1);  // checks that every copy follows its primary
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
