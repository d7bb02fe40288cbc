// Issue 38: every consumer evaluates through the one pipeline. One scene uses every stage (a
// noise modifier, a keyed IK target, a live spring chain, keyed morph weights, a bend
// deformer); the pipeline's own result at one time is compared with what `kinema pose`,
// `kinema skin`, `kinema render`, the editor's display and onion-skin ghost, the motion path
// and a BVH export give for that time; the library's jobs below the pipeline (retargeting, the
// simulation bakes, crowds) move on its poses when the CLI and the editor pass them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "anim/scalar_property.h"
#include "core/forward_kinematics.h"
#include "editor/model/document.h"
#include "editor/model/editor_state.h"
#include "editor/model/motion_path.h"
#include "editor/model/onion_skin.h"
#include "editor/model/timeline.h"
#include "evaluation/scene_evaluation_job.h"
#include "evaluation/scene_poses.h"
#include "retarget/retarget_clip.h"
#include "sim/crowd.h"
#include "sim/simulation_bake.h"
#include "io/image.h"
#include "io/scene_files.h"
#include "scene/default_character_scene.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr long long kFrame = 18;  // at the document's 24 fps: 0.75 s

Channel keyed(int joint, ChannelTarget target, std::vector<float> times, std::vector<glm::vec4> values,
              const std::string& property = "") {
  Channel c(joint, target, Interpolation::Linear, std::move(times), std::move(values));
  c.property = property;
  return c;
}

Scene everyStageScene() {
  Scene scene = makeDefaultCharacterScene();
  const Skeleton& s = scene.skeleton;
  Clip clip;
  clip.name = "every stage";
  // 1: keys on the hips, 2: noise on the spine's rotation.
  clip.channels.push_back(keyed(s.find("Hips"), ChannelTarget::Translation, {0.0f, 1.0f},
                                {glm::vec4(s.rest[0].translation, 0), glm::vec4(s.rest[0].translation + glm::vec3(0.05f, 0, 0), 0)}));
  Channel spine = keyed(s.find("Spine"), ChannelTarget::Rotation, {0.0f, 1.0f}, {glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1)});
  ChannelModifier noise;
  noise.kind = ChannelModifierKind::Noise;
  noise.noise.strength = 0.3f;
  noise.noise.scale = 0.5f;
  noise.noise.octaves = 2;
  noise.noise.seed = 7;
  spine.modifiers.push_back(noise);
  clip.channels.push_back(spine);
  // 5: the right hand's IK target, its position keyed from the chest's side to in front.
  IkTarget hand;
  hand.effector = s.find("Hand.R");
  hand.position = glm::vec3(-0.5f, 1.3f, 0.2f);
  scene.ik.targets.push_back(hand);
  IkTargetOptions options;
  options.chainLength = 2;
  options.solver = IkSolver::JacobianDls;
  scene.ik.targetOptions.push_back(options);
  const float xs[2] = {-0.35f, -0.25f}, ys[2] = {1.25f, 1.35f}, zs[2] = {0.15f, 0.3f};
  const float* components[3] = {xs, ys, zs};
  for (int c = 0; c < 3; ++c)
    clip.channels.push_back(keyed(-1, ChannelTarget::Scalar, {0.0f, 1.0f},
                                  {glm::vec4(components[c][0]), glm::vec4(components[c][1])}, ikTargetPositionProperty(0, c)));
  // 6: the left arm swings as a spring chain behind the chest's noise.
  SpringBoneChain chain;
  chain.name = "arm";
  chain.joints = {s.find("UpperArm.L"), s.find("LowerArm.L"), s.find("Hand.L")};
  chain.stiffness = 30.0f;
  chain.gravity = glm::vec3(0, -9.81f, 0);
  scene.simulation.springChains.push_back(chain);
  // 8: the smile's weight, keyed on the instance's joint.
  const int instanceJoint = scene.meshInstances[0].joint;
  clip.channels.push_back(keyed(instanceJoint, ChannelTarget::Scalar, {0.0f, 1.0f}, {glm::vec4(0.0f), glm::vec4(1.0f)},
                                morphWeightProperty(1)));
  // 9: a bend of the whole body, its angle keyed.
  Deformer bend;
  bend.name = "bend";
  bend.type = DeformerType::Bend;
  bend.axis.kind = AxisDeformerKind::Bend;
  bend.axis.axis = DeformAxis::Y;
  bend.axis.low = 0.0f;
  bend.axis.high = 1.8f;
  bend.axis.amount = 0.0f;
  scene.editDeformerStack(0).deformers.push_back(bend);
  clip.channels.push_back(keyed(instanceJoint, ChannelTarget::Scalar, {0.0f, 1.0f}, {glm::vec4(0.0f), glm::vec4(0.6f)},
                                deformerParameterProperty("bend", "angle")));
  scene.clips.push_back(clip);
  return scene;
}

