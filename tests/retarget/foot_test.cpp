// Foot contacts (hysteresis on height and speed) and foot locking (two-bone IK; the
// locked ankle stays put, nothing else moves, no foot below the floor), on made-up takes
// of the default character whose answers follow from how they are built.
#include <gtest/gtest.h>

#include "core/default_character.h"
#include "retarget/bone_map.h"
#include "retarget/foot_contacts.h"
#include "retarget/foot_locking.h"
#include "retarget/retarget_test_support.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

struct Character {
  Skeleton s = makeDefaultCharacter();
  LegJoints legs[2];
  Character() { legsOf(findHumanoid(s).value().bones, legs); }
};

// The rest pose held for `frames` frames, with the hips at `hips(f)` (world = local: root).
template <class Hips>
Clip holdRest(int frames, Hips hips) {
  Clip clip;
  clip.name = "hold";
  clip.frameTime = 1.0 / 30.0;
  Channel root(0, ChannelTarget::Translation, Interpolation::Linear, {}, {});
  for (int f = 0; f < frames; ++f) {
    root.times.push_back(ownFrameGrid(clip).frameToTime(f));
    root.values.push_back(glm::vec4(hips(f), 0.0f));
  }
  clip.channels.push_back(std::move(root));
  return clip;
}

Clip lockFeet(const Character& c, const Clip& clip, const std::vector<ContactInterval> contacts[2], float floor) {
  Clip out;
  FootLockJob job;
  job.skeleton = &c.s;
  job.clip = &clip;
  job.legs[0] = c.legs[0];
  job.legs[1] = c.legs[1];
  job.contacts[0] = &contacts[0];
  job.contacts[1] = &contacts[1];
  job.floorHeight = floor;
  job.output = &out;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return out;
}

TEST(RetargetFootContacts, LiftedFootEndsAndRestartsItsContact) {
  const Character c;
  // The left thigh swings forward 50 degrees and back over frames 20..39; the right leg stands.
  Clip clip = holdRest(60, [&](int) { return c.s.rest[0].translation; });
  Channel swing(c.legs[0].upperLeg, ChannelTarget::Rotation, Interpolation::Linear, {}, {});
  for (int f = 0; f < 60; ++f) {
    const float u = f < 20 || f > 39 ? 0.0f : std::sin(3.14159265f * (f - 20) / 20.0f);
    const glm::quat q = axisAngle(glm::vec3(1, 0, 0), -0.87f * u * u);
    swing.times.push_back(ownFrameGrid(clip).frameToTime(f));
    swing.values.push_back(glm::vec4(q.x, q.y, q.z, q.w));
  }
  clip.channels.push_back(std::move(swing));
  std::vector<ContactInterval> contacts[2];
  FootContactJob job;
  job.skeleton = &c.s;
  job.clip = &clip;
  job.legs[0] = c.legs[0];
  job.legs[1] = c.legs[1];
  job.output[0] = &contacts[0];
  job.output[1] = &contacts[1];
  ASSERT_TRUE(job.run()) << job.validate();
  ASSERT_EQ(contacts[1].size(), 1u);
  EXPECT_EQ(contacts[1][0], (ContactInterval{0, 59}));
  ASSERT_EQ(contacts[0].size(), 2u);
  EXPECT_EQ(contacts[0][0].first, 0);
  EXPECT_GE(contacts[0][0].last, 20);  // the foot barely moves on the first frames of the swing
  EXPECT_LE(contacts[0][0].last, 26);
  EXPECT_GE(contacts[0][1].first, 33);
  EXPECT_LE(contacts[0][1].first, 40);
  EXPECT_EQ(contacts[0][1].last, 59);
}

