#include "io/assimp_reader.h"

#include <assimp/anim.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "gltf/glb_writer.h"
#include "io/scene_io.h"
#include "io_test_util.h"
#include "scene/transform.h"

namespace hullpack {
namespace {

using testing::TempDir;

void WriteText(const std::string& path, const std::string& text) {
  testing::WriteBytes(path, text.data(), text.size());
}

int NodeNamed(const Scene& s, const std::string& name) {
  for (size_t i = 0; i < s.nodes.size(); ++i) {
    if (s.nodes[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

const AnimationSampler* SamplerFor(const Animation& a, int node, AnimationPath path) {
  for (const AnimationChannel& c : a.channels) {
    if (c.node == node && c.path == path) return &a.samplers[c.sampler];
  }
  return nullptr;
}

bool MentionsAll(const Scene& s, const std::string& a, const std::string& b = "") {
  return std::any_of(s.dropped.begin(), s.dropped.end(), [&](const std::string& line) {
    return line.find(a) != std::string::npos && line.find(b) != std::string::npos;
  });
}

void ExpectNear(const std::vector<float>& got, const std::vector<float>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-5) << "at " << i;
}

// A triangle on node `child` under `root`: child moves along (0 1 0) (0 2 0) (3 1 0) and turns 0,
// 90, 180 degrees about z at 0, 0.5 and 2 seconds. Its material is COLLADA's <constant> (unshaded)
// with a transparency of 0.25.
const char kSkeletonDae[] = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_effects>
    <effect id="flat-fx"><profile_COMMON><technique sid="common"><constant>
      <emission><color>0.2 0.4 0.6 1</color></emission>
      <transparent opaque="A_ONE"><color>1 1 1 1</color></transparent>
      <transparency><float>0.25</float></transparency>
    </constant></technique></profile_COMMON></effect>
  </library_effects>
  <library_materials><material id="flat" name="flat"><instance_effect url="#flat-fx"/></material>
  </library_materials>
  <library_geometries>
    <geometry id="tri" name="tri"><mesh>
      <source id="tri-pos"><float_array id="tri-pos-a" count="9">0 0 0 1 0 0 0 1 0</float_array>
        <technique_common><accessor source="#tri-pos-a" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="tri-v"><input semantic="POSITION" source="#tri-pos"/></vertices>
      <triangles count="1" material="m"><input semantic="VERTEX" source="#tri-v" offset="0"/>
        <p>0 1 2</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_animations>
    <animation id="wave" name="wave">
      <source id="move-in"><float_array id="move-in-a" count="3">0 0.5 2</float_array>
        <technique_common><accessor source="#move-in-a" count="3" stride="1">
          <param name="TIME" type="float"/></accessor></technique_common></source>
      <source id="move-out"><float_array id="move-out-a" count="9">0 1 0  0 2 0  3 1 0</float_array>
        <technique_common><accessor source="#move-out-a" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <sampler id="move"><input semantic="INPUT" source="#move-in"/>
        <input semantic="OUTPUT" source="#move-out"/></sampler>
      <channel source="#move" target="child/location"/>
      <source id="turn-in"><float_array id="turn-in-a" count="3">0 0.5 2</float_array>
        <technique_common><accessor source="#turn-in-a" count="3" stride="1">
          <param name="TIME" type="float"/></accessor></technique_common></source>
      <source id="turn-out"><float_array id="turn-out-a" count="3">0 90 180</float_array>
        <technique_common><accessor source="#turn-out-a" count="3" stride="1">
          <param name="ANGLE" type="float"/></accessor></technique_common></source>
      <sampler id="turn"><input semantic="INPUT" source="#turn-in"/>
        <input semantic="OUTPUT" source="#turn-out"/></sampler>
      <channel source="#turn" target="child/rotZ.ANGLE"/>
    </animation>
  </library_animations>
  <library_visual_scenes>
    <visual_scene id="scene" name="scene">
      <node id="root" name="root" sid="root" type="JOINT">
        <translate sid="location">5 0 0</translate>
        <node id="child" name="child" sid="child" type="JOINT">
          <translate sid="location">0 1 0</translate>
          <rotate sid="rotZ">0 0 1 0</rotate>
          <instance_geometry url="#tri"><bind_material><technique_common>
            <instance_material symbol="m" target="#flat"/></technique_common></bind_material>
          </instance_geometry>
        </node>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";

TEST(AssimpReader, ColladaNodeAnimationKeepsTimesValuesAndNodes) {
  TempDir dir;
  const std::string path = dir.File("skeleton.dae");
  WriteText(path, kSkeletonDae);
  Result<Scene> s = ReadScene(path);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  const int child = NodeNamed(s.value(), "child"), root = NodeNamed(s.value(), "root");
  ASSERT_GE(child, 0);
  ASSERT_GE(root, 0);
  ASSERT_EQ(s->animations.size(), 1u);
  const Animation& a = s->animations[0];
  // assimp's COLLADA importer joins the clip's id to its name, and bakes every animated transform
  // of a node into one channel with all three paths keyed at the union of their times.
  EXPECT_EQ(a.name, "wave_wave");
  ASSERT_EQ(a.channels.size(), 3u);
  const AnimationSampler* move = SamplerFor(a, child, AnimationPath::kTranslation);
  const AnimationSampler* turn = SamplerFor(a, child, AnimationPath::kRotation);
  const AnimationSampler* size = SamplerFor(a, child, AnimationPath::kScale);
  ASSERT_TRUE(move && turn && size);
  // COLLADA's importer counts 1000 ticks per second: the keys come back in seconds.
  ExpectNear(move->times, {0, 0.5f, 2});
  ExpectNear(move->values, {0, 1, 0, 0, 2, 0, 3, 1, 0});
  ExpectNear(turn->times, {0, 0.5f, 2});
  const float h = std::sqrt(0.5f);
  ExpectNear(turn->values, {0, 0, 0, 1, 0, 0, h, h, 0, 0, 1, 0});  // x, y, z, w
  ExpectNear(size->values, {1, 1, 1, 1, 1, 1, 1, 1, 1});
  for (const AnimationSampler& sampler : a.samplers)
    EXPECT_EQ(sampler.interpolation, Interpolation::kLinear);

  // The animated node's rest transform as TRS, its matrix exactly that TRS; the others keep theirs.
  const Node& n = s->nodes[child];
  ASSERT_TRUE(n.trs.has_value());
  ExpectNear(
      {float(n.trs->translation[0]), float(n.trs->translation[1]), float(n.trs->translation[2])},
      {0, 1, 0});
  ExpectNear({float(n.trs->rotation[3]), float(n.trs->scale[0])}, {1, 1});
  EXPECT_EQ(n.local_transform, TrsMatrix(*n.trs));
  EXPECT_FALSE(s->nodes[root].trs.has_value());
  EXPECT_FALSE(MentionsAll(s.value(), "animation")) << s->dropped[0];
}

TEST(AssimpReader, ColladaConstantShadingIsUnlitAndTransparencyBlends) {
  TempDir dir;
  const std::string path = dir.File("skeleton.dae");
  WriteText(path, kSkeletonDae);
  Result<Scene> s = ReadScene(path);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->materials.size(), 1u);
  const Material& m = s->materials[0];
  EXPECT_TRUE(m.unlit);
  EXPECT_EQ(m.alpha_mode, AlphaMode::kBlend);
  EXPECT_FLOAT_EQ(m.base_color[3], 0.25f);
}

// DirectX .x leaves the tick rate unset unless the file gives AnimTicksPerSecond; the second
// position key repeats time 50.
TEST(AssimpReader, UnsetTickRateMeans25PerSecondAndRepeatedTimesGo) {
  TempDir dir;
  const std::string path = dir.File("arm.x");
  WriteText(path, R"(xof 0303txt 0032
Frame Root {
  FrameTransformMatrix { 1.0,0.0,0.0,0.0, 0.0,1.0,0.0,0.0, 0.0,0.0,1.0,0.0, 0.0,0.0,0.0,1.0;; }
  Frame Arm {
    FrameTransformMatrix { 1.0,0.0,0.0,0.0, 0.0,1.0,0.0,0.0, 0.0,0.0,1.0,0.0, 0.0,2.0,0.0,1.0;; }
    Mesh { 3; 0.0;0.0;0.0;, 1.0;0.0;0.0;, 0.0;1.0;0.0;; 1; 3;0,1,2;; }
  }
}
AnimationSet Walk {
  Animation {
    { Arm }
    AnimationKey { 2; 3; 0;3;0.0,2.0,0.0;;, 50;3;1.0,2.0,0.0;;, 50;3;5.0,2.0,0.0;;; }
  }
}
)");
  Result<Scene> s = ReadWithAssimp(path, FileFormat::kUnknown);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->animations.size(), 1u);
  const int arm = NodeNamed(s.value(), "Arm");
  ASSERT_GE(arm, 0);
  const AnimationSampler* move = SamplerFor(s->animations[0], arm, AnimationPath::kTranslation);
  ASSERT_TRUE(move);
  ExpectNear(move->times, {0, 2});
  ExpectNear(move->values, {0, 2, 0, 1, 2, 0});
  ASSERT_TRUE(s->nodes[arm].trs.has_value());
  EXPECT_DOUBLE_EQ(s->nodes[arm].trs->translation[1], 2.0);
}

// What files rarely hold, built by hand: a quaternion to reorder, a key before time 0, a name two
// nodes share, a sheared node, a channel of no node, mesh and morph channels, and a clip left with
// nothing.
TEST(AssimpReader, ChannelsMapToNodesOrAreReportedDropped) {
  aiScene ai;
  ai.mRootNode = new aiNode("root");
  aiNode* children[] = {new aiNode("twin"), new aiNode("sheared"), new aiNode("twin")};
  children[1]->mTransformation.a2 = 0.5f;  // x gains half of y: shear
  ai.mRootNode->addChildren(3, children);

  auto node_anim = [](const char* name) {
    aiNodeAnim* c = new aiNodeAnim;
    c->mNodeName = name;
    c->mNumRotationKeys = 2;
    c->mRotationKeys = new aiQuatKey[2];
    const float h = std::sqrt(0.5f);
    c->mRotationKeys[0] = aiQuatKey(-5, aiQuaternion(1, 0, 0, 0));  // w, x, y, z
    c->mRotationKeys[1] = aiQuatKey(10, aiQuaternion(h, h, 0, 0));
    return c;
  };
  ai.mNumAnimations = 2;
  ai.mAnimations = new aiAnimation*[2];
  aiAnimation* spin = ai.mAnimations[0] = new aiAnimation;
  spin->mName = "spin";
  spin->mTicksPerSecond = 10;
  spin->mNumChannels = 3;
  spin->mChannels =
      new aiNodeAnim* [3] { node_anim("twin"), node_anim("sheared"), node_anim("ghost") };
  spin->mNumMeshChannels = 1;
  spin->mMeshChannels = new aiMeshAnim* [1] { new aiMeshAnim };
  spin->mNumMorphMeshChannels = 1;
  spin->mMorphMeshChannels = new aiMeshMorphAnim* [1] { new aiMeshMorphAnim };
  aiAnimation* lost = ai.mAnimations[1] = new aiAnimation;
  lost->mName = "lost";
  lost->mNumChannels = 1;
  lost->mChannels = new aiNodeAnim* [1] { node_anim("ghost") };

  const Scene s = ConvertAssimpScene(ai, "by hand");
  ASSERT_EQ(s.nodes.size(), 4u);
  ASSERT_EQ(s.animations.size(), 1u);
  const Animation& a = s.animations[0];
  EXPECT_EQ(a.name, "spin");
  ASSERT_EQ(a.channels.size(), 1u);
  // The first "twin" in depth-first order, as assimp's aiNode::FindNode resolves it.
  EXPECT_EQ(a.channels[0].node, 1);
  EXPECT_EQ(a.channels[0].path, AnimationPath::kRotation);
  const AnimationSampler& turn = a.samplers[a.channels[0].sampler];
  // -0.5 s and 1 s: glTF times cannot be negative, so the clip starts at 0.
  ExpectNear(turn.times, {0, 1.5f});
  const float h = std::sqrt(0.5f);
  ExpectNear(turn.values, {0, 0, 0, 1, h, 0, 0, h});
  EXPECT_TRUE(s.nodes[1].trs.has_value());
  EXPECT_FALSE(s.nodes[2].trs.has_value());
  EXPECT_FALSE(s.nodes[3].trs.has_value());

  EXPECT_TRUE(MentionsAll(s, "'spin'", "2 nodes are named 'twin'"));
  EXPECT_TRUE(MentionsAll(s, "'spin': channels of nodes with sheared", "'sheared'"));
  EXPECT_TRUE(MentionsAll(s, "'spin': channels of nodes the scene does not have", "'ghost'"));
  EXPECT_TRUE(MentionsAll(s, "'spin'", "mesh (vertex) animation"));
  EXPECT_TRUE(MentionsAll(s, "'spin'", "morph animation"));
  EXPECT_TRUE(MentionsAll(s, "'lost' has no node channel left"));
  EXPECT_TRUE(MentionsAll(s, "'spin' started at -0.5 s: shifted to start at 0"));
}

// A triangle with two blend shapes (anim meshes hold target positions; one also normals, one a
// default weight) and a clip whose morph channel names the mesh, not the node.
TEST(AssimpReader, AnimMeshesBecomeMorphTargetsAndMorphChannelsWeightTracks) {
  aiScene ai;
  ai.mNumMeshes = 1;
  ai.mMeshes = new aiMesh*[1];
  aiMesh* mesh = ai.mMeshes[0] = new aiMesh;
  mesh->mName = "face";
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = 3;
  mesh->mVertices = new aiVector3D[3]{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->mNormals = new aiVector3D[3]{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  mesh->mNumFaces = 1;
  mesh->mFaces = new aiFace[1];
  mesh->mFaces[0].mNumIndices = 3;
  mesh->mFaces[0].mIndices = new unsigned[3]{0, 1, 2};
  mesh->mMethod = aiMorphingMethod_MORPH_NORMALIZED;
  mesh->mNumAnimMeshes = 2;
  mesh->mAnimMeshes = new aiAnimMesh*[2];
  aiAnimMesh* smile = mesh->mAnimMeshes[0] = new aiAnimMesh;
  smile->mName = "smile";
  smile->mNumVertices = 3;
  smile->mVertices = new aiVector3D[3]{{0, 0, 0}, {1, 0.5f, 0}, {0, 1, 0}};
  aiAnimMesh* blink = mesh->mAnimMeshes[1] = new aiAnimMesh;
  blink->mName = "blink";
  blink->mNumVertices = 3;
  blink->mWeight = 0.25f;
  blink->mVertices = new aiVector3D[3]{{0, 0, 2}, {1, 0, 0}, {0, 1, 0}};
  blink->mNormals = new aiVector3D[3]{{0, 1, 0}, {0, 0, 1}, {0, 0, 1}};
  ai.mRootNode = new aiNode("head");
  ai.mRootNode->mNumMeshes = 1;
  ai.mRootNode->mMeshes = new unsigned[1]{0};
  ai.mNumAnimations = 1;
  ai.mAnimations = new aiAnimation*[1];
  aiAnimation* talk = ai.mAnimations[0] = new aiAnimation;
  talk->mName = "talk";
  talk->mTicksPerSecond = 10;
  talk->mNumMorphMeshChannels = 2;
  talk->mMorphMeshChannels = new aiMeshMorphAnim* [2] { new aiMeshMorphAnim, new aiMeshMorphAnim };
  aiMeshMorphAnim* channel = talk->mMorphMeshChannels[0];
  channel->mName = "face";
  channel->mNumKeys = 2;
  channel->mKeys = new aiMeshMorphKey[2];
  channel->mKeys[0].mTime = 0;
  channel->mKeys[0].mNumValuesAndWeights = 1;
  channel->mKeys[0].mValues = new unsigned[1]{1};
  channel->mKeys[0].mWeights = new double[1]{0.5};
  channel->mKeys[1].mTime = 5;
  channel->mKeys[1].mNumValuesAndWeights = 2;
  channel->mKeys[1].mValues = new unsigned[2]{0, 1};
  channel->mKeys[1].mWeights = new double[2]{1, 0};
  talk->mMorphMeshChannels[1]->mName = "nobody";  // no node or mesh of that name: dropped

  const Scene s = ConvertAssimpScene(ai, "by hand");
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.morph_targets.size(), 2u);
  EXPECT_EQ(m.morph_targets[0].name, "smile");
  ExpectNear(m.morph_targets[0].positions, {0, 0, 0, 0, 0.5f, 0, 0, 0, 0});
  ExpectNear(m.morph_targets[0].normals, std::vector<float>(9, 0.0f));  // zeros: blink has some
  ExpectNear(m.morph_targets[1].positions, {0, 0, 2, 0, 0, 0, 0, 0, 0});
  ExpectNear(m.morph_targets[1].normals, {0, 1, -1, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(m.morph_weights, (std::vector<float>{0, 0.25f}));
  ASSERT_EQ(s.animations.size(), 1u);
  const Animation& a = s.animations[0];
  ASSERT_EQ(a.channels.size(), 1u);
  EXPECT_EQ(a.channels[0].path, AnimationPath::kWeights);
  EXPECT_EQ(a.channels[0].node, 0);
  ExpectNear(a.samplers[0].times, {0, 0.5f});
  ExpectNear(a.samplers[0].values, {0, 0.5f, 1, 0});
  EXPECT_TRUE(MentionsAll(s, "'talk': morph animation channels of no node or mesh"));
  EXPECT_TRUE(ValidateSceneForGltf(s).ok()) << ValidateSceneForGltf(s).ToString();
}

// A triangle on FBX model `arm` with a pre-rotation (Maya's joint orient) of 90 degrees about x,
// turning 0, 90, 180 degrees about z at 0, 0.5 and 1 s (30 frames per second).
const char kPreRotatedFbx[] = R"(; FBX 7.4.0 project file
FBXHeaderExtension:  {
	FBXHeaderVersion: 1003
	FBXVersion: 7400
}
GlobalSettings:  {
	Version: 1000
	Properties70:  {
		P: "TimeMode", "enum", "", "",6
	}
}
Objects:  {
	Geometry: 600, "Geometry::tri", "Mesh" {
		Vertices: *9 {
			a: 0,0,0,1,0,0,0,1,0
		}
		PolygonVertexIndex: *3 {
			a: 0,1,-3
		}
	}
	Model: 100, "Model::arm", "Mesh" {
		Version: 232
		Properties70:  {
			P: "PreRotation", "Vector3D", "Vector", "",90,0,0
			P: "Lcl Translation", "Lcl Translation", "", "A",0,2,0
		}
	}
	AnimationStack: 200, "AnimStack::wave", "" {
	}
	AnimationLayer: 300, "AnimLayer::base", "" {
	}
	AnimationCurveNode: 400, "AnimCurveNode::R", "" {
		Properties70:  {
			P: "d|X", "Number", "", "A",0
			P: "d|Y", "Number", "", "A",0
			P: "d|Z", "Number", "", "A",0
		}
	}
	AnimationCurve: 500, "AnimCurve::", "" {
		Default: 0
		KeyVer: 4009
		KeyTime: *3 {
			a: 0,23093079000,46186158000
		}
		KeyValueFloat: *3 {
			a: 0,90,180
		}
		KeyAttrFlags: *1 {
			a: 8456
		}
		KeyAttrDataFloat: *4 {
			a: 0,0,0,0
		}
		KeyAttrRefCount: *1 {
			a: 3
		}
	}
}
Connections:  {
	C: "OO",100,0
	C: "OO",600,100
	C: "OO",300,200
	C: "OO",400,300
	C: "OP",400,100, "Lcl Rotation"
	C: "OP",500,400, "d|Z"
}
)";

TEST(AssimpReader, FbxPreRotationCountsOnceInTheAnimatedNode) {
  TempDir dir;
  const std::string path = dir.File("arm.fbx");
  WriteText(path, kPreRotatedFbx);
  Result<Scene> s = ReadScene(path);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  const int arm = NodeNamed(s.value(), "arm");
  const int pre = NodeNamed(s.value(), "arm_$AssimpFbx$_PreRotation");
  ASSERT_GE(arm, 0);
  ASSERT_GE(pre, 0);  // assimp's helper node: kept, but identity now
  ASSERT_EQ(s->animations.size(), 1u);
  const Animation& a = s->animations[0];
  EXPECT_EQ(a.name, "wave");
  const AnimationSampler* move = SamplerFor(a, arm, AnimationPath::kTranslation);
  const AnimationSampler* turn = SamplerFor(a, arm, AnimationPath::kRotation);
  ASSERT_TRUE(move && turn);
  ExpectNear(turn->times, {0, 0.5f, 1});
  // The first key holds the rest pose: translation (0 2 0), the pre-rotation and no turn yet.
  const float h = std::sqrt(0.5f);
  ExpectNear({move->values[0], move->values[1], move->values[2]}, {0, 2, 0});
  ExpectNear({turn->values[0], turn->values[1], turn->values[2], turn->values[3]}, {h, 0, 0, h});
  // Played from the first key, the node lands where its rest pose puts it: its rest transform is
  // that key, and the helpers above it no longer add translation and pre-rotation a second time.
  ASSERT_TRUE(s->nodes[arm].trs.has_value());
  const Trs& rest = *s->nodes[arm].trs;
  ExpectNear({float(rest.translation[0]), float(rest.translation[1]), float(rest.translation[2]),
              float(rest.rotation[0]), float(rest.rotation[1]), float(rest.rotation[2]),
              float(rest.rotation[3])},
             {0, 2, 0, h, 0, 0, h});
  for (int p = s->nodes[arm].parent; p >= 0; p = s->nodes[p].parent)
    EXPECT_EQ(s->nodes[p].local_transform, kIdentity) << s->nodes[p].name;
}

// assimp's OBJ importer: `d` is the opacity, `map_d` an opacity map, `illum 0` unshaded and
// `-clamp on` the clamp map mode. (Packing reads OBJ with the project's own parser; this checks the
// assimp side of the same material statements.)
TEST(AssimpReader, ObjOpacityMapsClampAndUnshadedMaterials) {
  TempDir dir;
  WriteText(dir.File("a.mtl"), R"(newmtl glass
Kd 0.2 0.4 0.6
d 0.5
illum 2
newmtl leaf
map_Kd -clamp on leaf.png
map_d leaf.png
newmtl stencil
map_Kd paint.png
map_d mask.png
newmtl flat
Kd 1 0 0
illum 0
)");
  const std::string path = dir.File("a.obj");
  WriteText(path, R"(mtllib a.mtl
v 0 0 0
v 1 0 0
v 0 1 0
vt 0 0
vt 1 0
vt 0 1
usemtl glass
f 1/1 2/2 3/3
usemtl leaf
f 1/1 3/3 2/2
usemtl stencil
f 2/2 1/1 3/3
usemtl flat
f 2/2 3/3 1/1
)");
  Result<Scene> s = ReadWithAssimp(path, FileFormat::kObj);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  auto material = [&](const std::string& name) -> const Material& {
    for (const Material& m : s->materials) {
      if (m.name == name) return m;
    }
    ADD_FAILURE() << "no material " << name;
    return s->materials.at(0);
  };
  const Material& glass = material("glass");
  EXPECT_EQ(glass.alpha_mode, AlphaMode::kBlend);
  EXPECT_FLOAT_EQ(glass.base_color[3], 0.5f);
  EXPECT_FLOAT_EQ(glass.base_color[2], 0.6f);
  EXPECT_FALSE(glass.unlit);
  const Material& leaf = material("leaf");
  EXPECT_EQ(leaf.alpha_mode, AlphaMode::kBlend);
  EXPECT_FLOAT_EQ(leaf.base_color[3], 1.0f);
  ASSERT_TRUE(leaf.base_color_texture.used());
  EXPECT_EQ(leaf.base_color_texture.sampler.wrap_s, 33071);
  EXPECT_EQ(leaf.base_color_texture.sampler.wrap_t, 33071);
  EXPECT_EQ(material("stencil").alpha_mode, AlphaMode::kBlend);
  EXPECT_EQ(material("stencil").base_color_texture.sampler.wrap_s, 10497);
  EXPECT_TRUE(material("flat").unlit);
  EXPECT_EQ(material("flat").alpha_mode, AlphaMode::kOpaque);
  // The leaf's opacity map is its base colour image; the stencil's is another, which glTF cannot
  // hold.
  EXPECT_TRUE(MentionsAll(s.value(), "opacity map 'mask.png'", "'stencil'"));
  EXPECT_FALSE(MentionsAll(s.value(), "'leaf'"));
}

// glTF read through assimp: the file's alpha mode wins over the opacity assimp derives from the
// base colour (0.8 here), and the sampler's codes pass through.
TEST(AssimpReader, GltfAlphaModeUnlitAndSamplerThroughAssimp) {
  TempDir dir;
  const std::string path = dir.File("fence.gltf");
  WriteText(path, R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_unlit"],
 "scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],
 "materials":[{"name":"fence","alphaMode":"MASK","alphaCutoff":0.3,
   "pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.8],"baseColorTexture":{"index":0}},
   "extensions":{"KHR_materials_unlit":{}}}],
 "textures":[{"sampler":0,"source":0}],
 "samplers":[{"magFilter":9728,"minFilter":9728,"wrapS":33648,"wrapT":33071}],
 "images":[{"uri":"fence.png"}],
 "buffers":[{"byteLength":60,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/"}],
 "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},
   {"buffer":0,"byteOffset":36,"byteLength":24}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],
   "max":[1,1,0]},{"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}]})");
  Result<Scene> s = ReadWithAssimp(path, FileFormat::kGltf);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_FALSE(s->materials.empty());
  const Material& m = s->materials[0];
  EXPECT_EQ(m.name, "fence");
  EXPECT_EQ(m.alpha_mode, AlphaMode::kMask);
  EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.3f);
  EXPECT_FLOAT_EQ(m.base_color[3], 0.8f);
  EXPECT_TRUE(m.unlit);
  const Sampler& sampler = m.base_color_texture.sampler;
  EXPECT_EQ(sampler.wrap_s, 33648);
  EXPECT_EQ(sampler.wrap_t, 33071);
  EXPECT_EQ(sampler.mag_filter, 9728);
  EXPECT_EQ(sampler.min_filter, 9728);
}

// As Blender writes copies of one camera object (the UR10's visual meshes): two cameras of one id
// on two nodes of one name, a third camera on a node of its own, and a triangle.
const char kTwinCamerasDae[] = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_cameras>
    <camera id="Cam-camera" name="Cam"><optics><technique_common><perspective>
      <xfov>49</xfov><aspect_ratio>1.5</aspect_ratio><znear>0.1</znear><zfar>100</zfar>
    </perspective></technique_common></optics></camera>
    <camera id="Cam-camera" name="Cam.001"><optics><technique_common><perspective>
      <xfov>49</xfov><aspect_ratio>1.5</aspect_ratio><znear>0.1</znear><zfar>100</zfar>
    </perspective></technique_common></optics></camera>
    <camera id="Solo-camera" name="Solo"><optics><technique_common><perspective>
      <xfov>30</xfov><aspect_ratio>1</aspect_ratio><znear>0.1</znear><zfar>100</zfar>
    </perspective></technique_common></optics></camera>
  </library_cameras>
  <library_geometries>
    <geometry id="tri" name="tri"><mesh>
      <source id="tri-pos"><float_array id="tri-pos-a" count="9">0 0 0 1 0 0 0 1 0</float_array>
        <technique_common><accessor source="#tri-pos-a" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="tri-v"><input semantic="POSITION" source="#tri-pos"/></vertices>
      <triangles count="1"><input semantic="VERTEX" source="#tri-v" offset="0"/><p>0 1 2</p>
      </triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene" name="scene">
      <node id="Cam" name="Cam"><translate>0 0 5</translate>
        <instance_camera url="#Cam-camera"/></node>
      <node id="Cam" name="Cam"><translate>0 0 6</translate>
        <instance_camera url="#Cam-camera"/></node>
      <node id="Solo" name="Solo"><translate>0 0 7</translate>
        <instance_camera url="#Solo-camera"/></node>
      <node id="part" name="part"><instance_geometry url="#tri"/></node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";

// assimp's validation rejects such a file whole; it is read again with the cameras no single node
// can be told for dropped, and the rest validated as usual.
TEST(AssimpReader, ColladaTwinCamerasAreDroppedNotTheFile) {
  TempDir dir;
  const std::string path = dir.File("twins.dae");
  WriteText(path, kTwinCamerasDae);
  Result<Scene> s = ReadWithAssimp(path, FileFormat::kDae);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->meshes.size(), 1u);
  EXPECT_EQ(s->meshes[0].triangle_count(), 1u);
  ASSERT_EQ(s->cameras.size(), 1u);  // Solo's
  const int solo = NodeNamed(s.value(), "Solo");
  ASSERT_GE(solo, 0);
  EXPECT_EQ(s->nodes[static_cast<size_t>(solo)].camera, 0);
  EXPECT_TRUE(MentionsAll(s.value(), "cameras or lights not kept", "same name"));

  // The same bytes from memory (a file inside a container).
  const std::string text(kTwinCamerasDae);
  Result<Scene> m = ReadWithAssimpFromMemory(reinterpret_cast<const uint8_t*>(text.data()),
                                             text.size(), FileFormat::kDae, "twins.dae");
  ASSERT_TRUE(m.ok()) << m.status().ToString();
  EXPECT_EQ(m->cameras.size(), 1u);
}

TEST(AssimpReader, AFileOfOnlyACameraHasNoTrianglesNotAnIncompleteScene) {
  const std::string text = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_cameras>
    <camera id="Solo-camera" name="Solo"><optics><technique_common><perspective>
      <xfov>30</xfov><aspect_ratio>1</aspect_ratio><znear>0.1</znear><zfar>100</zfar>
    </perspective></technique_common></optics></camera>
  </library_cameras>
  <library_visual_scenes>
    <visual_scene id="scene" name="scene">
      <node id="Solo" name="Solo"><instance_camera url="#Solo-camera"/></node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
  Result<Scene> s = ReadWithAssimpFromMemory(reinterpret_cast<const uint8_t*>(text.data()),
                                             text.size(), FileFormat::kDae, "camera.dae");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.status().code(), StatusCode::kInvalidMesh);
  EXPECT_NE(s.status().message().find("camera.dae: contains no triangles"), std::string::npos)
      << s.status().message();
}

}  // namespace
}  // namespace hullpack
