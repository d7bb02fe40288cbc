#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/motion_path.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// Three joints: root (translation keys), mid 1 m above it (Z rotation keys), tip 0.5 m above
// mid. The tip's world position in closed form: root(t) + (0,1,0) + Rz(angle(t)) (0,0.5,0).
Scene threeJointScene() {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform{});
  scene.skeleton.addJoint("mid", 0, Transform::fromTranslation(glm::vec3(0, 1, 0)));
  scene.skeleton.addJoint("tip", 1, Transform::fromTranslation(glm::vec3(0, 0.5f, 0)));
  Clip clip;
  clip.frameTime = 1.0 / 30.0;
  clip.channels.push_back(Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f, 2.0f},
                                  {glm::vec4(0, 0, 0, 0), glm::vec4(2, 0, 0, 0), glm::vec4(2, 0, -1, 0)}));
  const glm::quat q = glm::angleAxis(glm::radians(120.0f), glm::vec3(0, 0, 1));
  clip.channels.push_back(Channel(1, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 2.0f},
                                  {glm::vec4(0, 0, 0, 1), glm::vec4(q.x, q.y, q.z, q.w)}));
  scene.clips.push_back(clip);
  return scene;
}

glm::dvec3 tipAt(double t) {
  const glm::dvec3 root = t <= 1 ? glm::dvec3(2 * t, 0, 0) : glm::dvec3(2, 0, -(t - 1));
  const double a = std::min(t, 2.0) / 2.0 * (120.0 * M_PI / 180.0);
  return root + glm::dvec3(0, 1, 0) + glm::dvec3(-0.5 * std::sin(a), 0.5 * std::cos(a), 0);
}

TEST(MotionPath, SamplesAreForwardKinematicsOfTheClipAtEveryFrame) {
  const Scene scene = threeJointScene();
  const MotionPath p = computeMotionPath(scene, 0, 2, 0, 60);
  ASSERT_EQ(p.points.size(), 61u);
  for (size_t i = 0; i < p.points.size(); ++i) {
    EXPECT_EQ(p.frames[i], static_cast<long long>(i));
    const glm::dvec3 e = tipAt(double(i) / 30.0);
    EXPECT_NEAR(glm::length(glm::dvec3(p.points[i]) - e), 0.0, 1e-5) << "frame " << i;
  }
}

TEST(MotionPath, KeyedFramesAreTheJointsOwnKeys) {
  const Scene scene = threeJointScene();
  const MotionPath root = computeMotionPath(scene, 0, 0, 10, 60);
  for (size_t i = 0; i < root.frames.size(); ++i)
    EXPECT_EQ(root.keyed[i], root.frames[i] == 30 || root.frames[i] == 60) << root.frames[i];
  const MotionPath tip = computeMotionPath(scene, 0, 2, 0, 60);
  for (char k : tip.keyed) EXPECT_EQ(k, 0);  // the tip has no channels
}

TEST(MotionPath, RangeIsTheClipOrAroundTheCurrentFrameClamped) {
  const Scene scene = threeJointScene();
  MotionPathSettings s;
  long long first = -1, last = -1;
  motionPathRange(s, scene.clips[0], ownFrameGrid(scene.clips[0]), 12, first, last);
  EXPECT_EQ(first, 0);
  EXPECT_EQ(last, 60);
  s.wholeClip = false;
  s.before = 20;
  s.after = 5;
  motionPathRange(s, scene.clips[0], ownFrameGrid(scene.clips[0]), 12, first, last);
  EXPECT_EQ(first, 0);  // 12 - 20 clamped
  EXPECT_EQ(last, 17);
  motionPathRange(s, scene.clips[0], ownFrameGrid(scene.clips[0]), 58, first, last);
  EXPECT_EQ(first, 38);
  EXPECT_EQ(last, 60);  // 63 clamped
  EXPECT_TRUE(computeMotionPath(scene, 0, 7, 0, 10).points.empty());  // no such joint
  EXPECT_TRUE(computeMotionPath(scene, 1, 0, 0, 10).points.empty());  // no such clip
}

}  // namespace
}  // namespace kinema
