// Channel modifiers in .kinema (exact round trip, written only when present, errors that
// name the JSON path) and in export (glTF and BVH play what Kinema plays).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "anim/channel_modifiers.h"
#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "io/bvh.h"
#include "io/bvh_writer.h"
#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
#include "io/kinema_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Scene twoJoints() {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform::fromTranslation({0, 1, 0}));
  scene.skeleton.addJoint("arm", 0, Transform::fromTranslation({0.3f, 0, 0}));
  return scene;
}

// A clip with every kind of modifier and non-default, non-round parameters.
Scene modifiedScene() {
  Scene scene = twoJoints();
  Clip clip;
  clip.name = "procedural";
  clip.frameTime = 1.0 / 30;
  const glm::quat a = glm::angleAxis(0.3f, glm::normalize(glm::vec3(1, 2, 0))), b = glm::angleAxis(-0.7f, glm::vec3(0, 0, 1));
  clip.channels.emplace_back(1, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{{a.x, a.y, a.z, a.w}, {b.x, b.y, b.z, b.w}});
  clip.channels.emplace_back(0, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 0.4f, 1.0f},
                             std::vector<glm::vec4>{{0, 1, 0, 0}, {0.2f, 1.1f, 0, 0}, {0.1f, 1, 0.3f, 0}});
  ChannelModifier n;
  n.kind = ChannelModifierKind::Noise;
  n.noise.strength = 0.1f;
  n.noise.scale = 1.0f / 3.0f;
  n.noise.phase = -2.7f;
  n.noise.octaves = 5;
  n.noise.roughness = 0.35f;
  n.noise.seed = 4000000000u;
  n.components = 0x5;  // x and z
  ChannelModifier c;
  c.kind = ChannelModifierKind::Cycles;
  c.cycles.before = CycleMode::Mirror;
  c.cycles.after = CycleMode::RepeatWithOffset;
  c.cycles.afterCount = 3;
  c.enabled = false;
  ChannelModifier w;
  w.kind = ChannelModifierKind::Wave;
  w.wave.amplitude = 0.07f;
  w.wave.omega = 3.1f;
  w.wave.k = glm::vec3(0.1f, -1.7f, 0.0f);
  w.wave.phi = 0.9f;
  w.wave.position = glm::vec3(0.3f, 1.0f, 0.0f);
  clip.channels[0].modifiers = {c, n, w};
  n.components = 0x7;
  n.noise.seed = 9;
  clip.channels[1].modifiers = {n};
  scene.clips.push_back(clip);
  return scene;
}

TEST(KinemaFileModifiers, RoundTripIsExact) {
  const Scene scene = modifiedScene();
  const std::string text = toKinemaJson(scene);
  Result<Scene> back = parseKinemaJson(text, "m.kinema");
  ASSERT_TRUE(back.ok()) << back.error();
  ASSERT_EQ(back.value().clips.size(), 1u);
  for (size_t c = 0; c < 2; ++c) {
    const std::vector<ChannelModifier>& want = scene.clips[0].channels[c].modifiers;
    const std::vector<ChannelModifier>& got = back.value().clips[0].channels[c].modifiers;
    ASSERT_EQ(got.size(), want.size());
    for (size_t m = 0; m < want.size(); ++m) EXPECT_TRUE(got[m] == want[m]) << c << " " << m;  // float for float
  }
  EXPECT_EQ(toKinemaJson(back.value()), text);
  // What the file says, by name.
  const nlohmann::json j = nlohmann::json::parse(text);
  const nlohmann::json& m = j["clips"][0]["channels"][0]["modifiers"];
  EXPECT_EQ(m[0]["type"], "cycles");
  EXPECT_EQ(m[0]["enabled"], false);
  EXPECT_EQ(m[0]["after"], "repeat_offset");
  EXPECT_EQ(m[1]["components"], "xz");
  EXPECT_EQ(m[1]["seed"], 4000000000u);
  EXPECT_FALSE(m[1].contains("enabled"));
  EXPECT_EQ(m[2]["rest_position"].size(), 3u);
}

