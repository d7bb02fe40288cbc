// .kinema clips keep their foot contacts and the bone map they were retargeted through
// (issue 21): an exact round trip, files written before load unchanged, and bad values refused
// with one line naming the JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "anim/clip.h"
#include "io/kinema_file.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Scene legs() {
  Scene scene;
  scene.skeleton.addJoint("Hips", -1, Transform::fromTranslation({0, 1, 0}));
  scene.skeleton.addJoint("UpperLeg.L", 0, Transform::fromTranslation({0.1f, 0, 0}));
  scene.skeleton.addJoint("UpperLeg.R", 0, Transform::fromTranslation({-0.1f, 0, 0}));
  Clip clip;
  clip.name = "walk";
  clip.frameTime = 1.0 / 120;
  clip.channels.emplace_back(0, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{glm::vec4(0, 1, 0, 0), glm::vec4(0, 1, 1, 0)});
  scene.clips.push_back(clip);
  return scene;
}

std::string withClipMember(const Scene& scene, const std::string& key, const nlohmann::json& value) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(toKinemaJson(scene));
  j["clips"][0][key] = value;
  return j.dump();
}

TEST(KinemaContacts, ContactsAndBoneMapRoundTripExactly) {
  Scene scene = legs();
  Clip& clip = scene.clips[0];
  // Touching intervals stay two; frame 0 and a large frame survive; an empty foot list too.
  clip.contacts.of(Foot::Left) = {{0, 0}, {1, 14}, {15, 40}, {90, 2000000000}};
  clip.contacts.of(Foot::Right) = {};
  clip.sourceMap.file = "../shared/data/bvh/cmu 01.bvh";
  clip.sourceMap.clip = 3;
  // Source names that are no joints here; target order not sorted (kept as given).
  clip.sourceMap.pairs = {{"RightUpLeg", 2}, {"Hips", 0}, {"LeftUpLeg", 1}};
  ASSERT_EQ(clip.validate(scene.skeleton), "");

  const std::string text = toKinemaJson(scene);
  Result<Scene> back = parseKinemaJson(text, "rt.kinema");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->clips.size(), 1u);
  EXPECT_EQ(back->clips[0].contacts, clip.contacts);
  EXPECT_EQ(back->clips[0].sourceMap, clip.sourceMap);
  EXPECT_EQ(toKinemaJson(back.value()), text) << "a second save writes the same bytes";

  // The written form the format page documents: [first, last] pairs and name pairs.
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["clips"][0]["foot_contacts"]["left"][1], nlohmann::json::array({1, 14}));
  EXPECT_TRUE(j["clips"][0]["foot_contacts"]["right"].empty());
  EXPECT_EQ(j["clips"][0]["bone_map"]["pairs"][0], nlohmann::json::array({"RightUpLeg", "UpperLeg.R"}));
  EXPECT_EQ(j["clips"][0]["bone_map"]["clip"], 3);
}

TEST(KinemaContacts, TargetJointsAreSavedByTheirCurrentName) {
  Scene scene = legs();
  scene.clips[0].sourceMap.pairs = {{"LeftUpLeg", 1}};
  scene.skeleton.names[1] = "thigh.L";  // a rename in the editor: the index stays, the name follows
  const nlohmann::json j = nlohmann::json::parse(toKinemaJson(scene));
  EXPECT_EQ(j["clips"][0]["bone_map"]["pairs"][0][1], "thigh.L");
}

TEST(KinemaContacts, FilesWithoutThemLoadAsBefore) {
  const Scene scene = legs();
  const std::string text = toKinemaJson(scene);
  EXPECT_EQ(text.find("foot_contacts"), std::string::npos) << "nothing written for a clip without contacts";
  EXPECT_EQ(text.find("bone_map"), std::string::npos);
  // A version-1 clip as written before issue 21 (no such keys).
  const std::string old = R"({"format": "kinema", "version": 1,
    "skeleton": {"joints": [{"name": "Hips", "parent": -1}]},
    "clips": [{"name": "m", "channels": [{"joint": "Hips", "target": "rotation", "times": [0], "values": [[0, 0, 0, 1]]}]}]})";
  Result<Scene> loaded = parseKinemaJson(old, "old.kinema");
  ASSERT_TRUE(loaded) << loaded.error();
  EXPECT_TRUE(loaded->clips[0].contacts.empty());
  EXPECT_TRUE(loaded->clips[0].sourceMap.empty());
}

