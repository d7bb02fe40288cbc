// Keying commands and auto-key on the document (keying.h): insert / delete keys as one
// undo step each, undo and redo restore the clips bit for bit, the key preferences, and
// auto-key recording FK edits and IK drags in the same undo step as the pose.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>

#include "anim/sampling.h"
#include "editor/model/document_files.h"
#include "editor/model/ik_posing.h"
#include "editor/model/keying.h"
#include "editor/model/pose_edits.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

int joint(const Document& d, const char* name) { return d.skeleton().find(name); }

// The clips as bytes (names, ranges, channels with their times, values and key settings).
std::string clipBytes(const std::vector<Clip>& clips) {
  std::string b;
  auto raw = [&b](const void* p, size_t n) { b.append(static_cast<const char*>(p), n); };
  for (const Clip& c : clips) {
    b += c.name + '\0';
    raw(&c.frameTime, sizeof c.frameTime);
    const float range[] = {c.hasRange ? 1.0f : 0.0f, c.rangeStart, c.rangeEnd};
    raw(range, sizeof range);
    for (const Channel& ch : c.channels) {
      const int head[] = {ch.joint, static_cast<int>(ch.target), static_cast<int>(ch.interpolation), ch.keyCount(),
                          static_cast<int>(ch.keys.size())};
      raw(head, sizeof head);
      raw(ch.times.data(), ch.times.size() * sizeof(float));
      raw(ch.values.data(), ch.values.size() * sizeof(glm::vec4));
      for (const KeySettings& k : ch.keys) {
        const int s[] = {static_cast<int>(k.interpolation), static_cast<int>(k.leftHandleType),
                         static_cast<int>(k.rightHandleType)};
        raw(s, sizeof s);
      }
    }
  }
  return b;
}

const Channel* channel(const Clip& c, int joint, ChannelTarget target) {
  for (const Channel& ch : c.channels)
    if (ch.joint == joint && ch.target == target) return &ch;
  return nullptr;
}

// Angle of q about +Z (q is a rotation about Z).
float angleAboutZ(const glm::quat& q) { return 2.0f * std::atan2(q.z, q.w); }

TEST(Keying, RotationInterpolationMapsToOnesTheEngineAccepts) {
  EXPECT_EQ(rotationInterpolation(Interpolation::Bezier), Interpolation::Bezier);  // quaternion F-curves
  EXPECT_EQ(rotationInterpolation(Interpolation::CatmullRom), Interpolation::Squad);
  EXPECT_EQ(rotationInterpolation(Interpolation::TCB), Interpolation::Squad);
  EXPECT_EQ(rotationInterpolation(Interpolation::Linear), Interpolation::Linear);
  EXPECT_EQ(rotationInterpolation(Interpolation::Step), Interpolation::Step);
  const KeySettings t = keySettingsFor(KeyPreferences{}, ChannelTarget::Translation);
  EXPECT_EQ(t.interpolation, Interpolation::Bezier);
  EXPECT_EQ(t.leftHandleType, HandleType::AutoClamped);
  EXPECT_EQ(t.rightHandleType, HandleType::AutoClamped);
  // Every preference gives keys Clip::validate accepts on every target.
  Document doc = newDocument();
  for (Interpolation i : {Interpolation::Step, Interpolation::Linear, Interpolation::Hermite, Interpolation::CatmullRom,
                          Interpolation::TCB, Interpolation::Bezier, Interpolation::Ease, Interpolation::Nlerp,
                          Interpolation::Squad}) {
    std::vector<Clip> clips;
    int c = -1;
    KeyPreferences p;
    p.interpolation = i;
    Pose pose = doc.pose();
    pose.local[1].scale = glm::vec3(1.5f);
    ASSERT_GT(keyJoints(clips, c, doc.skeleton(), pose, {0, 1, 2}, 0.5f, p, documentFrameGrid(kDefaultFrameRate)), 0);
    EXPECT_EQ(clips[c].validate(doc.skeleton()), "") << toString(i);
  }
}