struct Evaluated {
  Pose pose;
  std::vector<glm::mat4> world;
  std::vector<DeformedPrimitive> meshes;
};

Evaluated evaluate(const Scene& scene, double time, const EvaluationStages& stages = {}) {
  Evaluated e;
  SceneEvaluationJob job;
  job.scene = &scene;
  job.clip = 0;
  job.time = time;
  job.stages = stages;
  job.pose = &e.pose;
  job.world = &e.world;
  job.meshes = &e.meshes;
  job.skinnedOnly = true;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return e;
}

void expectSameWorld(const std::vector<glm::mat4>& a, const std::vector<glm::mat4>& b, float tolerance, const char* who) {
  ASSERT_EQ(a.size(), b.size()) << who;
  for (size_t j = 0; j < a.size(); ++j)
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) ASSERT_NEAR(a[j][c][r], b[j][c][r], tolerance) << who << ": joint " << j;
}

class ConsumersAgree : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::makeTempDir();
    scene_ = everyStageScene();
    file_ = dir_ + "/every_stage.kinema";
    ASSERT_EQ(saveScene(file_, scene_), "");
    time_ = scene_.frameGrid(0).frameToTime(kFrame);
    expected_ = evaluate(scene_, time_);
  }
  void TearDown() override { test::runCommand("rm -rf '" + dir_ + "'"); }
  std::string dir_, file_;
  Scene scene_;
  double time_ = 0.0;
  Evaluated expected_;
};

// Each stage changes the result, so the comparisons below could not pass by leaving one out.
TEST_F(ConsumersAgree, EveryStageChangesTheResult) {
  EvaluationStages noIk, noDynamics, noDeformers;
  noIk.ikTargets = false;
  noDynamics.dynamics = false;
  noDeformers.deformers = false;
  const int hand = scene_.skeleton.find("Hand.R"), arm = scene_.skeleton.find("Hand.L");
  // The keyed target is reached (within the solver's tolerance) and moved the hand.
  const glm::vec3 target(-0.35f + 0.75f * 0.1f, 1.25f + 0.75f * 0.1f, 0.15f + 0.75f * 0.15f);
  EXPECT_LT(glm::length(glm::vec3(expected_.world[hand][3]) - target), 2e-3f);
  EXPECT_GT(glm::length(glm::vec3(evaluate(scene_, time_, noIk).world[hand][3]) - target), 0.05f);
  EXPECT_GT(glm::length(glm::vec3(evaluate(scene_, time_, noDynamics).world[arm][3]) - glm::vec3(expected_.world[arm][3])), 1e-3f);
  const Evaluated flat = evaluate(scene_, time_, noDeformers);
  float moved = 0.0f;
  for (size_t v = 0; v < flat.meshes[0].positions.size(); ++v)
    moved = std::max(moved, glm::length(flat.meshes[0].positions[v] - expected_.meshes[0].positions[v]));
  EXPECT_GT(moved, 0.01f);
}

TEST_F(ConsumersAgree, KinemaPoseAndSkin) {
  std::string out;
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " pose '" + file_ + "' --frame " + std::to_string(kFrame) + " --json", &out), 0);
  const nlohmann::json pose = nlohmann::json::parse(out);
  ASSERT_EQ(pose["joints"].size(), expected_.world.size());
  for (size_t j = 0; j < expected_.world.size(); ++j)
    for (int k = 0; k < 16; ++k)
      ASSERT_NEAR(pose["joints"][j]["world"][k].get<double>(), glm::value_ptr(expected_.world[j])[k], 1e-6) << "joint " << j;
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " skin '" + file_ + "' --frame " + std::to_string(kFrame) + " --json", &out), 0);
  const nlohmann::json skin = nlohmann::json::parse(out);
  ASSERT_EQ(skin["meshes"].size(), expected_.meshes.size());
  const nlohmann::json& positions = skin["meshes"][0]["positions"];
  ASSERT_EQ(positions.size(), expected_.meshes[0].positions.size());
  for (size_t v = 0; v < positions.size(); ++v)
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(positions[v][c].get<double>(), expected_.meshes[0].positions[v][c], 1e-6) << v;
}

