#include "gltf_test_scenes.h"

#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "common/test_shapes.h"
#include "scene/transform.h"

namespace hullpack {
namespace testing_gltf {

const std::vector<uint8_t>& TinyPng() {
  static const std::vector<uint8_t> kPng = {
      0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00,
      0x00, 0x1F, 0x15, 0xC4, 0x89, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x44, 0x41, 0x54, 0x78,
      0x9C, 0x63, 0xF8, 0xDF, 0xC0, 0xF0, 0x1F, 0x00, 0x06, 0x80, 0x02, 0x7F, 0x10, 0x4C,
      0x1B, 0xE1, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4E, 0x44, 0xAE, 0x42, 0x60, 0x82};
  return kPng;
}

Mesh MakeGrid(int nx, int ny, int uv_sets, float z) {
  const test_shapes::Shape grid = test_shapes::Grid(nx, ny);
  Mesh m;
  m.indices = grid.triangles;
  m.uv_sets.resize(static_cast<size_t>(uv_sets));
  for (size_t v = 0; v < grid.vertex_count(); ++v) {
    const int x = static_cast<int>(grid.positions[3 * v]);
    const float fx = static_cast<float>(x) / static_cast<float>(nx);
    const float fy = static_cast<float>(grid.positions[3 * v + 1]) / static_cast<float>(ny);
    m.positions.insert(m.positions.end(),
                       {fx * 2.0f - 1.0f, fy * 3.0f + 0.125f, z + 0.1f * fx * fy});
    m.normals.insert(m.normals.end(), {0.0f, 0.0f, 1.0f});
    m.tangents.insert(m.tangents.end(), {1.0f, 0.0f, 0.0f, (x % 2) ? -1.0f : 1.0f});
    for (int u = 0; u < uv_sets; ++u) {
      m.uv_sets[static_cast<size_t>(u)].insert(m.uv_sets[static_cast<size_t>(u)].end(),
                                               {fx * static_cast<float>(u + 1), 1.0f - fy});
    }
    m.colors.insert(m.colors.end(), {fx, fy, 0.5f, 1.0f - 0.25f * fx});
  }
  return m;
}

Scene MakeRichScene() {
  Scene s;
  Image png;
  png.name = "checker";
  png.mime_type = "image/png";
  png.bytes = TinyPng();
  s.images.push_back(png);
  Image external;
  external.name = "wood";
  external.uri = "textures/wood%20dark.png";  // write_validation_samples puts a PNG there
  external.mime_type = "image/png";
  s.images.push_back(external);

  Material m0;
  m0.name = "painted";
  m0.base_color = {0.8f, 0.25f, 0.125f, 1.0f};
  m0.metallic = 0.0f;
  m0.roughness = 0.5f;
  m0.base_color_texture = {0, 0, {}};
  m0.base_color_texture.sampler = {9728, 9728, 33071, 33648};  // pixel art: nearest, clamped
  m0.normal_texture = {0, 1, {}};
  m0.normal_scale = 0.5f;
  m0.alpha_mode = AlphaMode::kMask;
  m0.alpha_cutoff = 0.25f;
  s.materials.push_back(m0);
  Material m1;
  m1.name = "metal";
  m1.metallic = 1.0f;
  m1.roughness = 0.25f;
  m1.emissive = {0.5f, 0.25f, 0.0f};
  m1.double_sided = true;
  m1.metallic_roughness_texture = {1, 0, {}};
  m1.occlusion_texture = {1, 1, {}};
  m1.emissive_texture = {0, 0, {}};
  m1.occlusion_strength = 0.75f;
  m1.alpha_mode = AlphaMode::kBlend;
  m1.emissive_strength = 4.0f;
  s.materials.push_back(m1);
  Material m2;
  m2.name = "glow";
  m2.unlit = true;
  m2.base_color_texture = {0, 0, {}};  // the same image as m0's, another sampler
  s.materials.push_back(m2);

  Mesh skinned = MakeGrid(4, 3, 2, 0.0f);
  skinned.name = "skinned grid";
  const size_t vc = skinned.vertex_count();
  for (size_t v = 0; v < vc; ++v) {
    const float w = static_cast<float>(v % 5) / 4.0f;  // exact binary fractions, sums to 1
    // A joint with zero weight is written as joint 0, as the glTF-Validator recommends.
    skinned.joints.insert(skinned.joints.end(), {0, static_cast<uint16_t>(w > 0.0f ? 1 : 0), 0, 0});
    skinned.weights.insert(skinned.weights.end(), {1.0f - w, w, 0.0f, 0.0f});
  }
  // Two blend shapes: a bulge of the middle vertices (with normal offsets) and a shear.
  MorphTarget bulge, shear;
  bulge.name = "bulge";
  for (size_t v = 0; v < vc; ++v) {
    const bool middle = v % 5 == 2 || v % 5 == 3;
    bulge.positions.insert(bulge.positions.end(), {0, 0, middle ? 0.5f : 0.0f});
    bulge.normals.insert(bulge.normals.end(), {middle ? 0.25f : 0.0f, 0, 0});
    shear.positions.insert(shear.positions.end(), {skinned.positions[3 * v + 1] * 0.125f, 0, 0});
    shear.normals.insert(shear.normals.end(), {0, 0, 0});
  }
  skinned.morph_targets = {bulge, shear};
  skinned.morph_weights = {0.25f, 0.0f};
  // Non-decreasing material ids: the first 10 triangles metal-free, the rest metal.
  for (size_t t = 0; t < skinned.triangle_count(); ++t)
    skinned.material_ids.push_back(t < 10 ? 0 : 1);
  s.meshes.push_back(skinned);

  Mesh hull = MakeGrid(2, 2, 0, 1.0f);
  hull.name = "trigger volume";
  hull.colors.clear();
  hull.tangents.clear();
  hull.collides = false;
  s.meshes.push_back(hull);

  Mesh plain;
  plain.name = "tetra";
  plain.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  plain.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  plain.material_ids = {1, 1, 2, 2};
  s.meshes.push_back(plain);

  // Nodes: 0 root -> 1 joint0 -> 2 joint1; 3 skinned (a root, as glTF wants skinned meshes);
  // 4 root with two meshes.
  s.nodes.resize(5);
  s.nodes[0].name = "root";
  s.nodes[0].children = {1};
  s.nodes[0].local_transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2.5, -1, 0.75, 1};
  s.nodes[1].name = "joint0";
  s.nodes[1].parent = 0;
  s.nodes[1].children = {2};
  s.nodes[2].name = "joint1";
  s.nodes[2].parent = 1;
  s.nodes[2].trs = Trs();
  s.nodes[2].trs->translation = {0, 1.5, 0};
  s.nodes[2].trs->rotation = {0, 0, 0.6, 0.8};
  s.nodes[2].local_transform = TrsMatrix(*s.nodes[2].trs);
  s.nodes[1].trs = Trs();
  s.nodes[3].name = "skinned";
  s.nodes[3].meshes = {0};
  s.nodes[3].skin = 0;
  s.nodes[4].name = "multi";
  s.nodes[4].meshes = {1, 2};
  // 90 degrees about z, scaled by 2.
  s.nodes[4].local_transform = {0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 0, 0, -3, 1};

