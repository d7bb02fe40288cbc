// One frame grid per clip (issue 17): a clip without its own frame time (glTF) is counted at
// kDefaultFrameRate (24 fps) by the timeline, the dope sheet, the curve editor, the onion
// skin, the motion path and motion control alike. Before, the timeline counted at 24 and
// the others at 30, so on Fox.glb the timeline said 31 where the dope sheet said 39.
#include <gtest/gtest.h>

#include <cmath>

#include "anim/sampling.h"
#include "editor/model/curve_editor.h"
#include "editor/model/document_files.h"
#include "editor/model/dope_sheet.h"
#include "editor/model/editor_state.h"
#include "editor/model/motion_control.h"
#include "editor/model/motion_path.h"
#include "editor/model/onion_skin.h"
#include "editor/model/timeline.h"
#include "scene/scene.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// A glTF-like clip (no frame grid) moving the root along X with x = 24 t: at 24 fps the
// root's x is the frame number, which makes every view's frame easy to check by hand.
// Linear keys at 0, at frame 31 (31/24 s) and at 2 s.
Scene gltfLikeScene() {
  Scene scene;
  scene.skeleton.addJoint("Root", -1, Transform{});
  scene.skeleton.addJoint("Tip", 0, Transform{glm::vec3(0, 1, 0)});
  Clip clip;
  clip.name = "glTF";
  const float t31 = static_cast<float>(31.0 / 24.0);
  clip.channels.push_back(Channel{0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, t31, 2.0f},
                                  {glm::vec4(0), glm::vec4(31, 0, 0, 0), glm::vec4(48, 0, 0, 0)}});
  EXPECT_EQ(clip.frameTime, 0.0);  // no rate of its own: it counts at the document's
  scene.clips.push_back(clip);
  return scene;
}

float rootX(const std::vector<glm::mat4>& world) { return world[0][3].x; }

TEST(FrameGrid, AClipWithoutAGridCountsAtTheDocumentsRate) {
  Clip clip;
  EXPECT_EQ(ownFrameGrid(clip).secondsPerFrame, 0.0);  // no rate of its own
  EXPECT_FALSE(hasOwnFrameRate(clip));
  EXPECT_DOUBLE_EQ(frameGridOf(clip, 30.0).secondsPerFrame, 1.0 / 30.0);  // the document's
  EXPECT_DOUBLE_EQ(frameGridOf(clip, 0.0).secondsPerFrame, 1.0 / 24.0);   // an unusable rate: the default
  EXPECT_DOUBLE_EQ(frameGridOf(clip, kDefaultFrameRate).secondsPerFrame, 1.0 / 24.0);  // Blender's default
  EXPECT_DOUBLE_EQ(frameGridOf(clip, kDefaultFrameRate).framesPerSecond(), 24.0);
  EXPECT_FLOAT_EQ(frameGridOf(clip, kDefaultFrameRate).frameToTime(31), 31.0f / 24.0f);
  EXPECT_EQ(frameGridOf(clip, kDefaultFrameRate).nearestFrame(1.3), 31);  // 31.2
  EXPECT_DOUBLE_EQ(frameGridOf(clip, kDefaultFrameRate).timeToFrame(0.5), 12.0);
  clip.frameTime = 1.0 / 30.0;  // a clip's own grid wins
  EXPECT_EQ(frameGridOf(clip, kDefaultFrameRate).nearestFrame(1.3), 39);
}

