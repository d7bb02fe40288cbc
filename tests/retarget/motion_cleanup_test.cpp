// MotionCleanupJob (issue 21): the computation `kinema retarget --fix-feet --reduce` and the
// editor's Clean Up share. A standing character sliding at a known speed gives the foot
// skate in closed form; locking removes it; nothing chosen changes nothing; and the CLI's JSON
// figures are the job's own, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/default_character.h"
#include "io/json_number.h"
#include "io/kinema_file.h"
#include "retarget/bone_map.h"
#include "retarget/motion_cleanup.h"
#include "retarget/retarget_motion.h"
#include "retarget/retarget_test_support.h"
#include "test_support.h"
#include "io/scene_files.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

constexpr float kSlide = 0.1f;  // units per second, well under the contact speed threshold

// The default character standing in its rest pose while the hips slide along +X.
Clip slidingStand(const Skeleton& s, int frames) {
  Clip clip;
  clip.name = "slide";
  clip.frameTime = 1.0 / 30.0;
  Channel root(0, ChannelTarget::Translation, Interpolation::Linear, {}, {});
  for (int f = 0; f < frames; ++f) {
    const float t = ownFrameGrid(clip).frameToTime(f);
    root.times.push_back(t);
    root.values.push_back(glm::vec4(s.rest[0].translation + glm::vec3(kSlide * t, 0, 0), 0));
  }
  clip.channels.push_back(root);
  return clip;
}

struct Legs {
  LegJoints legs[2];
};

Legs defaultLegs(const Skeleton& s) {
  Legs l;
  const Result<HumanoidReading> h = findHumanoid(s);
  EXPECT_TRUE(h) << h.error();
  EXPECT_EQ(humanoidLegs(s, h->bones, l.legs), "");
  return l;
}

TEST(MotionCleanup, SlidingFeetGiveTheSkateInClosedFormAndLockingRemovesIt) {
  const Skeleton s = makeDefaultCharacter();
  const int frames = 40;
  Clip clip = slidingStand(s, frames);
  const Legs l = defaultLegs(s);
  FootContacts& contacts = clip.contacts;
  ASSERT_EQ(detectFootContacts(s, clip, l.legs, contacts), "");
  // Both feet stand still on the floor but for the slow slide: one contact over the clip each.
  ASSERT_EQ(contacts.feet[0], (std::vector<ContactInterval>{{0, frames - 1}}));
  ASSERT_EQ(contacts.feet[1], (std::vector<ContactInterval>{{0, frames - 1}}));

  MotionCleanupJob job;
  job.skeleton = &s;
  job.clip = &clip;
  job.legs[0] = l.legs[0];
  job.legs[1] = l.legs[1];
  job.contacts = &contacts;
  job.settings.reduce = false;
  Clip out;
  MotionCleanupReport report;
  job.output = &out;
  job.report = &report;
  ASSERT_TRUE(job.run()) << job.validate();
  // Each contact frame after the first slides kSlide / 30 units; the legs are equally long.
  const float leg = restLegLength(s, l.legs[0]);
  EXPECT_NEAR(report.skateBefore, kSlide / 30.0f / leg, 1e-4f * kSlide / 30.0f / leg);
  EXPECT_EQ(report.contactFrames, 2 * frames);
  // Locked: the ankles slide a twentieth of what they did (what is left is the lock's blend).
  EXPECT_LT(report.skateAfter, 0.05f * report.skateBefore);
  EXPECT_EQ(out.contacts, contacts) << "the cleaned clip keeps its contacts";
  EXPECT_EQ(report.keys.keysBefore, report.keys.keysAfter) << "no reduction asked";
}

TEST(MotionCleanup, NothingChosenLeavesTheClipAsItWas) {
  const Skeleton s = makeDefaultCharacter();
  const Clip clip = slidingStand(s, 20);
  const Legs l = defaultLegs(s);
  FootContacts contacts;
  contacts.feet[0] = {{2, 9}};
  MotionCleanupJob job;
  job.skeleton = &s;
  job.clip = &clip;
  job.legs[0] = l.legs[0];
  job.legs[1] = l.legs[1];
  job.contacts = &contacts;
  job.settings.lockFeet = false;
  job.settings.reduce = false;
  Clip out;
  MotionCleanupReport report;
  job.output = &out;
  job.report = &report;
  ASSERT_TRUE(job.run());
  ASSERT_EQ(out.channels.size(), clip.channels.size());
  EXPECT_EQ(out.channels[0].values, clip.channels[0].values);
  EXPECT_EQ(report.skateBefore, report.skateAfter);
  EXPECT_EQ(report.keys.keysBefore, 20);
  EXPECT_EQ(report.contactFrames, 8);
}

