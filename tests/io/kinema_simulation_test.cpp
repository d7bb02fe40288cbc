// .kinema files keep their dynamic chains (spring bones) and ragdolls (issue 23): an exact
// round trip of every setting, files without them written byte for byte as before, and bad
// values refused with one line naming the JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/kinema_file.h"
#include "test_support.h"
#include "io/kinema_refusals.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// Hips -> Spine -> Tail1 -> Tail2 -> Tail3, plus Leg under the hips.
Scene tailed() {
  Scene scene;
  Skeleton& s = scene.skeleton;
  s.addJoint("Hips", -1, Transform::fromTranslation({0, 1, 0}));
  s.addJoint("Spine", 0, Transform::fromTranslation({0, 0.2f, 0}));
  s.addJoint("Tail1", 0, Transform::fromTranslation({0, 0, -0.1f}));
  s.addJoint("Tail2", 2, Transform::fromTranslation({0, 0, -0.2f}));
  s.addJoint("Tail3", 3, Transform::fromTranslation({0, 0, -0.2f}));
  s.addJoint("Leg", 0, Transform::fromTranslation({0.1f, -0.5f, 0}));
  return scene;
}

Scene withSettings() {
  Scene scene = tailed();
  SpringBoneChain tail;
  tail.name = "tail";
  tail.joints = {2, 3, 4};
  // Values with no short decimal form, to catch a writer that rounds.
  tail.stiffness = 123.456789f;
  tail.damping = 0.1f / 3.0f;
  tail.drag = 1e-7f;
  tail.gravity = {0.0f, -9.81f, 1.0f / 7.0f};
  tail.radius = 0.0125f;
  SpringCollider body;
  body.joint = 1;
  body.a = {0.0f, -0.3f, 0.0f};
  body.b = {0.0f, 0.3f, 1.0f / 3.0f};
  body.radius = 0.15f;
  SpringCollider floor;  // in the world
  floor.a = {-10.0f, -0.5f, 0.0f};
  floor.b = {10.0f, -0.5f, 0.0f};
  floor.radius = 0.5f;
  tail.colliders = {body, floor};
  SpringBoneChain ear;  // defaults, one joint
  ear.name = "";
  ear.joints = {1};
  scene.simulation.springChains = {tail, ear};
  RagdollSettings fall;
  fall.name = "fall";
  fall.root = 5;
  fall.startFrame = 12;
  fall.mass = 71.3f;
  fall.gravity = {0.0f, -3.71f, 0.0f};
  fall.groundHeight = -0.25f;
  fall.friction = 0.55f;
  fall.restitution = 0.2f;
  fall.damping = 0.05f;
  scene.simulation.ragdolls = {fall};
  return scene;
}

TEST(KinemaSimulation, ChainsAndRagdollsRoundTripExactly) {
  const Scene scene = withSettings();
  ASSERT_EQ(scene.simulation.validate(scene.skeleton), "");
  const std::string text = toKinemaJson(scene);
  Result<Scene> back = parseKinemaJson(text, "rt.kinema");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->simulation.springChains.size(), 2u);
  EXPECT_TRUE(back->simulation.springChains[0] == scene.simulation.springChains[0]);
  EXPECT_TRUE(back->simulation.springChains[1] == scene.simulation.springChains[1]);
  ASSERT_EQ(back->simulation.ragdolls.size(), 1u);
  EXPECT_TRUE(back->simulation.ragdolls[0] == scene.simulation.ragdolls[0]);
  EXPECT_EQ(toKinemaJson(back.value()), text) << "a second save writes the same bytes";

  // The written form the format page documents: joints by name, a world collider without one.
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["simulation"]["spring_chains"][0]["joints"], nlohmann::json::array({"Tail1", "Tail2", "Tail3"}));
  EXPECT_EQ(j["simulation"]["spring_chains"][0]["colliders"][0]["joint"], "Spine");
  EXPECT_FALSE(j["simulation"]["spring_chains"][0]["colliders"][1].contains("joint"));
  EXPECT_EQ(j["simulation"]["ragdolls"][0]["root"], "Leg");
  EXPECT_EQ(j["simulation"]["ragdolls"][0]["start_frame"], 12);
}

TEST(KinemaSimulation, MembersLeftOutTakeTheDefaults) {
  const Scene scene = tailed();
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(toKinemaJson(scene));
  j["simulation"] = {{"spring_chains", {{{"joints", {"Tail1", "Tail2"}}}}}, {"ragdolls", {{{"root", "Hips"}}}}};
  Result<Scene> back = parseKinemaJson(j.dump(), "d.kinema");
  ASSERT_TRUE(back) << back.error();
  SpringBoneChain expected;
  expected.joints = {2, 3};
  EXPECT_TRUE(back->simulation.springChains.at(0) == expected);
  RagdollSettings ragdoll;
  ragdoll.root = 0;
  EXPECT_TRUE(back->simulation.ragdolls.at(0) == ragdoll);
}

