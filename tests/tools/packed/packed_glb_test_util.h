#ifndef HULLPACK_TESTS_TOOLS_PACKED_PACKED_GLB_TEST_UTIL_H_
#define HULLPACK_TESTS_TOOLS_PACKED_PACKED_GLB_TEST_UTIL_H_

// Helpers for tests that feed the packed-GLB reader edited files: pack a mesh without hulls, then
// change the document and serialize it again.

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "gltf/glb_reader.h"
#include "gltf/gltf_document.h"
#include "pipeline/pack.h"

namespace hullpack {
namespace testing {

inline std::vector<uint8_t> PackWithoutHulls(Mesh mesh) {
  Scene scene;
  scene.meshes.push_back(std::move(mesh));
  AddRootNodeForAllMeshes(scene, "root");
  PackOptions options;
  options.collision.policy = HullPolicy::kNone;
  Result<PackResult> packed = PackScene(std::move(scene), options);
  EXPECT_TRUE(packed.ok()) << packed.status().ToString();
  return packed.ok() ? packed->glb : std::vector<uint8_t>();
}

// Parses `glb`, lets `edit` change its document (JSON and binary), and serializes it again.
template <typename Edit>
std::vector<uint8_t> RewriteGlb(const std::vector<uint8_t>& glb, Edit edit) {
  Result<GltfDocument> doc = DecodeGlbDocument(glb.data(), glb.size(), "in.glb");
  EXPECT_TRUE(doc.ok()) << doc.status().ToString();
  if (!doc.ok()) return {};
  edit(doc.value());
  Result<std::vector<uint8_t>> out = doc->Serialize();
  EXPECT_TRUE(out.ok()) << out.status().ToString();
  return out.ok() ? out.value() : std::vector<uint8_t>();
}

}  // namespace testing
}  // namespace hullpack

#endif  // HULLPACK_TESTS_TOOLS_PACKED_PACKED_GLB_TEST_UTIL_H_
