#include "batch/batch_plan.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace hullpack {
namespace {

TEST(BatchPlan, AbsolutePathIsLexicallyNormal) {
  EXPECT_EQ(AbsolutePath("/a/./b//c/../d.obj"), "/a/b/d.obj");
  EXPECT_EQ(AbsolutePath("/../x"), "/x");
  EXPECT_EQ(AbsolutePath("/"), "/");
  EXPECT_EQ(AbsolutePath("rel.obj")[0], '/');
}

TEST(BatchPlan, OutputsRelativeToTheCommonFolder) {
  auto plan = PlanBatch(
      {"/data/set/a.obj", "/data/set/sub/b.glb", "/data/set/sub/deep/c.x.fbx", "/data/set/noext"});
  ASSERT_TRUE(plan.ok()) << plan.status().message();
  EXPECT_EQ(plan.value()[0].output, "a.packed.glb");
  EXPECT_EQ(plan.value()[1].output, "sub/b.packed.glb");
  EXPECT_EQ(plan.value()[2].output, "sub/deep/c.x.packed.glb");
  EXPECT_EQ(plan.value()[3].output, "noext.packed.glb");
  EXPECT_EQ(plan.value()[2].index, 2u);
  // The same inputs in another folder get the same names.
  auto moved = PlanBatch({"/elsewhere/a.obj", "/elsewhere/sub/b.glb", "/elsewhere/sub/deep/c.x.fbx",
                          "/elsewhere/noext"});
  ASSERT_TRUE(moved.ok());
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(moved.value()[i].output, plan.value()[i].output);
}

TEST(BatchPlan, CommonFolderIsAWholeSegment) {
  auto plan = PlanBatch({"/d/model1/a.obj", "/d/model2/a.obj"});
  ASSERT_TRUE(plan.ok());
  EXPECT_EQ(plan.value()[0].output, "model1/a.packed.glb");
  EXPECT_EQ(plan.value()[1].output, "model2/a.packed.glb");
  auto one = PlanBatch({"/d/x/only.obj"});
  ASSERT_TRUE(one.ok());
  EXPECT_EQ(one.value()[0].output, "only.packed.glb");
}

TEST(BatchPlan, CollisionsAndRepeatsAreErrors) {
  auto clash = PlanBatch({"/d/a.obj", "/d/a.glb"});
  ASSERT_FALSE(clash.ok());
  EXPECT_NE(clash.status().message().find("/d/a.obj and /d/a.glb would both write a.packed.glb"),
            std::string::npos);
  auto twice = PlanBatch({"/d/a.obj", "/d/./a.obj"});
  ASSERT_FALSE(twice.ok());
  EXPECT_NE(twice.status().message().find("listed twice"), std::string::npos);
  EXPECT_FALSE(PlanBatch({}).ok());
}

TEST(BatchPlan, ManifestPathsAreRelativeToItsFolder) {
  const std::string dir = testing::TempDir();
  const std::string path = dir + "/manifest_test.txt";
  {
    std::ofstream out(path);
    out << "# comment\n\n  a/b.obj  \r\n/abs/c.glb\n\t# indented comment\nd.ply\n";
  }
  auto listed = ReadManifest(path);
  ASSERT_TRUE(listed.ok());
  ASSERT_EQ(listed->size(), 3u);
  EXPECT_EQ(listed.value()[0], AbsolutePath(dir + "/a/b.obj"));
  EXPECT_EQ(listed.value()[1], "/abs/c.glb");
  EXPECT_EQ(listed.value()[2], AbsolutePath(dir + "/d.ply"));
  std::remove(path.c_str());
  EXPECT_FALSE(ReadManifest(dir + "/no_such_manifest.txt").ok());
}

TEST(BatchPlan, ShardsPartitionTheBatch) {
  Shard s;
  EXPECT_TRUE(ParseShard("2/5", &s));
  EXPECT_EQ(s.index, 2u);
  EXPECT_EQ(s.count, 5u);
  for (const char* bad : {"5/5", "-1/3", "1/0", "a/3", "1/", "/3", "1", "1/3x", "1/+3"})
    EXPECT_FALSE(ParseShard(bad, &s)) << bad;
  std::vector<std::string> inputs;
  for (int i = 0; i < 23; ++i) inputs.push_back("/d/a" + std::to_string(i) + ".obj");
  auto plan = PlanBatch(inputs);
  ASSERT_TRUE(plan.ok());
  std::vector<int> seen(23, 0);
  for (size_t k = 0; k < 4; ++k) {
    const auto part = SelectShard(plan.value(), Shard{k, 4});
    EXPECT_GE(part.size(), 5u);
    EXPECT_LE(part.size(), 6u);
    for (const BatchAsset& a : part) ++seen[a.index];
  }
  for (int n : seen) EXPECT_EQ(n, 1);
}

}  // namespace
}  // namespace hullpack
