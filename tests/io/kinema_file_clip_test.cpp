// .kinema clips with every interpolation setting: exact round trips, version-1 files
// from before the keyframe engine, and errors that name the JSON path.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "anim/clip.h"
#include "io/kinema_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

Scene everySetting() {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform::fromTranslation({0, 1, 0}));
  scene.skeleton.addJoint("arm", 0, Transform::fromTranslation({0.3f, 0, 0}));
  Clip clip;
  clip.name = "all modes";
  clip.loop = true;
  clip.frameTime = 1.0 / 24;
  auto channel = [](int joint, ChannelTarget target, Interpolation mode) {
    Channel c;
    c.joint = joint;
    c.target = target;
    c.interpolation = mode;
    return c;
  };
  // Translation: one key per scalar mode, each with distinctive settings.
  Channel t = channel(0, ChannelTarget::Translation, Interpolation::Bezier);
  const Interpolation modes[] = {Interpolation::Step, Interpolation::Linear, Interpolation::Hermite,
                                 Interpolation::CatmullRom, Interpolation::TCB, Interpolation::Bezier,
                                 Interpolation::Ease};
  for (int k = 0; k < 7; ++k) {
    KeySettings s;
    s.interpolation = modes[k];
    s.easing = static_cast<EasingFunction>(k % 10);
    s.easingMode = static_cast<EasingMode>(k % 3);
    s.tension = 0.1f * k - 0.3f;
    s.continuity = 1.0f / 3.0f;
    s.bias = -0.7f + k * 1e-7f;
    s.inTangent = glm::vec4(k, -1.0f / 7, 1e-30f, 0);
    s.outTangent = glm::vec4(3.4e38f, 0.1f, -0.0f, 0);
    s.leftHandleType = static_cast<HandleType>(k % 5);
    s.rightHandleType = static_cast<HandleType>((k + 2) % 5);
    s.leftHandleTime = -0.1f * k;
    s.rightHandleTime = 0.2f / (k + 1);
    s.leftHandleValue = glm::vec4(0.5f, -0.25f, 1e-8f, 0);
    s.rightHandleValue = glm::vec4(-0.5f, 2.5f, 7.0f, 0);
    t.times.push_back(0.1f * k + 1.0f / 3.0f);
    t.values.emplace_back(k, k * k, -k / 3.0f, 0.0f);
    t.keys.push_back(s);
  }
  clip.channels.push_back(t);
  // Rotation: every rotation mode.
  Channel r = channel(1, ChannelTarget::Rotation, Interpolation::Squad);
  const Interpolation rmodes[] = {Interpolation::Step, Interpolation::Linear, Interpolation::Nlerp,
                                  Interpolation::Squad, Interpolation::Hermite, Interpolation::Ease,
                                  Interpolation::Bezier};
  for (int k = 0; k < 7; ++k) {
    KeySettings s;
    s.interpolation = rmodes[k];
    if (k == 6) {  // quaternion F-curve handles: four components
      s.leftHandleType = HandleType::Free;
      s.leftHandleTime = -0.1f;
      s.leftHandleValue = glm::vec4(0.01f, -0.02f, 0.03f, -0.04f);
    }
    s.outTangent = glm::vec4(0.1f, 0.2f, 0.3f, 0.4f * k);
    s.inTangent = glm::vec4(-0.1f, 0, 0, 1);
    const glm::quat q = glm::normalize(glm::quat(1.0f, 0.1f * k, -0.2f, 0.05f * k));
    r.times.push_back(0.25f * k);
    r.values.emplace_back(q.x, q.y, q.z, q.w);
    r.keys.push_back(s);
  }
  clip.channels.push_back(r);
  Channel e = channel(1, ChannelTarget::Euler, Interpolation::CatmullRom);
  e.eulerOrder = EulerOrder::YZX;
  e.times = {0, 1};
  e.values = {{0.1f, 0.2f, 0.3f, 0}, {7.0f, -6.5f, 0, 0}};
  clip.channels.push_back(e);
  Channel sc = channel(-1, ChannelTarget::Scalar, Interpolation::Ease);
  sc.property = "blend shape: smile";
  sc.times = {0, 0.5f};
  sc.values = {{0.25f, 0, 0, 0}, {1, 0, 0, 0}};
  clip.channels.push_back(sc);
  Channel sc2 = channel(0, ChannelTarget::Scale, Interpolation::Step);  // old-style: no per-key settings
  sc2.times = {0};
  sc2.values = {{1, 2, 3, 0}};
  clip.channels.push_back(sc2);
  scene.clips.push_back(clip);
  return scene;
}

