// `kinema simulate`: bakes a file's spring chains and ragdolls into its clip and writes
// .kinema, glTF or BVH; the report names each part with its steps and largest limit excess;
// the keys it writes replay the simulation (every frame, or within the reduction's
// tolerance); bad input is one line and a non-zero exit, with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "anim/sampling.h"
#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "sim/spring_bones.h"
#include "cli/simulate_cli_fixture.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// The default character turning its hips to and fro over 48 frames at 24 fps, with a tail:
// five 0.12 m bones behind the hips, and a ragdoll of the whole body from frame 30.
Scene tailedCharacter(bool withRagdoll) {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  Skeleton& s = scene.skeleton;
  const int hips = s.find("Hips");
  int parent = hips;
  std::vector<int> tail;
  for (int i = 0; i < 5; ++i) {
    s.addJoint("Tail" + std::to_string(i), parent, Transform::fromTranslation({0, -0.02f, -0.12f}));
    parent = s.size() - 1;
    tail.push_back(parent);
  }
  Clip clip;
  clip.name = "sway";
  clip.frameTime = 1.0 / 24.0;
  std::vector<float> times;
  std::vector<glm::vec4> values;
  for (int f = 0; f <= 48; f += 8) {
    const glm::quat q = glm::angleAxis((f % 16 == 0 ? 0.6f : -0.6f), glm::vec3(0, 1, 0));
    times.push_back(ownFrameGrid(clip).frameToTime(f));
    values.emplace_back(q.x, q.y, q.z, q.w);
  }
  clip.channels.emplace_back(hips, ChannelTarget::Rotation, Interpolation::Linear, times, values);
  scene.clips.push_back(clip);
  SpringBoneChain chain;
  chain.name = "tail";
  chain.joints = tail;
  chain.stiffness = 40.0f;
  chain.damping = 2.0f;
  chain.gravity = {0.0f, -9.81f, 0.0f};
  scene.simulation.springChains.push_back(chain);
  if (withRagdoll) {
    RagdollSettings ragdoll;
    ragdoll.name = "fall";
    ragdoll.root = hips;
    ragdoll.startFrame = 30;
    scene.simulation.ragdolls.push_back(ragdoll);
  }
  return scene;
}

class SimulateCli : public test::SimulateCliFixture {
 protected:
  static int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }
};

TEST_F(SimulateCli, EveryFrameKeysReplayTheSpringChain) {
  const Scene scene = tailedCharacter(false);
  const std::string in = save(scene, "tail.kinema"), out = dir_ + "/baked.kinema";
  ASSERT_EQ(kinema("'" + in + "' --frames 0:48 --out '" + out + "' --every-frame --json"), 0) << err_;
  const nlohmann::json j = nlohmann::json::parse(out_);
  ASSERT_EQ(j["parts"].size(), 1u);
  EXPECT_EQ(j["parts"][0]["kind"], "spring-chain");
  EXPECT_EQ(j["parts"][0]["name"], "tail");
  EXPECT_EQ(j["parts"][0]["joints"].size(), 5u);
  EXPECT_EQ(j["parts"][0]["steps"], 49 * 4);  // 49 frames of 4 substeps
  EXPECT_EQ(j["steps"], 49 * 4);
  EXPECT_EQ(j["frames"], nlohmann::json::array({0, 48}));
  EXPECT_EQ(j["keys"]["before"], 5 * 49);
  EXPECT_EQ(j["keys"]["after"], 5 * 49);
  EXPECT_NE(err_.find("spring-chain 'tail': frame 48"), std::string::npos) << "progress on stderr: " << err_;

  // The file's tail plays what the job computes frame by frame (its keys are the job's
  // rotations; sampling at a key's time gives it back to float rounding).
  Result<Scene> back = loadScene(out);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->simulation.springChains.size(), 1u) << "the settings stay in the file";
  const Clip& clip = scene.clips[0];
  SpringBoneState state;
  SamplingCache a, b;
  for (int f = 0; f <= 48; ++f) {
    Pose expected = Pose::rest(scene.skeleton), baked = Pose::rest(scene.skeleton);
    sampleClip(clip, ownFrameGrid(clip).frameToTime(f), expected, a);
    SpringBoneJob job;
    job.skeleton = &scene.skeleton;
    job.chains = &scene.simulation.springChains;
    job.dt = static_cast<float>(ownFrameGrid(clip).secondsPerFrame);
    job.pose = &expected;
    job.state = &state;
    ASSERT_TRUE(job.run());
    sampleClip(back->clips[0], ownFrameGrid(clip).frameToTime(f), baked, b);
    for (int joint : scene.simulation.springChains[0].joints)
      EXPECT_SAME_ROTATION(baked.local[joint].rotation, expected.local[joint].rotation, 1e-6f) << "frame " << f;
  }
}

