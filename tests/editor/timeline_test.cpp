// The timeline model (timeline.h): frames and times, step / jump / scrub / loop over the
// range, Blender's defaults without a clip, the range and rate saved in the clip, and the
// document posed from the clip on a frame change without an undo step.
#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/document_files.h"
#include "editor/model/editor_state.h"
#include "editor/model/keying.h"
#include "editor/model/pose_edits.h"
#include "editor/model/timeline.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

EditorState newState() {
  EditorState s;
  s.doc = newDocument();
  return s;
}

TEST(Timeline, WithoutAClipShowsBlendersDefaults) {
  EditorState s = newState();
  ASSERT_TRUE(s.doc.scene().clips.empty());
  EXPECT_TRUE(s.timelineShown());  // a skeleton: the timeline is there for keying
  EXPECT_DOUBLE_EQ(timelineFps(s), 24.0);
  EXPECT_EQ(rangeStartFrame(s), 1);
  EXPECT_EQ(rangeEndFrame(s), 250);
  EXPECT_DOUBLE_EQ(timeOfFrame(s, 12), 0.5);
  EXPECT_EQ(frameAtTime(s, 0.5), 12);
  EXPECT_EQ(frameAtTime(s, 0.5 + 0.49 / 24), 12);  // nearest frame
  EXPECT_EQ(frameAtTime(s, 0.5 + 0.51 / 24), 13);
  EditorState empty;
  EXPECT_FALSE(empty.timelineShown());
}

TEST(Timeline, StepJumpAndGoTo) {
  EditorState s = newState();
  goToFrame(s, 10);
  EXPECT_EQ(currentFrame(s), 10);
  EXPECT_DOUBLE_EQ(s.time, static_cast<float>(10.0 / 24.0));  // the time a key on frame 10 gets (Clip::frameToTime)
  EXPECT_FLOAT_EQ(static_cast<float>(s.doc.playhead().time), 10.0f / 24.0f);  // auto-key keys at the playhead
  stepFrame(s, 1);
  EXPECT_EQ(currentFrame(s), 11);
  stepFrame(s, -1);
  stepFrame(s, -1);
  EXPECT_EQ(currentFrame(s), 9);
  jumpToEnd(s);
  EXPECT_EQ(currentFrame(s), 250);
  stepFrame(s, 1);  // no wrap: past the end as in Blender
  EXPECT_EQ(currentFrame(s), 251);
  jumpToStart(s);
  EXPECT_EQ(currentFrame(s), 1);
}

TEST(Timeline, PlaybackLoopsOrStopsAtTheRangeEnd) {
  EditorState s = newState();
  ASSERT_EQ(setFrameRange(s, 1, 24), "");
  goToFrame(s, 23);
  togglePlayback(s);
  EXPECT_TRUE(s.playing);
  // 2.25 frames on: 25.25 wraps over the 23-frame loop to frame 2.25 -> frame 2.
  advanceTimeline(s, 2.25 / 24);
  EXPECT_NEAR(s.time, 2.25 / 24, 1e-6);
  EXPECT_EQ(currentFrame(s), 2);
  s.loop = false;
  advanceTimeline(s, 30.0 / 24);
  EXPECT_FALSE(s.playing);
  EXPECT_EQ(currentFrame(s), 24);
  // Pausing lands on a whole frame.
  togglePlayback(s);
  advanceTimeline(s, -20.4 / 24);  // (time runs backwards only here, to land off-grid)
  togglePlayback(s);
  EXPECT_FALSE(s.playing);
  EXPECT_DOUBLE_EQ(s.time, timeOfFrame(s, currentFrame(s)));
}