// Regression: before, the dope sheet, curve editor, onion skin, motion path and motion
// control counted this clip at 30 fps (frame 31 of the timeline was their 38.75), so each
// check below after the timeline's failed.
TEST(FrameGrid, TimelineDopeSheetCurveEditorAndOnionSkinAgreeOnAGltfClip) {
  EditorState s;
  s.doc = Document(gltfLikeScene());
  resetTimeline(s);
  const Clip& clip = s.doc.scene().clips[0];
  const float t31 = static_cast<float>(31.0 / 24.0);

  // Timeline: frame 31 is at 31/24 s and shows the root at x = 31.
  goToFrame(s, 31);
  EXPECT_EQ(currentFrame(s), 31);
  EXPECT_DOUBLE_EQ(s.time, t31);
  EXPECT_DOUBLE_EQ(timelineFps(s), 24.0);
  EXPECT_NEAR(rootX(s.world()), 31.0f, 1e-4f);

  // Dope sheet: the key at 31/24 s is in frame column 31 (a box over frame 31 takes it),
  // and moving it two frames lands on frame 33 = 33/24 s.
  const std::vector<DopeSheetRow> rows = dopeSheetRows(clip);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(frameGridOf(clip, kDefaultFrameRate).timeToFrame(rows[1].times[1]), 31.0, 1e-4);
  const std::vector<KeyColumn> box = columnsInBox(frameGridOf(clip, kDefaultFrameRate), rows, 31.0, 31.0, 1, 1);
  ASSERT_EQ(box.size(), 1u);
  EXPECT_FLOAT_EQ(box[0].time, t31);
  Clip moved = clip;
  moveKeyColumns(moved, frameGridOf(moved, kDefaultFrameRate), box, 2.0);
  EXPECT_FLOAT_EQ(moved.channels[0].times[1], 33.0f / 24.0f);

  // Curve editor: a key dragged to 1.3 s snaps to frame 31 (31.2 rounds down), not 1.3 s
  // (frame 39 of 30 fps).
  EXPECT_FLOAT_EQ(snapToFrame(frameGridOf(clip, kDefaultFrameRate), 1.3f), t31);

  // Onion skin: one ghost each side of frame 31, one frame apart: frames 30 and 32, posed
  // at 30/24 and 32/24 s (the root at x = 30 and 32).
  OnionSkinSettings onion;
  onion.enabled = true;
  onion.before = onion.after = onion.step = 1;
  const std::vector<GhostFrame> ghosts = ghostFrames(onion, frameGridOf(clip, kDefaultFrameRate).nearestFrame(s.time), frameGridOf(clip, kDefaultFrameRate).nearestFrame(clip.duration()) + 1);
  ASSERT_EQ(ghosts.size(), 2u);
  EXPECT_EQ(ghosts[0].frame, 30);
  EXPECT_EQ(ghosts[1].frame, 32);
  const std::vector<std::vector<glm::mat4>> poses = ghostPoses(s.doc.scene(), 0, ghosts);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_NEAR(rootX(poses[0]), 30.0f, 1e-4f);
  EXPECT_NEAR(rootX(poses[1]), 32.0f, 1e-4f);

  // Motion path: one point per frame, at the frame's x.
  const MotionPath path = computeMotionPath(s.doc.scene(), 0, 0, 30, 32);
  ASSERT_EQ(path.points.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(path.points[i].x, 30.0f + i, 1e-4f) << "frame " << 30 + i;
  EXPECT_EQ(path.keyed, (std::vector<char>{0, 1, 0}));  // the key on frame 31

  // Motion control bakes one key per frame: 48 intervals over the 2 s path.
  ASSERT_EQ(applyMotionControl(s.doc, 0, 0, MotionControlProfile::ConstantSpeed), "");
  const Channel& baked = s.doc.scene().clips[0].channels[0];
  ASSERT_EQ(baked.keyCount(), 49);
  EXPECT_NEAR(baked.times[1] - baked.times[0], 1.0 / 24.0, 1e-6);
}

TEST(FrameGrid, SettingTheRateInTheTimelineIsSavedAndEveryViewFollows) {
  EditorState s;
  s.doc = Document(gltfLikeScene());
  resetTimeline(s);
  ASSERT_TRUE(timelineRateIsTheDocuments(s));  // the clip has no rate of its own
  ASSERT_EQ(setFrameRate(s, 30.0), "");  // the timeline's fps field: the document's rate
  const Clip& clip = s.doc.scene().clips[0];
  EXPECT_DOUBLE_EQ(clip.frameTime, 0.0);
  EXPECT_DOUBLE_EQ(s.doc.scene().frameRate, 30.0);
  EXPECT_EQ(s.doc.historyLabels().back(), "Set document frame rate to 30 fps");
  EXPECT_EQ(frameAtTime(s, 1.3), 39);
  EXPECT_FLOAT_EQ(snapToFrame(s.doc.scene().frameGrid(0), 1.3f), static_cast<float>(39.0 / 30.0));
  EXPECT_NEAR(s.doc.scene().frameGrid(0).timeToFrame(1.3f), 39.0, 1e-4);
  // Saved with the document (.kinema frame_rate) and read back.
  const std::string dir = test::makeTempDir(), path = dir + "/rate.kinema";
  ASSERT_EQ(saveDocumentAs(s.doc, path), "");
  Result<Document> back = openDocument(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_DOUBLE_EQ(back.value().scene().frameRate, 30.0);  // .kinema frame_rate
  test::runCommand("rm -rf '" + dir + "'");
}

// The file of issue 17's report: Fox.glb keeps no frame rate, but its first clip's keys lie on
// the 24 fps grid (read as its rate). At every key the timeline's frame, the dope sheet's
// column and the curve editor's snapped frame are round(t * 24).
TEST(FrameGrid, FoxFramesAgreeAcrossTheViews) {
  KINEMA_REQUIRE_SHARED_DATA();
  Result<Document> opened = openDocument(test::sharedDataDir() + "/gltf/Fox.glb");
  ASSERT_TRUE(opened.ok()) << opened.error();
  EditorState s;
  s.doc = std::move(opened.value());
  resetTimeline(s);
  ASSERT_FALSE(s.doc.scene().clips.empty());
  const Clip& clip = s.doc.scene().clips[0];
  ASSERT_EQ(clip.frameTime, 1.0 / 24.0) << "Fox.glb's first clip's keys lie on the 24 fps grid";
  const std::vector<DopeSheetRow> rows = dopeSheetRows(clip);
  ASSERT_GT(rows.size(), 1u);
  int checked = 0;
  for (float t : rows[0].times) {
    const long long expected = std::llround(double(t) * 24.0);
    EXPECT_EQ(frameAtTime(s, t), expected) << "timeline at " << t;
    EXPECT_EQ(std::llround(frameGridOf(clip, kDefaultFrameRate).timeToFrame(t)), expected) << "dope sheet at " << t;
    EXPECT_EQ(frameGridOf(clip, kDefaultFrameRate).nearestFrame(snapToFrame(frameGridOf(clip, kDefaultFrameRate), t)), expected) << "curve editor at " << t;
    goToFrame(s, expected);
    EXPECT_EQ(frameGridOf(clip, kDefaultFrameRate).nearestFrame(s.time), expected) << "onion skin's current frame at " << t;
    ++checked;
  }
  EXPECT_GT(checked, 10);
  // The report's case: 1.3 s is frame 31 in the timeline and in the dope sheet.
  EXPECT_EQ(frameAtTime(s, 1.3), 31);
  EXPECT_EQ(std::llround(frameGridOf(clip, kDefaultFrameRate).timeToFrame(1.3)), 31);
}

// Issue 38's report in the editor: the retargeted glTF of a 120 fps take opens with frame 240
// at the take's 2.0 s (its rate kept in the file), where it was 10.0 s at 24 fps.
TEST(FrameGrid, ARetargetedGltfOpensOnItsSourcesFrames) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string dir = test::makeTempDir(), out = dir + "/onto.glb";
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " retarget '" + test::sharedDataDir() +
                             "/bvh/cmu_01_01_first720.bvh' '" + test::sharedDataDir() + "/gltf/CesiumMan.glb' --out '" + out +
                             "'"),
            0);
  Result<Document> opened = openDocument(out);
  ASSERT_TRUE(opened.ok()) << opened.error();
  EditorState s;
  s.doc = std::move(opened.value());
  resetTimeline(s);
  goToFrame(s, 240);
  EXPECT_NEAR(s.time, 240 * 0.0083333, 1e-6);
  EXPECT_NEAR(timelineFps(s), 1.0 / 0.0083333, 1e-6);
  EXPECT_EQ(rangeEndFrame(s), 719);  // the take's 720 frames
  test::runCommand("rm -rf '" + dir + "'");
}

