#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/onion_skin.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(OnionSkin, GhostFramesAroundTheCurrentFrameWithStepAndOrder) {
  OnionSkinSettings s;
  s.before = 2;
  s.after = 3;
  s.step = 2;
  const std::vector<GhostFrame> g = ghostFrames(s, 10, 100);
  ASSERT_EQ(g.size(), 5u);
  const long long frames[] = {6, 8, 12, 14, 16};
  const int offsets[] = {-2, -1, 1, 2, 3};
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(g[i].frame, frames[i]);
    EXPECT_EQ(g[i].offset, offsets[i]);
    const glm::vec3 tint = offsets[i] < 0 ? s.beforeColor : s.afterColor;
    EXPECT_EQ(glm::vec3(g[i].color), tint);
  }
}

TEST(OnionSkin, GhostsFadeWithDistance) {
  OnionSkinSettings s;
  s.before = 4;
  s.after = 2;
  s.step = 1;
  s.opacity = 0.8f;
  const std::vector<GhostFrame> g = ghostFrames(s, 50, 100);
  ASSERT_EQ(g.size(), 6u);
  // Before: farthest (k = 4) first: 0.8 * 1/4, 2/4, 3/4, 4/4.
  for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(g[k].color.a, 0.8f * float(k + 1) / 4.0f);
  EXPECT_FLOAT_EQ(g[4].color.a, 0.8f);        // nearest after
  EXPECT_FLOAT_EQ(g[5].color.a, 0.8f * 0.5f);  // farthest of two
}

TEST(OnionSkin, GhostsOutsideTheClipAreDropped) {
  OnionSkinSettings s;
  s.before = 3;
  s.after = 3;
  s.step = 2;
  // Frames 0..9: at frame 1 only after ghosts 3, 5, 7 remain; at frame 8 only 2, 4, 6 (10 is past the end).
  std::vector<GhostFrame> g = ghostFrames(s, 1, 10);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[0].frame, 3);
  EXPECT_EQ(g[2].frame, 7);
  g = ghostFrames(s, 8, 10);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[0].frame, 2);
  EXPECT_EQ(g[2].frame, 6);
  for (const GhostFrame& x : g) EXPECT_LT(x.offset, 0);
  // The first frame itself is a ghost when exactly reached (frame 4 - 2 * 2 = 0).
  g = ghostFrames(s, 4, 10);
  EXPECT_EQ(g.front().frame, 0);
  // Step 0 reads as 1; a one-frame clip has no ghosts.
  s.step = 0;
  EXPECT_EQ(ghostFrames(s, 5, 10).front().frame, 2);
  EXPECT_TRUE(ghostFrames(s, 0, 1).empty());
}

TEST(OnionSkin, GhostPosesAreTheClipAtTheGhostFrames) {
  // Root translated along X (1 m per second), child 1 m above it, turned about Z by the
  // root's rotation (0 -> 90 degrees over 1 s): closed-form positions.
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform{});
  scene.skeleton.addJoint("tip", 0, Transform::fromTranslation(glm::vec3(0, 1, 0)));
  Clip clip;
  clip.frameTime = 0.1;
  clip.channels.push_back(Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f},
                                  {glm::vec4(0, 0, 0, 0), glm::vec4(1, 0, 0, 0)}));
  const glm::quat q90 = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  clip.channels.push_back(Channel(0, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 1.0f},
                                  {glm::vec4(0, 0, 0, 1), glm::vec4(q90.x, q90.y, q90.z, q90.w)}));
  scene.clips.push_back(clip);
  OnionSkinSettings s;
  s.before = 1;
  s.after = 1;
  s.step = 3;
  const std::vector<GhostFrame> g = ghostFrames(s, 5, 11);  // frames 2 and 8
  const std::vector<std::vector<glm::mat4>> poses = ghostPoses(scene, 0, g);
  ASSERT_EQ(poses.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const double t = 0.1 * double(g[i].frame), a = t * M_PI / 2;
    const glm::vec3 root(float(t), 0, 0), tip(float(t - std::sin(a)), float(std::cos(a)), 0);
    EXPECT_NEAR(glm::length(glm::vec3(poses[i][0][3]) - root), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec3(poses[i][1][3]) - tip), 0.0f, 1e-5f) << "frame " << g[i].frame;
  }
  EXPECT_TRUE(ghostPoses(scene, 3, g).empty());  // no such clip
}

// The defaults must read on a character: ghosts several frames apart (at step 1 or 2 the
// poses nearly coincide with the current one and merge with it) and clearly opaque.
TEST(OnionSkin, DefaultsSpreadTheGhostsAndShowThem) {
  const OnionSkinSettings s;
  EXPECT_FALSE(s.enabled);
  EXPECT_GE(s.step, 4);
  EXPECT_GE(s.opacity, 0.4f);
  EXPECT_TRUE(s.bodies);
  EXPECT_GE(s.before, 1);
  EXPECT_GE(s.after, 1);
  // A 21-frame clip (0..20) at frame 10: the ghosts reach step * count frames each way, every
  // one inside the clip, the farthest still at least a quarter of the nearest's opacity.
  const std::vector<GhostFrame> g = ghostFrames(s, 10, 21);
  ASSERT_EQ(g.size(), static_cast<size_t>(s.before + s.after));
  EXPECT_EQ(g.front().frame, 10 - s.before * s.step);
  EXPECT_EQ(g.back().frame, 10 + s.after * s.step);
  for (const GhostFrame& x : g) {
    EXPECT_NE(x.frame, 10);
    EXPECT_GE(x.color.a, 0.25f * s.opacity);
  }
}

TEST(OnionSkin, GhostsAreBodiesWhereTheSceneHasMeshesElseBones) {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform{});
  OnionSkinSettings s;
  EXPECT_FALSE(ghostsShowBodies(s, scene)) << "no mesh: bones";
  scene.meshes.emplace_back();
  MeshInstance instance;
  instance.mesh = 0;
  scene.meshInstances.push_back(instance);
  EXPECT_TRUE(ghostsShowBodies(s, scene));
  s.bodies = false;
  EXPECT_FALSE(ghostsShowBodies(s, scene)) << "switched to bones in the settings";
}

}  // namespace
}  // namespace kinema