TEST(Timeline, RangeLivesInTheClipTheRateInTheDocumentAndBothAreUndoable) {
  EditorState s = newState();
  ASSERT_EQ(setFrameRange(s, 5, 40), "");
  ASSERT_EQ(s.doc.scene().clips.size(), 1u);  // the range needs a clip: "Action"
  const Clip& c = s.doc.scene().clips[0];
  EXPECT_EQ(c.name, "Action");
  EXPECT_TRUE(c.hasRange);
  EXPECT_FLOAT_EQ(c.rangeStart, 5.0f / 24);
  EXPECT_FLOAT_EQ(c.rangeEnd, 40.0f / 24);
  EXPECT_EQ(rangeStartFrame(s), 5);
  EXPECT_EQ(rangeEndFrame(s), 40);
  EXPECT_NE(setFrameRange(s, 10, 9), "");
  ASSERT_EQ(setFrameRate(s, 30.0), "");
  EXPECT_DOUBLE_EQ(timelineFps(s), 30.0);
  EXPECT_EQ(rangeStartFrame(s), 5);  // the range keeps its frame numbers
  EXPECT_EQ(rangeEndFrame(s), 40);
  EXPECT_NE(setFrameRate(s, 0.0), "");
  // Saved in .kinema: the range with the clip, the rate as the document's (the Action has none).
  const std::string path = test::makeTempDir() + "/range.kinema";
  ASSERT_EQ(saveDocumentAs(s.doc, path), "");
  Result<Document> back = openDocument(path);
  ASSERT_TRUE(back.ok()) << back.error();
  ASSERT_EQ(back.value().scene().clips.size(), 1u);
  EXPECT_FLOAT_EQ(back.value().scene().clips[0].rangeStart, 5.0f / 30);
  EXPECT_FLOAT_EQ(back.value().scene().clips[0].rangeEnd, 40.0f / 30);
  EXPECT_EQ(back.value().scene().clips[0].frameTime, 0.0);
  EXPECT_EQ(back.value().scene().frameRate, 30.0);
  ASSERT_TRUE(s.doc.undo());
  EXPECT_DOUBLE_EQ(timelineFps(s), 24.0);
  ASSERT_TRUE(s.doc.undo());
  EXPECT_TRUE(s.doc.scene().clips.empty());
}

// A frame change poses the document from the clip: Linear keys at frames 1 and 24 of a
// rotation about Z from 0.2 to 1.1 rad give 0.2 + 0.9 * 11/23 at frame 12 (slerp on one
// axis is linear in angle), with no undo step and no unsaved change.
TEST(Timeline, FrameChangesPoseTheDocumentWithoutAnUndoStep) {
  EditorState s = newState();
  const int arm = s.doc.skeleton().find("UpperArm.L"), leg = s.doc.skeleton().find("UpperLeg.L");
  s.doc.autoKey.preferences.interpolation = Interpolation::Linear;
  s.doc.selection.click(arm);
  goToFrame(s, 1);
  ASSERT_EQ(setJointRotation(s.doc, arm, glm::angleAxis(0.2f, glm::vec3(0, 0, 1))), "");
  keySelectedJoints(s);
  goToFrame(s, 24);
  ASSERT_EQ(setJointRotation(s.doc, arm, glm::angleAxis(1.1f, glm::vec3(0, 0, 1))), "");
  keySelectedJoints(s);
  // An unkeyed joint keeps its pose across frame changes.
  ASSERT_EQ(setJointRotation(s.doc, leg, glm::angleAxis(0.3f, glm::vec3(1, 0, 0))), "");
  const Transform legPose = s.doc.pose().local[leg];
  const size_t steps = s.doc.historyLabels().size();
  const long long changes = s.doc.changeCount();
  goToFrame(s, 12);
  const glm::quat q = s.doc.pose().local[arm].rotation;
  EXPECT_NEAR(2.0f * std::atan2(q.z, q.w), 0.2f + 0.9f * 11.0f / 23.0f, 1e-5f);
  EXPECT_EQ(s.doc.pose().local[leg], legPose);
  EXPECT_EQ(s.doc.historyLabels().size(), steps);
  EXPECT_EQ(s.doc.changeCount(), changes);  // nothing for autosave to write
  goToFrame(s, 1);
  EXPECT_NEAR(2.0f * std::atan2(s.doc.pose().local[arm].rotation.z, s.doc.pose().local[arm].rotation.w), 0.2f, 1e-6f);
}