TEST_F(ConsumersAgree, TheEditorsDisplayOnionSkinAndMotionPath) {
  EditorState s;
  s.doc = Document(scene_);
  resetTimeline(s);
  // Stepping to the frame, as a user plays towards it: the dynamics continue frame to frame.
  for (long long f = rangeStartFrame(s); f <= kFrame; ++f) goToFrame(s, f);
  expectSameWorld(s.world(), expected_.world, 1e-6f, "display after stepping");
  goToFrame(s, 3);
  goToFrame(s, kFrame);  // jumped to: simulated again from the start, the same pose
  expectSameWorld(s.world(), expected_.world, 1e-6f, "display after a jump");
  const IkRig rig = s.doc.savedRig();
  const std::vector<std::vector<glm::mat4>> ghosts =
      ghostPoses(s.doc.scene(), 0, {GhostFrame{kFrame - 5}, GhostFrame{kFrame}}, EvaluationStages{}, LLONG_MIN, 0, &rig);
  ASSERT_EQ(ghosts.size(), 2u);
  expectSameWorld(ghosts[1], expected_.world, 1e-6f, "onion-skin ghost");
  const int hand = scene_.skeleton.find("Hand.R");
  const MotionPath path = computeMotionPath(s.doc.scene(), 0, hand, kFrame - 2, kFrame, &rig);
  ASSERT_EQ(path.points.size(), 3u);
  EXPECT_LT(glm::length(path.points[2] - glm::vec3(expected_.world[hand][3])), 1e-6f);
}

TEST_F(ConsumersAgree, ABvhExportBakesEveryStage) {
  const std::string bvh = dir_ + "/baked.bvh";
  ASSERT_EQ(saveScene(bvh, scene_), "");
  Result<Scene> back = loadScene(bvh);
  ASSERT_TRUE(back.ok()) << back.error();
  // BVH keeps the joints (and adds End Sites): compare each joint's position by name.
  const std::vector<glm::mat4> world = computeWorld(back->skeleton, evaluatedPose(back.value(), 0, time_));
  for (int j = 0; j < scene_.skeleton.size(); ++j) {
    const int b = back->skeleton.find(scene_.skeleton.names[j]);
    ASSERT_GE(b, 0) << scene_.skeleton.names[j];
    EXPECT_LT(glm::length(glm::vec3(world[b][3]) - glm::vec3(expected_.world[j][3])), 1e-5f) << scene_.skeleton.names[j];
  }
}

// kinema render draws the pipeline's pose: the every-stage scene renders exactly as a scene
// whose clip holds that pose as keys and nothing else.
TEST_F(ConsumersAgree, KinemaRenderDrawsThePipelinesPose) {
  Scene still = scene_;
  still.simulation = SimulationSettings{};
  still.ik = IkRig{};
  Clip keys;
  for (int j = 0; j < still.skeleton.size(); ++j) {
    const Transform& t = expected_.pose.local[j];
    keys.channels.push_back(keyed(j, ChannelTarget::Translation, {0.0f}, {glm::vec4(t.translation, 0)}));
    keys.channels.push_back(keyed(j, ChannelTarget::Rotation, {0.0f}, {glm::vec4(t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w)}));
    keys.channels.push_back(keyed(j, ChannelTarget::Scale, {0.0f}, {glm::vec4(t.scale, 0)}));
  }
  still.clips = {keys};
  const std::string stillFile = dir_ + "/still.kinema";
  ASSERT_EQ(saveScene(stillFile, still), "");
  const std::string common = " --mesh off --size 320x240 --camera 30,10,4 ";
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " render '" + file_ + "' --frame " + std::to_string(kFrame) + common +
                             "--out '" + dir_ + "/a.png'"),
            0);
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " render '" + stillFile + "' --time 0" + common + "--out '" + dir_ + "/b.png'"), 0);
  Result<Image> a = loadPng(dir_ + "/a.png"), b = loadPng(dir_ + "/b.png");
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->rgba.size(), b->rgba.size());
  EXPECT_TRUE(a->rgba == b->rgba) << "the rendered skeletons differ";
  // And the control: without its live chain the frame draws differently.
  Scene noChain = scene_;
  noChain.simulation = SimulationSettings{};
  ASSERT_EQ(saveScene(dir_ + "/no_chain.kinema", noChain), "");
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " render '" + dir_ + "/no_chain.kinema' --frame " + std::to_string(kFrame) +
                             common + "--out '" + dir_ + "/c.png'"),
            0);
  Result<Image> c = loadPng(dir_ + "/c.png");
  ASSERT_TRUE(c);
  EXPECT_FALSE(a->rgba == c->rgba);
}