TEST(Keying, FirstKeyCreatesActionAndUndoRedoRestoreClipsExactly) {
  Document doc = newDocument();
  ASSERT_TRUE(doc.scene().clips.empty());
  const int arm = joint(doc, "UpperArm.L");
  const glm::quat q = glm::angleAxis(0.6f, glm::vec3(0, 0, 1));
  ASSERT_EQ(setJointRotation(doc, arm, q), "");
  int clip = 0;
  const float t1 = static_cast<float>(1.0 / 24.0);
  ASSERT_EQ(insertKeys(doc, clip, t1, {arm}, KeyPreferences{}), "");
  ASSERT_EQ(doc.scene().clips.size(), 1u);
  EXPECT_EQ(clip, 0);
  const Clip& c = doc.scene().clips[0];
  EXPECT_EQ(c.name, "Action");
  EXPECT_DOUBLE_EQ(c.frameTime, 0.0);  // no rate of its own: the document's, 24 fps
  EXPECT_DOUBLE_EQ(doc.scene().frameGrid(0).secondsPerFrame, 1.0 / 24.0);
  EXPECT_TRUE(c.hasRange);
  EXPECT_FLOAT_EQ(c.rangeStart, 1.0f / 24.0f);
  EXPECT_FLOAT_EQ(c.rangeEnd, 250.0f / 24.0f);
  // Translation and rotation; no scale (it is the rest scale).
  ASSERT_EQ(c.channels.size(), 2u);
  const Channel* rot = channel(c, arm, ChannelTarget::Rotation);
  const Channel* loc = channel(c, arm, ChannelTarget::Translation);
  ASSERT_TRUE(rot && loc);
  EXPECT_EQ(channel(c, arm, ChannelTarget::Scale), nullptr);
  ASSERT_EQ(rot->keyCount(), 1);
  EXPECT_EQ(rot->times[0], t1);
  EXPECT_NEAR(rot->values[0].z, std::sin(0.3f), 1e-6f);
  EXPECT_NEAR(rot->values[0].w, std::cos(0.3f), 1e-6f);
  EXPECT_EQ(rot->settings(0).interpolation, Interpolation::Bezier);  // eased, as Blender's default
  EXPECT_EQ(rot->settings(0).leftHandleType, HandleType::AutoClamped);
  EXPECT_EQ(rot->settings(0).rightHandleType, HandleType::AutoClamped);
  EXPECT_EQ(loc->settings(0).interpolation, Interpolation::Bezier);
  EXPECT_EQ(loc->settings(0).rightHandleType, HandleType::AutoClamped);
  EXPECT_EQ(glm::vec3(loc->values[0]), doc.pose().local[arm].translation);
  EXPECT_EQ(doc.historyLabels().back(), "Insert keys on UpperArm.L at frame 1");  // t1 = 1/24 s at 24 fps

  const std::string keyed = clipBytes(doc.scene().clips);
  const std::vector<Transform> pose = doc.pose().local;
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().clips.empty());
  EXPECT_EQ(doc.pose().local, pose);  // the key edit did not touch the pose
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(clipBytes(doc.scene().clips), keyed);
}

TEST(Keying, ScaleIsKeyedWhereItDiffersFromRestUnlessLocRotOnly) {
  Document doc = newDocument();
  Pose pose = doc.pose();
  pose.local[2].scale = glm::vec3(2.0f);
  std::vector<Clip> clips;
  int c = -1;
  keyJoints(clips, c, doc.skeleton(), pose, {1, 2}, 0.0f, KeyPreferences{}, documentFrameGrid(kDefaultFrameRate));
  EXPECT_EQ(channel(clips[c], 1, ChannelTarget::Scale), nullptr);
  ASSERT_NE(channel(clips[c], 2, ChannelTarget::Scale), nullptr);
  EXPECT_EQ(glm::vec3(channel(clips[c], 2, ChannelTarget::Scale)->values[0]), glm::vec3(2.0f));
  KeyPreferences locRot;
  locRot.locRotOnly = true;
  std::vector<Clip> other;
  int d = -1;
  keyJoints(other, d, doc.skeleton(), pose, {2}, 0.0f, locRot, documentFrameGrid(kDefaultFrameRate));
  EXPECT_EQ(channel(other[d], 2, ChannelTarget::Scale), nullptr);
  EXPECT_EQ(other[d].channels.size(), 2u);
}