// Playback poses through PlaybackSamplingJob (anim/playback_sampling_job.h): the same pose
// as sampleClip to 1e-6, and an edit of the clip while it plays shows on the next frame
// (the sampling form is rebuilt after any change of the document).
TEST(Timeline, PlaybackPosesFromTheSamplingFormAndFollowsEditsWhilePlaying) {
  Scene scene;
  constexpr int kJoints = 6;
  for (int j = 0; j < kJoints; ++j) scene.skeleton.addJoint("J" + std::to_string(j), j - 1, Transform{});
  Clip clip;
  clip.frameTime = 1.0 / 24.0;
  std::vector<float> times;
  for (int k = 0; k < 48; ++k) times.push_back(ownFrameGrid(clip).frameToTime(k));
  for (int j = 0; j < kJoints; ++j) {
    Channel t(j, ChannelTarget::Translation, Interpolation::Linear, times, {});
    Channel r(j, ChannelTarget::Rotation, Interpolation::Linear, times, {});
    for (int k = 0; k < 48; ++k) {
      t.values.emplace_back(0.1f * k, j, -0.05f * k * j, 0.0f);
      const glm::quat q = glm::angleAxis(0.05f * k * (j + 1), glm::normalize(glm::vec3(1, j, 2)));
      r.values.emplace_back(q.x, q.y, q.z, q.w);
    }
    clip.channels.push_back(std::move(t));
    clip.channels.push_back(std::move(r));
  }
  scene.clips.push_back(clip);
  EditorState s;
  s.doc = Document(scene);
  resetTimeline(s);
  auto expectPoseOfClip = [&](const char* when) {
    Pose expected = s.doc.pose();
    sampleClip(s.doc.scene().clips[0], static_cast<float>(s.time), expected);
    for (int j = 0; j < kJoints; ++j) {
      const Transform &a = s.doc.pose().local[j], &b = expected.local[j];
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.translation[i], b.translation[i], 1e-6f) << when << ", joint " << j;
      for (int i = 0; i < 4; ++i) EXPECT_NEAR(a.rotation[i], b.rotation[i], 1e-6f) << when << ", joint " << j;
    }
  };
  togglePlayback(s);
  for (int frame = 0; frame < 10; ++frame) {
    advancePlayback(s, 0.37 / 24.0);
    evaluateEditorPose(s);
    expectPoseOfClip("playing");
  }
  // The played clip went through its sampling form: one grid of all twelve channels.
  ASSERT_EQ(s.playbackSampler.clip.grids.size(), 1u);
  EXPECT_EQ(s.playbackSampler.clip.trackCount(), 2 * kJoints);
  // An edit while playing: every translation key of joint 2 moves up by 3.
  ASSERT_EQ(s.doc.edit("Move keys",
                       [](DocumentEdit& e) {
                         for (glm::vec4& v : e.clips[0].channels[4].values) v.y += 3.0f;
                         return std::string();
                       }),
            "");
  advancePlayback(s, 0.5 / 24.0);
  evaluateEditorPose(s);
  EXPECT_GT(s.doc.pose().local[2].translation.y, 4.9f);  // 2 + 3
  expectPoseOfClip("after the edit");
}

TEST(Timeline, RulerMapsFramesToPixelsAndBack) {
  EditorState s = newState();
  const TimelineRuler r = timelineRuler(s, 250, 700, 720, 40);
  EXPECT_EQ(r.first, 1);
  EXPECT_EQ(r.last, 250);
  EXPECT_FLOAT_EQ(r.xOfFrame(1), r.x + kTimelineRulerMargin);
  EXPECT_FLOAT_EQ(r.xOfFrame(250), r.x + r.w - kTimelineRulerMargin);
  for (long long f : {1LL, 2LL, 100LL, 249LL, 250LL}) EXPECT_EQ(r.frameAtX(r.xOfFrame(f)), f);
  EXPECT_EQ(r.frameAtX(r.x - 100), 1);  // clamped to the range
  EXPECT_EQ(r.frameAtX(r.x + r.w + 100), 250);
  EXPECT_LE(r.y + r.h, 700 + 40);
}

TEST(Timeline, DiamondsAreTheFramesOfTheSelectedJointsKeys) {
  EditorState s = newState();
  const int arm = s.doc.skeleton().find("UpperArm.L"), leg = s.doc.skeleton().find("UpperLeg.L");
  s.doc.selection.click(arm);
  goToFrame(s, 3);
  keySelectedJoints(s);
  s.doc.selection.click(leg);
  goToFrame(s, 7);
  keySelectedJoints(s);
  EXPECT_EQ(selectedKeyFrames(s), std::vector<long long>{7});
  s.doc.selection.shiftClick(arm);
  EXPECT_EQ(selectedKeyFrames(s), (std::vector<long long>{3, 7}));
  deleteSelectedJointKeys(s);  // frame 7, both joints
  EXPECT_EQ(selectedKeyFrames(s), std::vector<long long>{3});
}

}  // namespace
}  // namespace kinema
