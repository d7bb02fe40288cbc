// Foot contacts edited in the model (issue 21): add (overlaps join), delete, typed frames,
// bar drags clamped by their neighbours (one undo step each, Esc back to the start), the
// strip's hit testing, detection on a humanoid, Clean Up as one undo step with the job's own
// figures, and contacts and bone maps through save and reopen.
#include <gtest/gtest.h>

#include "core/default_character.h"
#include "editor/model/contact_lanes.h"
#include "editor/model/document.h"
#include "editor/model/document_files.h"
#include "editor/model/editor_state.h"
#include "editor/model/foot_contact_edits.h"
#include "editor/model/motion_cleanup_edit.h"
#include "editor/model/motion_import.h"
#include "io/kinema_file.h"
#include "retarget/bone_map.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using Intervals = std::vector<ContactInterval>;

// The default character standing still for `frames` frames while its hips slide slowly
// along +X (0.1 units/s, under the contact speed threshold): both feet in contact throughout.
Scene standingScene(int frames = 30) {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  Clip clip;
  clip.name = "stand";
  clip.frameTime = 1.0 / 30.0;
  Channel root(0, ChannelTarget::Translation, Interpolation::Linear, {}, {});
  for (int f = 0; f < frames; ++f) {
    root.times.push_back(ownFrameGrid(clip).frameToTime(f));
    root.values.push_back(glm::vec4(scene.skeleton.rest[0].translation + glm::vec3(0.1f * ownFrameGrid(clip).frameToTime(f), 0, 0), 0));
  }
  clip.channels.push_back(root);
  scene.clips.push_back(clip);
  return scene;
}

const Intervals& left(const Document& d) { return d.scene().clips[0].contacts.of(Foot::Left); }

TEST(FootContactEdits, AddJoinsOverlapsKeepsTouchingOnesAndUndoes) {
  Document doc(standingScene());
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 10, 14), "");
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 2, 5), "");
  EXPECT_EQ(left(doc), (Intervals{{2, 5}, {10, 14}}));
  // Touching (15 after 14) stays a contact of its own; reversed ends are put in order.
  int added = -1;
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 18, 15, &added), "");
  EXPECT_EQ(added, 2);
  EXPECT_EQ(left(doc), (Intervals{{2, 5}, {10, 14}, {15, 18}}));
  // Overlapping 4..11 joins 2..5 and 10..14 into 2..14.
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 4, 11, &added), "");
  EXPECT_EQ(added, 0);
  EXPECT_EQ(left(doc), (Intervals{{2, 14}, {15, 18}}));
  EXPECT_TRUE(doc.scene().clips[0].contacts.of(Foot::Right).empty());
  EXPECT_EQ(doc.historyLabels().back(), "Add foot contact");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(left(doc), (Intervals{{2, 5}, {10, 14}, {15, 18}}));
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(left(doc), (Intervals{{2, 14}, {15, 18}}));
  // Negative frames are clamped to frame 0.
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Right, -5, -1), "");
  EXPECT_EQ(doc.scene().clips[0].contacts.of(Foot::Right), (Intervals{{0, 0}}));
}

TEST(FootContactEdits, DeleteAndTypedFramesAreOneStepEach) {
  Document doc(standingScene());
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 0, 4), "");
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 10, 12), "");
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 20, 25), "");
  const int steps = doc.historyPosition();
  // Typed frames that would run into the neighbours stop at them.
  ASSERT_EQ(setFootContactEdit(doc, 0, Foot::Left, 1, 2, 30), "");
  EXPECT_EQ(left(doc), (Intervals{{0, 4}, {5, 19}, {20, 25}}));
  ASSERT_EQ(deleteFootContactEdit(doc, 0, Foot::Left, 0), "");
  EXPECT_EQ(left(doc), (Intervals{{5, 19}, {20, 25}}));
  EXPECT_EQ(doc.historyPosition(), steps + 2);
  EXPECT_NE(deleteFootContactEdit(doc, 0, Foot::Left, 7), "");
  EXPECT_NE(deleteFootContactEdit(doc, 0, Foot::Right, 0), "") << "the right foot has none";
  EXPECT_EQ(doc.historyPosition(), steps + 2) << "refusals add no step";
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(left(doc), (Intervals{{0, 4}, {10, 12}, {20, 25}}));
}