// The stages the jobs below the pipeline see (ScenePoses): 1 to 5, the live chains left out.
EvaluationStages withoutDynamics() {
  EvaluationStages stages;
  stages.dynamics = false;
  return stages;
}

// The angle between two rotations (radians), accurate near 0 (acos of a dot product is not).
float rotationAngle(const glm::quat& a, const glm::quat& b) {
  const glm::quat d = glm::conjugate(a) * b;
  return 2.0f * std::atan2(glm::length(glm::vec3(d.x, d.y, d.z)), std::abs(d.w));
}

// Retargeting a take onto its own skeleton with every joint mapped gives back its world
// rotations (RetargetJob's rule with A = identity): the pipeline's when it is the source.
TEST_F(ConsumersAgree, RetargetingMovesTheTargetAsThePipelinePlaysTheSource) {
  Scene take = scene_;
  take.clips[0].frameTime = 1.0 / 24.0;  // retargeting counts the source's own frames
  const Skeleton& s = take.skeleton;
  BoneMap map;
  for (int j = 0; j < s.size(); ++j) map.pairs.push_back(BonePair{j, j});
  auto retarget = [&](PoseSource* poses) {
    Clip out;
    RetargetJob job;
    job.source = &s;
    job.sourceClip = &take.clips[0];
    job.sourcePoses = poses;
    job.target = &s;
    job.map = &map;
    job.output = &out;
    EXPECT_EQ(job.validate(), "");
    EXPECT_TRUE(job.run());
    return out;
  };
  ScenePoses poses(take, 0);
  const Clip throughPipeline = retarget(&poses);
  const Clip bare = retarget(nullptr);
  Pose got = Pose::rest(s), plain = Pose::rest(s);
  sampleClip(throughPipeline, static_cast<float>(time_), got);
  sampleClip(bare, static_cast<float>(time_), plain);
  const std::vector<glm::mat4> world = computeWorld(s, got), plainWorld = computeWorld(s, plain);
  const int hand = s.find("LowerArm.R");
  float worst = 0.0f;
  for (int j = 0; j < s.size(); ++j)
    worst = std::max(worst, rotationAngle(rotationOf(world[j]), rotationOf(expected_.world[j])));
  EXPECT_LT(worst, 1e-4f) << "radians, the worst joint";
  // The control: the bare keys leave the IK target's arm where the clip keys it.
  EXPECT_GT(rotationAngle(rotationOf(plainWorld[hand]), rotationOf(expected_.world[hand])), 0.05f);
}

// A spring chain hung below the IK target's arm, baked on the pipeline's poses, swings as it
// does when baked on a clip that holds those poses as keys.
TEST_F(ConsumersAgree, TheSimulationBakeMovesOnThePipelinesPoses) {
  Scene scene = scene_;
  const Skeleton& s = scene.skeleton;
  SpringBoneChain chain;
  chain.name = "hand";
  chain.joints = {s.find("Hand.R"), s.find("Fingertip.R")};
  chain.stiffness = 20.0f;
  scene.simulation.springChains = {chain};
  // The reference clip: stages 1 to 5 of every frame as keys, nothing else.
  Clip keys;
  keys.frameTime = 1.0 / 24.0;
  std::vector<Channel> rotation(s.size()), translation(s.size());
  for (int j = 0; j < s.size(); ++j) {
    rotation[j] = Channel(j, ChannelTarget::Rotation, Interpolation::Linear, {}, {});
    translation[j] = Channel(j, ChannelTarget::Translation, Interpolation::Linear, {}, {});
  }
  for (long long f = 0; f <= kFrame; ++f) {
    const float t = static_cast<float>(f) / 24.0f;
    Pose pose = Pose::rest(s);
    evaluateAnimatedPose(scene, 0, t, withoutDynamics(), pose);
    for (int j = 0; j < s.size(); ++j) {
      const Transform& x = pose.local[j];
      rotation[j].times.push_back(t);
      rotation[j].values.emplace_back(x.rotation.x, x.rotation.y, x.rotation.z, x.rotation.w);
      translation[j].times.push_back(t);
      translation[j].values.emplace_back(x.translation, 0.0f);
    }
  }
  for (int j = 0; j < s.size(); ++j) keys.channels.push_back(rotation[j]), keys.channels.push_back(translation[j]);
  auto bake = [&](const Clip& clip, PoseSource* poses) {
    SimulationBakeInput in;
    in.skeleton = &s;
    in.clip = &clip;
    in.poses = poses;
    in.settings = &scene.simulation;
    in.firstFrame = 0;
    in.lastFrame = kFrame;
    in.reduceKeys = false;
    Result<SimulationBake> baked = bakeSimulation(in);
    EXPECT_TRUE(baked.ok()) << baked.error();
    Pose pose = Pose::rest(s);
    if (baked) sampleClip(baked->clip, static_cast<float>(time_), pose);
    return pose;
  };
  ScenePoses poses(scene, 0, withoutDynamics());
  const Pose got = bake(scene.clips[0], &poses);
  const Pose want = bake(keys, nullptr);
  const Pose bare = bake(scene.clips[0], nullptr);
  // The bake writes the chain's local rotations (the arm above it is the pipeline's to place).
  for (int j : chain.joints)
    EXPECT_LT(rotationAngle(got.local[j].rotation, want.local[j].rotation), 1e-4f) << s.names[j];
  // The control: on the bare keys the arm swings differently, and the chain with it.
  EXPECT_GT(rotationAngle(bare.local[chain.joints[0]].rotation, want.local[chain.joints[0]].rotation), 0.01f);
}

