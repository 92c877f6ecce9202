// Memory bounds of the packed-GLB reader (the o3dgc stream itself:
// tests/o3dgc/malformed_stream_test.cc HugeVertexCountRejectedQuickly and legacy_decoder_test.cc
// LyingCountsAreRejectedBeforeAllocating): files that claim 2^32 vertices are rejected before
// anything that size is allocated, a small file cannot make the reader inflate one stream many
// times over, and a legitimately well-compressed file (decoded data far above 64 bytes per file
// byte) still reads back.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <fstream>
#include <iterator>

#include "../tools/pipeline/packed_glb_test_util.h"
#include "common/test_shapes.h"
#include "gltf/glb_reader.h"
#include "gltf/gltf_document.h"
#include "gltf/packed_glb_reader.h"
#include "pipeline/pack.h"

namespace hullpack {
namespace {

// A flat n x n grid of quads (test_shapes::Grid): regular enough that the codec stores it in very
// few bytes.
Mesh Grid(int n) {
  Mesh m;
  m.name = "grid";
  test_shapes::AppendTo(test_shapes::Grid(n, n), &m, /*with_normals=*/false);
  return m;
}

// The packed 250 x 250 grid (125,000 triangles), made once for the tests that need it.
const Mesh& BigGrid() {
  static const Mesh grid = Grid(250);
  return grid;
}
const std::vector<uint8_t>& BigGridGlb() {
  static const std::vector<uint8_t> glb = testing::PackWithoutHulls(BigGrid());
  return glb;
}

double PeakRssMegabytes() {
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

// The reader must refuse `glb` quickly and without growing the process by anything near the claim.
void ExpectRejectedCheaply(const std::vector<uint8_t>& glb, const std::string& what) {
  ASSERT_FALSE(glb.empty());
  const double rss_before = PeakRssMegabytes();
  const auto t0 = std::chrono::steady_clock::now();
  Result<Scene> scene = ReadPackedGltf(glb.data(), glb.size(), "hostile.glb", "", nullptr);
  EXPECT_FALSE(scene.ok()) << what;
  EXPECT_FALSE(scene.status().message().empty()) << what;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0)
      << what;
  EXPECT_LT(PeakRssMegabytes() - rss_before, 512.0) << what;
}

TEST(PackedGlbMemory, WellCompressedFileReadsBack) {
  const Mesh& grid = BigGrid();
  const std::vector<uint8_t>& glb = BigGridGlb();
  ASSERT_FALSE(glb.empty());
  const size_t decoded_bytes = grid.positions.size() * 4 + grid.indices.size() * 4;
  ASSERT_GT(decoded_bytes, 64 * glb.size())
      << "the case must exceed the reader's plain-file expansion limit";
  Result<Scene> scene = ReadPackedGltf(glb.data(), glb.size(), "grid.glb", "", nullptr);
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  ASSERT_EQ(scene->meshes.size(), 1u);
  EXPECT_EQ(scene->meshes[0].triangle_count(), grid.triangle_count());
}

TEST(PackedGlbMemory, AccessorsClaimingTwoToThe32VerticesAreRejected) {
  const std::vector<uint8_t> glb = testing::PackWithoutHulls(Grid(8));
  for (const char* attribute : {"POSITION", "indices"}) {
    const std::vector<uint8_t> bad = testing::RewriteGlb(glb, [&](GltfDocument& doc) {
      nlohmann::json& prim = doc.json()["meshes"][0]["primitives"][0];
      const int accessor = std::string(attribute) == "indices"
                               ? prim["indices"].get<int>()
                               : prim["attributes"][attribute].get<int>();
      doc.json()["accessors"][accessor]["count"] = uint64_t(1) << 32;
    });
    ExpectRejectedCheaply(bad, attribute);
  }
}

TEST(PackedGlbMemory, StreamClaimingTwoToThe32VerticesIsRejected) {
  // An original Open3DGC stream (which the decoder reads too) whose header claims 2^32 - 1
  // coordinates, in place of the packed file's own stream.
  std::ifstream in(std::string(HULLPACK_SOURCE_DIR) + "/tests/o3dgc/vectors/cup.binary.s3d",
                   std::ios::binary);
  std::vector<uint8_t> stream((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
  ASSERT_GT(stream.size(), 40u);
  for (int i = 0; i < 4; ++i) stream[14 + i] = 0xFF;  // coordinate count (little endian)
  const std::vector<uint8_t> glb = testing::PackWithoutHulls(Grid(8));
  const std::vector<uint8_t> bad = testing::RewriteGlb(glb, [&](GltfDocument& doc) {
    const int view = doc.json()["meshes"][0]["primitives"][0]["extensions"]
                               [kMeshCompressionExtension]["bufferView"];
    const int replaced = doc.AddBufferView(stream, 4);
    doc.json()["meshes"][0]["primitives"][0]["extensions"][kMeshCompressionExtension]
              ["bufferView"] = replaced;
    (void)view;
  });
  ExpectRejectedCheaply(bad, "stream");
}

TEST(PackedGlbMemory, OneStreamInflatedManyTimesIsRejected) {
  // 400 primitives, each with its own accessors, all pointing at one well-compressed stream: a
  // file of about 100 KB that would otherwise inflate to about 400 x 2.3 MB.
  const std::vector<uint8_t> bad = testing::RewriteGlb(BigGridGlb(), [](GltfDocument& doc) {
    nlohmann::json& js = doc.json();
    const nlohmann::json prim = js["meshes"][0]["primitives"][0];
    for (int copy = 0; copy < 400; ++copy) {
      nlohmann::json p = prim;
      for (auto& [name, accessor] : p["attributes"].items()) {
        js["accessors"].push_back(js["accessors"][accessor.get<int>()]);
        accessor = js["accessors"].size() - 1;
      }
      js["accessors"].push_back(js["accessors"][p["indices"].get<int>()]);
      p["indices"] = js["accessors"].size() - 1;
      js["meshes"][0]["primitives"].push_back(p);
    }
  });
  ExpectRejectedCheaply(bad, "400 inflations of one stream");
}

}  // namespace
}  // namespace hullpack
