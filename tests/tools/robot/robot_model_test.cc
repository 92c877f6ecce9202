#include "robot/robot_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "robot/hull_files.h"
#include "robot/mjcf_writer.h"
#include "robot/sdf_writer.h"
#include "robot/urdf_writer.h"

namespace hullpack {
namespace {

RobotModel Model() {
  RobotModel m;
  m.name = "part";
  m.visual_file = "meshes/part_visual.stl";
  m.hull_files = {"meshes/part_hull_0.stl", "meshes/part_hull_1.stl"};
  m.mass.mass = 2.5;
  m.mass.center = {0.1, 0.2, 0.3};
  m.mass.inertia = {1, 2, 3, -0.1, 0, 0};
  m.max_hull_vertices = 32;
  return m;
}

TEST(RobotModel, SanitizesNames) {
  EXPECT_EQ(SanitizeName("wheel left.v2"), "wheel_left_v2");
  EXPECT_EQ(SanitizeName("3d<part>&\"x\""), "m_3d_part___x_");
  EXPECT_EQ(SanitizeName(""), "model");
  EXPECT_EQ(SanitizeName("caf\xc3\xa9"), "caf__");
}

TEST(RobotModel, NumbersRoundTrip) {
  EXPECT_EQ(XmlNumber(0.1), "0.1");
  EXPECT_EQ(std::stod(XmlNumber(1.0 / 3)), 1.0 / 3);
  EXPECT_EQ(XmlNumber(std::nan("")), "0");
}

TEST(RobotModel, UrdfNamesEveryHull) {
  const std::string x = WriteUrdf(Model());
  EXPECT_NE(x.find("<robot name=\"part\">"), std::string::npos);
  EXPECT_NE(x.find("<mass value=\"2.5\"/>"), std::string::npos);
  EXPECT_NE(x.find("ixy=\"-0.1\""), std::string::npos);
  EXPECT_NE(x.find("filename=\"meshes/part_hull_1.stl\""), std::string::npos);
  EXPECT_NE(x.find("filename=\"meshes/part_visual.stl\""), std::string::npos);
}

TEST(RobotModel, MjcfCapsHullsAndKeepsTheVisualOutOfContacts) {
  const std::string x = WriteMjcf(Model());
  EXPECT_NE(x.find("maxhullvert=\"32\""), std::string::npos);
  EXPECT_NE(x.find("fullinertia=\"1 2 3 -0.1 0 0\""), std::string::npos);
  EXPECT_NE(x.find("contype=\"0\" conaffinity=\"0\""), std::string::npos);
}

TEST(RobotModel, SdfHasOneCollisionPerHull) {
  const std::string x = WriteSdf(Model());
  EXPECT_NE(x.find("<collision name=\"part_hull_1\">"), std::string::npos);
  EXPECT_NE(x.find("<uri>meshes/part_hull_0.stl</uri>"), std::string::npos);
}

TEST(RobotModel, BinaryStlHoldsEveryTriangle) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  m.indices = {0, 1, 2};
  std::vector<uint8_t> stl;
  EncodeBinaryStl(m, [&](const void* data, size_t size) {
    stl.insert(stl.end(), static_cast<const uint8_t*>(data),
               static_cast<const uint8_t*>(data) + size);
  });
  ASSERT_EQ(stl.size(), 84u + 50u);
  EXPECT_EQ(stl[80], 1);
  float nz;
  std::memcpy(&nz, &stl[84 + 8], 4);
  EXPECT_EQ(nz, 1.0f);
}

TEST(RobotModel, BinaryStlOfALargeMeshComesInPiecesThatJoinUp) {
  Mesh m;
  const uint32_t n = 60000;  // 3 MB of STL
  for (uint32_t t = 0; t < n; ++t) {
    const float x = static_cast<float>(t);
    const float corners[9] = {x, 0, 0, x + 1, 0, 0, x, 1, 0};
    m.positions.insert(m.positions.end(), corners, corners + 9);
    for (uint32_t k = 0; k < 3; ++k) m.indices.push_back(3 * t + k);
  }
  std::vector<uint8_t> stl;
  size_t pieces = 0;
  EncodeBinaryStl(m, [&](const void* data, size_t size) {
    stl.insert(stl.end(), static_cast<const uint8_t*>(data),
               static_cast<const uint8_t*>(data) + size);
    ++pieces;
  });
  EXPECT_GT(pieces, 1u);
  ASSERT_EQ(stl.size(), 84u + 50u * n);
  uint32_t count;
  std::memcpy(&count, &stl[80], 4);
  EXPECT_EQ(count, n);
  for (uint32_t t = 0; t < n; ++t) {
    float x;
    std::memcpy(&x, &stl[84 + 50 * size_t(t) + 12], 4);  // the first corner's x
    ASSERT_EQ(x, static_cast<float>(t)) << t;
  }
}

}  // namespace
}  // namespace hullpack