  Skin skin;
  skin.name = "rig";
  skin.joints = {1, 2};
  skin.skeleton = 1;
  const float ibm0[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const float ibm1[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1.5f, 0, 1};
  skin.inverse_bind_matrices.assign(ibm0, ibm0 + 16);
  skin.inverse_bind_matrices.insert(skin.inverse_bind_matrices.end(), ibm1, ibm1 + 16);
  s.skins.push_back(skin);

  // One clip driving both joints: each interpolation, and two samplers sharing their key times.
  Animation wave;
  wave.name = "wave";
  AnimationSampler turn;
  turn.times = {0.0f, 0.5f, 1.0f};
  turn.values = {0, 0, 0, 1, 0, 0, 0.6f, 0.8f, 0, 0, 0, 1};
  wave.samplers.push_back(turn);
  AnimationSampler hop;
  hop.interpolation = Interpolation::kStep;
  hop.times = {0.0f, 0.5f, 1.0f};
  hop.values = {0, 1.5f, 0, 0, 2, 0, 0, 1.5f, 0};
  wave.samplers.push_back(hop);
  AnimationSampler swell;
  swell.interpolation = Interpolation::kCubicSpline;
  swell.times = {0.25f, 0.75f};
  swell.values = {0,     0,     0,     1,    1,    1,    0.5f, 0.5f, 0.5f,
                  -0.5f, -0.5f, -0.5f, 1.5f, 1.5f, 1.5f, 0,    0,    0};
  wave.samplers.push_back(swell);
  AnimationSampler blend;  // the skinned mesh's two morph weights per key
  blend.times = {0.0f, 0.5f, 1.0f};
  blend.values = {0, 0, 1, 0.5f, 0, 1};
  wave.samplers.push_back(blend);
  wave.channels = {{0, 1, AnimationPath::kRotation},
                   {1, 2, AnimationPath::kTranslation},
                   {2, 2, AnimationPath::kScale},
                   {3, 3, AnimationPath::kWeights}};
  s.animations.push_back(wave);

  Camera lens;
  lens.name = "lens";
  lens.yfov = 0.75;
  lens.aspect_ratio = 1.5;
  lens.zfar = 100;
  s.cameras.push_back(lens);
  Light lamp;
  lamp.type = LightType::kSpot;
  lamp.color = {1, 0.75f, 0.5f};
  lamp.intensity = 20;
  lamp.range = 8;
  lamp.inner_cone_angle = 0.25f;
  lamp.outer_cone_angle = 0.5f;
  s.lights.push_back(lamp);
  s.nodes[0].camera = 0;
  s.nodes[2].light = 0;
  return s;
}

Scene MakeLargeScene() {
  Scene s;
  Mesh m = MakeGrid(300, 250, 1, 0.0f);  // 301 * 251 = 75551 vertices
  m.name = "large";
  s.meshes.push_back(m);
  AddRootNodeForAllMeshes(s, "large root");
  return s;
}

namespace {

template <typename T>
void ExpectBitEqual(const std::vector<T>& a, const std::vector<T>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  if (!a.empty()) {
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(T))) << what;
  }
}

}  // namespace

