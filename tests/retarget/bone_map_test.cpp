// The humanoid reading of real files (by names, and by topology for CesiumMan), the map
// onto the default character, and bone map files. Expected joints were read off each
// file's hierarchy by hand.
#include <gtest/gtest.h>

#include <map>

#include "core/default_character.h"
#include "io/bone_map_file.h"
#include "io/bvh.h"
#include "io/gltf_reader.h"
#include "io/message_text.h"
#include "io/scene_files.h"
#include "retarget/bone_map.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using Expected = std::map<std::string, std::string>;  // canonical bone -> joint name

void expectReading(const Skeleton& s, const Expected& expected, HumanoidSource how, const std::string& file) {
  const Result<HumanoidReading> r = findHumanoid(s);
  ASSERT_TRUE(r.ok()) << file << ": " << r.error();
  EXPECT_EQ(r->source, how) << file;
  for (int i = 0; i < kHumanoidBoneCount; ++i) {
    const std::string bone = toString(humanoidBone(i));
    const int j = r->bones.joint[i];
    const auto e = expected.find(bone);
    if (e == expected.end()) {
      EXPECT_EQ(j, -1) << file << ": " << bone << " should be unmapped, got " << (j >= 0 ? s.names[j] : "");
    } else {
      ASSERT_GE(j, 0) << file << ": " << bone << " unmapped, expected " << e->second;
      EXPECT_EQ(s.names[j], e->second) << file << ": " << bone;
    }
  }
  // Onto the default character every canonical bone the source has (and the default
  // character has: it has no fingers) is paired.
  const Skeleton character = makeDefaultCharacter();
  const Result<HumanoidReading> d = findHumanoid(character);
  ASSERT_TRUE(d.ok()) << d.error();
  const BoneMap map = mapThroughHumanoid(r->bones, d->bones);
  EXPECT_EQ(map.validate(s, character), "") << file;
  for (const auto& [bone, joint] : expected) {
    const HumanoidBone b = *humanoidBoneFromString(bone);
    if (isFinger(b)) continue;
    EXPECT_EQ(map.targetOf(s.find(joint)), d->bones[b]) << file << ": " << bone;
  }
}

Expected sides(const Expected& left) {
  Expected out;
  for (const auto& [bone, joint] : left) {
    out[bone] = joint;
    if (bone.rfind("Left", 0) != 0) continue;
    std::string j = joint;
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"Left", "Right"}, {"_L", "_R"}, {".L", ".R"}, {"L", "R"}, {"l", "r"}}) {
      const size_t at = j.find(from);
      if (at != std::string::npos) {
        j.replace(at, from.size(), to);
        break;
      }
    }
    out["Right" + bone.substr(4)] = j;
  }
  return out;
}

Skeleton bvhSkeleton(const std::string& name) {
  const Result<Scene> s = loadScene(sharedDataDir() + "/bvh/" + name);
  EXPECT_TRUE(s.ok()) << s.error();
  return s.ok() ? s->skeleton : Skeleton{};
}

TEST(RetargetBoneMap, DefaultCharacterByNames) {
  expectReading(makeDefaultCharacter(),
                sides({{"Hips", "Hips"}, {"Spine", "Spine"}, {"Chest", "Chest"}, {"UpperChest", "UpperChest"},
                       {"Neck", "Neck"}, {"Head", "Head"}, {"LeftShoulder", "Shoulder.L"},
                       {"LeftUpperArm", "UpperArm.L"}, {"LeftLowerArm", "LowerArm.L"}, {"LeftHand", "Hand.L"},
                       {"LeftUpperLeg", "UpperLeg.L"}, {"LeftLowerLeg", "LowerLeg.L"}, {"LeftFoot", "Foot.L"},
                       {"LeftToes", "Toe.L"}}),
                HumanoidSource::Names, "default character");
}

