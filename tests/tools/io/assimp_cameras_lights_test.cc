#include "io/assimp_cameras_lights.h"

#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gltf/glb_writer.h"
#include "io/assimp_reader.h"

namespace hullpack {
namespace {

// A root with children "cam", "lamp" and "spot"; one triangle on the root, so the scene is valid.
void AddNodesAndMesh(aiScene* ai) {
  ai->mRootNode = new aiNode("root");
  ai->mRootNode->mNumChildren = 3;
  ai->mRootNode->mChildren =
      new aiNode* [3] { new aiNode("cam"), new aiNode("lamp"), new aiNode("spot") };
  for (unsigned i = 0; i < 3; ++i) ai->mRootNode->mChildren[i]->mParent = ai->mRootNode;
  ai->mNumMeshes = 1;
  ai->mMeshes = new aiMesh*[1];
  aiMesh* mesh = ai->mMeshes[0] = new aiMesh;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = 3;
  mesh->mVertices = new aiVector3D[3]{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->mNumFaces = 1;
  mesh->mFaces = new aiFace[1];
  mesh->mFaces[0].mNumIndices = 3;
  mesh->mFaces[0].mIndices = new unsigned[3]{0, 1, 2};
  ai->mRootNode->mNumMeshes = 1;
  ai->mRootNode->mMeshes = new unsigned[1]{0};
}

int NodeNamed(const Scene& s, const std::string& name) {
  for (size_t i = 0; i < s.nodes.size(); ++i) {
    if (s.nodes[i].name == name && s.nodes[i].parent >= 0 &&
        s.nodes[static_cast<size_t>(s.nodes[i].parent)].name == "root")
      return static_cast<int>(i);
  }
  return -1;
}

TEST(AssimpCamerasLights, EachLandsOnItsNodeLookingAndShiningWhereAssimpSays) {
  aiScene ai;
  AddNodesAndMesh(&ai);
  ai.mNumCameras = 3;
  ai.mCameras = new aiCamera* [3] { new aiCamera, new aiCamera, new aiCamera };
  aiCamera* cam = ai.mCameras[0];  // looking along +x from (1, 2, 3), 90 degrees wide at 2:1
  cam->mName = "cam";
  cam->mPosition = aiVector3D(1, 2, 3);
  cam->mLookAt = aiVector3D(5, 0, 0);
  cam->mHorizontalFOV = float(M_PI / 2);
  cam->mAspect = 2;
  cam->mClipPlaneNear = 0.5f;
  cam->mClipPlaneFar = 50;
  aiCamera* ortho = ai.mCameras[1];  // glTF's own orientation: on the node itself
  ortho->mName = "lamp";
  ortho->mLookAt = aiVector3D(0, 0, -1);
  ortho->mOrthographicWidth = 4;
  ortho->mAspect = 2;
  ai.mCameras[2]->mName = "nowhere";
  ai.mNumLights = 3;
  ai.mLights = new aiLight* [3] { new aiLight, new aiLight, new aiLight };
  aiLight* spot = ai.mLights[0];
  spot->mName = "spot";
  spot->mType = aiLightSource_SPOT;
  spot->mDirection = aiVector3D(0, -2, 0);
  spot->mUp = aiVector3D(0, 0, 1);
  spot->mColorDiffuse = aiColor3D(2, 1, 0);
  spot->mAngleOuterCone = 1.0f;
  spot->mAngleInnerCone = 0.5f;
  aiLight* point = ai.mLights[1];
  point->mName = "lamp";
  point->mType = aiLightSource_POINT;
  point->mColorDiffuse = aiColor3D(0.5f, 0.5f, 0.5f);
  ai.mLights[2]->mName = "lamp";
  ai.mLights[2]->mType = aiLightSource_AMBIENT;

  const Scene s = ConvertAssimpScene(ai, "lit.fbx");
  ASSERT_EQ(s.cameras.size(), 2u);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_TRUE(ValidateSceneForGltf(s).ok()) << ValidateSceneForGltf(s).ToString();
  bool noted = false;
  for (const std::string& d : s.dropped) {
    noted |= d.find("1 cameras") != std::string::npos;
    noted |= d.find("1 lights") != std::string::npos && d.find("ambient") != std::string::npos;
  }
  EXPECT_TRUE(noted);

  // The perspective camera: vertical field of view 2 atan(tan(45 deg) / 2), on a child of "cam"
  // at (1, 2, 3) whose -z axis is +x.
  const Camera& c = s.cameras[0];
  EXPECT_TRUE(c.perspective);
  EXPECT_NEAR(c.yfov, 2 * std::atan(0.5), 1e-6);
  EXPECT_DOUBLE_EQ(c.aspect_ratio, 2);
  EXPECT_DOUBLE_EQ(c.znear, 0.5);
  EXPECT_DOUBLE_EQ(c.zfar, 50);
  const int cam_node = NodeNamed(s, "cam");
  ASSERT_GE(cam_node, 0);
  EXPECT_EQ(s.nodes[static_cast<size_t>(cam_node)].camera, -1);
  ASSERT_EQ(s.nodes[static_cast<size_t>(cam_node)].children.size(), 1u);
  const Node& holder =
      s.nodes[static_cast<size_t>(s.nodes[static_cast<size_t>(cam_node)].children[0])];
  EXPECT_EQ(holder.camera, 0);
  const Matrix4& m = holder.local_transform;
  EXPECT_NEAR(m[8], -1, 1e-12);  // the node's +z (back) is -x: it looks along +x
  EXPECT_NEAR(m[9], 0, 1e-12);
  EXPECT_NEAR(m[10], 0, 1e-12);
  EXPECT_NEAR(m[5], 1, 1e-12);  // +y stays up
  EXPECT_EQ(m[12], 1);
  EXPECT_EQ(m[13], 2);
  EXPECT_EQ(m[14], 3);

  // The orthographic one looks as glTF does: on its node, half widths 4 and 2.
  const int lamp_node = NodeNamed(s, "lamp");
  ASSERT_GE(lamp_node, 0);
  EXPECT_EQ(s.nodes[static_cast<size_t>(lamp_node)].camera, 1);
  EXPECT_FALSE(s.cameras[1].perspective);
  EXPECT_DOUBLE_EQ(s.cameras[1].xmag, 4);
  EXPECT_DOUBLE_EQ(s.cameras[1].ymag, 2);
  EXPECT_GT(s.cameras[1].zfar, s.cameras[1].znear);

  // The spot light: colour (1, 0.5, 0) at intensity 2, half cone angles 0.5 and 0.25, shining
  // down -y from a child of "spot"; the point light on "lamp" itself.
  const Light& l = s.lights[0];
  EXPECT_EQ(l.type, LightType::kSpot);
  EXPECT_FLOAT_EQ(l.intensity, 2);
  EXPECT_FLOAT_EQ(l.color[0], 1);
  EXPECT_FLOAT_EQ(l.color[1], 0.5f);
  EXPECT_FLOAT_EQ(l.outer_cone_angle, 0.5f);
  EXPECT_FLOAT_EQ(l.inner_cone_angle, 0.25f);
  const int spot_node = NodeNamed(s, "spot");
  ASSERT_GE(spot_node, 0);
  ASSERT_EQ(s.nodes[static_cast<size_t>(spot_node)].children.size(), 1u);
  const Node& lit =
      s.nodes[static_cast<size_t>(s.nodes[static_cast<size_t>(spot_node)].children[0])];
  EXPECT_EQ(lit.light, 0);
  EXPECT_NEAR(lit.local_transform[9], 1, 1e-12);  // +z (back) is +y: it shines down -y
  EXPECT_EQ(s.nodes[static_cast<size_t>(lamp_node)].light, 1);
  EXPECT_EQ(s.lights[1].type, LightType::kPoint);
  EXPECT_FLOAT_EQ(s.lights[1].intensity, 0.5f);
  EXPECT_FLOAT_EQ(s.lights[1].color[2], 1);
}

}  // namespace
}  // namespace hullpack
