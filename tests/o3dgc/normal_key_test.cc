#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace o3dgc {
namespace {

TEST(OctahedralNormalKey, NormalsApartByLessThanACellShareTheKey) {
  const float a[3] = {0.3f, -0.5f, 0.81f};
  const float scaled[3] = {0.6f, -1.0f, 1.62f};  // the coder ignores the length
  const float nudged[3] = {0.3f, -0.5f, std::nextafter(0.81f, 1.0f)};
  EXPECT_EQ(OctahedralNormalKey(a, 10), OctahedralNormalKey(scaled, 10));
  EXPECT_EQ(OctahedralNormalKey(a, 10), OctahedralNormalKey(nudged, 10));
  const float other[3] = {0.3f, -0.45f, 0.81f};
  EXPECT_NE(OctahedralNormalKey(a, 10), OctahedralNormalKey(other, 10));
}

TEST(OctahedralNormalKey, MirrorsInZAreKeptApart) {
  // The coder stores a normal or its mirror in z; a normal and its mirror differ in both.
  const float up[3] = {0.2f, 0.1f, 0.9f};
  const float down[3] = {0.2f, 0.1f, -0.9f};
  EXPECT_NE(OctahedralNormalKey(up, 10), OctahedralNormalKey(down, 10));
}

TEST(OctahedralNormalKey, ZeroNormalsAreStoredAsPlusZ) {
  const float zero[3] = {0, 0, 0};
  const float plus_z[3] = {0, 0, 1};
  EXPECT_EQ(OctahedralNormalKey(zero, 8), OctahedralNormalKey(plus_z, 8));
}

TEST(OctahedralNormalKey, BitsOutsideOneToSixteenGiveZero) {
  const float n[3] = {0, 0, 1};
  EXPECT_EQ(OctahedralNormalKey(n, 0), 0u);
  EXPECT_EQ(OctahedralNormalKey(n, 17), 0u);
  EXPECT_NE(OctahedralNormalKey(n, 16), 0u);
}

TEST(OctahedralNormalKey, EqualKeysDecodeToTheSameNormal) {
  // Two triangles of one plane, each vertex its own, with normals that differ in their last
  // bits: every decoded normal of an equal key is the same.
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<uint32_t> indices = {0, 1, 2, 3, 4, 5};
  std::vector<float> normals;
  for (int i = 0; i < 6; ++i) {
    normals.insert(normals.end(), {0.001f * float(i % 2), 0.3f, 0.95f + 1e-7f * float(i)});
  }
  MeshView mesh;
  mesh.positions = positions.data();
  mesh.num_vertices = 6;
  mesh.indices = indices.data();
  mesh.num_triangles = 2;
  mesh.normals = normals.data();
  EncodeParams params;
  params.keep_order = true;
  std::vector<uint8_t> stream;
  ASSERT_EQ(Encode(mesh, params, &stream), Status::kOk);
  DecodedMesh out;
  ASSERT_EQ(Decode(stream.data(), stream.size(), DecodeOptions(), &out), Status::kOk);
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      if (OctahedralNormalKey(&normals[3 * i], 10) != OctahedralNormalKey(&normals[3 * j], 10))
        continue;
      for (int k = 0; k < 3; ++k) EXPECT_EQ(out.normals[3 * i + k], out.normals[3 * j + k]);
    }
  }
}

}  // namespace
}  // namespace o3dgc
