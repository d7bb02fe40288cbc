// The editor's physics without a window (issue 23): which chain a selection makes dynamic,
// marking and baking as one undo step each, and the spring bones played live: a frame shows
// the same pose however the playhead got there (stepping, jumping, going backwards), the
// pose the bake keys at that frame.
#include <gtest/gtest.h>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "core/default_character.h"
#include "editor/model/document.h"
#include "editor/model/simulation_edits.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// The default character with a 4-joint tail behind its hips, turning its hips over 2 s at 24 fps.
Scene tailed() {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  Skeleton& s = scene.skeleton;
  int parent = s.find("Hips");
  for (int i = 0; i < 4; ++i) {
    s.addJoint("Tail" + std::to_string(i), parent, Transform::fromTranslation({0, -0.02f, -0.12f}));
    parent = s.size() - 1;
  }
  Clip clip;
  clip.name = "turn";
  clip.frameTime = 1.0 / 24.0;
  const glm::quat a = glm::angleAxis(-0.7f, glm::vec3(0, 1, 0)), b = glm::angleAxis(0.7f, glm::vec3(0, 1, 0));
  clip.channels.emplace_back(s.find("Hips"), ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f, 2.0f},
                             std::vector<glm::vec4>{glm::vec4(a.x, a.y, a.z, a.w), glm::vec4(b.x, b.y, b.z, b.w),
                                                    glm::vec4(a.x, a.y, a.z, a.w)});
  scene.clips.push_back(clip);
  return scene;
}

TEST(SimulationEdits, AChainFromTheSelection) {
  const Skeleton s = tailed().skeleton;
  const int t0 = s.find("Tail0"), t1 = s.find("Tail1"), t2 = s.find("Tail2"), t3 = s.find("Tail3");
  // One joint: it and the joints below it that have a bone (the leaf Tail3 has none).
  EXPECT_EQ(dynamicChainFrom(s, {t0}, t0), (std::vector<int>{t0, t1, t2}));
  EXPECT_EQ(dynamicChainFrom(s, {t1, t2, t3}, t3), (std::vector<int>{t1, t2, t3}));
  EXPECT_EQ(dynamicChainFrom(s, {t0, t3}, t3), (std::vector<int>{t0, t1, t2, t3}));  // the path between
  EXPECT_TRUE(dynamicChainFrom(s, {}, -1).empty());
  // The default settings are in the character's units: metres here.
  EXPECT_FLOAT_EQ(defaultSpringChain(s, {t0}).gravity.y, -9.81f);
  EXPECT_EQ(characterRoot(s), s.find("Hips"));
}

TEST(SimulationEdits, MarkingAndBakingAreOneUndoStepEach) {
  Document doc(tailed());
  const Skeleton& s = doc.skeleton();
  const Clip original = doc.scene().clips[0];
  const SpringBoneChain chain = defaultSpringChain(s, dynamicChainFrom(s, {s.find("Tail0")}, s.find("Tail0")));
  ASSERT_EQ(addSpringChainEdit(doc, chain), "");
  ASSERT_EQ(doc.scene().simulation.springChains.size(), 1u);
  EXPECT_TRUE(doc.sceneForSaving().simulation.springChains[0] == chain) << "saved with the file";
  SimulationBake bake;
  ASSERT_EQ(bakeSimulationEdit(doc, 0, 0, 48, &bake), "");
  ASSERT_EQ(bake.parts.size(), 1u);
  EXPECT_EQ(bake.parts[0].kind, "spring-chain");
  EXPECT_LT(bake.keysAfter, bake.keysBefore);
  int tailChannels = 0;
  for (const Channel& c : doc.scene().clips[0].channels)
    if (c.target == ChannelTarget::Rotation && (c.joint == chain.joints[0] || c.joint == chain.joints[1])) ++tailChannels;
  EXPECT_EQ(tailChannels, 2);
  EXPECT_EQ(doc.historyLabels().size(), 2u);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().clips[0].channels.size(), original.channels.size()) << "the bake undone";
  EXPECT_EQ(doc.scene().simulation.springChains.size(), 1u) << "the chain stays";
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().simulation.empty()) << "marking undone";
  ASSERT_TRUE(doc.redo());
  ASSERT_TRUE(doc.redo());
  EXPECT_GT(doc.scene().clips[0].channels.size(), original.channels.size());
  // Settings that do not fit are refused whole.
  SpringBoneChain bad = chain;
  bad.stiffness = -1.0f;
  EXPECT_NE(setSpringChainEdit(doc, 0, bad), "");
  EXPECT_TRUE(doc.scene().simulation.springChains[0] == chain);
}

