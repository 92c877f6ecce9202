#include "pipeline/codec_weld.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "o3dgc/o3dgc.h"
#include "pipeline/mesh_codec.h"

namespace hullpack {
namespace {

// A flat n x n grid as a CAD exporter writes it: every triangle has its own three vertices and
// its own normal, computed per triangle, which differ in their last bits.
Mesh FacetedGrid(int n) {
  Mesh m;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const float corners[4][2] = {{float(x), float(y)},
                                   {float(x + 1), float(y)},
                                   {float(x + 1), float(y + 1)},
                                   {float(x), float(y + 1)}};
      static const int kTriangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
      for (const auto& tri : kTriangles) {
        const float nz = std::nextafter(1.0f, 2.0f * float((x + y) % 2));
        for (int k = 0; k < 3; ++k) {
          m.indices.push_back(uint32_t(m.vertex_count()));
          m.positions.insert(m.positions.end(), {corners[tri[k]][0], corners[tri[k]][1], 0});
          m.normals.insert(m.normals.end(), {0, 0, nz});
        }
      }
    }
  }
  return m;
}

TEST(CodecWeld, FaceNormalsStoredAlikeWeldIntoSharedVertices) {
  const Mesh in = FacetedGrid(4);
  ASSERT_EQ(in.vertex_count(), 4u * 4u * 6u);
  const std::optional<Mesh> out = WeldNormalsStoredAlike(in, 10);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(out->vertex_count(), 5u * 5u);
  ASSERT_EQ(out->triangle_count(), in.triangle_count());
  for (size_t c = 0; c < in.indices.size(); ++c) {
    const uint32_t a = in.indices[c], b = out->indices[c];
    for (int k = 0; k < 3; ++k) EXPECT_EQ(out->positions[3 * b + k], in.positions[3 * a + k]);
    EXPECT_EQ(o3dgc::OctahedralNormalKey(&out->normals[3 * b], 10),
              o3dgc::OctahedralNormalKey(&in.normals[3 * a], 10));
  }
}

TEST(CodecWeld, OtherAttributesKeepVerticesApart) {
  Mesh in = FacetedGrid(2);
  in.uv_sets.resize(1);
  for (size_t v = 0; v < in.vertex_count(); ++v) {
    in.uv_sets[0].insert(in.uv_sets[0].end(), {float(v), 0});  // every vertex its own UV
  }
  EXPECT_FALSE(WeldNormalsStoredAlike(in, 10).has_value());
  Mesh no_normals = FacetedGrid(2);
  no_normals.normals.clear();
  EXPECT_FALSE(WeldNormalsStoredAlike(no_normals, 10).has_value());
  EXPECT_FALSE(WeldNormalsStoredAlike(FacetedGrid(2), 17).has_value());
}

TEST(CodecWeld, EncodeMeshCodesTheWeldedVerticesAndDecodesTheSameNormals) {
  const Mesh in = FacetedGrid(6);
  Result<EncodedMesh> enc = EncodeMesh(in, {}, MeshCodecSettings());
  ASSERT_TRUE(enc.ok()) << enc.status().ToString();
  Result<Mesh> dec = DecodeMesh(enc->stream.data(), enc->stream.size(), nullptr, "grid");
  ASSERT_TRUE(dec.ok()) << dec.status().ToString();
  EXPECT_EQ(dec->vertex_count(), 7u * 7u);
  for (size_t v = 0; v < dec->vertex_count(); ++v) {
    EXPECT_NEAR(dec->normals[3 * v + 2], 1.0f, 1e-6);
  }
  // keep_order promises the input's vertices: nothing is welded.
  MeshCodecSettings keep;
  keep.keep_order = true;
  Result<EncodedMesh> kept = EncodeMesh(in, {}, keep);
  ASSERT_TRUE(kept.ok());
  Result<Mesh> kept_dec = DecodeMesh(kept->stream.data(), kept->stream.size(), nullptr, "grid");
  ASSERT_TRUE(kept_dec.ok());
  EXPECT_EQ(kept_dec->vertex_count(), in.vertex_count());
  EXPECT_LT(enc->stream.size(), kept->stream.size());
}

}  // namespace
}  // namespace hullpack