void ExpectScenesEqual(const Scene& e, const Scene& a) {
  ASSERT_EQ(e.meshes.size(), a.meshes.size());
  for (size_t i = 0; i < e.meshes.size(); ++i) {
    const Mesh& em = e.meshes[i];
    const Mesh& am = a.meshes[i];
    const std::string w = "mesh " + std::to_string(i) + " ";
    EXPECT_EQ(em.name, am.name) << w;
    EXPECT_EQ(em.collides, am.collides) << w;
    ExpectBitEqual(em.positions, am.positions, w + "positions");
    ExpectBitEqual(em.indices, am.indices, w + "indices");
    ExpectBitEqual(em.normals, am.normals, w + "normals");
    ExpectBitEqual(em.tangents, am.tangents, w + "tangents");
    ASSERT_EQ(em.uv_sets.size(), am.uv_sets.size()) << w;
    for (size_t u = 0; u < em.uv_sets.size(); ++u)
      ExpectBitEqual(em.uv_sets[u], am.uv_sets[u], w + "uv");
    ExpectBitEqual(em.colors, am.colors, w + "colors");
    ExpectBitEqual(em.joints, am.joints, w + "joints");
    ExpectBitEqual(em.weights, am.weights, w + "weights");
    ExpectBitEqual(em.material_ids, am.material_ids, w + "material_ids");
    ASSERT_EQ(em.morph_targets.size(), am.morph_targets.size()) << w;
    for (size_t t = 0; t < em.morph_targets.size(); ++t) {
      EXPECT_EQ(em.morph_targets[t].name, am.morph_targets[t].name) << w << "target " << t;
      ExpectBitEqual(em.morph_targets[t].positions, am.morph_targets[t].positions,
                     w + "target positions");
      ExpectBitEqual(em.morph_targets[t].normals, am.morph_targets[t].normals,
                     w + "target normals");
    }
    ExpectBitEqual(em.morph_weights, am.morph_weights, w + "morph weights");
  }
  ASSERT_EQ(e.materials.size(), a.materials.size());
  for (size_t i = 0; i < e.materials.size(); ++i) {
    const Material& em = e.materials[i];
    const Material& am = a.materials[i];
    const std::string w = "material " + std::to_string(i);
    EXPECT_EQ(em.name, am.name) << w;
    EXPECT_EQ(em.base_color, am.base_color) << w;
    EXPECT_EQ(em.metallic, am.metallic) << w;
    EXPECT_EQ(em.roughness, am.roughness) << w;
    EXPECT_EQ(em.emissive, am.emissive) << w;
    EXPECT_EQ(em.double_sided, am.double_sided) << w;
    const TextureRef* et[] = {&em.base_color_texture, &em.metallic_roughness_texture,
                              &em.normal_texture, &em.occlusion_texture, &em.emissive_texture};
    const TextureRef* at[] = {&am.base_color_texture, &am.metallic_roughness_texture,
                              &am.normal_texture, &am.occlusion_texture, &am.emissive_texture};
    for (int k = 0; k < 5; ++k) {
      EXPECT_EQ(et[k]->image, at[k]->image) << w << " slot " << k;
      EXPECT_EQ(et[k]->uv_set, at[k]->uv_set) << w << " slot " << k;
      EXPECT_TRUE(et[k]->sampler == at[k]->sampler) << w << " slot " << k;
    }
    EXPECT_EQ(em.alpha_mode, am.alpha_mode) << w;
    EXPECT_EQ(em.alpha_cutoff, am.alpha_cutoff) << w;
    EXPECT_EQ(em.unlit, am.unlit) << w;
    EXPECT_EQ(em.emissive_strength, am.emissive_strength) << w;
    EXPECT_EQ(em.normal_scale, am.normal_scale) << w;
    EXPECT_EQ(em.occlusion_strength, am.occlusion_strength) << w;
  }
  ASSERT_EQ(e.images.size(), a.images.size());
  for (size_t i = 0; i < e.images.size(); ++i) {
    EXPECT_EQ(e.images[i].name, a.images[i].name);
    EXPECT_EQ(e.images[i].uri, a.images[i].uri);
    EXPECT_EQ(e.images[i].mime_type, a.images[i].mime_type);
    EXPECT_EQ(e.images[i].bytes, a.images[i].bytes);
  }
  ASSERT_EQ(e.skins.size(), a.skins.size());
  for (size_t i = 0; i < e.skins.size(); ++i) {
    EXPECT_EQ(e.skins[i].name, a.skins[i].name);
    EXPECT_EQ(e.skins[i].joints, a.skins[i].joints);
    EXPECT_EQ(e.skins[i].skeleton, a.skins[i].skeleton);
    ExpectBitEqual(e.skins[i].inverse_bind_matrices, a.skins[i].inverse_bind_matrices, "ibm");
  }
  ASSERT_EQ(e.nodes.size(), a.nodes.size());
  for (size_t i = 0; i < e.nodes.size(); ++i) {
    const std::string w = "node " + std::to_string(i);
    EXPECT_EQ(e.nodes[i].name, a.nodes[i].name) << w;
    EXPECT_EQ(e.nodes[i].parent, a.nodes[i].parent) << w;
    EXPECT_EQ(e.nodes[i].children, a.nodes[i].children) << w;
    EXPECT_EQ(e.nodes[i].local_transform, a.nodes[i].local_transform) << w;
    EXPECT_EQ(e.nodes[i].meshes, a.nodes[i].meshes) << w;
    EXPECT_EQ(e.nodes[i].skin, a.nodes[i].skin) << w;
    ASSERT_EQ(e.nodes[i].trs.has_value(), a.nodes[i].trs.has_value()) << w;
    if (e.nodes[i].trs) {
      EXPECT_EQ(e.nodes[i].trs->translation, a.nodes[i].trs->translation) << w;
      EXPECT_EQ(e.nodes[i].trs->rotation, a.nodes[i].trs->rotation) << w;
      EXPECT_EQ(e.nodes[i].trs->scale, a.nodes[i].trs->scale) << w;
    }
  }
  for (size_t i = 0; i < e.nodes.size(); ++i) {
    EXPECT_EQ(e.nodes[i].camera, a.nodes[i].camera) << i;
    EXPECT_EQ(e.nodes[i].light, a.nodes[i].light) << i;
  }
  ASSERT_EQ(e.cameras.size(), a.cameras.size());
  for (size_t i = 0; i < e.cameras.size(); ++i) {
    const Camera& ec = e.cameras[i];
    const Camera& ac = a.cameras[i];
    EXPECT_EQ(ec.name, ac.name);
    EXPECT_EQ(ec.perspective, ac.perspective);
    EXPECT_EQ(ec.yfov, ac.yfov);
    EXPECT_EQ(ec.aspect_ratio, ac.aspect_ratio);
    EXPECT_EQ(ec.znear, ac.znear);
    EXPECT_EQ(ec.zfar, ac.zfar);
  }
  ASSERT_EQ(e.lights.size(), a.lights.size());
  for (size_t i = 0; i < e.lights.size(); ++i) {
    const Light& el = e.lights[i];
    const Light& al = a.lights[i];
    EXPECT_EQ(el.type, al.type);
    EXPECT_EQ(el.color, al.color);
    EXPECT_EQ(el.intensity, al.intensity);
    EXPECT_EQ(el.range, al.range);
    EXPECT_EQ(el.inner_cone_angle, al.inner_cone_angle);
    EXPECT_EQ(el.outer_cone_angle, al.outer_cone_angle);
  }
  ASSERT_EQ(e.animations.size(), a.animations.size());
  for (size_t i = 0; i < e.animations.size(); ++i) {
    const Animation& ea = e.animations[i];
    const Animation& aa = a.animations[i];
    const std::string w = "animation " + std::to_string(i);
    EXPECT_EQ(ea.name, aa.name) << w;
    ASSERT_EQ(ea.samplers.size(), aa.samplers.size()) << w;
    for (size_t k = 0; k < ea.samplers.size(); ++k) {
      ExpectBitEqual(ea.samplers[k].times, aa.samplers[k].times, w + " times");
      ExpectBitEqual(ea.samplers[k].values, aa.samplers[k].values, w + " values");
      EXPECT_EQ(ea.samplers[k].interpolation, aa.samplers[k].interpolation) << w;
    }
    ASSERT_EQ(ea.channels.size(), aa.channels.size()) << w;
    for (size_t k = 0; k < ea.channels.size(); ++k) {
      EXPECT_EQ(ea.channels[k].sampler, aa.channels[k].sampler) << w;
      EXPECT_EQ(ea.channels[k].node, aa.channels[k].node) << w;
      EXPECT_EQ(ea.channels[k].path, aa.channels[k].path) << w;
    }
  }
}

}  // namespace testing_gltf
}  // namespace hullpack