TEST(SimulationEdits, LiveSpringsShowTheSamePoseHoweverTheFrameIsReached) {
  Document doc(tailed());
  const Skeleton& s = doc.skeleton();
  const SpringBoneChain chain = defaultSpringChain(s, dynamicChainFrom(s, {s.find("Tail0")}, s.find("Tail0")));
  ASSERT_EQ(addSpringChainEdit(doc, chain), "");
  const Clip& clip = doc.scene().clips[0];
  auto poseAt = [&](LiveSprings& live, long long frame) {
    Pose pose;
    SceneEvaluationJob job;  // as the timeline evaluates (timeline.cpp, poseAtPlayhead)
    job.scene = &doc.scene();
    job.clip = 0;
    job.time = doc.scene().frameGrid(0).frameToTime(frame);
    job.stages.dynamics = live.enabled;
    job.dynamicsStartFrame = 0;
    job.revision = doc.changeCount();
    job.context = &live.context;
    job.pose = &pose;
    EXPECT_TRUE(job.run());
    return pose;
  };
  LiveSprings stepped, jumped, back;
  Pose viaSteps;
  for (long long f = 0; f <= 30; ++f) viaSteps = poseAt(stepped, f);
  const Pose viaJump = poseAt(jumped, 30);
  poseAt(back, 40);
  const Pose viaBack = poseAt(back, 30);  // backwards: simulated again from the start
  // The bake keys each frame with the same simulation (no reduction here: every frame).
  SimulationSettings settings = doc.scene().simulation;
  Result<Clip> baked = bakeSpringBones(s, clip, settings.springChains, 0, 30);
  ASSERT_TRUE(baked);
  Pose keyed = Pose::rest(s);
  sampleClip(baked.value(), ownFrameGrid(clip).frameToTime(30), keyed);
  for (int j : chain.joints) {
    EXPECT_EQ(viaSteps.local[j].rotation, viaJump.local[j].rotation) << s.names[j];
    EXPECT_EQ(viaBack.local[j].rotation, viaJump.local[j].rotation) << s.names[j];
    EXPECT_GT(std::abs(glm::dot(keyed.local[j].rotation, viaJump.local[j].rotation)), 1.0f - 1e-6f) << s.names[j];
  }
  // The tail did swing: it is not where the clip alone puts it.
  Pose still = Pose::rest(s);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(30), still);
  EXPECT_LT(std::abs(glm::dot(still.local[chain.joints[0]].rotation, viaJump.local[chain.joints[0]].rotation)), 0.9999f);
  EXPECT_EQ(stepped.context.dynamics.framesSimulated, 31);
  EXPECT_EQ(back.context.dynamics.framesSimulated, 41 + 31);
  // Off: the clip's pose alone.
  LiveSprings off;
  off.enabled = false;
  const Pose plain = poseAt(off, 30);
  EXPECT_EQ(plain.local[chain.joints[0]].rotation, still.local[chain.joints[0]].rotation);
}

TEST(SimulationEdits, RagdollFromAFrameFallsAndIsOneStep) {
  Document doc(tailed());
  const Skeleton& s = doc.skeleton();
  SimulationBake bake;
  ASSERT_EQ(ragdollFromFrameEdit(doc, 0, characterRoot(s), 12, 12 + 72, &bake), "");
  ASSERT_EQ(doc.scene().simulation.ragdolls.size(), 1u);
  EXPECT_EQ(doc.scene().simulation.ragdolls[0].startFrame, 12);
  ASSERT_EQ(bake.parts.size(), 1u);
  EXPECT_EQ(bake.parts[0].kind, "ragdoll");
  EXPECT_LT(bake.parts[0].largestLimitExcess, 2.0f * 0.01745329f);
  Pose end = Pose::rest(s);
  sampleClip(doc.scene().clips[0], ownFrameGrid(doc.scene().clips[0]).frameToTime(84), end);
  EXPECT_LT(end.local[s.find("Hips")].translation.y, 0.5f) << "fallen";
  EXPECT_EQ(doc.historyLabels().size(), 1u);
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().simulation.empty());
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

// Distance from p to the segment a-b.
float segmentDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = b - a;
  const float t = glm::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0f, 1.0f);
  return glm::length(p - (a + t * d));
}

