#include "gltf/external_images.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "gltf_test_scenes.h"

namespace hullpack {
namespace {

void WriteBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

TEST(ExternalImages, ImagesBesideTheFileAreEmbeddedOthersKeptWithAReason) {
  char dir_template[] = "/tmp/hullpack_images_XXXXXX";
  ASSERT_NE(mkdtemp(dir_template), nullptr);
  const std::string root = dir_template;
  const std::string dir = root + "/model";  // the folder of the scene file; "../" leaves it
  mkdir(dir.c_str(), 0755);
  mkdir((dir + "/sub").c_str(), 0755);
  const std::vector<uint8_t>& png = testing_gltf::TinyPng();
  WriteBytes(dir + "/sub/wood dark.png", png);
  WriteBytes(dir + "/notes.txt", {'h', 'i'});
  WriteBytes(root + "/outside.png", png);

  Scene scene;
  for (const char* uri :
       {"sub/wood%20dark.png", "missing.png", "notes.txt", "../outside.png", "/etc/hostname"}) {
    Image image;
    image.uri = uri;
    scene.images.push_back(image);
  }
  Image embedded;
  embedded.bytes = {1, 2, 3};
  embedded.mime_type = "image/png";
  scene.images.push_back(embedded);

  const EmbedReport r = EmbedExternalImages(scene, dir);
  EXPECT_EQ(r.embedded, 1u);
  EXPECT_TRUE(scene.images[0].uri.empty());
  EXPECT_EQ(scene.images[0].bytes, png);
  EXPECT_EQ(scene.images[0].mime_type, "image/png");
  ASSERT_EQ(r.kept_as_references.size(), 4u);
  EXPECT_NE(r.kept_as_references[0].find("cannot read"), std::string::npos);
  EXPECT_NE(r.kept_as_references[1].find("not PNG, JPEG or WebP"), std::string::npos);
  EXPECT_NE(r.kept_as_references[2].find(".."), std::string::npos);
  for (size_t i = 1; i < 5; ++i) EXPECT_FALSE(scene.images[i].uri.empty()) << i;
  EXPECT_EQ(scene.images[5].bytes, std::vector<uint8_t>({1, 2, 3}));

  std::remove((dir + "/sub/wood dark.png").c_str());
  std::remove((dir + "/notes.txt").c_str());
  std::remove((root + "/outside.png").c_str());
  rmdir((dir + "/sub").c_str());
  rmdir(dir.c_str());
  rmdir(root.c_str());
}

}  // namespace
}  // namespace hullpack