TEST(KinemaFileModifiers, FilesWithoutModifiersHaveNoModifiersKey) {
  Scene scene = modifiedScene();
  for (Channel& ch : scene.clips[0].channels) ch.modifiers.clear();
  const std::string text = toKinemaJson(scene);
  EXPECT_EQ(text.find("modifiers"), std::string::npos);
  Result<Scene> back = parseKinemaJson(text, "plain.kinema");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(toKinemaJson(back.value()), text);
  // The project's own saved asset reads and writes back byte for byte.
  const std::string path = std::string(KINEMA_SOURCE_DIR) + "/assets/default_character.kinema";
  const std::string original = test::readFile(path);
  Result<Scene> asset = parseKinemaJson(original, path);
  ASSERT_TRUE(asset.ok()) << asset.error();
  EXPECT_EQ(toKinemaJson(asset.value()), original);
}

TEST(KinemaFileModifiers, AWaveWithoutRestPositionTakesTheJointsFromTheSkeleton) {
  nlohmann::json j = nlohmann::json::parse(toKinemaJson(modifiedScene()));
  nlohmann::json& wave = j["clips"][0]["channels"][0]["modifiers"][2];
  wave.erase("rest_position");
  Result<Scene> back = parseKinemaJson(j.dump(), "w.kinema");
  ASSERT_TRUE(back.ok()) << back.error();
  // The arm: root (0, 1, 0) + (0.3, 0, 0).
  EXPECT_VEC3_NEAR(back.value().clips[0].channels[0].modifiers[2].wave.position, glm::vec3(0.3f, 1.0f, 0.0f), 1e-6f);
}

TEST(KinemaFileModifiers, BadModifiersGiveOneLineNamingThePath) {
  const std::string base = toKinemaJson(modifiedScene());
  const std::string at = "w.kinema: clips[0].channels[0].modifiers";
  struct Case {
    const char* patch;  // replaces modifiers[1] (the noise) of channel 0
    std::string error;
  };
  const std::vector<Case> cases = {
      {R"({"type": "wobble"})", at + "[1].type: 'wobble' is not one of noise, cycles, wave"},
      {R"({"strength": 1})", at + "[1].type: missing"},
      {R"({"type": "noise", "octaves": 9})", at + "[1].octaves: 9 is out of range (1 to 8)"},
      {R"({"type": "noise", "octaves": 2.5})", at + "[1].octaves: expected an integer, found number"},
      {R"({"type": "noise", "strength": -1})", at + "[1].strength: must not be negative"},
      {R"({"type": "noise", "scale": 0})", at + "[1].scale: must be positive (seconds per noise cell)"},
      {R"({"type": "noise", "roughness": 1.5})", at + "[1].roughness: must be in [0, 1]"},
      {R"({"type": "noise", "seed": -1})", at + "[1].seed: -1 is out of range (0 to 4294967295)"},
      {R"({"type": "noise", "components": "xq"})", at + "[1].components: 'xq' is not a set of distinct letters from x, y, z, w"},
      {R"({"type": "noise", "components": ""})", at + "[1].components: names no component (letters from x, y, z, w)"},
      {R"({"type": "cycles", "after": "bounce"})", at + "[1].after: 'bounce' is not one of hold, repeat, repeat_offset, mirror"},
      {R"({"type": "cycles"})", at + ": modifier 2: a channel takes one Cycles modifier"},
      {R"({"type": "cycles", "before_count": -2})", at + "[1].before_count: -2 is out of range (0 to 2147483647)"},
      {R"({"type": "wave", "k": [1, 2]})", at + "[1].k: expected an array of 3 numbers"},
      {R"({"type": "wave", "amplitude": 1e39})", at + "[1].amplitude: number out of float range"},
      {R"({"type": "noise", "enabled": 1})", at + "[1].enabled: expected true or false, found number"},
      {R"(7)", at + "[1]: expected an object"},
  };
  for (const Case& c : cases) {
    nlohmann::json j = nlohmann::json::parse(base);
    j["clips"][0]["channels"][0]["modifiers"][1] = nlohmann::json::parse(c.patch);
    Result<Scene> r = parseKinemaJson(j.dump(), "w.kinema");
    ASSERT_FALSE(r.ok()) << c.patch;
    EXPECT_EQ(r.error(), c.error);
    EXPECT_EQ(r.error().find('\n'), std::string::npos);
  }
  nlohmann::json j = nlohmann::json::parse(base);
  j["clips"][0]["channels"][0]["modifiers"] = "noise";
  Result<Scene> r = parseKinemaJson(j.dump(), "w.kinema");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), at + ": expected an array of modifier objects");
}

