#include "gltf/glb_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "gltf/meshopt_deflate.h"
#include "gltf/node_forest.h"
#include "scene/transform.h"

namespace hullpack {
namespace {

using nlohmann::json;

Status MeshError(size_t mesh_index, const Mesh& mesh, const std::string& what) {
  std::string label = "mesh " + std::to_string(mesh_index);
  if (!mesh.name.empty()) label += " '" + mesh.name + "'";
  return Status(StatusCode::kInvalidMesh, label + ": " + what);
}

constexpr int kMaxUvSet = 31;

Status ArgError(const std::string& what) { return Status(StatusCode::kInvalidArgument, what); }

bool AllFinite(const std::vector<float>& v) {
  for (float f : v) {
    if (!std::isfinite(f)) return false;
  }
  return true;
}

template <typename Array>
bool AllFiniteArray(const Array& v) {
  for (auto f : v) {
    if (!std::isfinite(f)) return false;
  }
  return true;
}

Status CheckPerVertex(size_t mesh_index, const Mesh& mesh, size_t got, size_t width,
                      const char* what) {
  if (got != 0 && got != width * mesh.vertex_count()) {
    return MeshError(mesh_index, mesh,
                     std::string(what) + " has " + std::to_string(got) + " values, expected " +
                         std::to_string(width * mesh.vertex_count()) + " (" +
                         std::to_string(width) + " per vertex) or none");
  }
  return Status::Ok();
}

Status CheckTextureRef(const Scene& scene, size_t material_index, const TextureRef& ref,
                       const char* slot) {
  if (!ref.used()) return Status::Ok();
  if (static_cast<size_t>(ref.image) >= scene.images.size()) {
    return ArgError("material " + std::to_string(material_index) + " " + slot +
                    " references image " + std::to_string(ref.image) + " of " +
                    std::to_string(scene.images.size()));
  }
  if (ref.uv_set < 0 || ref.uv_set > kMaxUvSet) {
    return ArgError("material " + std::to_string(material_index) + " " + slot + " has uv set " +
                    std::to_string(ref.uv_set));
  }
  return Status::Ok();
}

std::vector<uint8_t> Bytes(const void* data, size_t size) {
  const uint8_t* p = static_cast<const uint8_t*>(data);
  return std::vector<uint8_t>(p, p + size);
}

// Adds a tightly packed vertex-attribute bufferView + accessor for `values` (`width` per vertex);
// without `write_data`, the accessor alone.
int AddFloatAttribute(GltfDocument* doc, const std::vector<float>& values, int width,
                      const char* type, bool with_bounds, bool write_data) {
  AccessorDesc desc;
  if (write_data) {
    desc.buffer_view =
        doc->AddBufferView(values.data(), values.size() * sizeof(float), 4, gltf::kArrayBuffer);
  }
  desc.component_type = gltf::kFloat;
  desc.count = values.size() / static_cast<size_t>(width);
  desc.type = type;
  if (with_bounds) {
    desc.min.assign(static_cast<size_t>(width), std::numeric_limits<double>::infinity());
    desc.max.assign(static_cast<size_t>(width), -std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < values.size(); ++i) {
      const size_t c = i % static_cast<size_t>(width);
      desc.min[c] = std::min(desc.min[c], static_cast<double>(values[i]));
      desc.max[c] = std::max(desc.max[c], static_cast<double>(values[i]));
    }
  }
  return doc->AddAccessor(desc);
}

// One glTF texture per image and sampler, one glTF sampler per distinct non-default sampler (a
// texture without one gets glTF's default: repeat, filters left to the viewer).
class TextureTable {
 public:
  explicit TextureTable(GltfDocument* doc) : doc_(doc) {}

  json Info(const TextureRef& ref) {
    const Key key = {ref.image, ref.sampler.mag_filter, ref.sampler.min_filter, ref.sampler.wrap_s,
                     ref.sampler.wrap_t};
    auto it = textures_.find(key);
    int texture;
    if (it != textures_.end()) {
      texture = it->second;
    } else {
      json j = {{"source", ref.image}};
      if (!ref.sampler.is_default()) j["sampler"] = SamplerIndex(ref.sampler);
      texture = doc_->Append("textures", std::move(j));
      textures_.emplace(key, texture);
    }
    json info = {{"index", texture}};
    if (ref.uv_set != 0) info["texCoord"] = ref.uv_set;
    return info;
  }

 private:
  using Key = std::array<int, 5>;

  int SamplerIndex(const Sampler& s) {
    const Key key = {0, s.mag_filter, s.min_filter, s.wrap_s, s.wrap_t};
    auto it = samplers_.find(key);
    if (it != samplers_.end()) return it->second;
    json j = json::object();
    if (s.mag_filter != 0) j["magFilter"] = s.mag_filter;
    if (s.min_filter != 0) j["minFilter"] = s.min_filter;
    if (s.wrap_s != 10497) j["wrapS"] = s.wrap_s;
    if (s.wrap_t != 10497) j["wrapT"] = s.wrap_t;
    const int index = doc_->Append("samplers", std::move(j));
    samplers_.emplace(key, index);
    return index;
  }