// The document's rate: a clip without its own counts at it, Set Document Frame Rate is one undo
// step, and a clip with its own rate keeps counting at that.
TEST(FrameGrid, TheDocumentsRateCountsClipsWithoutOne) {
  EditorState s;
  s.doc = Document(gltfLikeScene());
  resetTimeline(s);
  s.doc.edit("Set document frame rate", [](DocumentEdit& e) {
    e.frameRate = 30.0;
    return std::string();
  });
  EXPECT_EQ(s.doc.scene().frameRate, 30.0);
  EXPECT_DOUBLE_EQ(timelineFps(s), 30.0);
  goToFrame(s, 30);
  EXPECT_DOUBLE_EQ(s.time, static_cast<float>(1.0));
  ASSERT_TRUE(s.doc.undo());
  EXPECT_EQ(s.doc.scene().frameRate, kDefaultFrameRate);
  EXPECT_DOUBLE_EQ(timelineFps(s), 24.0);
  ASSERT_TRUE(s.doc.redo());
  EXPECT_EQ(s.doc.scene().frameRate, 30.0);
  EXPECT_NE(s.doc.edit("Bad rate", [](DocumentEdit& e) {
    e.frameRate = 0.0;
    return std::string();
  }), "");
  EXPECT_EQ(s.doc.scene().frameRate, 30.0);
}