TEST(KinemaContacts, BadValuesAreOneLineNamingThePlace) {
  const Scene scene = legs();
  struct Case {
    const char* key;
    nlohmann::json value;
    const char* message;
  };
  using J = nlohmann::json;
  const Case cases[] = {
      {"foot_contacts", J::array(), "bad.kinema: clips[0].foot_contacts: expected an object with \"left\" and \"right\" lists"},
      {"foot_contacts", J{{"left", J::array({J::array({5, 3})})}},
       "bad.kinema: clips[0].foot_contacts.left[0]: ends (frame 3) before it starts (frame 5)"},
      {"foot_contacts", J{{"right", J::array({J::array({0, 9}), J::array({9, 12})})}},
       "bad.kinema: clips[0].foot_contacts.right[1]: starts at frame 9, not after the previous contact ends (frame 9)"},
      {"foot_contacts", J{{"left", J::array({J::array({-1, 3})})}},
       "bad.kinema: clips[0].foot_contacts.left[0][0]: frame -1 is outside 0..2147483647"},
      {"foot_contacts", J{{"left", J::array({J::array({1.5, 3})})}},
       "bad.kinema: clips[0].foot_contacts.left[0][0]: expected an integer, found number"},
      {"foot_contacts", J{{"left", J::array({J::array({1, 2, 3})})}},
       "bad.kinema: clips[0].foot_contacts.left[0]: expected [first, last] (two frame numbers)"},
      {"bone_map", J{{"file", "a.bvh"}},
       "bad.kinema: clips[0].bone_map.pairs: missing"},
      {"bone_map", J{{"pairs", J::array()}},
       "bad.kinema: clips[0].bone_map.pairs: expected a non-empty array of [source joint, target joint] pairs"},
      {"bone_map", J{{"pairs", J::array({J::array({"LeftUpLeg", "Shin.L"})})}},
       "bad.kinema: clips[0].bone_map.pairs[0][1]: no joint named 'Shin.L'"},
      {"bone_map", J{{"pairs", J::array({J::array({"A", "Hips"}), J::array({"A", "UpperLeg.L"})})}},
       "bad.kinema: clips[0].bone_map.pairs[1][0]: source joint 'A' is mapped twice"},
      {"bone_map", J{{"pairs", J::array({J::array({"A", "Hips"}), J::array({"B", "Hips"})})}},
       "bad.kinema: clips[0].bone_map.pairs[1][1]: joint 'Hips' is mapped twice"},
      {"bone_map", J{{"pairs", J::array({J::array({"", "Hips"})})}},
       "bad.kinema: clips[0].bone_map.pairs[0][0]: empty source joint name"},
      {"bone_map", J{{"clip", -2}, {"pairs", J::array({J::array({"A", "Hips"})})}},
       "bad.kinema: clips[0].bone_map.clip: clip -2 is outside 0..2147483647"},
  };
  for (const Case& c : cases) {
    Result<Scene> r = parseKinemaJson(withClipMember(scene, c.key, c.value), "bad.kinema");
    ASSERT_FALSE(r) << c.message;
    EXPECT_EQ(r.error(), c.message);
    EXPECT_EQ(r.error().find('\n'), std::string::npos);
  }
}

TEST(KinemaContacts, ClipValidationRefusesWhatTheReaderRefuses) {
  const Scene scene = legs();
  Clip clip = scene.clips[0];
  clip.contacts.of(Foot::Right) = {{4, 8}, {8, 9}};
  EXPECT_NE(clip.validate(scene.skeleton), "");
  clip.contacts = {};
  clip.sourceMap.pairs = {{"A", 7}};
  EXPECT_NE(clip.validate(scene.skeleton), "") << "joint 7 does not exist";
  clip.sourceMap.pairs = {{"A", 0}, {"B", 0}};
  EXPECT_NE(clip.validate(scene.skeleton), "");
  clip.sourceMap.pairs = {{"A", 0}, {"B", 1}};
  EXPECT_EQ(clip.validate(scene.skeleton), "");
}

}  // namespace
}  // namespace kinema
