// Animations: samplers (key times and values) and the channels that drive node translation,
// rotation, scale and the morph-target weights of the node's mesh. Channels without a target node
// (KHR_animation_pointer) are dropped with a line in Scene::dropped. A node whose transform is
// animated keeps it as TRS, the only form glTF lets an animation drive.
#include "gltf/glb_reader_decoder.h"

#include "scene/transform.h"

#include <cmath>
#include <set>
#include <utility>

namespace hullpack {
namespace glb_reader_internal {

namespace {

bool ParsePath(const std::string& text, AnimationPath* out) {
  if (text == "translation") {
    *out = AnimationPath::kTranslation;
  } else if (text == "rotation") {
    *out = AnimationPath::kRotation;
  } else if (text == "scale") {
    *out = AnimationPath::kScale;
  } else if (text == "weights") {
    *out = AnimationPath::kWeights;
  } else {
    return false;
  }
  return true;
}

}  // namespace

Status Decoder::DecodeAnimationSampler(const json& j, const std::string& where, AnimationPath path,
                                       size_t width, AnimationSampler* out) {
  std::string interpolation = "LINEAR";
  HP_RETURN_IF_ERROR(GetString(j, "interpolation", where, &interpolation));
  size_t values_per_key = 1;
  if (interpolation == "LINEAR") {
    out->interpolation = Interpolation::kLinear;
  } else if (interpolation == "STEP") {
    out->interpolation = Interpolation::kStep;
  } else if (interpolation == "CUBICSPLINE") {
    out->interpolation = Interpolation::kCubicSpline;
    values_per_key = 3;
  } else {
    return Error(where, "interpolation '" + interpolation + "' is not LINEAR, STEP or CUBICSPLINE");
  }
  int64_t input = -1, output = -1;
  HP_RETURN_IF_ERROR(GetIndex(j, "input", where, &input));
  HP_RETURN_IF_ERROR(GetIndex(j, "output", where, &output));
  if (input < 0 || output < 0) return Error(where, "needs an input and an output accessor");
  int components = 0;
  HP_RETURN_IF_ERROR(ReadFloats(input, where + ".input", {1}, &out->times, &components));
  if (out->times.empty()) return Error(where, "has no key frames");
  for (size_t k = 0; k < out->times.size(); ++k) {
    if (!std::isfinite(out->times[k]) || out->times[k] < 0 ||
        (k > 0 && !(out->times[k] > out->times[k - 1]))) {
      return Error(where + ".input",
                   "key time " + std::to_string(k) + " is not finite, negative or not ascending");
    }
  }
  // Weights are SCALAR, one per morph target and key; translation, rotation and scale VEC3/VEC4.
  const int type_width = path == AnimationPath::kWeights ? 1 : static_cast<int>(width);
  HP_RETURN_IF_ERROR(
      ReadFloats(output, where + ".output", {type_width}, &out->values, &components));
  const size_t expected = out->times.size() * values_per_key * width;
  if (out->values.size() != expected) {
    return Error(where + ".output", "holds " + std::to_string(out->values.size() / width) +
                                        " values for " + std::to_string(out->times.size()) +
                                        " key times (" + interpolation + ")");
  }
  for (float v : out->values) {
    if (!std::isfinite(v)) return Error(where + ".output", "holds a value that is not finite");
  }
  return Status::Ok();
}

size_t Decoder::MorphTargetsOfNode(const Scene& scene, size_t node) const {
  const json& n = root_.at("nodes")[node];
  if (!n.is_object()) return 0;
  auto mesh = n.find("mesh");
  if (mesh == n.end() || !mesh->is_number_unsigned()) return 0;
  const uint64_t m = mesh->get<uint64_t>();
  return m < scene.meshes.size() ? scene.meshes[static_cast<size_t>(m)].morph_targets.size() : 0;
}

Status Decoder::DecodeAnimations(Scene* scene) {
  const json* animations = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("animations", &animations));
  if (animations == nullptr) return Status::Ok();
  const size_t node_count = TopCount("nodes");
  size_t weight_channels = 0, pointer_channels = 0, repeated_channels = 0, empty_animations = 0;
  for (size_t a = 0; a < animations->size(); ++a) {
    const json& j = (*animations)[a];
    const std::string aw = Item("animations", a);
    Animation animation;
    HP_RETURN_IF_ERROR(GetString(j, "name", aw, &animation.name));
    const json* samplers = nullptr;
    const json* channels = nullptr;
    HP_RETURN_IF_ERROR(GetArray(j, "samplers", aw, &samplers));
    HP_RETURN_IF_ERROR(GetArray(j, "channels", aw, &channels));
    if (samplers == nullptr || channels == nullptr) return Error(aw, "needs samplers and channels");
    // A sampler is read with the path of the first channel that uses it; the samplers no kept
    // channel uses are left out.
    std::vector<int> kept_sampler(samplers->size(), -1);
    std::vector<size_t> sampler_width(samplers->size(), 0);
    std::vector<AnimationPath> sampler_path(samplers->size());
    std::set<std::pair<int, int>> targets;  // (node, path): glTF allows each once per animation
    for (size_t c = 0; c < channels->size(); ++c) {
      const json& ch = (*channels)[c];
      const std::string cw = aw + ".channels[" + std::to_string(c) + "]";
      if (!ch.is_object()) return Error(cw, "is not an object");
      int64_t sampler = -1;
      HP_RETURN_IF_ERROR(GetIndex(ch, "sampler", cw, &sampler));
      if (sampler < 0 || static_cast<size_t>(sampler) >= samplers->size())
        return Error(cw, "sampler " + std::to_string(sampler) + " does not exist");
      auto target = ch.find("target");
      if (target == ch.end() || !target->is_object()) return Error(cw, "has no target");
      int64_t node = -1;
      std::string path_text;
      HP_RETURN_IF_ERROR(GetIndex(*target, "node", cw + ".target", &node));
      HP_RETURN_IF_ERROR(GetString(*target, "path", cw + ".target", &path_text));
      if (node >= 0 && static_cast<size_t>(node) >= node_count)
        return Error(cw + ".target", "node " + std::to_string(node) + " does not exist");
      AnimationPath path;
      if (node < 0 || !ParsePath(path_text, &path)) {
        if (node >= 0 && path_text != "pointer")
          return Error(cw + ".target", "path '" + path_text + "' is not a node property");
        ++pointer_channels;
        continue;
      }
      const size_t width = path == AnimationPath::kWeights
                               ? MorphTargetsOfNode(*scene, static_cast<size_t>(node))
                               : AnimationPathWidth(path);
      if (width == 0) {
        ++weight_channels;
        continue;
      }
      if (!targets.insert({static_cast<int>(node), static_cast<int>(path)}).second) {
        ++repeated_channels;
        continue;
      }
      const size_t s = static_cast<size_t>(sampler);
      if (kept_sampler[s] >= 0 &&
          (sampler_width[s] != width ||
           (sampler_path[s] == AnimationPath::kWeights) != (path == AnimationPath::kWeights))) {
        return Error(cw, "uses sampler " + std::to_string(s) + " for values of another width");
      }
      if (kept_sampler[s] < 0) {
        AnimationSampler decoded;
        const json& sj = (*samplers)[s];
        const std::string sw = aw + ".samplers[" + std::to_string(s) + "]";
        if (!sj.is_object()) return Error(sw, "is not an object");
        HP_RETURN_IF_ERROR(DecodeAnimationSampler(sj, sw, path, width, &decoded));
        kept_sampler[s] = static_cast<int>(animation.samplers.size());
        sampler_path[s] = path;
        sampler_width[s] = width;
        animation.samplers.push_back(std::move(decoded));
      }
      animation.channels.push_back({kept_sampler[s], static_cast<int>(node), path});
    }
    if (animation.channels.empty()) {
      ++empty_animations;
      continue;
    }
    scene->animations.push_back(std::move(animation));
  }
  if (weight_channels > 0) {
    Drop("dropped " + std::to_string(weight_channels) +
         " animation channels of morph-target weights of nodes without a mesh with morph targets");
  }
  if (pointer_channels > 0) {
    Drop("dropped " + std::to_string(pointer_channels) +
         " animation channels without a node property target");
  }
  if (repeated_channels > 0) {
    Drop("dropped " + std::to_string(repeated_channels) +
         " animation channels that repeat a node and path of their animation");
  }
  if (empty_animations > 0) {
    Drop("dropped " + std::to_string(empty_animations) + " animations left without a channel");
  }
  return Status::Ok();
}

void Decoder::GiveAnimatedNodesTrs(Scene* scene) {
  size_t dropped = 0;
  for (Animation& a : scene->animations) {
    std::vector<AnimationChannel> kept;
    for (const AnimationChannel& c : a.channels) {
      if (c.path == AnimationPath::kWeights) {
        kept.push_back(c);
        continue;
      }
      Node& node = scene->nodes[static_cast<size_t>(c.node)];
      Trs trs;
      if (!node.trs && DecomposeMatrix(node.local_transform, &trs)) node.trs = trs;
      if (node.trs) {
        kept.push_back(c);
      } else {
        ++dropped;
      }
    }
    a.channels = std::move(kept);
  }
  if (dropped > 0) {
    Drop("dropped " + std::to_string(dropped) +
         " animation channels of nodes whose matrix has no translation-rotation-scale form");
  }
}

}  // namespace glb_reader_internal
}  // namespace hullpack