TEST(MotionCleanup, BadInputIsRefused) {
  const Skeleton s = makeDefaultCharacter();
  const Clip clip = slidingStand(s, 10);
  const Legs l = defaultLegs(s);
  FootContacts contacts;
  MotionCleanupJob job;
  job.skeleton = &s;
  job.clip = &clip;
  job.contacts = &contacts;
  Clip out;
  job.output = &out;
  EXPECT_NE(job.validate(), "") << "no legs given";
  job.legs[0] = l.legs[0];
  job.legs[1] = l.legs[1];
  EXPECT_EQ(job.validate(), "");
  job.settings.reduction.positionTolerance = 0.0f;
  EXPECT_NE(job.validate(), "");
  job.settings.reduction.positionTolerance = 0.01f;
  contacts.feet[1] = {{5, 3}};
  EXPECT_NE(job.validate(), "");
  EXPECT_FALSE(job.run());
}

// The CLI's report is this job's: the same take retargeted in process gives the same
// contacts, skate, key counts and errors, and the saved clip keeps its contacts and map.
TEST(MotionCleanup, KinemaRetargetReportsTheJobsFigures) {
  const std::string dir = makeTempDir();
  Scene source;
  source.skeleton = makeDefaultCharacter();
  std::mt19937 rng(5);
  source.clips.push_back(makeSmoothTake(source.skeleton, 40, rng, 0.25f, 0.8f));
  const std::string take = dir + "/take.kinema", out = dir + "/out.kinema";
  ASSERT_EQ(saveKinemaFile(take, source), "");
  std::string stdoutText, stderrText;
  ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " retarget '" + take + "' --out '" + out +
                           "' --fix-feet --reduce 0.005,1 --json",
                       &stdoutText, &stderrText),
            0)
      << stderrText;
  const nlohmann::json j = nlohmann::json::parse(stdoutText);

  const Skeleton target = makeDefaultCharacter();
  const Result<HumanoidReading> sh = findHumanoid(source.skeleton), th = findHumanoid(target);
  ASSERT_TRUE(sh && th);
  Result<AutomaticBoneMap> map = automaticBoneMap(sh, th, take, "target");
  ASSERT_TRUE(map);
  RetargetMotionInput in;
  in.source = &source.skeleton;
  in.clip = &source.clips[0];
  in.sourceHuman = &sh.value();
  in.target = &target;
  in.targetHuman = &th.value();
  in.map = &map->map;
  Result<RetargetedMotion> retargeted = retargetMotion(in);
  ASSERT_TRUE(retargeted) << retargeted.error();
  const Legs l = defaultLegs(target);
  FootContacts contacts;
  ASSERT_EQ(detectFootContacts(target, retargeted->clip, l.legs, contacts), "");
  MotionCleanupJob job;
  job.skeleton = &target;
  job.clip = &retargeted->clip;
  job.legs[0] = l.legs[0];
  job.legs[1] = l.legs[1];
  job.contacts = &contacts;
  job.settings.reduction.positionTolerance = 0.005f;
  job.settings.reduction.angleTolerance = 1.0f * 0.01745329251994329577f;
  Clip cleaned;
  MotionCleanupReport report;
  job.output = &cleaned;
  job.report = &report;
  ASSERT_TRUE(job.run());

  for (int f = 0; f < 2; ++f) {
    const nlohmann::json& list = j["contacts"][f == 0 ? "left" : "right"];
    ASSERT_EQ(list.size(), contacts.feet[f].size());
    for (size_t i = 0; i < list.size(); ++i) {
      EXPECT_EQ(list[i][0], contacts.feet[f][i].first);
      EXPECT_EQ(list[i][1], contacts.feet[f][i].last);
    }
  }
  EXPECT_EQ(j["footSkate"]["before"], nlohmann::json(jsonFloat(report.skateBefore)));
  EXPECT_EQ(j["footSkate"]["after"], nlohmann::json(jsonFloat(report.skateAfter)));
  EXPECT_EQ(j["keys"]["before"], report.keys.keysBefore);
  EXPECT_EQ(j["keys"]["after"], report.keys.keysAfter);
  EXPECT_EQ(j["reductionError"]["position"], nlohmann::json(jsonFloat(report.keys.maxPositionError)));

  // The written clip remembers both (docs/kinema-format.md, clips[c].foot_contacts / bone_map).
  Result<Scene> saved = loadScene(out);
  ASSERT_TRUE(saved) << saved.error();
  ASSERT_EQ(saved->clips.size(), 1u);
  EXPECT_EQ(saved->clips[0].contacts, contacts);
  const ClipSourceMap expected = toClipSourceMap(map->map, source.skeleton, take, 0);
  EXPECT_EQ(saved->clips[0].sourceMap, expected);
  std::system(("rm -rf '" + dir + "'").c_str());
}

}  // namespace
}  // namespace kinema::test