TEST(RetargetFootLocking, LockedAnkleStaysAndNothingElseMoves) {
  const Character c;
  // Crouched on the left leg (thigh 30 degrees forward, knee bent 60: the ankle right below
  // the hip, 0.73 of the 0.84 reach), the hips glide 20 cm forward while the leg keeps its
  // pose: without locking the left foot slides 20 cm; with it the leg can still reach.
  const int frames = 31;
  Clip clip = holdRest(frames, [&](int f) { return c.s.rest[0].translation + glm::vec3(0.0f, 0.0f, 0.2f * f / (frames - 1)); });
  for (const auto& [joint, angle] : {std::pair<int, float>{c.legs[0].upperLeg, -0.5236f}, {c.legs[0].lowerLeg, 1.0472f}}) {
    const glm::quat q = axisAngle(glm::vec3(1, 0, 0), angle);
    clip.channels.emplace_back(joint, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{0.0f},
                               std::vector<glm::vec4>{glm::vec4(q.x, q.y, q.z, q.w)});
  }
  std::vector<ContactInterval> contacts[2] = {{{0, frames - 1}}, {}};
  const Clip out = lockFeet(c, clip, contacts, -1.0f);  // a floor far below: only the lock acts
  const glm::vec3 start = positionOf(worldAtFrame(c.s, clip, 0)[c.legs[0].foot]);
  float drift = 0.0f;
  for (int f = 0; f < frames; ++f) {
    const std::vector<glm::mat4> a = worldAtFrame(c.s, clip, f), b = worldAtFrame(c.s, out, f);
    const glm::vec3 p = positionOf(b[c.legs[0].foot]);
    drift = std::max(drift, glm::length(glm::vec2(p.x - start.x, p.z - start.z)));
    // Every joint outside the left leg is exactly where it was.
    for (int j = 0; j < c.s.size(); ++j)
      if (!c.s.isInSubtree(j, c.legs[0].upperLeg)) {
        EXPECT_EQ(positionOf(a[j]), positionOf(b[j])) << c.s.names[j];
      }
    // The foot keeps its world rotation.
    EXPECT_SAME_ROTATION(glm::quat_cast(glm::mat3(a[c.legs[0].foot])), glm::quat_cast(glm::mat3(b[c.legs[0].foot])), 1e-5f);
  }
  EXPECT_LT(drift, 1e-3f);
  // The unlocked clip slid the full 20 cm.
  const glm::vec3 end = positionOf(worldAtFrame(c.s, clip, frames - 1)[c.legs[0].foot]);
  EXPECT_NEAR(end.z - start.z, 0.2f, 1e-5f);
}

TEST(RetargetFootLocking, NoFootBelowTheFloor) {
  const Character c;
  // The hips sink 20 cm with straight legs: the ankles (8 cm up) and toes (2 cm) would go under.
  const Clip clip = holdRest(20, [&](int f) { return c.s.rest[0].translation + glm::vec3(0.0f, -0.01f * f, 0.0f); });
  std::vector<ContactInterval> none[2];
  const float floor = 0.02f;  // the toes' rest height
  const Clip out = lockFeet(c, clip, none, floor);
  for (int f = 0; f < 20; ++f) {
    const std::vector<glm::mat4> w = worldAtFrame(c.s, out, f);
    for (const LegJoints& l : c.legs) {
      EXPECT_GE(w[l.foot][3].y, floor - 1e-4f) << "frame " << f;
      EXPECT_GE(w[l.toes][3].y, floor - 1e-4f) << "frame " << f;
    }
  }
}

TEST(RetargetFootLocking, SkateIsTheMeanSlidePerContactFrame) {
  const Character c;
  // Hips (and so both feet) move 1 cm per frame along X: slide per frame = 0.01 / leg length.
  const Clip clip = holdRest(11, [&](int f) { return c.s.rest[0].translation + glm::vec3(0.01f * f, 0.0f, 0.0f); });
  std::vector<ContactInterval> contacts[2] = {{{0, 10}}, {{2, 5}}};
  const float leg = glm::length(glm::vec3(0.0f, 0.42f, 0.01f)) + glm::length(glm::vec3(0.0f, 0.42f, 0.03f));
  EXPECT_NEAR(restLegLength(c.s, c.legs[0]), leg, 1e-6f);
  EXPECT_NEAR(footSkate(c.s, clip, c.legs, contacts), 0.01f / leg, 1e-5f);
}

}  // namespace
}  // namespace kinema::test
