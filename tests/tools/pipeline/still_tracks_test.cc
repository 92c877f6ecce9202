#include "pipeline/still_tracks.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "pipeline/prune.h"

namespace hullpack {
namespace {

AnimationSampler Keys(std::vector<float> times, std::vector<float> values) {
  AnimationSampler s;
  s.times = std::move(times);
  s.values = std::move(values);
  return s;
}

// Two nodes: 0 at the origin without TRS, 1 with a translation and a half turn about z.
// One triangle, positions only.
void AddTriangleMesh(Mesh& m) {
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  m.indices = {0, 1, 2};
}

Scene TwoNodes() {
  Scene s;
  s.nodes.resize(2);
  s.nodes[1].trs = Trs();
  s.nodes[1].trs->translation = {0, 2, 0};
  s.nodes[1].trs->rotation = {0, 0, 1, 0};
  return s;
}

TEST(StillTracks, TracksAtRestGoHeldTracksKeepOneKeyMovingTracksStay) {
  Scene s = TwoNodes();
  Animation a;
  a.samplers.push_back(Keys({0, 1, 2}, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));  // node 0 at rest
  a.samplers.push_back(Keys({0, 1, 2}, {0, 2, 0, 0, 2, 0, 0, 2, 0}));           // node 1 at rest
  // Node 1's half turn written as -q: the same rotation, so at rest too.
  a.samplers.push_back(Keys({0, 1}, {0, 0, -1, 0, 0, 0, -1, 0}));
  a.samplers.push_back(Keys({0, 1, 2}, {2, 2, 2, 2, 2, 2, 2, 2, 2}));  // node 0 held at scale 2
  a.samplers.push_back(Keys({0, 1}, {0, 0, 0, 1, 0, 0}));              // node 0 moves
  a.channels = {{0, 0, AnimationPath::kRotation},
                {1, 1, AnimationPath::kTranslation},
                {2, 1, AnimationPath::kRotation},
                {3, 0, AnimationPath::kScale},
                {4, 0, AnimationPath::kTranslation}};
  s.animations.push_back(a);
  const StillTrackReport r = RemoveStillTracks(s);
  EXPECT_EQ(r.at_rest_removed, 3u);
  EXPECT_EQ(r.held_collapsed, 1u);
  const Animation& out = s.animations[0];
  ASSERT_EQ(out.channels.size(), 2u);
  ASSERT_EQ(out.samplers.size(), 2u);
  EXPECT_EQ(out.channels[0].path, AnimationPath::kScale);
  EXPECT_EQ(out.channels[0].sampler, 0);
  EXPECT_EQ(out.samplers[0].times, std::vector<float>({0}));
  EXPECT_EQ(out.samplers[0].values, std::vector<float>({2, 2, 2}));
  EXPECT_EQ(out.channels[1].path, AnimationPath::kTranslation);
  EXPECT_EQ(out.channels[1].sampler, 1);
  EXPECT_EQ(out.samplers[1].times.size(), 2u);
}

TEST(StillTracks, AClipAtRestKeepsOneChannelAndCubicSplinesAreLeftAlone) {
  Scene s = TwoNodes();
  Animation pose;
  pose.name = "T-pose";
  pose.samplers.push_back(Keys({0, 1}, {0, 0, 0, 1, 0, 0, 0, 1}));
  pose.samplers.push_back(Keys({0, 1}, {0, 2, 0, 0, 2, 0}));
  pose.channels = {{0, 0, AnimationPath::kRotation}, {1, 1, AnimationPath::kTranslation}};
  s.animations.push_back(pose);
  Animation spline;
  AnimationSampler cubic = Keys({0, 1}, {0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0});
  cubic.interpolation = Interpolation::kCubicSpline;
  spline.samplers.push_back(cubic);
  spline.channels = {{0, 0, AnimationPath::kScale}};
  s.animations.push_back(spline);
  const StillTrackReport r = RemoveStillTracks(s);
  EXPECT_EQ(r.at_rest_removed, 1u);
  ASSERT_EQ(s.animations[0].channels.size(), 1u);  // still listed, still a clip
  EXPECT_EQ(s.animations[0].channels[0].node, 1);
  EXPECT_EQ(s.animations[1].samplers[0].values.size(), 18u);
}

TEST(StillTracks, MorphWeightsAtTheMeshDefaultsGoOthersStay) {
  Scene s = TwoNodes();
  Mesh m;
  m.morph_targets.resize(2);
  m.morph_weights = {0.5f, 0.0f};
  s.meshes.push_back(m);
  s.nodes[0].meshes = {0};
  s.nodes[1].meshes = {0};
  Animation a;
  a.samplers.push_back(Keys({0, 1}, {0.5f, 0, 0.5f, 0}));  // node 0 at its mesh's defaults
  a.samplers.push_back(Keys({0, 1}, {0, 0, 1, 0}));        // node 1 blends
  a.channels = {{0, 0, AnimationPath::kWeights}, {1, 1, AnimationPath::kWeights}};
  s.animations.push_back(a);
  const StillTrackReport r = RemoveStillTracks(s);
  EXPECT_EQ(r.at_rest_removed, 1u);
  ASSERT_EQ(s.animations[0].channels.size(), 1u);
  EXPECT_EQ(s.animations[0].channels[0].node, 1);
  EXPECT_EQ(s.animations[0].samplers[0].values, (std::vector<float>{0, 0, 1, 0}));
}

TEST(StillTracks, WeightTracksWithoutTheirTargetsGoWhateverTheOptions) {
  Scene s = TwoNodes();
  Mesh m;
  AddTriangleMesh(m);
  m.morph_targets.resize(2, MorphTarget{"", std::vector<float>(9, 0.5f), {}});
  s.meshes.push_back(m);
  Mesh flat = m;  // the repairs removed every (degenerate) triangle: the mesh is left out
  flat.indices.clear();
  s.meshes.push_back(flat);
  s.nodes[0].meshes = {0};
  s.nodes[1].meshes = {1};
  Animation a;
  a.samplers.push_back(Keys({0, 1}, {0, 0, 1, 0}));
  a.samplers.push_back(Keys({0, 1}, {0, 0, 1, 0}));
  a.channels = {{0, 0, AnimationPath::kWeights}, {1, 1, AnimationPath::kWeights}};
  s.animations.push_back(a);
  PruneOptions options;
  options.still_animation_tracks = false;
  const PruneReport r = LeaveOutUnused(s, options);
  EXPECT_EQ(r.weight_tracks_removed, 1u);
  ASSERT_EQ(s.animations[0].channels.size(), 1u);
  EXPECT_EQ(s.animations[0].channels[0].node, 0);
  EXPECT_EQ(s.animations[0].samplers.size(), 1u);
  EXPECT_NE(std::find(r.lines.begin(), r.lines.end(), "1 morph weight tracks of meshes left out"),
            r.lines.end());
}

TEST(StillTracks, LeaveOutUnusedReportsThem) {
  Scene s = TwoNodes();
  Animation a;
  a.samplers.push_back(Keys({0, 1}, {0, 0, 0, 1, 0, 0, 0, 1}));
  a.samplers.push_back(Keys({0, 1}, {0, 0, 0, 0, 3, 0}));
  a.channels = {{0, 0, AnimationPath::kRotation}, {1, 0, AnimationPath::kTranslation}};
  s.animations.push_back(a);
  PruneOptions keep;
  keep.still_animation_tracks = false;
  Scene untouched = s;
  EXPECT_EQ(LeaveOutUnused(untouched, keep).animation_tracks_removed, 0u);
  EXPECT_EQ(untouched.animations[0].channels.size(), 2u);
  const PruneReport r = LeaveOutUnused(s);
  EXPECT_EQ(r.animation_tracks_removed, 1u);
  bool reported = false;
  for (const std::string& line : r.lines)
    reported = reported || line.find("hold their node at rest") != std::string::npos;
  EXPECT_TRUE(reported);
}

}  // namespace
}  // namespace hullpack