TEST(RetargetBoneMap, CmuByNames) {
  KINEMA_REQUIRE_SHARED_DATA();
  expectReading(bvhSkeleton("cmu_01_01_first720.bvh"),
                sides({{"Hips", "Hips"}, {"Spine", "LowerBack"}, {"Chest", "Spine"}, {"UpperChest", "Spine1"},
                       {"Neck", "Neck"}, {"Head", "Head"}, {"LeftShoulder", "LeftShoulder"},
                       {"LeftUpperArm", "LeftArm"}, {"LeftLowerArm", "LeftForeArm"}, {"LeftHand", "LeftHand"},
                       {"LeftUpperLeg", "LeftUpLeg"}, {"LeftLowerLeg", "LeftLeg"}, {"LeftFoot", "LeftFoot"},
                       {"LeftToes", "LeftToeBase"}}),
                HumanoidSource::Names, "cmu");
}

TEST(RetargetBoneMap, Games105ByNames) {
  KINEMA_REQUIRE_SHARED_DATA();
  expectReading(bvhSkeleton("games105_walk60.bvh"),
                sides({{"Hips", "RootJoint"}, {"Spine", "pelvis_lowerback"}, {"Chest", "lowerback_torso"},
                       {"Head", "torso_head"}, {"LeftShoulder", "lTorso_Clavicle"}, {"LeftUpperArm", "lShoulder"},
                       {"LeftLowerArm", "lElbow"}, {"LeftHand", "lWrist"}, {"LeftUpperLeg", "lHip"},
                       {"LeftLowerLeg", "lKnee"}, {"LeftFoot", "lAnkle"}, {"LeftToes", "lToeJoint"}}),
                HumanoidSource::Names, "games105");
}

TEST(RetargetBoneMap, MocapBankCollarMakesShoulderTheUpperArm) {
  KINEMA_REQUIRE_SHARED_DATA();
  expectReading(bvhSkeleton("mocapbank_test.bvh"),
                sides({{"Hips", "Hips"}, {"Spine", "Chest"}, {"Chest", "Chest2"}, {"Neck", "Neck"}, {"Head", "Head"},
                       {"LeftShoulder", "LeftCollar"}, {"LeftUpperArm", "LeftShoulder"}, {"LeftLowerArm", "LeftElbow"},
                       {"LeftHand", "LeftWrist"}, {"LeftUpperLeg", "LeftHip"}, {"LeftLowerLeg", "LeftKnee"},
                       {"LeftFoot", "LeftAnkle"}}),
                HumanoidSource::Names, "mocapbank");
}

TEST(RetargetBoneMap, GenoWithFingers) {
  KINEMA_REQUIRE_SHARED_DATA();
  Expected e{{"Hips", "Hips"}, {"Spine", "Spine"}, {"Chest", "Spine1"}, {"UpperChest", "Spine3"}, {"Neck", "Neck"},
             {"Head", "Head"}, {"LeftShoulder", "LeftShoulder"}, {"LeftUpperArm", "LeftArm"},
             {"LeftLowerArm", "LeftForeArm"}, {"LeftHand", "LeftHand"}, {"LeftUpperLeg", "LeftUpLeg"},
             {"LeftLowerLeg", "LeftLeg"}, {"LeftFoot", "LeftFoot"}, {"LeftToes", "LeftToeBase"}};
  const char* fingers[][2] = {{"Thumb", "Thumb"}, {"Index", "Index"}, {"Middle", "Middle"}, {"Ring", "Ring"},
                              {"Little", "Pinky"}};
  const char* segments[] = {"Proximal", "Intermediate", "Distal"};
  for (const auto& f : fingers)
    for (int k = 0; k < 3; ++k)
      e[std::string("Left") + f[0] + segments[k]] = std::string("LeftHand") + f[1] + std::to_string(k + 1);
  expectReading(bvhSkeleton("geno_bind.bvh"), sides(e), HumanoidSource::Names, "geno");
}