TEST_F(SimulateCli, ReducedKeysStayWithinTheTolerance) {
  const Scene scene = tailedCharacter(false);
  const std::string in = save(scene, "tail.kinema");
  const std::string every = dir_ + "/every.kinema", reduced = dir_ + "/reduced.kinema";
  ASSERT_EQ(kinema("'" + in + "' --frames 0:48 --out '" + every + "' --every-frame"), 0) << err_;
  ASSERT_EQ(kinema("'" + in + "' --frames 0:48 --out '" + reduced + "' --reduce 0.002,0.5 --json"), 0) << err_;
  const nlohmann::json j = nlohmann::json::parse(out_);
  EXPECT_LT(j["keys"]["after"].get<int>(), j["keys"]["before"].get<int>());
  Result<Scene> e = loadScene(every), r = loadScene(reduced);
  ASSERT_TRUE(e && r);
  SamplingCache ca, cb;
  for (int f = 0; f <= 48; ++f) {
    Pose pe = Pose::rest(e->skeleton), pr = Pose::rest(r->skeleton);
    sampleClip(e->clips[0], ownFrameGrid(e->clips[0]).frameToTime(f), pe, ca);
    sampleClip(r->clips[0], ownFrameGrid(r->clips[0]).frameToTime(f), pr, cb);
    const std::vector<glm::mat4> we = computeWorld(e->skeleton, pe), wr = computeWorld(r->skeleton, pr);
    for (int joint = 0; joint < e->skeleton.size(); ++joint)
      EXPECT_LE(glm::length(glm::vec3(we[joint][3] - wr[joint][3])), 0.002f + 1e-5f) << "frame " << f;
  }
}

TEST_F(SimulateCli, RagdollsAndChainsToEveryFormat) {
  const Scene scene = tailedCharacter(true);
  const std::string in = save(scene, "both.kinema");
  for (const char* ext : {".kinema", ".glb", ".bvh"}) {
    const std::string out = dir_ + "/out" + ext;
    ASSERT_EQ(kinema("'" + in + "' --frames 0:100 --out '" + out + "' --json"), 0) << err_;
    const nlohmann::json j = nlohmann::json::parse(out_);
    ASSERT_EQ(j["parts"].size(), 2u);
    EXPECT_EQ(j["parts"][1]["kind"], "ragdoll");
    EXPECT_EQ(j["parts"][1]["name"], "fall");
    EXPECT_EQ(j["parts"][1]["frames"], nlohmann::json::array({30, 100}));
    EXPECT_EQ(j["parts"][1]["steps"], 70 * 10);  // 70 frames of 1/24 s, 10 steps of 1/240 s each
    EXPECT_LT(j["parts"][1]["largestLimitExcessDegrees"].get<double>(), 2.0) << out_;
    EXPECT_EQ(j["steps"], 101 * 4 + 70 * 10);
    Result<Scene> back = loadScene(out);
    ASSERT_TRUE(back) << back.error();
    // By the end the character lies on the ground: its hips are low, no joint below y = 0.
    Pose pose = Pose::rest(back->skeleton);
    SamplingCache cache;
    sampleClip(back->clips[0], static_cast<float>(100.0 / 24.0), pose, cache);
    const std::vector<glm::mat4> world = computeWorld(back->skeleton, pose);
    const int hips = back->skeleton.find("Hips");
    ASSERT_GE(hips, 0);
    EXPECT_LT(world[hips][3].y, 0.5f) << ext;
    // The simulated joints only: a BVH adds End Sites a bone's length past each leaf, points
    // no body carries.
    for (int j = 0; j < back->skeleton.size(); ++j)
      if (scene.skeleton.find(back->skeleton.names[j]) >= 0) {
        EXPECT_GT(world[j][3].y, -0.02f) << ext << " " << back->skeleton.names[j];
      }
  }
}

TEST_F(SimulateCli, BadInputIsOneLineAndWritesNothing) {
  const std::string in = save(tailedCharacter(false), "tail.kinema");
  Scene still;
  still.skeleton = makeDefaultCharacter();
  const std::string plain = save(still, "plain.kinema");
  const std::string out = dir_ + "/never.kinema";
  struct Case {
    std::string args;
    int code;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"'" + dir_ + "/missing.kinema' --out '" + out + "'", 1, "missing.kinema"},
      {"'" + plain + "' --out '" + out + "'", 1, "has nothing to simulate"},
      {"'" + in + "' --frames 3 --out '" + out + "'", 2, "--frames takes A:B"},
      {"'" + in + "' --frames 9:3 --out '" + out + "'", 1, "the first frame comes after the last"},
      {"'" + in + "' --frames -1:3 --out '" + out + "'", 1, "frames start at 0"},
      {"'" + in + "' --out '" + dir_ + "/x.png'", 2, "cannot write '.png'"},
      {"'" + in + "' --clip 4 --out '" + out + "'", 1, "clip"},
      {"'" + in + "' --reduce 0,1 --out '" + out + "'", 1, "positive"},
      {"'" + in + "' --reduce 1 --every-frame --out '" + out + "'", 2, "exclude each other"},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(kinema(c.args), c.code) << c.args << "\n" << err_;
    EXPECT_EQ(lines(err_), 1) << c.args << "\n" << err_;
    EXPECT_NE(err_.find(c.says), std::string::npos) << c.args << "\n" << err_;
    EXPECT_FALSE(exists(out)) << c.args;
  }
}

}  // namespace
}  // namespace kinema::test