// Kinema's world positions of every joint at time t.
std::vector<glm::vec3> positions(const Scene& s, float t) {
  Pose pose = Pose::rest(s.skeleton);
  sampleClip(s.clips[0], t, pose);
  std::vector<glm::vec3> out;
  for (const glm::mat4& m : computeWorld(s.skeleton, pose)) out.emplace_back(m[3]);
  return out;
}

TEST(KinemaFileModifiers, GltfExportBakesTheModifiedMotion) {
  Scene scene = modifiedScene();
  scene.clips[0].channels[0].modifiers[0].enabled = true;  // cycles on too (inside the range: no change)
  std::vector<std::string> report;
  Result<std::string> bytes = gltfBytes(scene, GltfWriteOptions(), &report);
  ASSERT_TRUE(bytes.ok()) << bytes.error();
  bool said = false;
  for (const std::string& line : report) said |= line.find("channel modifiers baked to keys at 30 fps") != std::string::npos;
  EXPECT_TRUE(said);
  Result<Scene> back = parseGltf(bytes.value(), "m.gltf");
  ASSERT_TRUE(back.ok()) << back.error();
  ASSERT_EQ(back.value().clips.size(), 1u);
  ASSERT_EQ(back.value().skeleton.names, scene.skeleton.names);
  double largest = 0.0, modified = 0.0;
  for (int f = 0; f <= 30; ++f) {
    const float t = ownFrameGrid(scene.clips[0]).frameToTime(f);
    // The local rotation of the arm and translation of the root, as both programs play them.
    Pose a = Pose::rest(scene.skeleton), b = Pose::rest(back.value().skeleton);
    sampleClip(scene.clips[0], t, a);
    sampleClip(back.value().clips[0], t, b);
    EXPECT_SAME_ROTATION(a.local[1].rotation, b.local[1].rotation, 1e-4f);
    EXPECT_VEC3_NEAR(a.local[0].translation, b.local[0].translation, 1e-4f);
    const std::vector<glm::vec3> pa = positions(scene, t), pb = positions(back.value(), t);
    for (size_t j = 0; j < pa.size(); ++j) largest = std::max(largest, double(glm::length(pa[j] - pb[j])));
    // Against the keys alone: the noise really moved the root.
    modified = std::max(modified, double(glm::length(a.local[0].translation - glm::vec3(sampleChannel(scene.clips[0].channels[1], t)))));
  }
  EXPECT_LT(largest, 1e-4);
  EXPECT_GT(modified, 0.02);
}

TEST(KinemaFileModifiers, BvhExportWritesTheModifiedMotion) {
  const Scene scene = modifiedScene();
  Result<std::string> text = bvhText(scene.skeleton, &scene.clips[0], BvhWriteOptions());
  ASSERT_TRUE(text.ok()) << text.error();
  Result<BvhData> back = parseBvh(text.value(), "m.bvh");
  ASSERT_TRUE(back.ok()) << back.error();
  Scene read;
  read.skeleton = back.value().skeleton();
  read.clips = {back.value().clip()};
  for (int f = 0; f <= 30; ++f) {
    const float t = ownFrameGrid(scene.clips[0]).frameToTime(f);
    const std::vector<glm::vec3> pa = positions(scene, t), pb = positions(read, t);
    ASSERT_EQ(pa.size(), 2u);
    ASSERT_GE(pb.size(), 2u);
    for (size_t j = 0; j < 2; ++j) EXPECT_VEC3_NEAR(pa[j], pb[j], 1e-4f);
  }
}

}  // namespace
}  // namespace kinema