TEST(KinemaFileClips, EveryInterpolationSettingRoundTripsExactly) {
  const Scene a = everySetting();
  ASSERT_EQ(a.clips[0].validate(a.skeleton), "");
  const std::string text = toKinemaJson(a);
  Result<Scene> loaded = parseKinemaJson(text, "all.kinema");
  ASSERT_TRUE(loaded) << loaded.error();
  const Clip &x = a.clips[0], &y = loaded.value().clips[0];
  EXPECT_EQ(y.name, x.name);
  EXPECT_EQ(y.loop, true);
  ASSERT_EQ(y.channels.size(), x.channels.size());
  for (size_t c = 0; c < x.channels.size(); ++c) {
    const Channel &p = x.channels[c], &q = y.channels[c];
    EXPECT_EQ(q.joint, p.joint) << c;
    EXPECT_EQ(q.target, p.target) << c;
    EXPECT_EQ(q.interpolation, p.interpolation) << c;
    EXPECT_EQ(q.eulerOrder, p.eulerOrder) << c;
    EXPECT_EQ(q.property, p.property) << c;
    ASSERT_EQ(q.times.size(), p.times.size());
    for (size_t k = 0; k < p.times.size(); ++k) {
      EXPECT_TRUE(sameBits(q.times[k], p.times[k])) << c << " " << k;
      for (int i = 0; i < p.valueSize(); ++i) EXPECT_TRUE(sameBits(q.values[k][i], p.values[k][i])) << c << " " << k;
    }
    ASSERT_EQ(q.keys.size(), p.keys.size()) << c;
    for (size_t k = 0; k < p.keys.size(); ++k) {
      // Components past the value size are not stored (translation keys have 3).
      KeySettings expected = p.keys[k];
      for (int i = p.valueSize(); i < 4; ++i)
        expected.inTangent[i] = expected.outTangent[i] = expected.leftHandleValue[i] = expected.rightHandleValue[i] = 0;
      EXPECT_TRUE(q.keys[k] == expected) << c << " " << k;
      EXPECT_TRUE(sameBits(q.keys[k].bias, expected.bias));
      EXPECT_TRUE(sameBits(q.keys[k].outTangent.z, expected.outTangent.z));  // -0.0 stays -0.0
    }
  }
  // Writing what was read gives the same text.
  EXPECT_EQ(toKinemaJson(loaded.value()), text);
  // Defaults are left out: a key that only changes its interpolation is one member.
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["clips"][0]["channels"][3]["property"], "blend shape: smile");
  EXPECT_FALSE(j["clips"][0]["channels"][3].contains("joint"));
  EXPECT_FALSE(j["clips"][0]["channels"][4].contains("keys"));
}

TEST(KinemaFileClips, VersionOneFilesFromBeforeTheEngineStillLoad) {
  const std::string old = R"({"format": "kinema", "version": 1,
    "skeleton": {"joints": [{"name": "Hips", "parent": -1}]},
    "clips": [{"name": "m", "channels": [
      {"joint": "Hips", "target": "translation", "interpolation": "step", "times": [0, 1], "values": [[0,0,0],[2,0,0]]},
      {"joint": "Hips", "target": "rotation", "times": [0, 1], "values": [[0,0,0,1],[0,1,0,0]]}]}]})";
  Result<Scene> s = parseKinemaJson(old, "old.kinema");
  ASSERT_TRUE(s) << s.error();
  const Clip& c = s.value().clips[0];
  EXPECT_EQ(c.channels[0].interpolation, Interpolation::Step);
  EXPECT_TRUE(c.channels[0].keys.empty());
  EXPECT_EQ(c.channels[1].interpolation, Interpolation::Linear);
  EXPECT_FALSE(c.loop);
}

TEST(KinemaFileClips, PlaybackRangeRoundTripsAndDefaultsToTheKeys) {
  const std::string text = R"({"format": "kinema", "version": 1,
    "skeleton": {"joints": [{"name": "Hips", "parent": -1}]},
    "clips": [{"name": "m", "loop": true, "range": [0.5, 1.5], "channels": [
      {"joint": "Hips", "target": "translation", "times": [0, 2], "values": [[0,0,0],[2,0,0]]}]},
      {"name": "n", "channels": [
      {"joint": "Hips", "target": "translation", "times": [0, 2], "values": [[0,0,0],[2,0,0]]}]}]})";
  Result<Scene> s = parseKinemaJson(text, "range.kinema");
  ASSERT_TRUE(s) << s.error();
  const Clip& c = s.value().clips[0];
  EXPECT_TRUE(c.hasRange);
  EXPECT_EQ(c.playStart(), 0.5f);
  EXPECT_EQ(c.playEnd(), 1.5f);
  EXPECT_FALSE(s.value().clips[1].hasRange);  // no range: 0 .. last key
  EXPECT_EQ(s.value().clips[1].playStart(), 0.0f);
  EXPECT_EQ(s.value().clips[1].playEnd(), 2.0f);
  Result<Scene> back = parseKinemaJson(toKinemaJson(s.value()), "again.kinema");
  ASSERT_TRUE(back) << back.error();
  EXPECT_TRUE(back.value().clips[0].hasRange);
  EXPECT_EQ(back.value().clips[0].rangeStart, 0.5f);
  EXPECT_EQ(back.value().clips[0].rangeEnd, 1.5f);
  EXPECT_FALSE(back.value().clips[1].hasRange);

  std::string reversed = text;
  reversed.replace(reversed.find("[0.5, 1.5]"), 10, "[1.5, 0.5]");
  Result<Scene> bad = parseKinemaJson(reversed, "bad.kinema");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("bad.kinema: clips[0].range:"), std::string::npos) << bad.error();
  Clip invalid = c;
  invalid.rangeEnd = 0.0f;  // end before start
  EXPECT_NE(invalid.validate(s.value().skeleton), "");
}

