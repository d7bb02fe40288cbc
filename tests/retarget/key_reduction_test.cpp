// Key reduction: every frame stays within the tolerances (checked here by plain forward
// kinematics of both clips), and motion that is a straight line or a constant turn needs
// only its end keys.
#include <gtest/gtest.h>

#include "core/default_character.h"
#include "retarget/key_reduction.h"
#include "retarget/retarget_test_support.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

constexpr float kDegree = 0.01745329251994329577f;

Clip reduce(const Skeleton& s, const Clip& clip, float pos, float deg, KeyReductionReport* report) {
  Clip out;
  KeyReductionJob job;
  job.skeleton = &s;
  job.clip = &clip;
  job.settings.positionTolerance = pos;
  job.settings.angleTolerance = deg * kDegree;
  job.output = &out;
  job.report = report;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return out;
}

int keys(const Clip& c) {
  int n = 0;
  for (const Channel& ch : c.channels) n += ch.keyCount();
  return n;
}

TEST(RetargetKeyReduction, EveryFrameWithinTolerance) {
  const Skeleton s = makeDefaultCharacter();
  const int cases = propertyCases(6);
  for (int c = 0; c < cases; ++c) {
    std::mt19937 rng(500 + c);
    const Clip clip = makeSmoothTake(s, 90, rng, 0.6f);
    for (const auto& [pos, deg] : {std::pair<float, float>{0.01f, 2.0f}, {0.002f, 0.5f}}) {
      KeyReductionReport report;
      const Clip out = reduce(s, clip, pos, deg, &report);
      float worstPos = 0.0f, worstDeg = 0.0f;
      for (int f = 0; f < clipFrameCount(clip); ++f) {
        Pose a = Pose::rest(s), b = Pose::rest(s);
        sampleClip(clip, ownFrameGrid(clip).frameToTime(f), a);
        sampleClip(out, ownFrameGrid(clip).frameToTime(f), b);
        const std::vector<glm::mat4> wa = computeWorld(s, a), wb = computeWorld(s, b);
        for (int j = 0; j < s.size(); ++j) {
          worstPos = std::max(worstPos, glm::length(positionOf(wa[j]) - positionOf(wb[j])));
          // The angle of the rotation between them, in double.
          const glm::dquat r = glm::conjugate(glm::dquat(a.local[j].rotation)) * glm::dquat(b.local[j].rotation);
          const double angle = 2.0 * std::atan2(glm::length(glm::dvec3(r.x, r.y, r.z)), std::abs(r.w));
          worstDeg = std::max(worstDeg, static_cast<float>(angle / kDegree));
        }
      }
      EXPECT_LE(worstPos, pos) << "case " << c;
      EXPECT_LE(worstDeg, deg) << "case " << c;
      EXPECT_NEAR(report.maxPositionError, worstPos, 1e-6f);
      EXPECT_EQ(report.keysBefore, keys(clip));
      EXPECT_EQ(report.keysAfter, keys(out));
      // A centimetre is loose for this take: most keys go. Two millimetres on a take that
      // turns every joint by up to 0.6 rad at up to 5 rad/s needs nearly a key a frame.
      if (pos >= 0.01f) {
        EXPECT_LT(report.keysAfter, report.keysBefore / 2) << "case " << c;
      } else {
        EXPECT_LE(report.keysAfter, report.keysBefore) << "case " << c;
      }
    }
  }
}

TEST(RetargetKeyReduction, StraightMotionKeepsItsEnds) {
  const Skeleton s = makeDefaultCharacter();
  Clip clip;
  clip.frameTime = 1.0 / 30.0;
  Channel move(0, ChannelTarget::Translation, Interpolation::Linear, {}, {});
  Channel turn(s.find("UpperArm.L"), ChannelTarget::Rotation, Interpolation::Linear, {}, {});
  for (int f = 0; f < 50; ++f) {
    const float t = ownFrameGrid(clip).frameToTime(f);
    move.times.push_back(t);
    move.values.push_back(glm::vec4(s.rest[0].translation + glm::vec3(0.3f * t, 0.0f, -0.7f * t), 0.0f));
    const glm::quat q = axisAngle(glm::vec3(0, 0, 1), 1.2f * t);  // 1.2 rad/s: 2 rad in all, < pi
    turn.times.push_back(t);
    turn.values.push_back(glm::vec4(q.x, q.y, q.z, q.w));
  }
  clip.channels = {move, turn};
  KeyReductionReport report;
  const Clip out = reduce(s, clip, 1e-4f, 0.01f, &report);
  EXPECT_EQ(out.channels[0].keyCount(), 2);
  EXPECT_EQ(out.channels[1].keyCount(), 2);
  EXPECT_EQ(report.keysBefore, 100);
  EXPECT_EQ(report.keysAfter, 4);
}

TEST(RetargetKeyReduction, RefusesBadTolerances) {
  const Skeleton s = makeDefaultCharacter();
  Clip clip, out;
  KeyReductionJob job;
  job.skeleton = &s;
  job.clip = &clip;
  job.output = &out;
  job.settings.positionTolerance = 0.0f;
  EXPECT_NE(job.validate(), "");
  job.settings.positionTolerance = std::nanf("");
  EXPECT_NE(job.validate(), "");
  EXPECT_FALSE(job.run());
}

}  // namespace
}  // namespace kinema::test