// A crowd member stands as the character's scene plays at its clip time (here at the origin,
// facing forward, without drift: its pose is the pipeline's, stages 1 to 5).
TEST_F(ConsumersAgree, CrowdMembersStandAsThePipelinePlaysTheCharacter) {
  const Skeleton& s = scene_.skeleton;
  CrowdClipMotion motion;
  CrowdMemberState member;
  member.clipTime = time_;
  member.yaw = motion.forwardYaw;
  ScenePoses poses(scene_, 0, withoutDynamics());
  Pose got, bare;
  crowdMemberPose(s, scene_.clips[0], motion, member, got, &poses);
  crowdMemberPose(s, scene_.clips[0], motion, member, bare);
  Pose want = Pose::rest(s);
  evaluateAnimatedPose(scene_, 0, time_, withoutDynamics(), want);
  ASSERT_EQ(got.size(), s.size());
  for (int j = 0; j < s.size(); ++j) {
    EXPECT_LT(glm::length(got.local[j].translation - want.local[j].translation), 1e-6f) << s.names[j];
    EXPECT_LT(rotationAngle(got.local[j].rotation, want.local[j].rotation), 1e-5f) << s.names[j];
  }
  const int arm = s.find("UpperArm.R");
  EXPECT_GT(rotationAngle(bare.local[arm].rotation, want.local[arm].rotation), 0.05f);
}

// A clip the chains were baked into plays its keys: the pipeline does not simulate the chains
// again over them (in the CLI, the editor and the writers alike), and .kinema keeps the mark.
TEST_F(ConsumersAgree, ABakedClipPlaysItsKeys) {
  ScenePoses poses(scene_, 0, withoutDynamics());
  SimulationBakeInput in;
  in.skeleton = &scene_.skeleton;
  in.clip = &scene_.clips[0];
  in.poses = &poses;
  in.settings = &scene_.simulation;
  in.firstFrame = 0;
  in.lastFrame = kFrame;
  in.reduceKeys = false;
  Result<SimulationBake> baked = bakeSimulation(in);
  ASSERT_TRUE(baked.ok()) << baked.error();
  EXPECT_TRUE(baked->clip.dynamicsBaked);
  Scene scene = scene_;
  scene.clips[0] = baked->clip;
  const std::string path = dir_ + "/baked.kinema";
  ASSERT_EQ(saveScene(path, scene), "");
  Result<Scene> back = loadScene(path);
  ASSERT_TRUE(back.ok()) << back.error();
  ASSERT_TRUE(back->clips[0].dynamicsBaked);
  const int hand = scene.skeleton.find("Hand.L");
  const Evaluated played = evaluate(back.value(), time_);
  const Evaluated keysAlone = evaluate(back.value(), time_, withoutDynamics());
  EXPECT_LT(glm::length(glm::vec3(played.world[hand][3]) - glm::vec3(keysAlone.world[hand][3])), 1e-6f);
  // The baked keys hold the swing the live chain had (one simulation, the same steps).
  EXPECT_LT(glm::length(glm::vec3(played.world[hand][3]) - glm::vec3(expected_.world[hand][3])), 1e-3f);
  // The control: unmarked, the chain swings again on top of its own baked swing.
  back->clips[0].dynamicsBaked = false;
  const Evaluated twice = evaluate(back.value(), time_);
  EXPECT_GT(glm::length(glm::vec3(twice.world[hand][3]) - glm::vec3(keysAlone.world[hand][3])), 1e-3f);
}

}  // namespace
}  // namespace kinema
