// The scene model: what every reader produces, every check inspects and every writer consumes.
// Plain data, no behaviour beyond size queries; the pipeline stages live in their own folders.
#ifndef HULLPACK_TOOLS_SCENE_SCENE_H_
#define HULLPACK_TOOLS_SCENE_SCENE_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hullpack {

// Column-major 4x4 matrix, as glTF stores it.
using Matrix4 = std::array<double, 16>;
constexpr Matrix4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// An image as the source file held it: encoded bytes (PNG/JPEG/...) or an external URI.
struct Image {
  std::string name;
  std::string uri;        // empty when the bytes are embedded
  std::string mime_type;  // "image/png", "image/jpeg", ... (may be empty for URIs)
  std::vector<uint8_t> bytes;
};

// How a texture is filtered and wrapped, in glTF's codes (9728 NEAREST, 9729 LINEAR, the four
// mipmap filters; 33071 CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT, 10497 REPEAT). A filter of 0 is not
// given: the viewer chooses. Pixel-art textures need NEAREST, atlases often CLAMP_TO_EDGE.
struct Sampler {
  int mag_filter = 0;
  int min_filter = 0;
  int wrap_s = 10497;
  int wrap_t = 10497;

  bool is_default() const { return *this == Sampler(); }
  bool operator==(const Sampler& o) const {
    return mag_filter == o.mag_filter && min_filter == o.min_filter && wrap_s == o.wrap_s &&
           wrap_t == o.wrap_t;
  }
  bool operator!=(const Sampler& o) const { return !(*this == o); }
};

// A reference from a material slot to an image, read through one UV set.
struct TextureRef {
  int image = -1;  // index into Scene::images; -1 = no texture in this slot
  int uv_set = 0;  // which Mesh::uv_sets entry the texture is sampled with
  Sampler sampler;
  bool used() const { return image >= 0; }
};

// glTF's alpha modes: MASK cuts away texels below alpha_cutoff (foliage, fences), BLEND mixes.
enum class AlphaMode { kOpaque, kMask, kBlend };

struct Material {
  std::string name;
  std::array<float, 4> base_color = {1, 1, 1, 1};
  float metallic = 1.0f;
  float roughness = 1.0f;
  std::array<float, 3> emissive = {0, 0, 0};
  bool double_sided = false;
  AlphaMode alpha_mode = AlphaMode::kOpaque;
  float alpha_cutoff = 0.5f;        // used by kMask
  bool unlit = false;               // KHR_materials_unlit: shaded by base colour alone
  float emissive_strength = 1.0f;   // KHR_materials_emissive_strength
  float normal_scale = 1.0f;        // normalTexture.scale
  float occlusion_strength = 1.0f;  // occlusionTexture.strength
  TextureRef base_color_texture;
  TextureRef metallic_roughness_texture;
  TextureRef normal_texture;
  TextureRef occlusion_texture;
  TextureRef emissive_texture;
};

// A morph target (blend shape): per-vertex offsets that a weight scales and adds to the mesh's
// positions and normals (glTF's primitive `targets`). positions holds 3 per vertex; normals is
// empty or 3 per vertex. Facial expressions and corrective shapes are morph targets.
struct MorphTarget {
  std::string name;  // glTF keeps it in mesh.extras.targetNames; may be empty
  std::vector<float> positions;
  std::vector<float> normals;
};

// An indexed triangle mesh. Every per-vertex array is either empty or holds exactly
// vertex_count() entries of its width; material_ids is empty or one per triangle.
struct Mesh {
  std::string name;
  std::vector<float> positions;             // 3 per vertex
  std::vector<uint32_t> indices;            // 3 per triangle
  std::vector<float> normals;               // 3 per vertex, or empty
  std::vector<float> tangents;              // 4 per vertex (xyz, handedness), or empty
  std::vector<std::vector<float>> uv_sets;  // each 2 per vertex; glTF convention (v = 0 at the top)
  std::vector<float> colors;                // 4 per vertex (RGBA, 0..1), or empty
  std::vector<uint16_t> joints;        // 4 per vertex (indices into the skin's joints), or empty
  std::vector<float> weights;          // 4 per vertex, or empty
  std::vector<uint32_t> material_ids;  // 1 per triangle (index into Scene::materials), or empty
  // Every target holds positions; either every target holds normals or none does.
  std::vector<MorphTarget> morph_targets;
  std::vector<float> morph_weights;  // the default weight of each target, or empty (all 0)
  bool collides = true;              // false when the source marks it as non-colliding

