// PackScene end to end on generated scenes: unpack(pack(x)) against x.
#include "pipeline/pack.h"

#include <gtest/gtest.h>

#include "test_torus.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "gltf/glb_reader.h"
#include "mesh/topology.h"
#include "packed/packed_glb_reader.h"
#include "pipeline/mesh_codec.h"

namespace hullpack {
namespace {

Mesh Torus(int rings, int sides, float cx) { return testing::TorusMesh(rings, sides, cx); }

// A textured two-material torus under a transformed parent, and a skinned torus.
Scene TestScene() {
  Scene s;
  Mesh textured = Torus(32, 12, 0);
  textured.name = "wheel";
  textured.uv_sets.emplace_back();
  for (size_t v = 0; v < textured.vertex_count(); ++v) {
    textured.uv_sets[0].insert(textured.uv_sets[0].end(), {float(v % 32) / 32, float(v / 32) / 12});
  }
  for (size_t t = 0; t < textured.triangle_count(); ++t)
    textured.material_ids.push_back(t % 7 == 0 ? 1 : 0);
  Mesh skinned = Torus(16, 8, 4);
  skinned.name = "arm";
  for (size_t v = 0; v < skinned.vertex_count(); ++v) {
    skinned.joints.insert(skinned.joints.end(), {uint16_t(v % 2), uint16_t(1 - v % 2), 0, 0});
    skinned.weights.insert(skinned.weights.end(), {0.75f, 0.25f, 0, 0});
  }
  s.meshes = {textured, skinned};
  s.images.resize(1);
  s.images[0].name = "checker";
  s.images[0].mime_type = "image/png";
  s.images[0].bytes = {0x89, 'P', 'N', 'G', 13, 10, 26, 10};
  s.materials.resize(2);
  s.materials[0].name = "rubber";
  s.materials[0].base_color_texture.image = 0;
  s.materials[1].name = "rim";
  Node root, wheel, arm, bone0, bone1;
  root.name = "root";
  root.local_transform[12] = 10;  // translate x
  root.children = {1, 2};
  wheel.name = "wheel";
  wheel.parent = 0;
  wheel.meshes = {0};
  arm.name = "arm";
  arm.parent = 0;
  arm.meshes = {1};
  arm.skin = 0;
  arm.children = {3, 4};
  bone0.name = "bone0";
  bone0.parent = 2;
  bone1.name = "bone1";
  bone1.parent = 2;
  s.nodes = {root, wheel, arm, bone0, bone1};
  Skin skin;
  skin.joints = {3, 4};
  for (int j = 0; j < 2; ++j)
    skin.inverse_bind_matrices.insert(skin.inverse_bind_matrices.end(), kIdentity.begin(),
                                      kIdentity.end());
  s.skins = {skin};
  return s;
}

PackOptions FastOptions() {
  PackOptions o;
  o.collision.parameters.resolution = 20000;
  return o;
}

// Index of the vertex of `m` nearest to `p`.
size_t Nearest(const Mesh& m, const float* p) {
  size_t best = 0;
  double best_d = 1e300;
  for (size_t i = 0; i < m.vertex_count(); ++i) {
    double d = 0;
    for (int k = 0; k < 3; ++k)
      d += (double(m.positions[i * 3 + k]) - p[k]) * (double(m.positions[i * 3 + k]) - p[k]);
    if (d < best_d) best_d = d, best = i;
  }
  return best;
}

// The collision-hull points an engine reads from a packed file, hull by hull.
std::vector<std::vector<float>> HullPoints(const PackResult& packed) {
  GltfDocument d;
  EXPECT_TRUE(ReadPackedGltf(packed.glb.data(), packed.glb.size(), "p.glb", "", &d).ok());
  Result<std::vector<CollisionHull>> h = ReadCollisionHulls(d, "p.glb");
  EXPECT_TRUE(h.ok());
  std::vector<std::vector<float>> points;
  if (h.ok())
    for (const CollisionHull& c : h.value()) points.push_back(c.hull.positions);
  return points;
}

TEST(Pack, RoundTripKeepsGeometryWithinTheBudgetMaterialsSkinAndHierarchy) {
  const Scene in = TestScene();
  const PackOptions options = FastOptions();
  Result<PackResult> packed = PackScene(in, options);
  ASSERT_TRUE(packed.ok()) << packed.status().ToString();
  const PackReport& r = packed->report;
  ASSERT_EQ(r.meshes.size(), 2u);
  EXPECT_GT(r.meshes[0].hull_count, 1u);  // the wheel collides
  EXPECT_EQ(r.meshes[1].hull_count, 0u);  // the skinned arm does not, under auto
  EXPECT_NE(r.meshes[1].no_hulls_reason.find("skinned"), std::string::npos);
  EXPECT_GT(r.meshes[0].hull_quantization_error, 0);
  EXPECT_LE(r.meshes[0].hull_quantization_error, options.hull_error);
  for (const MeshPackReport& m : r.meshes) {
    EXPECT_LE(m.max_error_fraction, options.max_error) << m.name;
    EXPECT_LT(m.bytes_after, m.bytes_before / 4) << m.name;
  }

  GltfDocument doc;
  Result<Scene> out =
      ReadPackedGltf(packed->glb.data(), packed->glb.size(), "packed.glb", "", &doc);
  ASSERT_TRUE(out.ok()) << out.status().ToString();
  ASSERT_EQ(out->meshes.size(), 2 + r.meshes[0].hull_count);
  for (size_t i = 0; i < 2; ++i) {
    const Mesh& a = in.meshes[i];
    const Mesh& b = out->meshes[i];
    EXPECT_EQ(b.triangle_count(), a.triangle_count());
    EXPECT_EQ(b.vertex_count(), a.vertex_count());
    double worst = 0;
    for (size_t v = 0; v < b.vertex_count(); ++v) {
      const size_t o = Nearest(a, &b.positions[v * 3]);
      double d = 0;
      for (int k = 0; k < 3; ++k)
        d += std::pow(double(b.positions[v * 3 + k]) - a.positions[o * 3 + k], 2);
      worst = std::max(worst, std::sqrt(d));
      if (!a.joints.empty()) {  // skin data travels with its vertex, exactly for joints
        for (int k = 0; k < 4; ++k) {
          EXPECT_EQ(b.joints[v * 4 + k], a.joints[o * 4 + k]);
          EXPECT_NEAR(b.weights[v * 4 + k], a.weights[o * 4 + k], 1.0 / 1023);
        }
      }
    }
    const double diagonal = std::sqrt(2 * 2.6 * 2.6 + 0.6 * 0.6);
    EXPECT_LE(worst, options.max_error * diagonal * 1.0001) << a.name;
  }
  // Materials per triangle: the same counts.
  std::map<std::string, size_t> before, after;
  for (uint32_t id : in.meshes[0].material_ids) ++before[in.materials[id].name];
  for (uint32_t id : out->meshes[0].material_ids) ++after[out->materials[id].name];
  EXPECT_EQ(before, after);
  ASSERT_EQ(out->images.size(), 1u);
  EXPECT_EQ(out->images[0].bytes, in.images[0].bytes);
  ASSERT_EQ(out->skins.size(), 1u);
  EXPECT_EQ(out->nodes[0].local_transform[12], 10);

  const nlohmann::json& json = doc.json();
  // Colliders: OMI shapes, one per hull, each a convex mesh, on children of the wheel's node. The
  // hulls are plain points: no hullpack extension, nothing required because of them.
  Result<GltfDocument> raw = DecodeGlbDocument(packed->glb.data(), packed->glb.size(), "p.glb");
  ASSERT_TRUE(raw.ok());
  EXPECT_EQ(raw->json()["extensionsRequired"], nlohmann::json::array({kMeshCompressionExtension}));
  Result<std::vector<CollisionHull>> hulls = ReadCollisionHulls(doc, "packed.glb");
  ASSERT_TRUE(hulls.ok()) << hulls.status().ToString();
  ASSERT_EQ(hulls->size(), r.meshes[0].hull_count);
  for (size_t h = 0; h < hulls->size(); ++h) {
    const CollisionHull& hull = hulls.value()[h];
    EXPECT_EQ(hull.body_node, 1);
    EXPECT_GE(hull.hull.vertex_count(), 4u) << h;
    const nlohmann::json& prim = json["meshes"][hull.gltf_mesh]["primitives"][0];
    EXPECT_FALSE(prim.contains("extensions"));
    EXPECT_EQ(prim["mode"], 0);
  }

  ASSERT_TRUE(json.contains("extensions"));
  const nlohmann::json& shapes = json["extensions"]["OMI_physics_shape"]["shapes"];
  ASSERT_EQ(shapes.size(), r.meshes[0].hull_count);
  size_t colliders = 0;
  for (int child : json["nodes"][1]["children"]) {
    const int shape = json["nodes"][child]["extensions"]["OMI_physics_body"]["collider"]["shape"];
    EXPECT_EQ(shapes[shape]["type"], "convex");
    EXPECT_GE(shapes[shape]["convex"]["mesh"].get<int>(), 1);
    ++colliders;
  }
  EXPECT_EQ(colliders, r.meshes[0].hull_count);
}

// A mesh above PackOptions::part_triangles: streams of compact parts on one grid, no crack
// between them, its hulls on its node as before; a skinned mesh stays whole.
TEST(Pack, LargeMeshesAreCodedInPartsWithoutCracks) {
  const Scene in = TestScene();
  PackOptions options = FastOptions();
  options.part_triangles = 200;
  for (int qp : {0, 11}) {
    options.position_bits = qp;
    Result<PackResult> packed = PackScene(in, options);
    ASSERT_TRUE(packed.ok()) << packed.status().ToString();
    const PackReport& r = packed->report;
    ASSERT_EQ(r.meshes.size(), 2u);
    EXPECT_EQ(r.meshes[0].parts, 4u);  // 768 triangles
    EXPECT_EQ(r.meshes[1].parts, 1u);  // skinned
    EXPECT_GT(r.meshes[0].hull_count, 1u);
    EXPECT_LE(r.meshes[0].max_error_fraction, options.max_error);

    GltfDocument doc;
    Result<Scene> out =
        ReadPackedGltf(packed->glb.data(), packed->glb.size(), "packed.glb", "", &doc);
    ASSERT_TRUE(out.ok()) << out.status().ToString();
    const Mesh& wheel = in.meshes[0];
    const double budget = qp ? 1e9 : options.max_error * std::sqrt(2 * 2.6 * 2.6 + 0.6 * 0.6);
    std::map<size_t, std::array<float, 3>> decoded_of;  // wheel vertex -> its decoded position
    std::map<std::string, size_t> before, after;
    size_t parts = 0, triangles = 0, shared = 0;
    for (const Mesh& m : out->meshes) {
      if (m.name != "wheel") continue;
      ++parts;
      triangles += m.triangle_count();
      for (uint32_t id : m.material_ids) ++after[out->materials[id].name];
      for (size_t v = 0; v < m.vertex_count(); ++v) {
        const size_t o = Nearest(wheel, &m.positions[v * 3]);
        double d = 0;
        for (int k = 0; k < 3; ++k)
          d += std::pow(double(m.positions[v * 3 + k]) - wheel.positions[o * 3 + k], 2);
        EXPECT_LE(std::sqrt(d), budget * 1.0001);
        const std::array<float, 3> p = {m.positions[v * 3], m.positions[v * 3 + 1],
                                        m.positions[v * 3 + 2]};
        auto [it, added] = decoded_of.insert({o, p});
        if (!added) {
          ++shared;
          EXPECT_EQ(it->second, p) << "vertex " << o << " decodes differently in two parts";
        }
      }
    }
    EXPECT_EQ(parts, 4u);
    EXPECT_EQ(triangles, wheel.triangle_count());
    EXPECT_GT(shared, 0u);
    for (uint32_t id : wheel.material_ids) ++before[in.materials[id].name];
    EXPECT_EQ(before, after);
    Result<std::vector<CollisionHull>> hulls = ReadCollisionHulls(doc, "packed.glb");
    ASSERT_TRUE(hulls.ok()) << hulls.status().ToString();
    ASSERT_EQ(hulls->size(), r.meshes[0].hull_count);
    for (const CollisionHull& h : hulls.value()) EXPECT_EQ(h.body_node, 1);
    // Without parts, the same scene is one stream per mesh.
    PackOptions whole = options;
    whole.part_triangles = 0;
    Result<PackResult> one = PackScene(in, whole);
    ASSERT_TRUE(one.ok());
    EXPECT_EQ(one->report.meshes[0].parts, 1u);
  }
}

TEST(Pack, AnimationsAndMaterialLooksSurvivePacking) {
  Scene in = TestScene();
  in.materials[0].alpha_mode = AlphaMode::kMask;
  in.materials[0].alpha_cutoff = 0.3f;
  in.materials[0].base_color_texture.sampler.mag_filter = 9728;
  // The wheel spins (a quarter turn a second) and the arm's bone holds still: the still track is
  // left out, the clip keeps the spin.
  in.nodes[1].trs = Trs();
  Animation spin;
  spin.name = "spin";
  AnimationSampler turn;
  turn.times = {0, 1, 2};
  turn.values = {0, 0, 0, 1, 0, 0, 0.70710678f, 0.70710678f, 0, 0, 1, 0};
  AnimationSampler still;
  still.times = {0, 2};
  still.values = {0, 0, 0, 1, 0, 0, 0, 1};
  spin.samplers = {turn, still};
  spin.channels = {{0, 1, AnimationPath::kRotation}, {1, 3, AnimationPath::kRotation}};
  in.animations.push_back(spin);
  Result<PackResult> packed = PackScene(in, FastOptions());
  ASSERT_TRUE(packed.ok()) << packed.status().ToString();
  GltfDocument doc;
  Result<Scene> out = ReadPackedGltf(packed->glb.data(), packed->glb.size(), "p.glb", "", &doc);
  ASSERT_TRUE(out.ok()) << out.status().ToString();
  ASSERT_EQ(out->animations.size(), 1u);
  const Animation& a = out->animations[0];
  EXPECT_EQ(a.name, "spin");
  ASSERT_EQ(a.channels.size(), 1u);
  EXPECT_EQ(a.channels[0].node, 1);
  EXPECT_EQ(a.channels[0].path, AnimationPath::kRotation);
  const std::vector<float>& values = a.samplers[0].values;
  ASSERT_EQ(values.size(), turn.values.size());
  for (size_t k = 0; k < values.size(); ++k) EXPECT_NEAR(values[k], turn.values[k], 1e-4) << k;
  EXPECT_EQ(a.samplers[0].times, turn.times);
  // Three key times and three short quaternions: too few to gain from compression, so plain.
  EXPECT_EQ(packed->report.key_frame_bytes_before, 3 * 4 + 3 * 8u);
  EXPECT_EQ(packed->report.key_frame_bytes_after, packed->report.key_frame_bytes_before);
  ASSERT_TRUE(out->nodes[1].trs.has_value());
  EXPECT_EQ(out->materials[0].alpha_mode, AlphaMode::kMask);
  EXPECT_EQ(out->materials[0].alpha_cutoff, 0.3f);
  EXPECT_EQ(out->materials[0].base_color_texture.sampler.mag_filter, 9728);
  // The wheel's colliders are children of its node, so they turn with it.
  EXPECT_GT(packed->report.meshes[0].hull_count, 1u);
  EXPECT_FALSE(doc.json()["nodes"][1]["children"].empty());
}

TEST(Pack, MorphTargetsAndTheirClipsSurvivePackingWithinTheBudget) {
  Scene in = TestScene();
  Mesh& wheel = in.meshes[0];
  MorphTarget puff, twist;
  puff.name = "puff";
  for (size_t v = 0; v < wheel.vertex_count(); ++v) {
    const float* p = &wheel.positions[3 * v];
    puff.positions.insert(puff.positions.end(), {0.1f * p[0], 0.1f * p[1], 0.1f * p[2]});
    puff.normals.insert(puff.normals.end(), {0, 0, v % 3 == 0 ? 0.2f : 0.0f});
    twist.positions.insert(twist.positions.end(), {0.3f * p[2], 0, 0});
    twist.normals.insert(twist.normals.end(), {0, 0, 0});
  }
  wheel.morph_targets = {puff, twist};
  wheel.morph_weights = {0.5f, 0.0f};
  in.nodes[1].trs = Trs();
  Animation breathe;
  breathe.name = "breathe";
  AnimationSampler weights;
  weights.times = {0, 1, 2};
  weights.values = {0, 0, 1, 0.25f, 0, 1};
  breathe.samplers = {weights};
  breathe.channels = {{0, 1, AnimationPath::kWeights}};
  in.animations.push_back(breathe);
  PackOptions options = FastOptions();
  options.collision.policy = HullPolicy::kNone;
  Result<PackResult> packed = PackScene(in, options);
  ASSERT_TRUE(packed.ok()) << packed.status().ToString();
  Result<Scene> out = ReadPackedGltf(packed->glb.data(), packed->glb.size(), "p.glb", "", nullptr);
  ASSERT_TRUE(out.ok()) << out.status().ToString();
  const Mesh& m = out->meshes[0];
  ASSERT_EQ(m.morph_targets.size(), 2u);
  EXPECT_EQ(m.morph_targets[0].name, "puff");
  EXPECT_EQ(m.morph_weights, wheel.morph_weights);
  ASSERT_EQ(m.morph_targets[1].normals.size(), 3 * m.vertex_count());
  // Each decoded vertex's offsets lie within the position budget of its source vertex's.
  const double budget = options.max_error * BoundingBoxDiagonal(wheel);
  double worst = 0, worst_normal = 0;
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    const size_t src = Nearest(wheel, &m.positions[3 * v]);
    for (size_t t = 0; t < 2; ++t) {
      double d = 0, n = 0;
      for (size_t k = 0; k < 3; ++k) {
        d += std::pow(
            m.morph_targets[t].positions[3 * v + k] - wheel.morph_targets[t].positions[3 * src + k],
            2);
        n = std::max<double>(n, std::fabs(m.morph_targets[t].normals[3 * v + k] -
                                          wheel.morph_targets[t].normals[3 * src + k]));
      }
      worst = std::max(worst, std::sqrt(d));
      worst_normal = std::max(worst_normal, n);
    }
  }
  EXPECT_GT(worst, 0.0);
  EXPECT_LE(worst, budget * (1 + 1e-6));
  EXPECT_LE(worst_normal, 0.2 / 1023 * 0.5 + 1e-6);  // half a step of 10 bits over 0.2
  ASSERT_EQ(out->animations.size(), 1u);
  ASSERT_EQ(out->animations[0].channels.size(), 1u);
  EXPECT_EQ(out->animations[0].channels[0].path, AnimationPath::kWeights);
  EXPECT_EQ(out->animations[0].samplers[0].values, weights.values);
}

TEST(Pack, WithoutFallbackTheExtensionIsRequiredAndAccessorsHoldNoData) {
  PackOptions options = FastOptions();
  options.collision.policy = HullPolicy::kNone;
  Result<PackResult> packed = PackScene(TestScene(), options);
  ASSERT_TRUE(packed.ok());
  Result<GltfDocument> doc = DecodeGlbDocument(packed->glb.data(), packed->glb.size(), "p.glb");
  ASSERT_TRUE(doc.ok());
  EXPECT_EQ(doc->json()["extensionsRequired"], nlohmann::json::array({kMeshCompressionExtension}));
  for (const auto& accessor : doc->json()["accessors"]) {
    if (accessor.value("type", "") != "MAT4") {  // inverse bind matrices are not mesh data
      EXPECT_FALSE(accessor.contains("bufferView"));
    }
  }
  // A plain reader cannot read it: the extension is required.
  EXPECT_FALSE(DecodeGltfDocument(doc.value(), "p.glb").ok());
}

TEST(Pack, FallbackFilesReadWithoutTheExtension) {
  PackOptions options = FastOptions();
  options.glb.fallback = true;
  options.collision.policy = HullPolicy::kNone;
  Result<PackResult> packed = PackScene(TestScene(), options);
  ASSERT_TRUE(packed.ok());
  Result<GltfDocument> doc = DecodeGlbDocument(packed->glb.data(), packed->glb.size(), "p.glb");
  ASSERT_TRUE(doc.ok());
  EXPECT_FALSE(doc->json().contains("extensionsRequired"));
  // The plain reader ignores the extension and reads the fallback: the decoded data.
  Result<Scene> plain = DecodeGltfDocument(doc.value(), "p.glb");
  ASSERT_TRUE(plain.ok()) << plain.status().ToString();
  Result<Scene> decoded =
      ReadPackedGltf(packed->glb.data(), packed->glb.size(), "p.glb", "", nullptr);
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(plain->meshes[0].positions, decoded->meshes[0].positions);
  EXPECT_EQ(plain->meshes[0].indices, decoded->meshes[0].indices);
}

TEST(Pack, FallbackFilesWithHullsRequireNoExtension) {
  // The hulls of a fallback file hold their grid integers as floats: no KHR_mesh_quantization,
  // and an engine gets the same points as from the default file.
  PackOptions options = FastOptions();
  Result<PackResult> plain = PackScene(TestScene(), options);
  options.glb.fallback = true;
  Result<PackResult> fallback = PackScene(TestScene(), options);
  ASSERT_TRUE(plain.ok() && fallback.ok());
  Result<GltfDocument> doc = DecodeGlbDocument(fallback->glb.data(), fallback->glb.size(), "f.glb");
  ASSERT_TRUE(doc.ok());
  EXPECT_FALSE(doc->json().contains("extensionsRequired"));
  for (const auto& name : doc->json()["extensionsUsed"])
    EXPECT_NE(name.get<std::string>(), "KHR_mesh_quantization");
  const std::vector<std::vector<float>> a = HullPoints(plain.value());
  EXPECT_GT(a.size(), 1u);
  EXPECT_EQ(a, HullPoints(fallback.value()));
}

TEST(Pack, QuantizedHullsRequireKhrMeshQuantizationAndGiveTheSamePoints) {
  // Default hulls hold their grid integers as floats; --quantized-hulls stores the same integers
  // as bytes or shorts (smaller) and requires KHR_mesh_quantization. An engine gets the same
  // points.
  PackOptions options = FastOptions();
  Result<PackResult> floats = PackScene(TestScene(), options);
  options.glb.quantized_hulls = true;
  Result<PackResult> quantized = PackScene(TestScene(), options);
  ASSERT_TRUE(floats.ok() && quantized.ok());
  EXPECT_LT(quantized->glb.size(), floats->glb.size());
  auto read = [](const PackResult& p, std::vector<std::vector<float>>* points) {
    *points = HullPoints(p);
    Result<GltfDocument> raw = DecodeGlbDocument(p.glb.data(), p.glb.size(), "p.glb");
    EXPECT_TRUE(raw.ok());
    std::set<int> types;
    for (const auto& mesh : raw->json()["meshes"]) {
      const auto& prim = mesh["primitives"][0];
      if (prim.value("mode", 4) == 0)
        types.insert(
            raw->json()["accessors"][prim["attributes"]["POSITION"].get<int>()]["componentType"]
                .get<int>());
    }
    return std::make_pair(raw->json()["extensionsRequired"], types);
  };
  std::vector<std::vector<float>> a, b;
  const auto [required_floats, types_floats] = read(floats.value(), &a);
  const auto [required_quantized, types_quantized] = read(quantized.value(), &b);
  EXPECT_EQ(required_floats, nlohmann::json::array({kMeshCompressionExtension}));
  EXPECT_EQ(types_floats, std::set<int>({gltf::kFloat}));
  EXPECT_EQ(required_quantized,
            nlohmann::json::array({kMeshCompressionExtension, "KHR_mesh_quantization"}));
  EXPECT_EQ(types_quantized.count(gltf::kFloat), 0u);
  EXPECT_GT(a.size(), 1u);
  EXPECT_EQ(a, b);
}

TEST(Pack, KhrPhysicsForm) {
  PackOptions options = FastOptions();
  options.glb.physics = PhysicsForm::kKhr;
  Result<PackResult> packed = PackScene(TestScene(), options);
  ASSERT_TRUE(packed.ok());
  Result<GltfDocument> doc = DecodeGlbDocument(packed->glb.data(), packed->glb.size(), "p.glb");
  ASSERT_TRUE(doc.ok());
  const nlohmann::json& json = doc->json();
  EXPECT_FALSE(json.contains("extensions") && json["extensions"].contains("OMI_physics_shape"));
  const int child = json["nodes"][1]["children"][0];
  const nlohmann::json& geometry =
      json["nodes"][child]["extensions"]["KHR_physics_rigid_bodies"]["collider"]["geometry"];
  EXPECT_TRUE(geometry["convexHull"].get<bool>());
  // The draft's current form: the collider's geometry names a node (outside the scene) holding the
  // hull mesh; the collider node's transform dequantizes it.
  const int holder = geometry["node"].get<int>();
  EXPECT_GE(json["nodes"][holder]["mesh"].get<int>(), 2);
  EXPECT_TRUE(json["nodes"][child].contains("scale"));
  Result<std::vector<CollisionHull>> hulls = ReadCollisionHulls(doc.value(), "p.glb");
  ASSERT_TRUE(hulls.ok()) << hulls.status().ToString();
  EXPECT_EQ(hulls->size(), packed->report.meshes[0].hull_count);
}

TEST(Pack, KeepOrderAndExplicitBits) {
  PackOptions options = FastOptions();
  options.keep_order = true;
  options.position_bits = 16;
  options.collision.policy = HullPolicy::kNone;
  const Scene in = TestScene();
  Result<PackResult> packed = PackScene(in, options);
  ASSERT_TRUE(packed.ok());
  EXPECT_EQ(packed->report.meshes[0].position_bits, 16);
  Result<Scene> out = ReadPackedGltf(packed->glb.data(), packed->glb.size(), "p.glb", "", nullptr);
  ASSERT_TRUE(out.ok());
  // Order kept: the same index buffer, primitive after primitive (material 0 then 1).
  std::vector<uint32_t> expected;
  for (uint32_t m : {0u, 1u}) {
    for (size_t t = 0; t < in.meshes[0].triangle_count(); ++t) {
      if (in.meshes[0].material_ids[t] != m) continue;
      expected.insert(expected.end(), in.meshes[0].indices.begin() + t * 3,
                      in.meshes[0].indices.begin() + t * 3 + 3);
    }
  }
  EXPECT_EQ(out->meshes[0].indices, expected);
  EXPECT_EQ(out->meshes[1].joints, in.meshes[1].joints);
}

TEST(Pack, InvalidMeshesAreErrors) {
  Scene s = TestScene();
  s.meshes[0].positions[4] = std::nanf("");
  Result<PackResult> r = PackScene(s, FastOptions());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidMesh);
  PackOptions bad = FastOptions();
  bad.max_error = 0;
  EXPECT_FALSE(PackScene(TestScene(), bad).ok());
}