// A clip with its own rate (BVH's, say) keeps it its own: the fps field sets it, not the document's.
TEST(FrameGrid, TheFpsFieldSetsAClipsOwnRateWhenItHasOne) {
  Scene scene = gltfLikeScene();
  scene.clips[0].frameTime = 1.0 / 120.0;
  EditorState s;
  s.doc = Document(scene);
  resetTimeline(s);
  ASSERT_FALSE(timelineRateIsTheDocuments(s));
  goToFrame(s, 240);
  ASSERT_EQ(setFrameRate(s, 60.0), "");
  EXPECT_DOUBLE_EQ(s.doc.scene().clips[0].frameTime, 1.0 / 60.0);
  EXPECT_EQ(s.doc.scene().frameRate, kDefaultFrameRate);
  EXPECT_EQ(currentFrame(s), 240);  // the playhead keeps its frame number
  EXPECT_EQ(s.doc.historyLabels().back(), "Set frame rate to 60 fps");
}

// Foot contacts are frames of the clip's grid, but the planted feet are in the keys, which keep
// their times: a new rate counts the contacts again so each keeps its moments.
TEST(FrameGrid, FootContactsKeepTheirMomentsWhenTheRateChanges) {
  const FrameGrid at24 = documentFrameGrid(24.0), at48 = documentFrameGrid(48.0), at10 = documentFrameGrid(10.0);
  FootContacts c;
  c.of(Foot::Left) = {{6, 12}, {13, 20}};  // 0.25..0.5 s and 0.54..0.83 s, touching: two steps
  c.of(Foot::Right) = {{0, 0}, {1, 1}};
  const FootContacts doubled = contactsOnGrid(c, at24, at48);
  EXPECT_EQ(doubled.of(Foot::Left), (std::vector<ContactInterval>{{12, 24}, {26, 40}}));
  EXPECT_EQ(doubled.of(Foot::Right), (std::vector<ContactInterval>{{0, 0}, {2, 2}}));
  EXPECT_EQ(contactsOnGrid(doubled, at48, at24), c);  // and back
  // At 10 fps frames 0 and 1 (0 s and 1/24 s) both fall on frame 0: one contact, still valid.
  const FootContacts coarse = contactsOnGrid(c, at24, at10);
  EXPECT_EQ(coarse.of(Foot::Right), (std::vector<ContactInterval>{{0, 0}}));
  EXPECT_EQ(coarse.validate(), "");
  // Through the timeline's fps field, for a clip without a rate (the document's) and with one.
  for (const bool own : {false, true}) {
    EditorState s;
    Scene scene = gltfLikeScene();
    if (own) scene.clips[0].frameTime = 1.0 / 24.0;
    scene.clips[0].contacts = c;
    s.doc = Document(scene);
    resetTimeline(s);
    ASSERT_EQ(setFrameRate(s, 48.0), "");
    EXPECT_EQ(s.doc.scene().clips[0].contacts, doubled) << (own ? "the clip's own rate" : "the document's rate");
  }
}

}  // namespace
}  // namespace kinema