// Frame 1 and frame 24 keyed with rotations about Z of a1 and a2; Linear keys slerp, so
// at frame 12 the angle is a1 + (a2 - a1) * 11/23 (one axis: slerp is linear in angle).
// The default (Bezier, auto-clamped) eases: two end keys get flat handles a third of the
// interval long, so each quaternion component follows a + (b - a) s with the smoothstep
// s = 3u^2 - 2u^3, and the rotation is that blend normalised (zero slope at both keys).
TEST(Keying, TwoKeysInterpolateBetweenThePoses) {
  for (Interpolation i : {Interpolation::Linear, Interpolation::Bezier}) {
    Document doc = newDocument();
    const int arm = joint(doc, "UpperArm.L");
    KeyPreferences p;
    p.interpolation = i;
    const float a1 = 0.2f, a2 = 1.1f, t1 = 1.0f / 24, t24 = 24.0f / 24, t12 = 12.0f / 24;
    int clip = 0;
    ASSERT_EQ(setJointRotation(doc, arm, glm::angleAxis(a1, glm::vec3(0, 0, 1))), "");
    ASSERT_EQ(insertKeys(doc, clip, t1, {arm}, p), "");
    ASSERT_EQ(setJointRotation(doc, arm, glm::angleAxis(a2, glm::vec3(0, 0, 1))), "");
    ASSERT_EQ(insertKeys(doc, clip, t24, {arm}, p), "");
    Pose pose = Pose::rest(doc.skeleton());
    sampleClip(doc.scene().clips[clip], t12, pose);
    const float a = angleAboutZ(pose.local[arm].rotation);
    if (i == Interpolation::Linear) {
      EXPECT_NEAR(a, a1 + (a2 - a1) * 11.0f / 23.0f, 1e-5f);
    } else {
      auto eased = [&](double u) {
        const double s = 3 * u * u - 2 * u * u * u;
        const double z = (1 - s) * std::sin(a1 / 2.0) + s * std::sin(a2 / 2.0);
        const double w = (1 - s) * std::cos(a1 / 2.0) + s * std::cos(a2 / 2.0);
        return 2 * std::atan2(z, w);
      };
      EXPECT_NEAR(a, eased(11.0 / 23.0), 1e-5);
      // A quarter of the way in it lags the straight line; three quarters in it leads it.
      for (double u : {0.25, 0.75}) {
        sampleClip(doc.scene().clips[clip], float(t1 + u * (t24 - t1)), pose);
        const double got = angleAboutZ(pose.local[arm].rotation), linear = a1 + (a2 - a1) * u;
        EXPECT_NEAR(got, eased(u), 1e-5);
        if (u < 0.5) EXPECT_LT(got, linear - 0.05);
        else EXPECT_GT(got, linear + 0.05);
      }
      sampleClip(doc.scene().clips[clip], t12, pose);
    }
    EXPECT_NEAR(std::abs(glm::dot(pose.local[arm].rotation, glm::angleAxis(a, glm::vec3(0, 0, 1)))), 1.0f, 1e-6f);
  }
}

TEST(Keying, DeleteRemovesOnlyThatFramesKeysAsOneUndoStep) {
  Document doc = newDocument();
  const int arm = joint(doc, "UpperArm.L"), leg = joint(doc, "UpperLeg.L");
  ASSERT_GE(leg, 0);
  int clip = 0;
  ASSERT_EQ(insertKeys(doc, clip, 0.5f, {arm, leg}, KeyPreferences{}), "");
  ASSERT_EQ(setJointRotation(doc, arm, glm::angleAxis(0.4f, glm::vec3(1, 0, 0))), "");
  ASSERT_EQ(insertKeys(doc, clip, 1.0f, {arm, leg}, KeyPreferences{}), "");
  const std::string before = clipBytes(doc.scene().clips);
  const size_t steps = doc.historyLabels().size();
  ASSERT_EQ(deleteKeys(doc, clip, 1.0f, {arm}), "");
  EXPECT_EQ(doc.historyLabels().size(), steps + 1);
  const Clip& c = doc.scene().clips[clip];
  for (ChannelTarget t : {ChannelTarget::Translation, ChannelTarget::Rotation}) {
    ASSERT_NE(channel(c, arm, t), nullptr);
    EXPECT_EQ(channel(c, arm, t)->times, std::vector<float>{0.5f});
    EXPECT_EQ(channel(c, leg, t)->times, (std::vector<float>{0.5f, 1.0f}));
  }
  EXPECT_NE(deleteKeys(doc, clip, 1.0f, {arm}), "");  // nothing left there: no step
  EXPECT_EQ(doc.historyLabels().size(), steps + 1);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(clipBytes(doc.scene().clips), before);
  // Deleting a channel's last key drops the channel.
  ASSERT_TRUE(doc.redo());
  ASSERT_EQ(deleteKeys(doc, clip, 0.5f, {arm}), "");
  EXPECT_EQ(channel(doc.scene().clips[clip], arm, ChannelTarget::Rotation), nullptr);
}

