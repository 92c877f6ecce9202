#include "batch/asset_cache.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "common/file_util.h"

namespace hullpack {
namespace {

class AssetCacheTest : public testing::Test {
 protected:
  void SetUp() override {
    root_ = testing::TempDir() + "/asset_cache_test_" +
            testing::UnitTest::GetInstance()->current_test_info()->name();
    ASSERT_EQ(std::system(("rm -rf '" + root_ + "'").c_str()), 0);  // a previous run's cache
    ASSERT_TRUE(MakeDirectories(root_ + "/in").ok());
  }
  void Write(const std::string& name, const std::string& text) {
    std::ofstream(root_ + "/in/" + name, std::ios::binary) << text;
  }
  std::string root_;
  const std::vector<uint8_t> glb_ = {1, 2, 3, 4};
};

TEST_F(AssetCacheTest, MissThenHit) {
  Write("a.obj", "v 0 0 0\n");
  AssetCache cache(root_ + "/cache", "salt");
  ASSERT_TRUE(cache.Prepare().ok());
  auto probe = cache.Lookup(root_ + "/in/a.obj");
  ASSERT_TRUE(probe.ok());
  EXPECT_FALSE(probe->hit);
  ASSERT_TRUE(cache.Store(root_ + "/in/a.obj", probe->input_key, {}, glb_, "{\"m\":1}").ok());
  auto again = cache.Lookup(root_ + "/in/a.obj");
  ASSERT_TRUE(again.ok());
  EXPECT_TRUE(again->hit);
  EXPECT_EQ(again->glb, glb_);
  EXPECT_EQ(again->meta, "{\"m\":1}");
  // Another salt (options, tool) or other bytes: a miss.
  EXPECT_FALSE(AssetCache(root_ + "/cache", "other").Lookup(root_ + "/in/a.obj")->hit);
  Write("a.obj", "v 0 0 1\n");
  EXPECT_FALSE(cache.Lookup(root_ + "/in/a.obj")->hit);
  EXPECT_FALSE(cache.Lookup(root_ + "/in/missing.obj").ok());
}

TEST_F(AssetCacheTest, ReferencedFilesAreInTheKey) {
  Write("m.obj", "mtllib m.mtl extra.mtl\nv 0 0 0\n");
  Write("m.mtl", "newmtl x\nmap_Kd t.png\n");
  Write("t.png", "png bytes");
  const std::string input = root_ + "/in/m.obj";
  const auto referenced = ReferencedFiles(input, {"t.png", "../escape.png", "data:x"});
  EXPECT_EQ(referenced, (std::vector<std::string>{"extra.mtl", "m.mtl", "t.png"}));
  AssetCache cache(root_ + "/cache", "salt");
  ASSERT_TRUE(cache.Prepare().ok());
  ASSERT_TRUE(cache.Store(input, cache.Lookup(input)->input_key, referenced, glb_, "{}").ok());
  EXPECT_TRUE(cache.Lookup(input)->hit);
  Write("t.png", "other png bytes");  // a changed texture
  EXPECT_FALSE(cache.Lookup(input)->hit);
  Write("t.png", "png bytes");
  EXPECT_TRUE(cache.Lookup(input)->hit);
  Write("extra.mtl", "newmtl y\n");  // a referenced file that appears
  EXPECT_FALSE(cache.Lookup(input)->hit);
}

TEST_F(AssetCacheTest, GltfBuffersAreReferenced) {
  Write("s.gltf", R"({"asset":{"version":"2.0"},"buffers":[{"uri":"s%20data.bin","byteLength":4},)"
                  R"({"uri":"data:application/octet-stream;base64,AAAA","byteLength":3}]})");
  EXPECT_EQ(ReferencedFiles(root_ + "/in/s.gltf", {}), std::vector<std::string>{"s data.bin"});
}

TEST_F(AssetCacheTest, AnEntryWithoutItsReportIsAMiss) {
  Write("a.obj", "v 0 0 0\n");
  AssetCache cache(root_ + "/cache", "salt");
  ASSERT_TRUE(cache.Prepare().ok());
  const std::string input = root_ + "/in/a.obj";
  ASSERT_TRUE(cache.Store(input, cache.Lookup(input)->input_key, {}, glb_, "{}").ok());
  // Remove every report: what a run killed between writing the output and its report leaves.
  for (const char* sub : {"objects"}) {
    const std::string cmd = "find '" + root_ + "/cache/" + sub + "' -name '*.json' -delete";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
  }
  EXPECT_FALSE(cache.Lookup(input)->hit);
}

}  // namespace
}  // namespace hullpack