TEST(FootContactEdits, DraggingAnEndStopsAtTheNextContactAndIsOneStep) {
  Document doc(standingScene());
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 0, 4), "");
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 10, 12), "");
  const int steps = doc.historyPosition();
  FootContactDrag drag;
  ASSERT_EQ(drag.begin(doc, 0, Foot::Left, 0, ContactDragPart::End, 4), "");
  ASSERT_EQ(drag.update(doc, 7), "");
  EXPECT_EQ(left(doc)[0], (ContactInterval{0, 7}));
  ASSERT_EQ(drag.update(doc, 40), "");
  EXPECT_EQ(left(doc)[0], (ContactInterval{0, 9})) << "stops a frame before the next contact";
  ASSERT_EQ(drag.update(doc, -3), "");
  EXPECT_EQ(left(doc)[0], (ContactInterval{0, 0})) << "never before its own start";
  ASSERT_EQ(drag.update(doc, 6), "");
  drag.commit(doc);
  EXPECT_FALSE(drag.active());
  EXPECT_EQ(doc.historyPosition(), steps + 1);
  EXPECT_EQ(doc.historyLabels().back(), "Move foot contact end");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(left(doc)[0], (ContactInterval{0, 4}));
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(left(doc)[0], (ContactInterval{0, 6}));

  // The start, the whole bar (keeps its length), cancel.
  ASSERT_EQ(drag.begin(doc, 0, Foot::Left, 1, ContactDragPart::Start, 10), "");
  ASSERT_EQ(drag.update(doc, 2), "");
  EXPECT_EQ(left(doc)[1], (ContactInterval{7, 12}));
  drag.cancel(doc);
  EXPECT_EQ(left(doc)[1], (ContactInterval{10, 12}));
  EXPECT_EQ(doc.historyPosition(), steps + 1) << "a cancelled drag adds no step";
  ASSERT_EQ(drag.begin(doc, 0, Foot::Left, 1, ContactDragPart::Whole, 11), "");
  ASSERT_EQ(drag.update(doc, 1), "");
  EXPECT_EQ(left(doc)[1], (ContactInterval{7, 9})) << "moved left until it meets 0..6, length kept";
  drag.commit(doc);
  EXPECT_EQ(doc.historyLabels().back(), "Move foot contact");
}

TEST(FootContactEdits, DrawingOnAnEmptyLaneAddsAContact) {
  Document doc(standingScene());
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Right, 10, 12), "");
  FootContactDrag drag;
  EXPECT_NE(drag.begin(doc, 0, Foot::Right, -1, ContactDragPart::New, 11), "") << "inside a contact";
  EXPECT_FALSE(doc.dragging());
  ASSERT_EQ(drag.begin(doc, 0, Foot::Right, -1, ContactDragPart::New, 16), "");
  EXPECT_EQ(drag.index(), 1);
  ASSERT_EQ(drag.update(doc, 5), "");  // backwards from 16: stops after 10..12
  EXPECT_EQ(doc.scene().clips[0].contacts.of(Foot::Right), (Intervals{{10, 12}, {13, 16}}));
  ASSERT_EQ(drag.update(doc, 20), "");
  EXPECT_EQ(doc.scene().clips[0].contacts.of(Foot::Right), (Intervals{{10, 12}, {16, 20}}));
  drag.commit(doc);
  EXPECT_EQ(doc.historyLabels().back(), "Add foot contact");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().clips[0].contacts.of(Foot::Right), (Intervals{{10, 12}}));
}

TEST(FootContactEdits, TheStripFindsEndsMiddlesAndEmptyLanes) {
  EditorState state;
  state.doc = Document(standingScene(101));
  state.clip = 0;
  ASSERT_EQ(addFootContactEdit(state.doc, 0, Foot::Left, 20, 40), "");
  const PanelRect strip{100.0f, 500.0f, 1000.0f + 8.0f, 30.0f};
  const ContactLanes lanes = contactLanes(state, strip);
  // The ruler's own mapping over frames 0..100 (the clip's range).
  ASSERT_EQ(lanes.frames.first, 0);
  ASSERT_EQ(lanes.frames.last, 100);
  const float x20 = lanes.frames.xOfFrame(20), x40 = lanes.frames.xOfFrame(40), x30 = lanes.frames.xOfFrame(30);
  const float leftLane = lanes.laneTop(Foot::Left) + 2.0f, rightLane = lanes.laneTop(Foot::Right) + 2.0f;
  const Clip& clip = state.doc.scene().clips[0];
  ContactHit h = hitContactLanes(lanes, clip, {x20 + 2.0f, leftLane}, 5.0f);
  EXPECT_TRUE(h.lane);
  EXPECT_EQ(h.index, 0);
  EXPECT_EQ(h.part, ContactDragPart::Start);
  h = hitContactLanes(lanes, clip, {x40 - 1.0f, leftLane}, 5.0f);
  EXPECT_EQ(h.part, ContactDragPart::End);
  h = hitContactLanes(lanes, clip, {x30, leftLane}, 5.0f);
  EXPECT_EQ(h.part, ContactDragPart::Whole);
  EXPECT_EQ(h.frame, 30);
  h = hitContactLanes(lanes, clip, {x30, rightLane}, 5.0f);
  EXPECT_TRUE(h.lane);
  EXPECT_EQ(h.foot, Foot::Right);
  EXPECT_EQ(h.index, -1);
  EXPECT_EQ(h.part, ContactDragPart::New);
  EXPECT_FALSE(hitContactLanes(lanes, clip, {x30, strip.y + strip.h + 5.0f}, 5.0f).lane);
}

