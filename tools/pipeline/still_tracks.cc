#include "pipeline/still_tracks.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace hullpack {
namespace {

bool Close(double a, double b) {
  return std::fabs(a - b) <= 1e-6 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

// Whether every key of `s` holds the first key's value (LINEAR and STEP tracks only).
bool Holds(const AnimationSampler& s, size_t width) {
  if (s.interpolation == Interpolation::kCubicSpline) return false;
  for (size_t v = width; v < s.values.size(); ++v) {
    if (!Close(s.values[v], s.values[v % width])) return false;
  }
  return true;
}

// The node's own value of `path`, the pose it has where no animation drives it.
std::vector<double> RestValue(const Scene& scene, const AnimationChannel& ch) {
  const Node& node = scene.nodes[static_cast<size_t>(ch.node)];
  const Trs trs = node.trs ? *node.trs : Trs();
  switch (ch.path) {
    case AnimationPath::kWeights: {
      const Mesh& mesh = scene.meshes[static_cast<size_t>(node.meshes[0])];
      std::vector<double> weights(mesh.morph_targets.size(), 0.0);
      for (size_t t = 0; t < weights.size() && t < mesh.morph_weights.size(); ++t)
        weights[t] = mesh.morph_weights[t];
      return weights;
    }
    case AnimationPath::kRotation:
      return {trs.rotation.begin(), trs.rotation.end()};
    case AnimationPath::kScale:
      return {trs.scale.begin(), trs.scale.end()};
    case AnimationPath::kTranslation:
      break;
  }
  return {trs.translation.begin(), trs.translation.end()};
}

bool AtRest(const AnimationSampler& s, const Scene& scene, const AnimationChannel& ch) {
  const AnimationPath path = ch.path;
  const std::vector<double> rest = RestValue(scene, ch);
  // q and -q are the same rotation.
  double dot = 0;
  for (size_t c = 0; c < rest.size(); ++c) dot += s.values[c] * rest[c];
  const double sign = path == AnimationPath::kRotation && dot < 0 ? -1.0 : 1.0;
  for (size_t c = 0; c < rest.size(); ++c) {
    if (!Close(sign * s.values[c], rest[c])) return false;
  }
  return true;
}

// Makes `kept` the animation's channels; samplers keep their order, those no channel uses go.
void KeepChannels(Animation& a, std::vector<AnimationChannel> kept) {
  std::vector<int> new_index(a.samplers.size(), -1);
  for (const AnimationChannel& ch : kept) new_index[static_cast<size_t>(ch.sampler)] = 0;
  std::vector<AnimationSampler> samplers;
  for (size_t s = 0; s < a.samplers.size(); ++s) {
    if (new_index[s] < 0) continue;
    new_index[s] = static_cast<int>(samplers.size());
    samplers.push_back(std::move(a.samplers[s]));
  }
  for (AnimationChannel& ch : kept) ch.sampler = new_index[static_cast<size_t>(ch.sampler)];
  a.samplers = std::move(samplers);
  a.channels = std::move(kept);
}

}  // namespace

StillTrackReport RemoveStillTracks(Scene& scene) {
  StillTrackReport report;
  for (Animation& a : scene.animations) {
    std::vector<AnimationChannel> kept;
    std::vector<bool> collapse(a.samplers.size(), false);
    for (size_t c = 0; c < a.channels.size(); ++c) {
      const AnimationChannel& ch = a.channels[c];
      const AnimationSampler& s = a.samplers[static_cast<size_t>(ch.sampler)];
      const size_t width = ChannelWidth(scene, ch);
      const bool holds = width > 0 && Holds(s, width);
      const bool last_chance = kept.empty() && c + 1 == a.channels.size();
      if (holds && !last_chance && AtRest(s, scene, ch)) {
        ++report.at_rest_removed;
        continue;
      }
      if (holds && s.times.size() > 1) collapse[static_cast<size_t>(ch.sampler)] = true;
      kept.push_back(ch);
    }
    for (size_t s = 0; s < a.samplers.size(); ++s) {
      if (!collapse[s]) continue;
      AnimationSampler& sampler = a.samplers[s];
      const size_t width = sampler.values.size() / sampler.times.size();
      sampler.times.resize(1);
      sampler.values.resize(width);
      ++report.held_collapsed;
    }
    KeepChannels(a, std::move(kept));
  }
  return report;
}

size_t RemoveWeightTracksWithoutTargets(Scene& scene) {
  size_t removed = 0;
  for (Animation& a : scene.animations) {
    std::vector<AnimationChannel> kept;
    for (const AnimationChannel& ch : a.channels) {
      if (ch.path == AnimationPath::kWeights) {
        const AnimationSampler& s = a.samplers[static_cast<size_t>(ch.sampler)];
        const size_t per_key = s.interpolation == Interpolation::kCubicSpline ? 3 : 1;
        const size_t width = ChannelWidth(scene, ch);
        if (width == 0 || s.values.size() != s.times.size() * per_key * width) {
          ++removed;
          continue;
        }
      }
      kept.push_back(ch);
    }
    if (kept.size() != a.channels.size()) KeepChannels(a, std::move(kept));
  }
  return removed;
}

}  // namespace hullpack