  GltfDocument* doc_;
  std::map<Key, int> textures_;
  std::map<Key, int> samplers_;
};

const char* AlphaModeName(AlphaMode mode) {
  switch (mode) {
    case AlphaMode::kMask:
      return "MASK";
    case AlphaMode::kBlend:
      return "BLEND";
    case AlphaMode::kOpaque:
      break;
  }
  return "OPAQUE";
}

const char* PathName(AnimationPath path) {
  switch (path) {
    case AnimationPath::kRotation:
      return "rotation";
    case AnimationPath::kScale:
      return "scale";
    case AnimationPath::kWeights:
      return "weights";
    case AnimationPath::kTranslation:
      break;
  }
  return "translation";
}

const char* InterpolationName(Interpolation interpolation) {
  switch (interpolation) {
    case Interpolation::kStep:
      return "STEP";
    case Interpolation::kCubicSpline:
      return "CUBICSPLINE";
    case Interpolation::kLinear:
      break;
  }
  return "LINEAR";
}

// The node's transform as glTF JSON members: TRS when the scene kept it or an animation drives the
// node (glTF animates TRS only), else a matrix; nothing for the identity.
void WriteTransform(const Node& n, bool animated, json* j) {
  std::optional<Trs> trs = n.trs;
  Trs decomposed;
  if (!trs && animated && DecomposeMatrix(n.local_transform, &decomposed)) trs = decomposed;
  if (trs) {
    if (trs->translation != Trs().translation) (*j)["translation"] = trs->translation;
    if (trs->rotation != Trs().rotation) (*j)["rotation"] = trs->rotation;
    if (trs->scale != Trs().scale) (*j)["scale"] = trs->scale;
  } else if (n.local_transform != kIdentity) {
    (*j)["matrix"] = n.local_transform;
  }
}

// Animations as glTF. The key data goes into three bufferViews (key times, float values, and
// rotations as normalized shorts) with one accessor per array, instead of a view per accessor:
// clips hold dozens of small tracks, whose JSON would otherwise outweigh their bytes. Samplers with
// equal key times share one input accessor (its min/max, which glTF requires, included).
class AnimationWriter {
 public:
  AnimationWriter(const Scene& scene, const GlbWriteOptions& options)
      : scene_(scene),
        quantize_rotations_(options.quantize_rotations),
        compress_(options.compress_animations) {}

  // `gltf_node`: the glTF node of each scene node. `extra_mesh_nodes`: per scene node, the glTF
  // nodes of its meshes after the first (with the scene mesh each shows): a weights channel
  // drives each of them whose mesh has as many targets as the node's first, as it does in the
  // scene.
  void Write(const std::vector<int>& gltf_node,
             const std::vector<std::vector<std::pair<int, int>>>& extra_mesh_nodes,
             GltfDocument* doc, GltfSceneLayout* layout) {
    struct PendingSampler {
      int input, output;
      Interpolation interpolation;
    };
    std::vector<std::vector<PendingSampler>> samplers(scene_.animations.size());
    std::vector<std::vector<int>> sampler_index(scene_.animations.size());
    for (size_t ai = 0; ai < scene_.animations.size(); ++ai) {
      const Animation& a = scene_.animations[ai];
      sampler_index[ai].assign(a.samplers.size(), -1);
      for (const AnimationChannel& c : a.channels) {
        const size_t si = static_cast<size_t>(c.sampler);
        if (sampler_index[ai][si] >= 0) continue;
        const AnimationSampler& s = a.samplers[si];
        sampler_index[ai][si] = static_cast<int>(samplers[ai].size());
        samplers[ai].push_back({TimesAccessor(s.times),
                                ValuesAccessor(s, c.path, ChannelWidth(scene_, c)),
                                s.interpolation});
      }
    }
    int views[kKinds];
    Compress();
    for (int k = 0; k < kKinds; ++k) {
      const Kind kind = static_cast<Kind>(k);
      views[k] = AddView(kind, doc);
      const size_t plain = values_[kind].size() / kFloatsPer[kind] * kStride[kind];
      layout->key_frame_bytes += plain;
      layout->key_frame_stored_bytes += encoded_[kind].empty() ? plain : encoded_[kind].size();
    }
    std::vector<int> accessor_index;
    for (Pending& p : pending_) {
      p.desc.buffer_view = views[p.kind];
      accessor_index.push_back(doc->AddAccessor(p.desc));
    }
    for (size_t ai = 0; ai < scene_.animations.size(); ++ai) {
      const Animation& a = scene_.animations[ai];
      if (a.channels.empty()) continue;
      json sampler_json = json::array();
      for (const PendingSampler& p : samplers[ai]) {
        json sj = {{"input", accessor_index[static_cast<size_t>(p.input)]},
                   {"output", accessor_index[static_cast<size_t>(p.output)]}};
        if (p.interpolation != Interpolation::kLinear)
          sj["interpolation"] = InterpolationName(p.interpolation);
        sampler_json.push_back(std::move(sj));
      }
      json channels = json::array();
      for (const AnimationChannel& c : a.channels) {
        const int sampler = sampler_index[ai][static_cast<size_t>(c.sampler)];
        channels.push_back(
            {{"sampler", sampler},
             {"target",
              {{"node", gltf_node[static_cast<size_t>(c.node)]}, {"path", PathName(c.path)}}}});
        if (c.path != AnimationPath::kWeights) continue;
        const size_t width = ChannelWidth(scene_, c);
        for (const auto& [node, mesh] : extra_mesh_nodes[static_cast<size_t>(c.node)]) {
          if (scene_.meshes[static_cast<size_t>(mesh)].morph_targets.size() != width) continue;
          channels.push_back(
              {{"sampler", sampler}, {"target", {{"node", node}, {"path", PathName(c.path)}}}});
        }
      }
      json j = {{"samplers", std::move(sampler_json)}, {"channels", std::move(channels)}};
      if (!a.name.empty()) j["name"] = a.name;
      doc->Append("animations", std::move(j));
    }
  }

 private:
  // The key-frame data goes to one bufferView per kind of element, so that each view has one
  // element size (what EXT_meshopt_compression's codec needs) and an accessor is a run of elements.
  enum Kind { kTimes, kScalars, kVec3, kVec4, kRotations, kKinds };
  // Floats per element, as the scene holds them.
  static constexpr size_t kFloatsPer[kKinds] = {1, 1, 3, 4, 4};
  // Bytes per element in the file: rotations are normalized shorts.
  static constexpr size_t kStride[kKinds] = {4, 4, 12, 16, 8};

  struct Pending {
    Kind kind;
    AccessorDesc desc;
  };

  // The elements of `kind` as a plain file stores them.
  std::vector<uint8_t> PlainBytes(Kind kind) const {
    const std::vector<float>& v = values_[kind];
    std::vector<uint8_t> bytes(v.size() / kFloatsPer[kind] * kStride[kind]);
    if (kind != kRotations) {
      std::memcpy(bytes.data(), v.data(), bytes.size());
      return bytes;
    }
    std::vector<int16_t> q(v.size());
    for (size_t k = 0; k < v.size(); k += 4) {
      const double n = std::sqrt(double(v[k]) * v[k] + double(v[k + 1]) * v[k + 1] +
                                 double(v[k + 2]) * v[k + 2] + double(v[k + 3]) * v[k + 3]);
      for (size_t c = 0; c < 4; ++c) {
        const double x = n > 0 ? v[k + c] / n : (c == 3 ? 1.0 : 0.0);
        q[k + c] = static_cast<int16_t>(std::lround(std::clamp(x, -1.0, 1.0) * 32767.0));
      }
    }
    std::memcpy(bytes.data(), q.data(), bytes.size());
    return bytes;
  }