TEST(FootContactEdits, DetectFindsBothFeetPlantedAndCleanUpIsOneStep) {
  Document doc(standingScene(30));
  ASSERT_EQ(detectFootContactsEdit(doc, 0), "");
  EXPECT_EQ(left(doc), (Intervals{{0, 29}}));
  EXPECT_EQ(doc.scene().clips[0].contacts.of(Foot::Right), (Intervals{{0, 29}}));
  EXPECT_EQ(doc.historyLabels().back(), "Detect foot contacts");

  const Clip before = doc.scene().clips[0];
  CleanUpOptions o;
  o.reduce = true;
  o.positionTolerance = 0.002f;
  o.rotationDegrees = 0.5f;
  CleanUpResult result;
  const int steps = doc.historyPosition();
  ASSERT_EQ(cleanUpMotionEdit(doc, 0, o, &result), "");
  EXPECT_EQ(doc.historyPosition(), steps + 1);
  EXPECT_EQ(doc.historyLabels().back(), "Clean up motion stand");
  // The figures are the job's on the same input.
  const Result<HumanoidReading> h = findHumanoid(doc.skeleton());
  ASSERT_TRUE(h);
  MotionCleanupJob job;
  ASSERT_EQ(humanoidLegs(doc.skeleton(), h->bones, job.legs), "");
  job.skeleton = &doc.skeleton();
  job.clip = &before;
  job.contacts = &before.contacts;
  job.settings.reduction.positionTolerance = 0.002f;
  job.settings.reduction.angleTolerance = 0.5f * 0.01745329251994329577f;
  Clip direct;
  MotionCleanupReport report;
  job.output = &direct;
  job.report = &report;
  ASSERT_TRUE(job.run());
  EXPECT_EQ(result.report.skateBefore, report.skateBefore);
  EXPECT_EQ(result.report.skateAfter, report.skateAfter);
  EXPECT_EQ(result.report.keys.keysAfter, report.keys.keysAfter);
  EXPECT_GT(result.report.skateBefore, 0.0f);
  EXPECT_LT(result.report.skateAfter, 0.05f * result.report.skateBefore);
  EXPECT_EQ(doc.scene().clips[0].contacts, before.contacts) << "contacts are kept";
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().clips[0].channels.size(), before.channels.size());
  EXPECT_EQ(doc.scene().clips[0].channels[0].values, before.channels[0].values);
}

TEST(FootContactEdits, RefusalsChangeNothing) {
  Document doc(standingScene());
  CleanUpOptions o;
  EXPECT_NE(cleanUpMotionEdit(doc, 0, o), "") << "locking without contacts";
  o.lockFeet = false;
  o.reduce = false;
  EXPECT_NE(cleanUpMotionEdit(doc, 0, o), "") << "nothing chosen";
  o.reduce = true;
  o.positionTolerance = -1.0f;
  EXPECT_NE(cleanUpMotionEdit(doc, 0, o), "");
  EXPECT_NE(cleanUpMotionEdit(doc, 3, CleanUpOptions{}), "") << "no such clip";
  // Not a humanoid: a two-joint stick.
  Scene stick;
  stick.skeleton.addJoint("a", -1, Transform{});
  stick.skeleton.addJoint("b", 0, Transform::fromTranslation({0, 1, 0}));
  stick.clips.push_back(Clip{});
  Document sdoc(stick);
  EXPECT_NE(detectFootContactsEdit(sdoc, 0), "");
  EXPECT_FALSE(doc.canUndo());
  EXPECT_FALSE(sdoc.canUndo());
}