TEST(RetargetBoneMap, CesiumManByTopology) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Result<Scene> s = loadGltf(sharedDataDir() + "/gltf/CesiumMan.glb");
  ASSERT_TRUE(s.ok()) << s.error();
  expectReading(s->skeleton,
                {{"Hips", "Skeleton_torso_joint_1"}, {"Spine", "Skeleton_torso_joint_2"}, {"Chest", "torso_joint_3"},
                 {"Neck", "Skeleton_neck_joint_1"}, {"Head", "Skeleton_neck_joint_2"},
                 {"LeftUpperArm", "Skeleton_arm_joint_L__4_"}, {"LeftLowerArm", "Skeleton_arm_joint_L__3_"},
                 {"LeftHand", "Skeleton_arm_joint_L__2_"}, {"RightUpperArm", "Skeleton_arm_joint_R"},
                 {"RightLowerArm", "Skeleton_arm_joint_R__2_"}, {"RightHand", "Skeleton_arm_joint_R__3_"},
                 {"LeftUpperLeg", "leg_joint_L_1"}, {"LeftLowerLeg", "leg_joint_L_2"}, {"LeftFoot", "leg_joint_L_3"},
                 {"RightUpperLeg", "leg_joint_R_1"}, {"RightLowerLeg", "leg_joint_R_2"},
                 {"RightFoot", "leg_joint_R_3"}},
                HumanoidSource::Topology, "CesiumMan");
}

TEST(RetargetBoneMap, FoxIsNoHumanoid) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Result<Scene> s = loadGltf(sharedDataDir() + "/gltf/Fox.glb");
  ASSERT_TRUE(s.ok()) << s.error();
  const Result<HumanoidReading> r = findHumanoid(s->skeleton);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("no humanoid found"), std::string::npos) << r.error();
}

// The default character renamed into other conventions reads the same.
Skeleton renamed(const std::map<std::string, std::string>& names) {
  Skeleton s = makeDefaultCharacter();
  for (std::string& n : s.names) {
    const auto it = names.find(n);
    if (it != names.end()) n = it->second;
  }
  return s;
}

TEST(RetargetBoneMap, MixamoAndRigifyConventions) {
  const Skeleton character = makeDefaultCharacter();
  const Result<HumanoidReading> reference = findHumanoid(character);
  ASSERT_TRUE(reference.ok());
  const std::map<std::string, std::string> mixamo = {
      {"Hips", "mixamorig:Hips"}, {"Spine", "mixamorig:Spine"}, {"Chest", "mixamorig:Spine1"},
      {"UpperChest", "mixamorig:Spine2"}, {"Neck", "mixamorig:Neck"}, {"Head", "mixamorig:Head"},
      {"HeadTop", "mixamorig:HeadTop_End"}, {"Shoulder.L", "mixamorig:LeftShoulder"},
      {"UpperArm.L", "mixamorig:LeftArm"}, {"LowerArm.L", "mixamorig:LeftForeArm"}, {"Hand.L", "mixamorig:LeftHand"},
      {"UpperLeg.L", "mixamorig:LeftUpLeg"}, {"LowerLeg.L", "mixamorig:LeftLeg"}, {"Foot.L", "mixamorig:LeftFoot"},
      {"Toe.L", "mixamorig:LeftToeBase"}, {"Shoulder.R", "mixamorig:RightShoulder"},
      {"UpperArm.R", "mixamorig:RightArm"}, {"LowerArm.R", "mixamorig:RightForeArm"},
      {"Hand.R", "mixamorig:RightHand"}, {"UpperLeg.R", "mixamorig:RightUpLeg"}, {"LowerLeg.R", "mixamorig:RightLeg"},
      {"Foot.R", "mixamorig:RightFoot"}, {"Toe.R", "mixamorig:RightToeBase"}};
  const std::map<std::string, std::string> rigify = {
      {"Hips", "spine"}, {"Spine", "spine.001"}, {"Chest", "spine.002"}, {"UpperChest", "spine.003"},
      {"Neck", "spine.004"}, {"Head", "spine.006"}, {"Shoulder.L", "shoulder.L"}, {"UpperArm.L", "upper_arm.L"},
      {"LowerArm.L", "forearm.L"}, {"Hand.L", "hand.L"}, {"UpperLeg.L", "thigh.L"}, {"LowerLeg.L", "shin.L"},
      {"Foot.L", "foot.L"}, {"Toe.L", "toe.L"}, {"Shoulder.R", "shoulder.R"}, {"UpperArm.R", "upper_arm.R"},
      {"LowerArm.R", "forearm.R"}, {"Hand.R", "hand.R"}, {"UpperLeg.R", "thigh.R"}, {"LowerLeg.R", "shin.R"},
      {"Foot.R", "foot.R"}, {"Toe.R", "toe.R"}};
  for (const auto* names : {&mixamo, &rigify}) {
    const Result<HumanoidReading> r = findHumanoid(renamed(*names));
    ASSERT_TRUE(r.ok()) << r.error();
    // Rigify calls neck and head "spine.004" and "spine.006": its reading comes from the
    // hierarchy, and must agree all the same.
    for (int i = 0; i < kHumanoidBoneCount; ++i)
      EXPECT_EQ(r->bones.joint[i], reference->bones.joint[i]) << toString(humanoidBone(i));
  }
}