  // With compress_animations, the kinds whose elements are smaller compressed with meshoptimizer
  // (key times exactly; rotations through the quaternion filter, other values the exponential one)
  // get their encoded bytes in encoded_, when the file as a whole gets smaller.
  void Compress() {
    if (!compress_) return;
    size_t saved = 0;
    for (int k = 0; k < kKinds; ++k) {
      const Kind kind = static_cast<Kind>(k);
      const std::vector<float>& v = values_[kind];
      if (v.empty()) continue;
      const size_t count = v.size() / kFloatsPer[kind];
      filter_[kind] = kind == kTimes       ? MeshoptFilter::kNone
                      : kind == kRotations ? MeshoptFilter::kQuaternion
                                           : MeshoptFilter::kExponential;
      const std::vector<uint8_t> stored =
          filter_[kind] == MeshoptFilter::kNone
              ? PlainBytes(kind)
              : ApplyMeshoptFilter(filter_[kind], v.data(), count, kStride[kind]);
      encoded_[kind] = EncodeMeshoptAttributes(stored, kStride[kind]);
      const size_t plain = count * kStride[kind];
      if (encoded_[kind].size() + kMeshoptViewJsonBytes < plain) {
        saved += plain - encoded_[kind].size() - kMeshoptViewJsonBytes;
      } else {
        encoded_[kind].clear();
      }
    }
    if (saved <= kMeshoptFileJsonBytes) {
      for (auto& e : encoded_) e.clear();
    }
  }

  int AddView(Kind kind, GltfDocument* doc) const {
    if (values_[kind].empty()) return -1;
    if (!encoded_[kind].empty()) {
      return AddMeshoptBufferView(*doc, encoded_[kind], values_[kind].size() / kFloatsPer[kind],
                                  kStride[kind], filter_[kind]);
    }
    return doc->AddBufferView(PlainBytes(kind), 4);
  }

  int Add(Kind kind, const std::vector<float>& values, AccessorDesc desc) {
    std::vector<float>& v = values_[kind];
    desc.byte_offset = v.size() / kFloatsPer[kind] * kStride[kind];
    v.insert(v.end(), values.begin(), values.end());
    pending_.push_back({kind, std::move(desc)});
    return static_cast<int>(pending_.size() - 1);
  }

  int TimesAccessor(const std::vector<float>& times) {
    auto known = times_.find(times);
    if (known != times_.end()) return known->second;
    AccessorDesc desc;
    desc.count = times.size();
    desc.min = {times.front()};
    desc.max = {times.back()};
    const int index = Add(kTimes, times, desc);
    times_.emplace(times, index);
    return index;
  }

  int ValuesAccessor(const AnimationSampler& s, AnimationPath path, size_t width) {
    AccessorDesc desc;
    if (path == AnimationPath::kWeights) {  // one SCALAR per target and key
      desc.count = s.values.size();
      desc.type = "SCALAR";
      return Add(kScalars, s.values, desc);
    }
    desc.count = s.values.size() / width;
    desc.type = width == 4 ? "VEC4" : "VEC3";
    // Cubic-spline tangents may exceed 1, which a normalized short cannot hold.
    if (path == AnimationPath::kRotation && quantize_rotations_ &&
        s.interpolation != Interpolation::kCubicSpline) {
      desc.component_type = gltf::kShort;
      desc.normalized = true;
      return Add(kRotations, s.values, desc);
    }
    return Add(width == 4 ? kVec4 : kVec3, s.values, desc);
  }

  const Scene& scene_;
  const bool quantize_rotations_;
  const bool compress_;
  std::vector<float> values_[kKinds];
  std::vector<uint8_t> encoded_[kKinds];  // compressed elements, or empty for plain ones
  MeshoptFilter filter_[kKinds] = {};
  std::vector<Pending> pending_;
  std::map<std::vector<float>, int> times_;
};

// Makes an image reference a valid URI without changing one that already is: backslashes become
// '/', and bytes that may never appear in a URI (controls, space, "<>\^`{|}, non-ASCII) are
// percent-encoded. '%' is left alone, so an already encoded URI passes through unchanged.
std::string EscapeUri(const std::string& uri) {
  static const char* kHex = "0123456789ABCDEF";
  std::string out;
  for (char ch : uri) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == '\\') {
      out.push_back('/');
    } else if (c <= 0x20 || c >= 0x7F || std::strchr("\"<>^`{|}", c) != nullptr) {
      out.push_back('%');
      out.push_back(kHex[c >> 4]);
      out.push_back(kHex[c & 15]);
    } else {
      out.push_back(static_cast<char>(c));
    }
  }
  return out;
}

// UV sets the materials used by `m` sample (the highest texCoord + 1), at least m.uv_sets.size().
size_t UvSetsNeeded(const Scene& scene, const Mesh& m) {
  size_t needed = m.uv_sets.size();
  std::vector<bool> used(scene.materials.size(), false);
  for (uint32_t id : m.material_ids) used[id] = true;
  for (size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) continue;
    const Material& mat = scene.materials[i];
    for (const TextureRef* ref :
         {&mat.base_color_texture, &mat.metallic_roughness_texture, &mat.normal_texture,
          &mat.occlusion_texture, &mat.emissive_texture}) {
      if (ref->used()) needed = std::max(needed, static_cast<size_t>(ref->uv_set) + 1);
    }
  }
  return needed;
}