TEST(FootContactEdits, ContactsAndBoneMapSurviveSaveAndReopen) {
  const std::string dir = test::makeTempDir();
  Document doc(standingScene());
  ASSERT_EQ(addFootContactEdit(doc, 0, Foot::Left, 3, 9), "");
  ASSERT_EQ(doc.edit("map", [](DocumentEdit& e) {
    e.clips[0].sourceMap = ClipSourceMap{"take.bvh", 1, {{"LeftUpLeg", 1}, {"Hips", 0}}};
    return std::string();
  }), "");
  ASSERT_EQ(saveDocumentAs(doc, dir + "/c.kinema"), "");
  Result<Document> back = openDocument(dir + "/c.kinema");
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->scene().clips[0].contacts, doc.scene().clips[0].contacts);
  EXPECT_EQ(back->scene().clips[0].sourceMap, doc.scene().clips[0].sourceMap);
  EXPECT_FALSE(back->dirty());
  test::runCommand("rm -rf '" + dir + "'");
}

// An imported clip keeps its map and contacts, and Edit Bone Map of Clip… shows that map.
TEST(FootContactEdits, ImportedClipKeepsItsMapAndContactsAndReopensTheMap) {
  KINEMA_REQUIRE_SHARED_DATA();
  Document doc = newDocument();
  const std::string take = test::sharedDataDir() + "/bvh/cmu_01_01_first720.bvh";
  Result<MotionImport> prepared = prepareMotionImport(doc, take);
  ASSERT_TRUE(prepared) << prepared.error();
  MotionImport& m = prepared.value();
  int head = -1;
  for (int r = 0; r < static_cast<int>(m.rows.size()); ++r)
    if (m.rows[r].bone == "Head") head = r;
  ASSERT_GE(head, 0);
  ASSERT_EQ(setMotionImportSource(m, doc.skeleton(), head, -1), "");  // an edited map
  ASSERT_EQ(applyMotionImport(doc, m), "");
  const int clip = doc.activeClip();
  const Clip& imported = doc.scene().clips[clip];
  EXPECT_EQ(imported.sourceMap, toClipSourceMap(m.map, m.source.skeleton, take, 0));
  EXPECT_FALSE(imported.contacts.feet[0].empty());
  EXPECT_FALSE(imported.contacts.feet[1].empty());

  Result<MotionImport> again = prepareMotionImportOfClip(doc, clip);
  ASSERT_TRUE(again) << again.error();
  EXPECT_EQ(again->replaceClip, clip);
  EXPECT_EQ(again->mapBy, "saved with the clip");
  ASSERT_EQ(again->map.pairs.size(), m.map.pairs.size());
  EXPECT_EQ(again->rows[head].source, -1) << "the edit is remembered";
  // The map edited again (the head driven by the take's head once more) and applied.
  ASSERT_EQ(setMotionImportSource(again.value(), doc.skeleton(), head, m.source.skeleton.find("Head")), "");
  // Apply replaces the clip in one step, keeping the clip count.
  const std::string name = imported.name;
  const size_t clips = doc.scene().clips.size();
  ASSERT_EQ(applyMotionImport(doc, again.value()), "");
  EXPECT_EQ(doc.scene().clips.size(), clips);
  EXPECT_EQ(doc.historyLabels().back(), "Re-import motion " + name);
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

// The Import dialog's Clip combo: any clip of the file, not only its first (kinema retarget
// --clip); the new clip is named after it and its saved map says which.
TEST(MotionImportClip, TheChosenClipIsTheOneRetargeted) {
  const std::string dir = test::makeTempDir();
  Scene take = standingScene(12);
  Clip second = take.clips[0];
  second.name = "second";
  second.channels[0].values.back().y += 0.2f;  // a different motion: the hips rise at the end
  take.clips.push_back(second);
  ASSERT_EQ(saveKinemaFile(dir + "/two.kinema", take), "");
  Document doc = newDocument();
  Result<MotionImport> prepared = prepareMotionImport(doc, dir + "/two.kinema");
  ASSERT_TRUE(prepared) << prepared.error();
  EXPECT_EQ(prepared->clip, 0) << "the first by default";
  prepared->clip = 1;
  ASSERT_EQ(applyMotionImport(doc, prepared.value()), "");
  const Clip& imported = doc.scene().clips[doc.activeClip()];
  EXPECT_EQ(imported.name, "second");
  EXPECT_EQ(imported.sourceMap.clip, 1);
  EXPECT_EQ(imported.sourceMap.file, dir + "/two.kinema");
  test::runCommand("rm -rf '" + dir + "'");
}

}  // namespace
}  // namespace kinema