// A collapsed helper object (every triangle degenerate) is left out, not a failure of the scene;
// a scene of nothing else has nothing to pack.
TEST(Pack, MeshesWithOnlyDegenerateTrianglesAreLeftOut) {
  Scene s = TestScene();
  Mesh collapsed;
  collapsed.name = "collapsed";
  collapsed.positions = {5, 5, 5, 5, 5, 5, 5, 5, 5, 6, 5, 5};
  collapsed.indices = {0, 1, 2, 0, 1, 3};
  s.meshes.push_back(collapsed);
  s.nodes[1].meshes.push_back(2);
  Result<PackResult> r = PackScene(s, FastOptions());
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r->report.meshes.size(), 2u);
  const std::vector<std::string>& left_out = r->report.left_out;
  EXPECT_NE(std::find_if(left_out.begin(), left_out.end(),
                         [](const std::string& l) {
                           return l.find("no triangle left") != std::string::npos;
                         }),
            left_out.end());

  Scene only;
  only.meshes.push_back(collapsed);
  AddRootNodeForAllMeshes(only, "root");
  Result<PackResult> nothing = PackScene(only, FastOptions());
  ASSERT_FALSE(nothing.ok());
  EXPECT_EQ(nothing.status().code(), StatusCode::kInvalidMesh);
  EXPECT_NE(nothing.status().message().find("mesh 'collapsed': no triangle with an area"),
            std::string::npos);
}