void WriteCamerasAndLights(const Scene& scene, GltfDocument* doc) {
  for (const Camera& c : scene.cameras) {
    json j = json::object();
    if (!c.name.empty()) j["name"] = c.name;
    if (c.perspective) {
      json p = {{"yfov", c.yfov}, {"znear", c.znear}};
      if (c.aspect_ratio > 0) p["aspectRatio"] = c.aspect_ratio;
      if (c.zfar > 0) p["zfar"] = c.zfar;
      j["type"] = "perspective";
      j["perspective"] = std::move(p);
    } else {
      j["type"] = "orthographic";
      j["orthographic"] = {
          {"xmag", c.xmag}, {"ymag", c.ymag}, {"znear", c.znear}, {"zfar", c.zfar}};
    }
    doc->Append("cameras", std::move(j));
  }
  if (scene.lights.empty()) return;
  json lights = json::array();
  for (const Light& l : scene.lights) {
    static const char* kType[] = {"directional", "point", "spot"};
    json j = {{"type", kType[static_cast<int>(l.type)]}};
    if (!l.name.empty()) j["name"] = l.name;
    if (l.color != std::array<float, 3>{1, 1, 1}) j["color"] = l.color;
    if (l.intensity != 1) j["intensity"] = l.intensity;
    if (l.range > 0 && l.type != LightType::kDirectional) j["range"] = l.range;
    if (l.type == LightType::kSpot) {
      j["spot"] = {{"innerConeAngle", l.inner_cone_angle}, {"outerConeAngle", l.outer_cone_angle}};
    }
    lights.push_back(std::move(j));
  }
  doc->json()["extensions"]["KHR_lights_punctual"]["lights"] = std::move(lights);
  doc->UseExtension("KHR_lights_punctual", false);
}

Status CheckCamerasAndLights(const Scene& scene) {
  for (size_t i = 0; i < scene.cameras.size(); ++i) {
    const Camera& c = scene.cameras[i];
    const bool valid =
        c.perspective
            ? c.yfov > 0 && c.znear > 0 && c.aspect_ratio >= 0 && (c.zfar == 0 || c.zfar > c.znear)
            : c.xmag != 0 && c.ymag != 0 && c.znear >= 0 && c.zfar > c.znear;
    if (!valid || !std::isfinite(c.yfov + c.aspect_ratio + c.xmag + c.ymag + c.znear + c.zfar))
      return ArgError("camera " + std::to_string(i) +
                      " has invalid or non-finite projection values");
  }
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    if (!AllFiniteArray(l.color) || !std::isfinite(l.intensity) || !std::isfinite(l.range) ||
        l.intensity < 0 || l.range < 0 ||
        (l.type == LightType::kSpot &&
         !(l.inner_cone_angle >= 0 && l.inner_cone_angle < l.outer_cone_angle &&
           l.outer_cone_angle <= 1.5707964f))) {
      return ArgError("light " + std::to_string(i) + " has invalid or non-finite values");
    }
  }
  for (size_t i = 0; i < scene.nodes.size(); ++i) {
    const Node& n = scene.nodes[i];
    if (n.camera < -1 || n.camera >= static_cast<int>(scene.cameras.size()))
      return ArgError("node " + std::to_string(i) + " references camera " +
                      std::to_string(n.camera));
    if (n.light < -1 || n.light >= static_cast<int>(scene.lights.size()))
      return ArgError("node " + std::to_string(i) + " references light " + std::to_string(n.light));
  }
  return Status::Ok();
}

Status CheckSampler(const AnimationSampler& s, size_t width, const std::string& label) {
  if (s.times.empty()) return ArgError(label + " has no key frames");
  for (size_t k = 0; k < s.times.size(); ++k) {
    if (!std::isfinite(s.times[k]) || s.times[k] < 0 || (k > 0 && !(s.times[k] > s.times[k - 1])))
      return ArgError(label + " key time " + std::to_string(k) +
                      " is not finite, negative or not ascending");
  }
  const size_t per_key = (s.interpolation == Interpolation::kCubicSpline ? 3 : 1) * width;
  if (s.values.size() != s.times.size() * per_key) {
    return ArgError(label + " has " + std::to_string(s.values.size()) + " values for " +
                    std::to_string(s.times.size()) + " keys of " + std::to_string(per_key));
  }
  if (!AllFinite(s.values)) return ArgError(label + " holds a NaN or infinite value");
  return Status::Ok();
}

}  // namespace

Status ValidateAnimation(const Scene& scene, size_t index) {
  const Animation& a = scene.animations[index];
  const std::string label = "animation " + std::to_string(index);
  // Per sampler the values per key and whether they are weights (SCALAR accessors, where
  // transforms are VEC3/VEC4: a sampler serves one kind); width 0 = unused.
  std::vector<std::pair<size_t, bool>> width(a.samplers.size(), {0, false});
  std::map<std::pair<int, int>, size_t> targets;
  for (size_t c = 0; c < a.channels.size(); ++c) {
    const AnimationChannel& ch = a.channels[c];
    const std::string cl = label + " channel " + std::to_string(c);
    if (ch.sampler < 0 || static_cast<size_t>(ch.sampler) >= a.samplers.size())
      return ArgError(cl + " uses sampler " + std::to_string(ch.sampler));
    if (ch.node < 0 || static_cast<size_t>(ch.node) >= scene.nodes.size())
      return ArgError(cl + " targets node " + std::to_string(ch.node));
    if (!targets.emplace(std::make_pair(ch.node, static_cast<int>(ch.path)), c).second)
      return ArgError(cl + " repeats the node and path of another channel");
    const bool weights = ch.path == AnimationPath::kWeights;
    const std::pair<size_t, bool> kind = {ChannelWidth(scene, ch), weights};
    if (kind.first == 0)
      return ArgError(cl + " drives the morph weights of node " + std::to_string(ch.node) +
                      ", whose first mesh has no morph targets");
    std::pair<size_t, bool>& w = width[static_cast<size_t>(ch.sampler)];
    if (w.first != 0 && w != kind)
      return ArgError(cl + " uses a sampler for values of another width");
    w = kind;
    const Node& node = scene.nodes[static_cast<size_t>(ch.node)];
    Trs trs;
    if (!weights && !node.trs && !DecomposeMatrix(node.local_transform, &trs)) {
      return ArgError(cl + " animates node " + std::to_string(ch.node) +
                      ", whose matrix has no translation-rotation-scale form");
    }
  }
  for (size_t s = 0; s < a.samplers.size(); ++s) {
    if (width[s].first == 0) continue;  // unused: not written
    Status st =
        CheckSampler(a.samplers[s], width[s].first, label + " sampler " + std::to_string(s));
    if (!st.ok()) return st;
  }
  return Status::Ok();
}