TEST(RetargetBoneMap, ReversedHierarchyIsIncompatible) {
  const Skeleton s = makeDefaultCharacter();
  BoneMap map;
  map.pairs = {{s.find("UpperArm.L"), s.find("LowerArm.L")}, {s.find("LowerArm.L"), s.find("UpperArm.L")}};
  EXPECT_NE(map.validate(s, s).find("incompatible skeletons"), std::string::npos) << map.validate(s, s);
  map.pairs = {{0, 1}, {0, 2}};
  EXPECT_NE(map.validate(s, s).find("mapped twice"), std::string::npos);
}

class RetargetMapFile : public ::testing::Test {
 protected:
  Skeleton source = makeDefaultCharacter();
  Skeleton target = makeDefaultCharacter();
  HumanoidMap human = findHumanoid(source).value().bones;
  BoneMapSide from{&source, &human, "the source (a.bvh)"};
  BoneMapSide to{&target, &human, "the target (b.glb)"};
  Result<BoneMap> parse(const std::string& text) { return parseBoneMapJson(text, "map.json", from, to); }
};

TEST_F(RetargetMapFile, JointAndCanonicalNames) {
  const Result<BoneMap> m = parse(R"({"Hips": "Hips", "LeftUpperLeg": "UpperLeg.L", "LowerLeg.L": "LeftLowerLeg"})");
  ASSERT_TRUE(m.ok()) << m.error();
  ASSERT_EQ(m->pairs.size(), 3u);
  EXPECT_EQ(m->targetOf(source.find("UpperLeg.L")), target.find("UpperLeg.L"));
  EXPECT_EQ(m->targetOf(source.find("LowerLeg.L")), target.find("LowerLeg.L"));
  EXPECT_EQ(boneMapJson(m.value(), source, target).dump(), R"({"Hips":"Hips","UpperLeg.L":"UpperLeg.L","LowerLeg.L":"LowerLeg.L"})");
}

TEST_F(RetargetMapFile, ErrorsNameTheFileAndKey) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"Hips": "Nope"})", R"(map.json: "Hips": the target (b.glb) has no joint or humanoid bone named 'Nope')"},
      {R"({"Nope": "Hips"})", R"(map.json: "Nope": the source (a.bvh) has no joint or humanoid bone named 'Nope')"},
      {R"({"Hips": 3})", R"(map.json: "Hips": expected a target joint name (a string))"},
      {R"({"Hips": "Hips", "Spine": "Hips"})", R"(map.json: "Spine": target joint 'Hips' is already mapped from 'Hips')"},
      {R"(["Hips"])", "map.json: expected a JSON object from source joint names to target joint names"},
      {R"({})", "map.json: the map pairs no joints"},
  };
  for (const auto& [text, message] : cases) {
    const Result<BoneMap> m = parse(text);
    ASSERT_FALSE(m.ok()) << text;
    EXPECT_EQ(m.error(), message);
  }
  const Result<BoneMap> syntax = parse("{\"Hips\": ");
  ASSERT_FALSE(syntax.ok());
  EXPECT_EQ(syntax.error().rfind("map.json: not valid JSON: line 1", 0), 0u) << syntax.error();
  // A megabyte-long name is cut in the message, which stays one short line.
  const Result<BoneMap> huge = parse("{\"" + std::string(1 << 20, 'x') + "\": \"Hips\"}");
  ASSERT_FALSE(huge.ok());
  EXPECT_LE(huge.error().size(), kMaxMessageBytes) << huge.error().substr(0, 400);
  EXPECT_NE(huge.error().find("\xE2\x80\xA6"), std::string::npos) << "cut with an ellipsis";
}

}  // namespace
}  // namespace kinema::test
