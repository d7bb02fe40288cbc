#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/document.h"
#include "editor/model/motion_control.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// An L-shaped path: 1 m along X in the first second, then 3 m along Y in the next (so the
// keyed speed jumps from 1 to 3 m/s). Arc length from the start of a point on it: x + y.
Channel lPath() {
  return Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f, 2.0f},
                 {glm::vec4(0, 0, 0, 0), glm::vec4(1, 0, 0, 0), glm::vec4(1, 3, 0, 0)});
}
double arc(const glm::vec3& p) { return double(p.x) + double(p.y); }

TEST(MotionControl, ConstantSpeedCoversEqualArcLengthPerFrame) {
  const Channel path = lPath();
  MotionControlJob job;
  job.path = &path;
  job.frameTime = 0.1;
  std::vector<float> times;
  std::vector<glm::vec3> p;
  ASSERT_TRUE(job.run(times, p));
  ASSERT_EQ(times.size(), 21u);
  EXPECT_EQ(times.front(), 0.0f);
  EXPECT_EQ(times.back(), 2.0f);
  for (size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(std::abs(p[i].y > 0 ? p[i].x - 1.0f : p[i].y), 0.0f, 1e-4f) << "on the path, frame " << i;
    EXPECT_NEAR(arc(p[i]), 4.0 * i / 20.0, 2e-3) << "frame " << i;
    if (i > 0) {
      EXPECT_NEAR(arc(p[i]) - arc(p[i - 1]), 0.2, 2e-3) << "step " << i;
    }
  }
  // The keyed timing covered 0.1 m per frame in the first second, 0.3 m in the second.
}

TEST(MotionControl, EasesTakeSmallerStepsAtTheEnds) {
  const Channel path = lPath();
  for (MotionControlProfile profile : {MotionControlProfile::SineEase, MotionControlProfile::ParabolicEase}) {
    MotionControlJob job;
    job.path = &path;
    job.frameTime = 0.1;
    job.profile = profile;
    std::vector<float> times;
    std::vector<glm::vec3> p;
    ASSERT_TRUE(job.run(times, p));
    ASSERT_EQ(p.size(), 21u);
    std::vector<double> step;
    for (size_t i = 1; i < p.size(); ++i) step.push_back(arc(p[i]) - arc(p[i - 1]));
    const double middle = step[10];
    EXPECT_LT(step.front(), 0.5 * middle) << toString(profile);
    EXPECT_LT(step.back(), 0.5 * middle) << toString(profile);
    EXPECT_NEAR(arc(p.back()), 4.0, 1e-3);
    if (profile == MotionControlProfile::SineEase) {
      // s(t) = L (1 - cos(pi t / T)) / 2 with L = 4, T = 2.
      for (size_t i = 0; i < p.size(); ++i)
        EXPECT_NEAR(arc(p[i]), 2.0 * (1.0 - std::cos(M_PI * i / 20.0)), 2e-3) << "frame " << i;
    } else {
      // Accelerate over the first quarter, constant speed, decelerate over the last:
      // v0 = L / 0.75, so the middle steps are 4 / 0.75 * 0.05 m.
      for (int i = 6; i < 14; ++i) EXPECT_NEAR(step[i], 4.0 / 0.75 * 0.05, 2e-3) << "step " << i;
    }
  }
}

TEST(MotionControl, BakeKeysEveryFrameLinearAndValidates) {
  Channel path = lPath();
  MotionControlJob job;
  job.path = &path;
  job.frameTime = 0.25;
  Channel baked;
  ASSERT_TRUE(job.bake(baked));
  EXPECT_EQ(baked.joint, 0);
  EXPECT_EQ(baked.target, ChannelTarget::Translation);
  EXPECT_EQ(baked.keyCount(), 9);
  for (int k = 0; k < baked.keyCount(); ++k) {
    EXPECT_FLOAT_EQ(baked.times[k], 0.25f * k);
    EXPECT_EQ(baked.settings(k).interpolation, Interpolation::Linear);
  }
  // Ticks: the same positions at equal times.
  const std::vector<glm::vec3> ticks = equalTimeTicks(path, MotionControlProfile::ConstantSpeed, 8);
  ASSERT_EQ(ticks.size(), 9u);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(glm::length(ticks[k] - glm::vec3(baked.values[k])), 0.0f, 1e-5f);

  path.times.resize(1);
  path.values.resize(1);
  EXPECT_FALSE(job.validate().empty());
  std::vector<float> t;
  std::vector<glm::vec3> q;
  EXPECT_FALSE(job.run(t, q));
  EXPECT_TRUE(t.empty() && q.empty());
  Channel rotation = lPath();
  rotation.target = ChannelTarget::Rotation;
  job.path = &rotation;
  EXPECT_FALSE(job.validate().empty());
  job.path = nullptr;
  EXPECT_FALSE(job.validate().empty());
}

TEST(MotionControl, ApplyIsOneUndoStepThatRestoresTheChannelExactly) {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform{});
  scene.skeleton.addJoint("tip", 0, Transform::fromTranslation(glm::vec3(0, 1, 0)));
  Clip clip;
  clip.frameTime = 0.1;
  clip.channels.push_back(Channel(1, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 2.0f},
                                  {glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1)}));
  Channel path = lPath();
  path.keys.resize(3);
  path.keys[1].interpolation = Interpolation::CatmullRom;  // settings that a bake would lose
  clip.channels.push_back(path);
  scene.clips.push_back(clip);
  Document doc(scene);
  const int depth = doc.historyPosition();
  EXPECT_NE(applyMotionControl(doc, 0, 1, MotionControlProfile::SineEase), "");  // tip: no translation
  EXPECT_EQ(applyMotionControl(doc, 0, 0, MotionControlProfile::SineEase), "");
  EXPECT_EQ(doc.historyPosition(), depth + 1);
  const Channel& after = doc.scene().clips[0].channels[1];
  EXPECT_EQ(after.keyCount(), 21);
  EXPECT_TRUE(after.keys.empty());
  ASSERT_TRUE(doc.undo());
  const Channel& back = doc.scene().clips[0].channels[1];
  EXPECT_EQ(back.times, path.times);
  EXPECT_EQ(back.values, path.values);
  ASSERT_EQ(back.keys.size(), 3u);
  EXPECT_EQ(back.keys[1], path.keys[1]);
  EXPECT_EQ(back.interpolation, path.interpolation);
  EXPECT_EQ(doc.scene().clips[0].channels[0].times, clip.channels[0].times);
}

}  // namespace
}  // namespace kinema