std::string SniffImageMime(const std::vector<uint8_t>& b) {
  static const uint8_t kPng[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  if (b.size() >= 8 && std::equal(kPng, kPng + 8, b.begin())) return "image/png";
  if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return "image/jpeg";
  if (b.size() >= 12 && std::equal(b.begin(), b.begin() + 4, "RIFF") &&
      std::equal(b.begin() + 8, b.begin() + 12, "WEBP")) {
    return "image/webp";
  }
  return "";
}

Status ValidateSceneForGltf(const Scene& scene) {
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    const Mesh& m = scene.meshes[mi];
    if (m.positions.size() % 3 != 0) return MeshError(mi, m, "positions is not a multiple of 3");
    const size_t vc = m.vertex_count();
    if (vc == 0) return MeshError(mi, m, "no vertices (glTF has no empty meshes)");
    if (vc > std::numeric_limits<uint32_t>::max())
      return MeshError(mi, m, "more than 2^32-1 vertices");
    if (m.indices.empty() || m.indices.size() % 3 != 0) {
      return MeshError(
          mi, m,
          "indices must be a non-empty multiple of 3, got " + std::to_string(m.indices.size()));
    }
    for (size_t i = 0; i < m.indices.size(); ++i) {
      if (m.indices[i] >= vc) {
        return MeshError(mi, m,
                         "index " + std::to_string(i) + " is " + std::to_string(m.indices[i]) +
                             " but there are " + std::to_string(vc) + " vertices");
      }
    }
    Status s = CheckPerVertex(mi, m, m.normals.size(), 3, "normals");
    if (s.ok()) s = CheckPerVertex(mi, m, m.tangents.size(), 4, "tangents");
    if (s.ok()) s = CheckPerVertex(mi, m, m.colors.size(), 4, "colors");
    if (s.ok()) s = CheckPerVertex(mi, m, m.joints.size(), 4, "joints");
    if (s.ok()) s = CheckPerVertex(mi, m, m.weights.size(), 4, "weights");
    for (size_t u = 0; s.ok() && u < m.uv_sets.size(); ++u) {
      if (m.uv_sets[u].size() != 2 * vc) {
        s = MeshError(mi, m,
                      "uv set " + std::to_string(u) + " has " +
                          std::to_string(m.uv_sets[u].size()) + " values, expected " +
                          std::to_string(2 * vc));
      }
    }
    if (!s.ok()) return s;
    if (m.joints.empty() != m.weights.empty()) {
      return MeshError(mi, m, "joints and weights must both be present or both be absent");
    }
    for (size_t t = 0; t < m.morph_targets.size(); ++t) {
      const MorphTarget& target = m.morph_targets[t];
      const std::string name = "morph target " + std::to_string(t);
      if (target.positions.size() != 3 * vc)
        return MeshError(mi, m,
                         name + " has " + std::to_string(target.positions.size()) +
                             " position offsets, expected " + std::to_string(3 * vc));
      if (target.normals.size() != (m.morph_targets[0].normals.empty() ? 0 : 3 * vc))
        return MeshError(mi, m, name + ": every target or none must have normal offsets");
      if (!target.normals.empty() && m.normals.empty())
        return MeshError(mi, m, name + " has normal offsets but the mesh has no normals");
      if (!AllFinite(target.positions) || !AllFinite(target.normals))
        return MeshError(mi, m, name + " holds NaN or infinity");
    }
    if (!m.morph_weights.empty() &&
        (m.morph_weights.size() != m.morph_targets.size() || !AllFinite(m.morph_weights))) {
      return MeshError(mi, m, "morph weights must be one finite number per morph target");
    }
    bool finite = AllFinite(m.positions) && AllFinite(m.normals) && AllFinite(m.tangents) &&
                  AllFinite(m.colors) && AllFinite(m.weights);
    for (const auto& uv : m.uv_sets) finite = finite && AllFinite(uv);
    if (!finite) return MeshError(mi, m, "a vertex attribute holds NaN or infinity");
    if (!m.material_ids.empty()) {
      if (m.material_ids.size() != m.triangle_count()) {
        return MeshError(mi, m,
                         "material_ids has " + std::to_string(m.material_ids.size()) +
                             " entries for " + std::to_string(m.triangle_count()) + " triangles");
      }
      for (size_t t = 0; t < m.material_ids.size(); ++t) {
        if (m.material_ids[t] >= scene.materials.size()) {
          return MeshError(mi, m,
                           "triangle " + std::to_string(t) + " uses material " +
                               std::to_string(m.material_ids[t]) + " of " +
                               std::to_string(scene.materials.size()));
        }
      }
    }
  }
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& mat = scene.materials[i];
    if (!AllFiniteArray(mat.base_color) || !AllFiniteArray(mat.emissive) ||
        !std::isfinite(mat.metallic) || !std::isfinite(mat.roughness) ||
        !std::isfinite(mat.normal_scale) || !std::isfinite(mat.occlusion_strength)) {
      return ArgError("material " + std::to_string(i) + " has a NaN or infinite factor");
    }
    if (!(mat.alpha_cutoff >= 0) || !std::isfinite(mat.alpha_cutoff) ||
        !(mat.emissive_strength >= 0) || !std::isfinite(mat.emissive_strength)) {
      return ArgError("material " + std::to_string(i) +
                      " has a negative or non-finite alpha cutoff or emissive strength");
    }
    Status s = CheckTextureRef(scene, i, mat.base_color_texture, "base colour texture");
    if (s.ok())
      s = CheckTextureRef(scene, i, mat.metallic_roughness_texture, "metallic-roughness texture");
    if (s.ok()) s = CheckTextureRef(scene, i, mat.normal_texture, "normal texture");
    if (s.ok()) s = CheckTextureRef(scene, i, mat.occlusion_texture, "occlusion texture");
    if (s.ok()) s = CheckTextureRef(scene, i, mat.emissive_texture, "emissive texture");
    if (!s.ok()) return s;
  }
  for (size_t i = 0; i < scene.images.size(); ++i) {
    const Image& img = scene.images[i];
    if (img.uri.empty() && img.bytes.empty()) {
      return ArgError("image " + std::to_string(i) + " has neither bytes nor a uri");
    }
    if (img.uri.empty() && img.mime_type.empty() && SniffImageMime(img.bytes).empty()) {
      return ArgError("image " + std::to_string(i) +
                      " has no mime type and is neither PNG, JPEG nor WebP");
    }
  }
  const size_t node_count = scene.nodes.size();
  for (size_t i = 0; i < scene.skins.size(); ++i) {
    const Skin& skin = scene.skins[i];
    if (skin.joints.empty()) return ArgError("skin " + std::to_string(i) + " has no joints");
    std::vector<bool> seen(node_count, false);
    for (int j : skin.joints) {
      if (j < 0 || static_cast<size_t>(j) >= node_count) {
        return ArgError("skin " + std::to_string(i) + " joint " + std::to_string(j) +
                        " is not a node");
      }
      if (seen[static_cast<size_t>(j)]) {
        return ArgError("skin " + std::to_string(i) + " lists node " + std::to_string(j) +
                        " twice");
      }
      seen[static_cast<size_t>(j)] = true;
    }
    if (!skin.inverse_bind_matrices.empty() &&
        skin.inverse_bind_matrices.size() != 16 * skin.joints.size()) {
      return ArgError("skin " + std::to_string(i) + " has " +
                      std::to_string(skin.inverse_bind_matrices.size()) +
                      " inverse bind matrix values for " + std::to_string(skin.joints.size()) +
                      " joints");
    }
    if (!AllFinite(skin.inverse_bind_matrices)) {
      return ArgError("skin " + std::to_string(i) + " has a NaN or infinite inverse bind matrix");
    }
    if (skin.skeleton < -1 || skin.skeleton >= static_cast<int>(node_count)) {
      return ArgError("skin " + std::to_string(i) + " skeleton " + std::to_string(skin.skeleton) +
                      " is not a node");
    }
  }
  for (size_t i = 0; i < node_count; ++i) {
    const Node& n = scene.nodes[i];
    const std::string label = "node " + std::to_string(i);
    for (int m : n.meshes) {
      if (m < 0 || static_cast<size_t>(m) >= scene.meshes.size()) {
        return ArgError(label + " references mesh " + std::to_string(m));
      }
    }
    if (n.skin != -1) {
      if (n.skin < 0 || static_cast<size_t>(n.skin) >= scene.skins.size()) {
        return ArgError(label + " references skin " + std::to_string(n.skin));
      }
      if (n.meshes.empty()) return ArgError(label + " has a skin but no mesh");
      const size_t joint_count = scene.skins[static_cast<size_t>(n.skin)].joints.size();
      for (int m : n.meshes) {
        for (uint16_t j : scene.meshes[static_cast<size_t>(m)].joints) {
          if (j >= joint_count) {
            return ArgError(label + " skins mesh " + std::to_string(m) + " whose joint index " +
                            std::to_string(j) + " exceeds the skin's " +
                            std::to_string(joint_count) + " joints");
          }
        }
      }
    }
    if (!AllFiniteArray(n.local_transform))
      return ArgError(label + " has a NaN or infinite transform");
    if (n.parent < -1 || n.parent >= static_cast<int>(node_count)) {
      return ArgError(label + " has parent " + std::to_string(n.parent));
    }
    for (int c : n.children) {
      if (c < 0 || static_cast<size_t>(c) >= node_count) {
        return ArgError(label + " has child " + std::to_string(c));
      }
      if (scene.nodes[static_cast<size_t>(c)].parent != static_cast<int>(i)) {
        return ArgError(label + " lists child " + std::to_string(c) + " whose parent is " +
                        std::to_string(scene.nodes[static_cast<size_t>(c)].parent));
      }
    }
  }
  // Each non-root is listed exactly once, by its parent (children entries were checked above).
  std::vector<size_t> listed(node_count, 0);
  for (const Node& n : scene.nodes) {
    for (int c : n.children) ++listed[static_cast<size_t>(c)];
  }
  for (size_t i = 0; i < node_count; ++i) {
    const size_t expected = scene.nodes[i].parent >= 0 ? 1 : 0;
    if (listed[i] != expected) {
      return ArgError("node " + std::to_string(i) + " has parent " +
                      std::to_string(scene.nodes[i].parent) + " but is listed as a child " +
                      std::to_string(listed[i]) + " times");
    }
  }
  const int on_cycle = gltf_internal::FirstNodeOnCycle(scene.nodes);
  if (on_cycle >= 0)
    return ArgError("the node hierarchy has a cycle through node " + std::to_string(on_cycle));
  for (size_t i = 0; i < scene.animations.size(); ++i) {
    Status s = ValidateAnimation(scene, i);
    if (!s.ok()) return s;
  }
  return CheckCamerasAndLights(scene);
}