TEST(Keying, AutoKeyRecordsAnFkEditInTheSameUndoStep) {
  Document doc = newDocument();
  doc.autoKey.enabled = true;
  doc.setPlayheadTime(0.25);
  const int arm = joint(doc, "UpperArm.L");
  const Pose start = doc.pose();
  const glm::quat q = glm::angleAxis(0.9f, glm::normalize(glm::vec3(0.2f, 0.3f, 1.0f)));
  ASSERT_EQ(setJointRotation(doc, arm, q), "");
  ASSERT_EQ(doc.historyLabels().size(), 1u);
  ASSERT_EQ(doc.scene().clips.size(), 1u);
  const Clip& c = doc.scene().clips[0];
  ASSERT_EQ(c.channels.size(), 2u);  // only the edited joint: translation + rotation
  const Channel* rot = channel(c, arm, ChannelTarget::Rotation);
  ASSERT_NE(rot, nullptr);
  EXPECT_EQ(rot->times, std::vector<float>{0.25f});
  const glm::quat n = glm::normalize(q);
  EXPECT_NEAR(std::abs(glm::dot(glm::vec4(n.x, n.y, n.z, n.w), rot->values[0])), 1.0f, 1e-6f);
  // One undo takes back the pose and the keys.
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.pose().local, start.local);
  EXPECT_TRUE(doc.scene().clips.empty());
  // Off: edits key nothing.
  doc.autoKey.enabled = false;
  ASSERT_EQ(setJointRotation(doc, arm, q), "");
  EXPECT_TRUE(doc.scene().clips.empty());
}

TEST(Keying, AutoKeyRecordsTheChainOfAnIkDragOnce) {
  Document doc = newDocument();
  doc.autoKey.enabled = true;
  doc.setPlayheadTime(0.5);
  const int hand = joint(doc, "Hand.L");
  const Pose start = doc.pose();
  ASSERT_EQ(beginAutoIkDrag(doc, hand, 3), "");
  for (int k = 1; k <= 4; ++k)
    ASSERT_EQ(updateAutoIkDrag(doc, glm::mix(glm::vec3(0.71f, 1.45f, 0.0f), glm::vec3(0.5f, 1.1f, 0.3f), k / 4.0f)), "");
  doc.commitDrag();
  ASSERT_EQ(doc.historyLabels().size(), 1u);
  ASSERT_EQ(doc.scene().clips.size(), 1u);
  // The keyed joints are exactly those the drag moved: the hand's three ancestors.
  std::set<int> moved, keyed;
  for (int j = 0; j < doc.skeleton().size(); ++j)
    if (std::memcmp(&start.local[j], &doc.pose().local[j], sizeof(Transform)) != 0) moved.insert(j);
  for (const Channel& ch : doc.scene().clips[0].channels) {
    keyed.insert(ch.joint);
    EXPECT_EQ(ch.times, std::vector<float>{0.5f});  // every update restarted from the drag's start
  }
  const std::vector<int>& parents = doc.skeleton().parents;
  const std::set<int> chain = {parents[hand], parents[parents[hand]], parents[parents[parents[hand]]]};
  EXPECT_EQ(moved, chain);
  EXPECT_EQ(keyed, chain);
  // The keys hold the committed pose.
  Pose sampled = Pose::rest(doc.skeleton());
  sampleClip(doc.scene().clips[0], 0.5f, sampled);
  for (int j : chain) EXPECT_NEAR(std::abs(glm::dot(sampled.local[j].rotation, doc.pose().local[j].rotation)), 1.0f, 1e-6f);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.pose().local, start.local);
  EXPECT_TRUE(doc.scene().clips.empty());
}

}  // namespace
}  // namespace kinema