  size_t vertex_count() const { return positions.size() / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
  bool has_skin() const { return !joints.empty() && !weights.empty(); }
};

struct Skin {
  std::string name;
  std::vector<int> joints;                   // node indices
  std::vector<float> inverse_bind_matrices;  // 16 per joint (column-major), or empty
  int skeleton = -1;                         // root node, or -1
};

// A local transform as translation, rotation (unit quaternion x, y, z, w) and scale, applied
// scale first. glTF animates these three separately, so an animated node keeps them apart.
struct Trs {
  std::array<double, 3> translation = {0, 0, 0};
  std::array<double, 4> rotation = {0, 0, 0, 1};
  std::array<double, 3> scale = {1, 1, 1};
};

// A glTF camera. Perspective: yfov (radians), znear, and aspect_ratio and zfar when given (0 = not
// given: the viewport's aspect, an infinite far plane). Orthographic: xmag, ymag, znear, zfar.
struct Camera {
  std::string name;
  bool perspective = true;
  double yfov = 0.8;
  double aspect_ratio = 0;
  double xmag = 1;
  double ymag = 1;
  double znear = 0.01;
  double zfar = 0;
};

// A KHR_lights_punctual light, shining down its node's -z axis (directional and spot).
enum class LightType { kDirectional, kPoint, kSpot };
struct Light {
  std::string name;
  LightType type = LightType::kPoint;
  std::array<float, 3> color = {1, 1, 1};
  float intensity = 1;                  // candela (point, spot) or lux (directional)
  float range = 0;                      // 0 = not given: no cut-off
  float inner_cone_angle = 0;           // spot only, radians
  float outer_cone_angle = 0.7853982f;  // spot only, pi / 4 by default
};

struct Node {
  std::string name;
  int parent = -1;  // -1 for a root
  std::vector<int> children;
  Matrix4 local_transform = kIdentity;
  // The same transform as the file gave it, when it gave TRS (local_transform is then its matrix).
  std::optional<Trs> trs;
  std::vector<int> meshes;  // indices into Scene::meshes
  int skin = -1;            // index into Scene::skins, or -1
  int camera = -1;          // index into Scene::cameras, or -1
  int light = -1;           // index into Scene::lights, or -1
};

// kWeights drives the morph-target weights of the node's first mesh, and of each of its other
// meshes that has as many targets (assimp splits a mesh by material into several).
enum class AnimationPath { kTranslation, kRotation, kScale, kWeights };
enum class Interpolation { kLinear, kStep, kCubicSpline };

// Values per key of a node transform path: 3 for translation and scale, 4 for rotation (a
// quaternion). kWeights has one per morph target of the driven mesh: see ChannelWidth.
inline size_t AnimationPathWidth(AnimationPath path) {
  return path == AnimationPath::kRotation ? 4 : 3;
}

// Key frames of one animated property. values holds the channel's width of values per key, or
// three times as many with kCubicSpline (in-tangent, value, out-tangent per key, as glTF stores
// them).
struct AnimationSampler {
  std::vector<float> times;  // seconds, ascending
  std::vector<float> values;
  Interpolation interpolation = Interpolation::kLinear;
};

struct AnimationChannel {
  int sampler = 0;  // index into Animation::samplers
  int node = 0;     // index into Scene::nodes
  AnimationPath path = AnimationPath::kTranslation;
};

// A clip: channels that drive node properties from key frames, played together.
struct Animation {
  std::string name;
  std::vector<AnimationSampler> samplers;
  std::vector<AnimationChannel> channels;
};

struct Scene {
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Image> images;
  std::vector<Skin> skins;
  std::vector<Node> nodes;  // nodes[0..] in any order; roots have parent -1
  std::vector<Animation> animations;
  std::vector<Camera> cameras;
  std::vector<Light> lights;
  // What a reader could not keep, one human-readable line each ("dropped 2 animations: ...").
  std::vector<std::string> dropped;
  // Vertex records the file held (OBJ `v` lines, OFF/PLY vertices, ...) before unification; 0 =
  // unknown.
  size_t source_vertex_records = 0;

  size_t triangle_count() const {
    size_t n = 0;
    for (const Mesh& m : meshes) n += m.triangle_count();
    return n;
  }
  size_t vertex_count() const {
    size_t n = 0;
    for (const Mesh& m : meshes) n += m.vertex_count();
    return n;
  }
};

// Values per key of channel `c`: AnimationPathWidth, or for kWeights the morph-target count of the
// node's first mesh (0 when the node or mesh does not exist or has no targets).
inline size_t ChannelWidth(const Scene& scene, const AnimationChannel& c) {
  if (c.path != AnimationPath::kWeights) return AnimationPathWidth(c.path);
  if (c.node < 0 || static_cast<size_t>(c.node) >= scene.nodes.size()) return 0;
  const Node& n = scene.nodes[static_cast<size_t>(c.node)];
  if (n.meshes.empty() || n.meshes[0] < 0 ||
      static_cast<size_t>(n.meshes[0]) >= scene.meshes.size())
    return 0;
  return scene.meshes[static_cast<size_t>(n.meshes[0])].morph_targets.size();
}

// A scene with one root node that holds every mesh; what formats without a hierarchy produce.
// `name` may be the file's path: only its last component is kept, so the folders of the machine
// that packed a file never end up inside it.
inline void AddRootNodeForAllMeshes(Scene& scene, const std::string& name) {
  Node root;
  const size_t slash = name.find_last_of("/\\");
  root.name = slash == std::string::npos ? name : name.substr(slash + 1);
  for (size_t i = 0; i < scene.meshes.size(); ++i) root.meshes.push_back(static_cast<int>(i));
  scene.nodes.push_back(std::move(root));
}

// Keeps the meshes `keep` marks (one flag per mesh) and renumbers the nodes' references to them,
// dropping references to the others; returns how many meshes went.
inline size_t KeepMeshes(Scene& scene, const std::vector<bool>& keep) {
  std::vector<int> new_index(scene.meshes.size(), -1);
  std::vector<Mesh> kept;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    if (i >= keep.size() || !keep[i]) continue;
    new_index[i] = static_cast<int>(kept.size());
    kept.push_back(std::move(scene.meshes[i]));
  }
  const size_t removed = scene.meshes.size() - kept.size();
  scene.meshes = std::move(kept);
  for (Node& node : scene.nodes) {
    std::vector<int> meshes;
    for (int m : node.meshes) {
      if (m >= 0 && static_cast<size_t>(m) < new_index.size() && new_index[m] >= 0)
        meshes.push_back(new_index[m]);
    }
    node.meshes = std::move(meshes);
  }
  return removed;
}

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_SCENE_SCENE_H_
