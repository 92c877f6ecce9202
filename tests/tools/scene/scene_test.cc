#include "scene/scene.h"

#include <gtest/gtest.h>

namespace hullpack {
namespace {

Mesh Named(const std::string& name) {
  Mesh m;
  m.name = name;
  return m;
}

TEST(KeepMeshes, RenumbersTheNodesReferencesAndDropsThoseToRemovedMeshes) {
  Scene scene;
  scene.meshes = {Named("a"), Named("b"), Named("c"), Named("d")};
  Node first, second;
  first.meshes = {0, 1, 3};
  second.meshes = {2, 3, 7};  // 7 refers to no mesh and goes too
  scene.nodes = {first, second};
  EXPECT_EQ(KeepMeshes(scene, {true, false, false, true}), 2u);
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[0].name, "a");
  EXPECT_EQ(scene.meshes[1].name, "d");
  EXPECT_EQ(scene.nodes[0].meshes, (std::vector<int>{0, 1}));
  EXPECT_EQ(scene.nodes[1].meshes, (std::vector<int>{1}));
}

TEST(KeepMeshes, AShortFlagListDropsTheMeshesItDoesNotReach) {
  Scene scene;
  scene.meshes = {Named("a"), Named("b")};
  EXPECT_EQ(KeepMeshes(scene, {true}), 1u);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].name, "a");
}

}  // namespace
}  // namespace hullpack