TEST(KinemaFileClips, BadSettingsNameTheirPath) {
  const std::string head = R"({"format": "kinema", "version": 1,
    "skeleton": {"joints": [{"name": "Hips", "parent": -1}]}, "clips": [{"channels": [)";
  const std::string tail = "]}]}";
  struct Case {
    std::string channel, path, what;
  } cases[] = {
      {R"({"joint": "Hips", "target": "translation", "interpolation": "cubic", "times": [0], "values": [[0,0,0]]})",
       "clips[0].channels[0].interpolation", "catmull-rom"},
      {R"({"joint": "Hips", "target": "translation", "interpolation": "squad", "times": [0], "values": [[0,0,0]]})",
       "clips[0].channels[0].interpolation", "rotation channels only"},
      {R"({"joint": "Hips", "target": "rotation", "times": [0], "values": [[0,0,0,1]], "keys": [{"interpolation": "tcb"}]})",
       "clips[0].channels[0].keys[0].interpolation", "does not apply to rotation"},
      {R"({"joint": "Hips", "target": "translation", "times": [0, 1], "values": [[0,0,0],[1,1,1]], "keys": [{}]})",
       "clips[0].channels[0].keys", "one object per key"},
      {R"({"joint": "Hips", "target": "translation", "times": [0], "values": [[0,0,0]], "keys": [{"left_handle_time": 0.5}]})",
       "clips[0].channels[0].keys[0].left_handle_time", "must not be positive"},
      {R"({"joint": "Hips", "target": "translation", "times": [0], "values": [[0,0,0]], "keys": [{"tension": "high"}]})",
       "clips[0].channels[0].keys[0].tension", "expected a number"},
      {R"({"joint": "Hips", "target": "translation", "times": [0], "values": [[0,0,0]], "keys": [{"out_tangent": [1, 2]}]})",
       "clips[0].channels[0].keys[0].out_tangent", "3 numbers"},
      {R"({"joint": "Hips", "target": "euler", "euler_order": "XXY", "times": [0], "values": [[0,0,0]]})",
       "clips[0].channels[0].euler_order", "XYZ"},
      {R"({"joint": "Hips", "target": "translation", "times": [0], "values": [[0,0,0]], "keys": [{"easing": "wobble"}]})",
       "clips[0].channels[0].keys[0].easing", "bounce"},
  };
  for (const Case& c : cases) {
    Result<Scene> s = parseKinemaJson(head + c.channel + tail, "bad.kinema");
    ASSERT_FALSE(s) << c.channel;
    EXPECT_NE(s.error().find("bad.kinema: " + c.path + ":"), std::string::npos) << s.error();
    EXPECT_NE(s.error().find(c.what), std::string::npos) << s.error();
    EXPECT_EQ(s.error().find('\n'), std::string::npos);
  }
}

TEST(KinemaFileClips, PoseCommandSamplesAnEasedClip) {
  // Hips translation eased quad-in from (0,0,0) at 0 s to (2,0,0) at 1 s: at 0.5 s,
  // x = 2 * 0.5^2 = 0.5 (the channel replaces the rest translation).
  const std::string dir = test::makeTempDir();
  const std::string file = dir + "/eased.kinema";
  test::writeFile(file, R"({"format": "kinema", "version": 1,
    "skeleton": {"joints": [{"name": "Hips", "parent": -1, "translation": [0, 1, 0]}]},
    "clips": [{"channels": [{"joint": "Hips", "target": "translation", "interpolation": "ease",
      "times": [0, 1], "values": [[0,0,0],[2,0,0]], "keys": [{"easing": "quad", "easing_mode": "in"}, {}]}]}]})");
  std::string out, err;
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " pose " + file + " --time 0.5 --json", &out, &err), 0) << err;
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_NEAR(j["joints"][0]["world"][12].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(j["joints"][0]["world"][13].get<double>(), 0.0, 1e-6);
}

}  // namespace
}  // namespace kinema
