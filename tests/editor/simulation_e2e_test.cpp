// End-to-end test of the Simulate menu (issue 23) in the real `kinema edit` under Xvfb: on
// Fox.glb the script selects the tail's first joint, makes the chain dynamic, plays (the tail
// swings live), bakes, undoes and redoes the bake, exports glTF; the exported file, opened
// again, has the tail's baked keys: the ones the model's own bake (no window) computes.
#include "editor/e2e_harness.h"

#include "anim/sampling.h"
#include "editor/model/document.h"
#include "editor/model/simulation_edits.h"
#include "io/scene_files.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class SimulationE2e : public TempDirSuite<SimulationE2e> {
 public:
  static constexpr const char* kShotFolder = "simulation_e2e";
};

TEST_F(SimulationE2e, FoxsTailMadeDynamicPlayedBakedUndoneRedoneExported) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string fox = sharedDataDir() + "/gltf/Fox.glb";
  const std::string exported = dir_ + "/fox_tail.gltf";
  Script s(Script::Start::AsOpened);
  s.wait(2);
  // The tail is below the outliner's fold on Fox: found by the search field, as a user would.
  s.clickItem("Outliner/Search").wait(1).type("Tail01").wait(2).clickItem("Outliner/b_Tail01_012").wait(1);
  s.menu("Simulate", "Make Chain Dynamic");
  s.clickItem("Timeline/Play").wait(30);
  s.clickItem("Timeline/Play").wait(3);
  s.menu("Simulate", "Bake Simulation").wait(3);
  s.chord("Z", {"ctrl"}).wait(2);           // the bake undone
  s.chord("Z", {"ctrl", "shift"}).wait(2);  // and redone
  s.command("file.export_gltf").wait(2);
  s.type(exported).key("ENTER").wait(4);
  const json d = runEditor(dir_, shotDir(), s, "fox_tail", fox);
  ASSERT_TRUE(d.is_object());
  const json& sim = d["simulation"];
  ASSERT_EQ(sim["spring_chains"].size(), 1u) << sim.dump();
  EXPECT_EQ(sim["spring_chains"][0]["joints"], json({"b_Tail01_012", "b_Tail02_013"}));
  EXPECT_GT(sim["live_frames_simulated"].get<long long>(), 10) << "the tail swung during playback";
  ASSERT_TRUE(sim.contains("last_bake"));
  EXPECT_EQ(sim["last_bake"]["parts"][0]["kind"], "spring-chain");
  EXPECT_FALSE(sim["live"].get<bool>()) << "after the bake the keys play, not a second simulation on top";
  EXPECT_EQ(d["undo_depth"], 2) << "make dynamic, bake";
  EXPECT_EQ(d["redo_depth"], 0);
  EXPECT_TRUE(d["errors"].empty()) << d["errors"].dump();

  // The model's bake of the same chain on the same clip and range (no window).
  Result<Scene> loaded = loadScene(fox);
  ASSERT_TRUE(loaded);
  Document doc(loaded.value());
  const Skeleton& sk = doc.skeleton();
  const int tail = sk.find("b_Tail01_012");
  ASSERT_EQ(addSpringChainEdit(doc, defaultSpringChain(sk, dynamicChainFrom(sk, {tail}, tail))), "");
  const Clip& clip = doc.scene().clips[0];
  const long long last = ownFrameGrid(clip).nearestFrame(clip.duration());
  ASSERT_EQ(bakeSimulationEdit(doc, 0, 0, last), "");
  const Clip& expected = doc.scene().clips[0];

  // Reopened: the exported file's first clip carries those keys.
  Result<Scene> back = loadScene(exported);
  ASSERT_TRUE(back) << back.error();
  ASSERT_FALSE(back->clips.empty());
  const int backTail = back->skeleton.find("b_Tail01_012"), backTail2 = back->skeleton.find("b_Tail02_013");
  ASSERT_GE(backTail, 0);
  int keys = 0;
  for (const Channel& c : back->clips[0].channels)
    if (c.joint == backTail && c.target == ChannelTarget::Rotation) keys = c.keyCount();
  EXPECT_GT(keys, 2) << "the tail has baked keys";
  SamplingCache a, b;
  for (long long f = 0; f <= last; f += 5) {
    Pose pe = Pose::rest(sk), pb = Pose::rest(back->skeleton);
    sampleClip(expected, ownFrameGrid(clip).frameToTime(f), pe, a);
    sampleClip(back->clips[0], ownFrameGrid(clip).frameToTime(f), pb, b);
    const std::vector<std::pair<int, int>> pairs = {{tail, backTail}, {sk.find("b_Tail02_013"), backTail2}};
    for (const auto& [je, jb] : pairs)
      EXPECT_GT(std::abs(glm::dot(pe.local[je].rotation, pb.local[jb].rotation)), 1.0f - 1e-6f) << "frame " << f;
  }
}

// A collision capsule for the tail: on Fox the script makes the tail dynamic, selects the
// left thigh, Simulate > Add Collision Capsule, types a new radius in the Simulation window,
// then undoes that edit: the capsule stays with its first radius (a quarter of the thigh's
// bone) and is drawn in the 3D view.
TEST_F(SimulationE2e, ACollisionCapsuleAddedOnALegSizedAndTheSizeUndone) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string fox = sharedDataDir() + "/gltf/Fox.glb";
  Script s(Script::Start::AsOpened);
  s.wait(2);
  s.clickItem("Outliner/Search").wait(1).type("Tail01").wait(2).clickItem("Outliner/b_Tail01_012").wait(1);
  s.menu("Simulate", "Make Chain Dynamic");
  s.clickItem("Outliner/Search").wait(1).chord("A", {"ctrl"}).type("LeftLeg01").wait(2);
  s.clickItem("Outliner/b_LeftLeg01_015").wait(1);
  s.menu("Simulate", "Add Collision Capsule").wait(2);
  s.clickItem("Simulation/Chain 0/Capsule 0/Radius", {0.2, 0.5}).wait(1).chord("A", {"ctrl"}).type("9").key("ENTER").wait(2);
  s.chord("Z", {"ctrl"}).wait(3);  // the radius edit undone
  const json d = runEditor(dir_, shotDir(), s, "fox_capsule", fox);
  ASSERT_TRUE(d.is_object());
  const json& chains = d["simulation"]["spring_chains"];
  ASSERT_EQ(chains.size(), 1u) << d["simulation"].dump();
  ASSERT_EQ(chains[0]["colliders"].size(), 1u) << chains.dump() << d["log"].dump();
  const json& capsule = chains[0]["colliders"][0];
  EXPECT_EQ(capsule["joint"], "b_LeftLeg01_015");
  // The default: from the thigh's joint to its child, radius a quarter of that bone.
  Result<Scene> loaded = loadScene(fox);
  ASSERT_TRUE(loaded);
  const Skeleton& sk = loaded->skeleton;
  const glm::vec3 bone = sk.rest[sk.find("b_LeftLeg02_016")].translation;
  EXPECT_NEAR(capsule["radius"].get<double>(), 0.25 * glm::length(bone), 1e-4 * glm::length(bone));
  EXPECT_NEAR(capsule["b"][1].get<double>(), bone.y, 1e-4 * glm::length(bone));
  EXPECT_EQ(d["undo_depth"], 2) << "make dynamic, add capsule (the radius edit undone)";
  EXPECT_EQ(d["redo_depth"], 1);
  EXPECT_TRUE(d["errors"].empty()) << d["errors"].dump();
}

}  // namespace
}  // namespace kinema::test