TEST(SimulationEdits, ACollisionCapsuleIsOneUndoStepAndKeepsTheTailOut) {
  Document doc(tailed());
  const Skeleton& s = doc.skeleton();
  const int hips = s.find("Hips"), tail0 = s.find("Tail0");
  SpringCollider onHips = defaultCollider(s, hips);
  EXPECT_EQ(onHips.joint, hips);
  int firstChild = -1;
  for (int c = hips + 1; c < s.size() && firstChild < 0; ++c)
    if (s.parents[c] == hips) firstChild = c;
  EXPECT_EQ(onHips.b, s.rest[firstChild].translation) << "along the bone to the first child";
  EXPECT_FLOAT_EQ(onHips.radius, 0.25f * glm::length(s.rest[firstChild].translation));
  EXPECT_NE(addColliderEdit(doc, onHips), "") << "no dynamic chain yet";

  SpringBoneChain chain = defaultSpringChain(s, dynamicChainFrom(s, {tail0}, tail0));
  ASSERT_EQ(addSpringChainEdit(doc, chain), "");
  EXPECT_NE(addColliderEdit(doc, defaultCollider(s, tail0)), "") << "the chain's own joint";
  // A bar under the tail, in the hips' space (it turns with them): the tail rests on it.
  SpringCollider bar;
  bar.joint = hips;
  bar.a = {0.0f, -0.12f, -0.05f};
  bar.b = {0.0f, -0.12f, -0.6f};
  bar.radius = 0.07f;
  const size_t steps = doc.historyLabels().size();
  ASSERT_EQ(addColliderEdit(doc, bar), "");
  EXPECT_EQ(doc.historyLabels().size(), steps + 1);
  ASSERT_EQ(doc.scene().simulation.springChains[0].colliders.size(), 1u);
  EXPECT_TRUE(doc.sceneForSaving().simulation.springChains[0].colliders[0] == bar) << "saved with the file";

  // Baked with and without the bar: with it no tail point enters the bar (the point's own
  // radius aside, up to a millimetre); without it the sagging tail passes through it.
  const Clip& clip = doc.scene().clips[0];
  auto closest = [&](const std::vector<SpringBoneChain>& chains) {
    Result<Clip> baked = bakeSpringBones(s, clip, chains, 0, 48);
    EXPECT_TRUE(baked);
    float nearest = 1e9f;
    for (long long f = 0; baked && f <= 48; ++f) {
      Pose pose = Pose::rest(s);
      sampleClip(baked.value(), ownFrameGrid(clip).frameToTime(f), pose);
      const std::vector<glm::mat4> world = computeWorld(s, pose);
      const glm::vec3 a = glm::vec3(world[hips] * glm::vec4(bar.a, 1.0f)), b = glm::vec3(world[hips] * glm::vec4(bar.b, 1.0f));
      for (int k = 1; k <= 3; ++k) nearest = std::min(nearest, segmentDistance(glm::vec3(world[s.find("Tail" + std::to_string(k))][3]), a, b));
    }
    return nearest;
  };
  EXPECT_GE(closest(doc.scene().simulation.springChains), bar.radius - 1e-3f);
  EXPECT_LT(closest({chain}), bar.radius - 0.02f);

  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().simulation.springChains[0].colliders.empty());
  ASSERT_TRUE(doc.redo());
  ASSERT_EQ(removeColliderEdit(doc, 0, 0), "");
  EXPECT_TRUE(doc.scene().simulation.springChains[0].colliders.empty());
  EXPECT_NE(removeColliderEdit(doc, 0, 0), "");
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(SimulationEdits, ARagdollWithoutAClipFallsFromThePoseOnScreenIntoANewAction) {
  Scene scene = tailed();
  scene.clips.clear();
  Document doc(scene);
  const Skeleton& s = doc.skeleton();
  ASSERT_TRUE(doc.scene().clips.empty());
  SimulationBake bake;
  ASSERT_EQ(ragdollFromFrameEdit(doc, -1, characterRoot(s), 1, 1 + 72, &bake), "");
  ASSERT_EQ(doc.scene().clips.size(), 1u) << "a new Action holds the fall";
  EXPECT_EQ(doc.scene().clips[0].name, "Action");
  EXPECT_EQ(doc.activeClip(), 0);
  EXPECT_EQ(doc.historyLabels().size(), 1u) << "one undo step";
  // At the start frame the keys are the pose on screen (the rest pose here), up to the lift
  // the ground gives the foot bodies that reach below it (under 2 cm); three seconds later
  // the hips have fallen (lower than they stood).
  const Clip& clip = doc.scene().clips[0];
  Pose start = Pose::rest(s), end = Pose::rest(s);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(1), start);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(73), end);
  const int hips = s.find("Hips");
  const float standing = glm::vec3(computeWorld(s, Pose::rest(s))[hips][3]).y;
  EXPECT_NEAR(glm::vec3(computeWorld(s, start)[hips][3]).y, standing, 0.02f);
  EXPECT_LT(glm::vec3(computeWorld(s, end)[hips][3]).y, standing - 0.3f);
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().clips.empty());
  EXPECT_TRUE(doc.scene().simulation.ragdolls.empty());
}

}  // namespace
}  // namespace kinema
