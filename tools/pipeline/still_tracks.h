// Animation tracks that do not move: part of "leave out what the scene does not need" (prune.h).
#ifndef HULLPACK_TOOLS_PIPELINE_STILL_TRACKS_H_
#define HULLPACK_TOOLS_PIPELINE_STILL_TRACKS_H_

#include <cstddef>

#include "scene/scene.h"

namespace hullpack {

struct StillTrackReport {
  size_t at_rest_removed = 0;  // channels that hold their node at its rest value
  size_t held_collapsed = 0;   // channels that hold another value, now one key
};

// A channel whose every key holds the node's own TRS value (what the node shows without the
// animation) is removed; one that holds another constant value keeps a single key, which glTF
// holds for the whole clip. Cubic-spline tracks are left alone. An animation keeps at least one
// channel, so clips stay listed by name. Samplers no channel uses are removed. Values count as
// equal within a relative 1e-6 (the float precision exporters write them with).
StillTrackReport RemoveStillTracks(Scene& scene);

// Removes the morph-weight channels that no longer fit their node: its first mesh (left out, or
// never with morph targets) has no targets, or another count than the keys hold. Returns how
// many went. The writer refuses such channels, so the leave-out stage always runs this.
size_t RemoveWeightTracksWithoutTargets(Scene& scene);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_STILL_TRACKS_H_