TEST(Pack, CancelStopsIt) {
  struct Cancel : PackObserver {
    bool IsCancelled() override { return true; }
  } cancel;
  Result<PackResult> r = PackScene(TestScene(), FastOptions(), &cancel);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kCancelled);
}

// Every stage's threads (meshes and decompositions in parallel, candidate grids in parallel,
// repairs in parallel) leave the bytes as one thread writes them; the progress still reaches 1.
TEST(Pack, TheBytesDoNotDependOnTheThreadCount) {
  struct Progress : PackObserver {
    void OnProgress(double fraction, const std::string&) override {
      last = fraction;
      ++calls;
    }
    double last = -1;
    int calls = 0;
  };
  std::vector<uint8_t> first;
  for (int threads : {1, 2, 5}) {
    PackOptions options = FastOptions();
    options.collision.policy = HullPolicy::kAll;
    options.part_triangles = 300;
    options.threads = threads;
    options.collision.parameters.num_threads = static_cast<uint32_t>(threads);
    Progress progress;
    Result<PackResult> r = PackScene(TestScene(), options, &progress);
    ASSERT_TRUE(r.ok()) << r.status().message();
    EXPECT_EQ(r->report.meshes.size(), 2u);
    EXPECT_GT(r->report.meshes[0].hull_count, 0u);
    EXPECT_EQ(progress.last, 1.0);
    EXPECT_GT(progress.calls, 3);
    if (first.empty()) {
      first = r->glb;
    } else {
      EXPECT_EQ(r->glb, first) << threads << " threads";
    }
  }
}

// The stage seconds are the whole run's: none is hidden.
TEST(Pack, StageSecondsAddUpToTheTotal) {
  Result<PackResult> r = PackScene(TestScene(), FastOptions());
  ASSERT_TRUE(r.ok());
  const PackReport& p = r->report;
  const double stages = p.seconds_repair + p.seconds_prune + p.seconds_meshes + p.seconds_assemble;
  EXPECT_GT(p.seconds_total, 0);
  EXPECT_LE(stages, p.seconds_total);
  EXPECT_GT(stages, 0.95 * p.seconds_total - 1e-3);
}

}  // namespace
}  // namespace hullpack