Status BuildGltfDocument(const Scene& scene, const GlbWriteOptions& options, GltfDocument* doc,
                         GltfSceneLayout* layout) {
  Status valid = ValidateSceneForGltf(scene);
  if (!valid.ok()) return valid;
  GltfSceneLayout local_layout;
  GltfSceneLayout& out = layout != nullptr ? *layout : local_layout;
  out = GltfSceneLayout();

  json& root = doc->json();
  root["asset"] = json{{"version", "2.0"}, {"generator", options.generator}};

  // Images.
  for (const Image& img : scene.images) {
    json j = json::object();
    if (!img.name.empty()) j["name"] = img.name;
    if (!img.uri.empty()) {
      j["uri"] = EscapeUri(img.uri);
      if (!img.mime_type.empty()) j["mimeType"] = img.mime_type;
    } else {
      j["bufferView"] = doc->AddBufferView(img.bytes, 4);
      j["mimeType"] = img.mime_type.empty() ? SniffImageMime(img.bytes) : img.mime_type;
    }
    doc->Append("images", std::move(j));
  }

  // Materials (textures are created on first use, one per image and sampler).
  TextureTable textures(doc);
  for (const Material& mat : scene.materials) {
    json j = json::object();
    if (!mat.name.empty()) j["name"] = mat.name;
    json pbr = {{"baseColorFactor", mat.base_color},
                {"metallicFactor", mat.metallic},
                {"roughnessFactor", mat.roughness}};
    if (mat.base_color_texture.used()) {
      pbr["baseColorTexture"] = textures.Info(mat.base_color_texture);
    }
    if (mat.metallic_roughness_texture.used()) {
      pbr["metallicRoughnessTexture"] = textures.Info(mat.metallic_roughness_texture);
    }
    j["pbrMetallicRoughness"] = std::move(pbr);
    if (mat.normal_texture.used()) {
      j["normalTexture"] = textures.Info(mat.normal_texture);
      if (mat.normal_scale != 1.0f) j["normalTexture"]["scale"] = mat.normal_scale;
    }
    if (mat.occlusion_texture.used()) {
      j["occlusionTexture"] = textures.Info(mat.occlusion_texture);
      if (mat.occlusion_strength != 1.0f)
        j["occlusionTexture"]["strength"] = mat.occlusion_strength;
    }
    if (mat.emissive_texture.used()) j["emissiveTexture"] = textures.Info(mat.emissive_texture);
    if (mat.emissive != std::array<float, 3>{0, 0, 0}) j["emissiveFactor"] = mat.emissive;
    if (mat.double_sided) j["doubleSided"] = true;
    if (mat.alpha_mode != AlphaMode::kOpaque) j["alphaMode"] = AlphaModeName(mat.alpha_mode);
    if (mat.alpha_mode == AlphaMode::kMask && mat.alpha_cutoff != 0.5f)
      j["alphaCutoff"] = mat.alpha_cutoff;
    if (mat.unlit) {
      j["extensions"]["KHR_materials_unlit"] = json::object();
      doc->UseExtension("KHR_materials_unlit", false);
    }
    if (mat.emissive_strength != 1.0f) {
      j["extensions"]["KHR_materials_emissive_strength"] = {
          {"emissiveStrength", mat.emissive_strength}};
      doc->UseExtension("KHR_materials_emissive_strength", false);
    }
    doc->Append("materials", std::move(j));
  }

  // Meshes.
  out.meshes.resize(scene.meshes.size());
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    const Mesh& m = scene.meshes[mi];
    GltfSceneLayout::MeshLayout& ml = out.meshes[mi];
    const size_t vc = m.vertex_count();
    const bool write_data = mi >= options.data_elsewhere.size() || !options.data_elsewhere[mi];
    json attributes = json::object();
    ml.position_accessor = AddFloatAttribute(doc, m.positions, 3, "VEC3", true, write_data);
    attributes["POSITION"] = ml.position_accessor;
    if (!m.normals.empty())
      attributes["NORMAL"] = AddFloatAttribute(doc, m.normals, 3, "VEC3", false, write_data);
    if (!m.tangents.empty())
      attributes["TANGENT"] = AddFloatAttribute(doc, m.tangents, 4, "VEC4", false, write_data);
    for (size_t u = 0; u < m.uv_sets.size(); ++u) {
      attributes["TEXCOORD_" + std::to_string(u)] =
          AddFloatAttribute(doc, m.uv_sets[u], 2, "VEC2", false, write_data);
    }
    // A material texture read through a UV set the mesh lacks makes the primitive invalid glTF, so
    // the missing sets are added as zero-filled accessors (no bufferView, no bytes) and the reader
    // drops them again (extras.hullpack.uv_sets).
    const size_t needed_uv_sets = UvSetsNeeded(scene, m);
    for (size_t u = m.uv_sets.size(); u < needed_uv_sets; ++u) {
      AccessorDesc zeros;
      zeros.count = vc;
      zeros.type = "VEC2";
      attributes["TEXCOORD_" + std::to_string(u)] = doc->AddAccessor(zeros);
    }
    if (!m.colors.empty())
      attributes["COLOR_0"] = AddFloatAttribute(doc, m.colors, 4, "VEC4", false, write_data);
    if (!m.joints.empty()) {
      const bool bytes =
          options.compact_joints && *std::max_element(m.joints.begin(), m.joints.end()) < 256;
      AccessorDesc desc;
      desc.component_type = bytes ? gltf::kUnsignedByte : gltf::kUnsignedShort;
      if (write_data && bytes) {
        std::vector<uint8_t> packed(m.joints.begin(), m.joints.end());
        desc.buffer_view = doc->AddBufferView(packed, 4, gltf::kArrayBuffer);
      } else if (write_data) {
        desc.buffer_view = doc->AddBufferView(m.joints.data(), m.joints.size() * sizeof(uint16_t),
                                              4, gltf::kArrayBuffer);
      }
      desc.count = vc;
      desc.type = "VEC4";
      attributes["JOINTS_0"] = doc->AddAccessor(desc);
      attributes["WEIGHTS_0"] = AddFloatAttribute(doc, m.weights, 4, "VEC4", false, write_data);
    }

    // Morph targets: accessors shared by the primitives, as the vertex attributes are.
    json targets = json::array();
    for (const MorphTarget& t : m.morph_targets) {
      json target = {
          {"POSITION", AddFloatAttribute(doc, t.positions, 3, "VEC3", true, write_data)}};
      if (!t.normals.empty())
        target["NORMAL"] = AddFloatAttribute(doc, t.normals, 3, "VEC3", false, write_data);
      targets.push_back(std::move(target));
    }

    // Triangles grouped by material id, ascending; original order inside each group.
    std::vector<std::pair<int, std::vector<uint32_t>>> groups;  // material -> triangle indices
    if (m.material_ids.empty()) {
      groups.emplace_back(-1, std::vector<uint32_t>());
      groups.back().second.resize(m.triangle_count());
      for (size_t t = 0; t < m.triangle_count(); ++t)
        groups.back().second[t] = static_cast<uint32_t>(t);
    } else {
      std::map<uint32_t, std::vector<uint32_t>> by_material;
      for (size_t t = 0; t < m.material_ids.size(); ++t) {
        by_material[m.material_ids[t]].push_back(static_cast<uint32_t>(t));
      }
      for (auto& kv : by_material)
        groups.emplace_back(static_cast<int>(kv.first), std::move(kv.second));
    }

    const bool short_indices = vc < 65536;
    json primitives = json::array();
    for (const auto& group : groups) {
      std::vector<uint8_t> index_bytes;
      const size_t n = group.second.size() * 3;
      if (write_data && short_indices) {
        std::vector<uint16_t> idx(n);
        for (size_t k = 0; k < group.second.size(); ++k) {
          for (size_t c = 0; c < 3; ++c)
            idx[3 * k + c] = static_cast<uint16_t>(m.indices[3 * group.second[k] + c]);
        }
        index_bytes = Bytes(idx.data(), idx.size() * sizeof(uint16_t));
      } else if (write_data) {
        std::vector<uint32_t> idx(n);
        for (size_t k = 0; k < group.second.size(); ++k) {
          for (size_t c = 0; c < 3; ++c) idx[3 * k + c] = m.indices[3 * group.second[k] + c];
        }
        index_bytes = Bytes(idx.data(), idx.size() * sizeof(uint32_t));
      }
      AccessorDesc desc;
      if (write_data)
        desc.buffer_view = doc->AddBufferView(index_bytes, 4, gltf::kElementArrayBuffer);
      desc.component_type = short_indices ? gltf::kUnsignedShort : gltf::kUnsignedInt;
      desc.count = n;
      desc.type = "SCALAR";
      GltfSceneLayout::Primitive prim_layout;
      prim_layout.material = group.first;
      prim_layout.indices_accessor = doc->AddAccessor(desc);
      prim_layout.triangle_count = group.second.size();
      json prim = {{"attributes", attributes}, {"indices", prim_layout.indices_accessor}};
      if (!targets.empty()) prim["targets"] = targets;
      if (group.first >= 0) prim["material"] = group.first;
      primitives.push_back(std::move(prim));
      ml.primitives.push_back(prim_layout);
      ml.triangle_order.insert(ml.triangle_order.end(), group.second.begin(), group.second.end());
    }
    json mesh_json = {{"primitives", std::move(primitives)}};
    if (!m.name.empty()) mesh_json["name"] = m.name;
    if (!m.morph_weights.empty()) mesh_json["weights"] = m.morph_weights;
    if (std::any_of(m.morph_targets.begin(), m.morph_targets.end(),
                    [](const MorphTarget& t) { return !t.name.empty(); })) {
      json names = json::array();
      for (const MorphTarget& t : m.morph_targets) names.push_back(t.name);
      mesh_json["extras"]["targetNames"] = std::move(names);
    }
    if (!m.collides) mesh_json["extras"]["hullpack"]["collides"] = false;
    if (needed_uv_sets > m.uv_sets.size())
      mesh_json["extras"]["hullpack"]["uv_sets"] = m.uv_sets.size();
    ml.gltf_mesh = doc->Append("meshes", std::move(mesh_json));
  }

  // Skins.
  for (const Skin& skin : scene.skins) {
    json j = {{"joints", skin.joints}};
    if (!skin.name.empty()) j["name"] = skin.name;
    if (skin.skeleton >= 0) j["skeleton"] = skin.skeleton;
    if (!skin.inverse_bind_matrices.empty()) {
      AccessorDesc desc;
      desc.buffer_view = doc->AddBufferView(skin.inverse_bind_matrices.data(),
                                            skin.inverse_bind_matrices.size() * sizeof(float), 4);
      desc.component_type = gltf::kFloat;
      desc.count = skin.joints.size();
      desc.type = "MAT4";
      j["inverseBindMatrices"] = doc->AddAccessor(desc);
    }
    doc->Append("skins", std::move(j));
  }

  // Nodes. Scene nodes keep their indices; extra-mesh children come after them.
  out.mesh_nodes.assign(scene.meshes.size(), {});
  std::vector<Node> nodes = scene.nodes;
  if (nodes.empty()) {
    for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
      Node n;
      n.name = scene.meshes[mi].name;
      n.meshes.push_back(static_cast<int>(mi));
      nodes.push_back(std::move(n));
    }
  }
  std::vector<bool> animated(nodes.size(), false);
  for (const Animation& a : scene.animations) {
    for (const AnimationChannel& c : a.channels) {
      if (c.path != AnimationPath::kWeights) animated[static_cast<size_t>(c.node)] = true;
    }
  }
  json node_array = json::array();
  json extra_nodes = json::array();
  std::vector<std::vector<std::pair<int, int>>> extra_mesh_nodes(nodes.size());
  std::vector<int> roots;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const Node& n = nodes[i];
    json j = json::object();
    if (!n.name.empty()) j["name"] = n.name;
    std::vector<int> children = n.children;
    if (!n.meshes.empty()) {
      j["mesh"] = n.meshes[0];
      out.mesh_nodes[static_cast<size_t>(n.meshes[0])].push_back(static_cast<int>(i));
      if (n.skin >= 0) j["skin"] = n.skin;
      for (size_t k = 1; k < n.meshes.size(); ++k) {
        const int index = static_cast<int>(nodes.size() + extra_nodes.size());
        json extra = {{"mesh", n.meshes[k]},
                      {"extras", {{"hullpack", {{"mesh_of_parent", true}}}}}};
        if (n.skin >= 0) extra["skin"] = n.skin;
        extra_nodes.push_back(std::move(extra));
        children.push_back(index);
        out.mesh_nodes[static_cast<size_t>(n.meshes[k])].push_back(index);
        extra_mesh_nodes[i].push_back({index, n.meshes[k]});
      }
    }
    if (!children.empty()) j["children"] = children;
    WriteTransform(n, animated[i], &j);
    if (n.camera >= 0) j["camera"] = n.camera;
    if (n.light >= 0) j["extensions"]["KHR_lights_punctual"] = {{"light", n.light}};
    node_array.push_back(std::move(j));
    out.nodes.push_back(static_cast<int>(i));
    if (n.parent < 0) roots.push_back(static_cast<int>(i));
  }
  for (auto& e : extra_nodes) node_array.push_back(std::move(e));
  if (scene.nodes.empty()) out.nodes.clear();
  if (!node_array.empty()) root["nodes"] = std::move(node_array);
  json scene_json = json::object();
  if (!roots.empty()) scene_json["nodes"] = roots;
  root["scenes"] = json::array({std::move(scene_json)});
  root["scene"] = 0;
  AnimationWriter(scene, options).Write(out.nodes, extra_mesh_nodes, doc, &out);
  WriteCamerasAndLights(scene, doc);
  return Status::Ok();
}

Result<std::vector<uint8_t>> EncodeGlb(const Scene& scene, const GlbWriteOptions& options) {
  GltfDocument doc;
  Status s = BuildGltfDocument(scene, options, &doc, nullptr);
  if (!s.ok()) return s;
  return doc.Serialize();
}

}  // namespace hullpack