TEST(KinemaSimulation, FilesWithoutSettingsStayByteForByte) {
  // The default character as shipped: written before simulation settings existed.
  const std::string path = std::string(KINEMA_SOURCE_DIR) + "/assets/default_character.kinema";
  const std::string before = test::readFile(path);
  Result<Scene> scene = parseKinemaJson(before, path);
  ASSERT_TRUE(scene) << scene.error();
  EXPECT_TRUE(scene->simulation.empty());
  EXPECT_EQ(toKinemaJson(scene.value()), before);
  // And a scene without settings never gains the key.
  EXPECT_EQ(toKinemaJson(tailed()).find("simulation"), std::string::npos);
}

TEST(KinemaSimulation, BadValuesAreOneLineNamingTheJsonPath) {
  const Scene scene = tailed();
  const nlohmann::ordered_json base = nlohmann::ordered_json::parse(toKinemaJson(scene));
  struct Case {
    nlohmann::ordered_json simulation;
    std::string expected;  // the start of the message after the file name
  };
  const nlohmann::ordered_json chain = {{"joints", {"Tail1", "Tail2"}}};
  auto chainWith = [&](const char* key, const nlohmann::ordered_json& v) {
    nlohmann::ordered_json c = chain;
    c[key] = v;
    return nlohmann::ordered_json{{"spring_chains", {c}}};
  };
  auto ragdollWith = [&](const char* key, const nlohmann::ordered_json& v) {
    nlohmann::ordered_json r = {{"root", "Hips"}};
    r[key] = v;
    return nlohmann::ordered_json{{"ragdolls", {r}}};
  };
  const std::vector<Case> cases = {
      {nlohmann::ordered_json::array(), "simulation: expected an object"},
      {{{"spring_chains", 3}}, "simulation.spring_chains: expected an array"},
      {{{"spring_chains", {{{"joints", {"Tail1", "Nope"}}}}}}, "simulation.spring_chains[0].joints[1]: no joint named 'Nope'"},
      {{{"spring_chains", {{{"joints", {"Tail1", "Tail3"}}}}}}, "simulation.spring_chains[0].joints[1]: 'Tail3' is not a child of 'Tail1'"},
      {{{"spring_chains", {{{"joints", nlohmann::ordered_json::array()}}}}}, "simulation.spring_chains[0].joints: expected a non-empty array"},
      {{{"spring_chains", {{{"name", "x"}}}}}, "simulation.spring_chains[0].joints: missing"},
      {chainWith("stiffness", -1), "simulation.spring_chains[0].stiffness: must be >= 0"},
      {chainWith("damping", "high"), "simulation.spring_chains[0].damping: expected a number, found string"},
      {chainWith("drag", -0.5), "simulation.spring_chains[0].drag: must be >= 0"},
      {chainWith("gravity", {0, -9.81}), "simulation.spring_chains[0].gravity: expected an array of 3 numbers"},
      {chainWith("colliders", {{{"a", {0, 0, 0}}, {"b", {0, 1, 0}}}}), "simulation.spring_chains[0].colliders[0].radius: missing"},
      {chainWith("colliders", {{{"a", {0, 0, 0}}, {"b", {0, 1, 0}}, {"radius", 0}}}),
       "simulation.spring_chains[0].colliders[0].radius: must be above 0"},
      {chainWith("colliders", {{{"joint", "Arm"}, {"a", {0, 0, 0}}, {"b", {0, 1, 0}}, {"radius", 1}}}),
       "simulation.spring_chains[0].colliders[0].joint: no joint named 'Arm'"},
      {{{"spring_chains", {chain, chain}}}, "simulation: spring chain '': joint 'Tail1' is already in chain ''"},
      {{{"ragdolls", {{{"name", "r"}}}}}, "simulation.ragdolls[0].root: missing"},
      {ragdollWith("start_frame", -2), "simulation.ragdolls[0].start_frame: must be 0 to 1000000000"},
      {ragdollWith("start_frame", 1.5), "simulation.ragdolls[0].start_frame: expected an integer, found number"},
      {ragdollWith("mass", 0), "simulation.ragdolls[0].mass: must be above 0"},
      {ragdollWith("restitution", 1.5), "simulation.ragdolls[0].restitution: must be 0 to 1"},
      {ragdollWith("damping", -0.1), "simulation.ragdolls[0].damping: must be 0 to 1"},
      {{{"ragdolls", {{{"root", "Hips"}}, {{"root", "Tail2"}, {"name", "b"}}}}},
       "simulation: ragdoll 'b': its joints overlap ragdoll ''"},
  };
  for (const Case& c : cases) test::expectSimulationRefused(base, c.simulation, c.expected);
}

TEST(KinemaSimulation, SavingRefusesSettingsThatDoNotFit) {
  Scene scene = withSettings();
  scene.simulation.springChains[0].joints = {2, 4};  // skips Tail2
  const std::string dir = test::makeTempDir();
  const std::string error = saveKinemaFile(dir + "/x.kinema", scene);
  EXPECT_NE(error.find("not saved: simulation: spring chain 'tail'"), std::string::npos) << error;
}

}  // namespace
}  // namespace kinema
