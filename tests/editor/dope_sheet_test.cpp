// The dope sheet's model (src/editor/dope_sheet.h): rows and key columns, click and box
// selection, the pixel mapping, and the key edits (move with snapping, delete, copy/paste)
// as undo steps that restore the clip exactly. Expected frames and values are worked out by
// hand from the clip built below.
#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/document.h"
#include "editor/model/dope_sheet.h"
#include "editor/model/keying.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr double kFt = 1.0 / 24.0;  // the clip's frame time
float at(double frame) { return static_cast<float>(frame * kFt); }

// Root: translation keys at frames 0, 10, 20 and rotation keys at 0, 10 (channel-wide
// linear interpolation); A: rotation keys at 5, 10, 12 with per-key settings (5 is Step);
// B: one scale key off the grid at frame 10.3.
Scene testScene() {
  Scene scene;
  const int root = scene.skeleton.addJoint("Root", -1, Transform{});
  const int a = scene.skeleton.addJoint("A", root, Transform{});
  const int b = scene.skeleton.addJoint("B", a, Transform{});
  Clip clip;
  clip.name = "test";
  clip.frameTime = kFt;
  clip.channels.emplace_back(root, ChannelTarget::Translation, Interpolation::Linear,
                             std::vector<float>{at(0), at(10), at(20)},
                             std::vector<glm::vec4>{{0, 0, 0, 0}, {1, 0, 0, 0}, {2, 0, 0, 0}});
  clip.channels.emplace_back(root, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{at(0), at(10)},
                             std::vector<glm::vec4>{{0, 0, 0, 1}, {0, 0.6f, 0, 0.8f}});
  Channel ca(a, ChannelTarget::Rotation, Interpolation::Linear, {at(5), at(10), at(12)},
             {{0, 0, 0, 1}, {0.6f, 0, 0, 0.8f}, {0, 0, 0.6f, 0.8f}});
  ca.keys.assign(3, KeySettings{});
  ca.keys[0].interpolation = Interpolation::Step;
  clip.channels.push_back(ca);
  clip.channels.emplace_back(b, ChannelTarget::Scale, Interpolation::Linear, std::vector<float>{at(10.3)},
                             std::vector<glm::vec4>{{2, 2, 2, 0}});
  scene.clips.push_back(clip);
  return scene;
}

std::vector<double> framesOf(const Channel& ch) {
  std::vector<double> out;
  for (float t : ch.times) out.push_back(std::round(t / kFt * 1000.0) / 1000.0);
  return out;
}

bool sameClip(const Clip& x, const Clip& y) {
  if (x.channels.size() != y.channels.size()) return false;
  for (size_t c = 0; c < x.channels.size(); ++c) {
    const Channel &p = x.channels[c], &q = y.channels[c];
    if (p.joint != q.joint || p.target != q.target || p.interpolation != q.interpolation || p.times != q.times ||
        p.values != q.values || p.keys != q.keys)
      return false;
  }
  return true;
}

TEST(DopeSheet, RowsAreTheKeyedJointsUnderASummary) {
  const Clip clip = testScene().clips[0];
  const std::vector<DopeSheetRow> rows = dopeSheetRows(clip);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].joint, -1);
  EXPECT_EQ(rows[1].joint, 0);
  EXPECT_EQ(rows[2].joint, 1);
  EXPECT_EQ(rows[3].joint, 2);
  // Root's two channels share the columns at 0 and 10.
  EXPECT_EQ(rows[1].times, (std::vector<float>{at(0), at(10), at(20)}));
  EXPECT_EQ(rows[2].times, (std::vector<float>{at(5), at(10), at(12)}));
  EXPECT_EQ(rows[0].times, (std::vector<float>{at(0), at(5), at(10), at(10.3), at(12), at(20)}));
  EXPECT_EQ(allKeyColumns(clip).size(), 7u);
  // The summary's diamond at 10 stands for Root's and A's columns there (not B's 10.3).
  EXPECT_EQ(columnsOfCell(rows, 0, at(10)), (std::vector<KeyColumn>{{0, at(10)}, {1, at(10)}}));
  EXPECT_EQ(columnsOfCell(rows, 2, at(10)), (std::vector<KeyColumn>{{1, at(10)}}));
}

TEST(DopeSheet, ClickShiftClickAndBoxSelect) {
  const Clip clip = testScene().clips[0];
  const std::vector<DopeSheetRow> rows = dopeSheetRows(clip);
  KeyColumnSelection s;
  s.click(columnsOfCell(rows, 1, at(10)), false);
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{0, at(10)}}));
  s.click(columnsOfCell(rows, 2, at(5)), true);  // Shift adds
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{0, at(10)}, {1, at(5)}}));
  s.click(columnsOfCell(rows, 1, at(10)), true);  // Shift on a selected one removes it
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{1, at(5)}}));
  s.click(columnsOfCell(rows, 3, at(10.3)), false);  // a plain click replaces
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{2, at(10.3)}}));

  // Frames 4 .. 11 on rows 1-2 (Root, A): Root@10, A@5, A@10; the corners in either order.
  const std::vector<KeyColumn> box = {{0, at(10)}, {1, at(5)}, {1, at(10)}};
  EXPECT_EQ(columnsInBox(ownFrameGrid(clip), rows, 4, 11, 1, 2), box);
  EXPECT_EQ(columnsInBox(ownFrameGrid(clip), rows, 11, 4, 2, 1), box);
  s.box(columnsInBox(ownFrameGrid(clip), rows, 4, 11, 1, 2), BoxSelectMode::Replace);
  EXPECT_EQ(s.columns(), box);
  // The summary row alone takes in every joint: frames 9.5 .. 10.5 hold Root@10, A@10, B@10.3.
  s.box(columnsInBox(ownFrameGrid(clip), rows, 9.5, 10.5, 0, 0), BoxSelectMode::Extend);
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{0, at(10)}, {1, at(5)}, {1, at(10)}, {2, at(10.3)}}));
  s.box(columnsInBox(ownFrameGrid(clip), rows, 10, 10, 1, 3), BoxSelectMode::Subtract);
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{1, at(5)}, {2, at(10.3)}}));
  // A box on no rows or frames with no keys selects nothing.
  EXPECT_TRUE(columnsInBox(ownFrameGrid(clip), rows, 13, 19, 0, 3).empty());
  EXPECT_TRUE(columnsInBox(ownFrameGrid(clip), rows, 0, 30, 5, 9).empty());
  s.clear();
  EXPECT_TRUE(s.empty());
}

TEST(DopeSheet, ViewMapsPixelsToFramesAndRows) {
  DopeSheetView v;
  v.x = 410;
  v.y = 517;
  v.width = 560;
  v.firstFrame = -2;
  v.pixelsPerFrame = 12;
  v.rowHeight = 20;
  EXPECT_DOUBLE_EQ(v.frameToX(10), 410 + 12 * 12);
  EXPECT_DOUBLE_EQ(v.xToFrame(410 + 12 * 12 + 6), 10.5);
  EXPECT_EQ(v.rowAt(517 + 0.5f), 0);
  EXPECT_EQ(v.rowAt(517 + 45), 2);
  EXPECT_FLOAT_EQ(v.rowCenterY(2), 517 + 50);
  // Zooming about a pixel keeps its frame there.
  const double f = v.xToFrame(600);
  v.zoomAt(600, 1.5);
  EXPECT_DOUBLE_EQ(v.pixelsPerFrame, 18);
  EXPECT_NEAR(v.xToFrame(600), f, 1e-9);
  v.frameRange(0, 20);  // 20 frames and a frame each side over 560 px
  EXPECT_DOUBLE_EQ(v.pixelsPerFrame, 560.0 / 22.0);
  EXPECT_DOUBLE_EQ(v.firstFrame, -1);

  // Hit test: the diamond at A's frame 12 on row 2, within the radius only.
  const Clip clip = testScene().clips[0];
  const std::vector<DopeSheetRow> rows = dopeSheetRows(clip);
  v.firstFrame = -2;
  v.pixelsPerFrame = 12;
  int row = -1;
  float time = 0;
  ASSERT_TRUE(hitKeyColumn(rows, v, ownFrameGrid(clip), glm::vec2(410 + 14 * 12 + 4, 517 + 50), 7, row, time));
  EXPECT_EQ(row, 2);
  EXPECT_EQ(time, at(12));
  EXPECT_FALSE(hitKeyColumn(rows, v, ownFrameGrid(clip), glm::vec2(410 + 14 * 12 + 9, 517 + 50), 7, row, time));
  EXPECT_FALSE(hitKeyColumn(rows, v, ownFrameGrid(clip), glm::vec2(410 + 14 * 12, 517 + 90), 7, row, time));  // row 4: none
}

TEST(DopeSheet, MovingSnapsEachKeyToTheNearestFrame) {
  Clip clip = testScene().clips[0];
  std::vector<KeyColumn> moved;
  // Root's column at 10 by +5.4 frames: 15.4 -> 15, in both of Root's channels.
  moveKeyColumns(clip, ownFrameGrid(clip), {{0, at(10)}}, 5.4, &moved);
  EXPECT_EQ(framesOf(clip.channels[0]), (std::vector<double>{0, 15, 20}));
  EXPECT_EQ(framesOf(clip.channels[1]), (std::vector<double>{0, 15}));
  EXPECT_EQ(clip.channels[0].values[1], glm::vec4(1, 0, 0, 0));
  EXPECT_EQ(clip.channels[1].values[1], glm::vec4(0, 0.6f, 0, 0.8f));
  EXPECT_TRUE(clip.channels[0].keys.empty()) << "a channel-wide channel stays compact";
  EXPECT_EQ(moved, (std::vector<KeyColumn>{{0, at(15)}}));
  // B's key off the grid (10.3) by +2: 12.3 -> 12.
  moveKeyColumns(clip, ownFrameGrid(clip), {{2, at(10.3)}}, 2.0, &moved);
  EXPECT_EQ(framesOf(clip.channels[3]), (std::vector<double>{12}));
  EXPECT_EQ(clip.channels[3].times[0], at(12));
  // By -0.4 a key on the grid stays where it is.
  moveKeyColumns(clip, ownFrameGrid(clip), {{0, at(20)}}, -0.4);
  EXPECT_EQ(framesOf(clip.channels[0]), (std::vector<double>{0, 15, 20}));
  EXPECT_TRUE(clip.validate(testScene().skeleton).empty());
}

TEST(DopeSheet, MovingKeysPastEachOtherNeverLosesAMovingKey) {
  const Clip start = testScene().clips[0];
  const Channel& a0 = start.channels[2];
  // A's 10 and 12 by +2: 10 lands where 12 was while 12 moves on to 14. Moving one key at a
  // time would have replaced 12 with 10 and then moved that to 14.
  Clip clip = start;
  moveKeyColumns(clip, ownFrameGrid(clip), {{1, at(10)}, {1, at(12)}}, 2.0);
  const Channel& a = clip.channels[2];
  EXPECT_EQ(framesOf(a), (std::vector<double>{5, 12, 14}));
  EXPECT_EQ(a.values[1], a0.values[1]);
  EXPECT_EQ(a.values[2], a0.values[2]);
  // A's 5 (Step) and 10 by +7: 5 jumps past 10 to 12, replacing the key there that stays
  // (Blender), 10 goes to 17; the settings travel with the keys.
  clip = start;
  moveKeyColumns(clip, ownFrameGrid(clip), {{1, at(5)}, {1, at(10)}}, 7.0);
  const Channel& b = clip.channels[2];
  EXPECT_EQ(framesOf(b), (std::vector<double>{12, 17}));
  EXPECT_EQ(b.values[0], a0.values[0]);
  EXPECT_EQ(b.values[1], a0.values[1]);
  EXPECT_EQ(b.keys[0].interpolation, Interpolation::Step);
  EXPECT_EQ(b.keys[1].interpolation, Interpolation::Linear);
  // 10 and 12 by -5 pass back over 5, which stays and is replaced by 10's key landing on it.
  clip = start;
  moveKeyColumns(clip, ownFrameGrid(clip), {{1, at(10)}, {1, at(12)}}, -5.0);
  EXPECT_EQ(framesOf(clip.channels[2]), (std::vector<double>{5, 7}));
  EXPECT_EQ(clip.channels[2].values[0], a0.values[1]);
  EXPECT_EQ(clip.channels[2].values[1], a0.values[2]);
}

TEST(DopeSheet, DeleteRemovesEveryChannelKeyOfTheColumns) {
  Clip clip = testScene().clips[0];
  deleteKeyColumns(clip, {{0, at(10)}, {2, at(10.3)}});
  ASSERT_EQ(clip.channels.size(), 3u) << "B's channel lost its only key and is gone";
  EXPECT_EQ(framesOf(clip.channels[0]), (std::vector<double>{0, 20}));
  EXPECT_EQ(framesOf(clip.channels[1]), (std::vector<double>{0}));
  EXPECT_EQ(framesOf(clip.channels[2]), (std::vector<double>{5, 10, 12}));
  EXPECT_EQ(clip.channels[0].values[1], glm::vec4(2, 0, 0, 0));
  EXPECT_TRUE(clip.validate(testScene().skeleton).empty());
}

TEST(DopeSheet, CopyPasteAtAnotherFrameOntoTheSameOrOtherJoints) {
  const Scene scene = testScene();
  Clip clip = scene.clips[0];
  const KeyClipboard copied = copyKeyColumns(clip, ownFrameGrid(clip), {{1, at(5)}, {1, at(10)}});
  ASSERT_EQ(copied.keys.size(), 2u);
  EXPECT_DOUBLE_EQ(copied.keys[0].frameOffset, 0.0);
  EXPECT_NEAR(copied.keys[1].frameOffset, 5.0, 1e-4);
  std::vector<KeyColumn> pasted;
  // At frame 30: A gets keys at 30 and 35 with the copied values and settings.
  ASSERT_EQ(pasteKeys(clip, ownFrameGrid(clip), scene.skeleton, copied, 30, {}, &pasted), "");
  const Channel& a = clip.channels[2];
  EXPECT_EQ(framesOf(a), (std::vector<double>{5, 10, 12, 30, 35}));
  EXPECT_EQ(a.values[3], scene.clips[0].channels[2].values[0]);
  EXPECT_EQ(a.values[4], scene.clips[0].channels[2].values[1]);
  EXPECT_EQ(a.keys[3].interpolation, Interpolation::Step);
  EXPECT_EQ(pasted, (std::vector<KeyColumn>{{1, at(30)}, {1, at(35)}}));
  // Onto the selected joints: B has no rotation channel, one is made.
  ASSERT_EQ(pasteKeys(clip, ownFrameGrid(clip), scene.skeleton, copied, 2, {2}), "");
  ASSERT_EQ(clip.channels.size(), 5u);
  EXPECT_EQ(clip.channels[4].joint, 2);
  EXPECT_EQ(clip.channels[4].target, ChannelTarget::Rotation);
  EXPECT_EQ(framesOf(clip.channels[4]), (std::vector<double>{2, 7}));
  EXPECT_TRUE(clip.validate(scene.skeleton).empty());
  // Keys of two joints cannot go onto three; an empty clipboard says so.
  const KeyClipboard two = copyKeyColumns(clip, ownFrameGrid(clip), {{0, at(0)}, {1, at(5)}});
  EXPECT_NE(pasteKeys(clip, ownFrameGrid(clip), scene.skeleton, two, 0, {0, 1, 2}), "");
  EXPECT_NE(pasteKeys(clip, ownFrameGrid(clip), scene.skeleton, KeyClipboard{}, 0, {}), "");
  // Pasting onto a key that exists replaces its value.
  Clip again = scene.clips[0];
  ASSERT_EQ(pasteKeys(again, ownFrameGrid(again), scene.skeleton, copyKeyColumns(again, ownFrameGrid(again), {{1, at(12)}}), 5, {}), "");
  EXPECT_EQ(framesOf(again.channels[2]), (std::vector<double>{5, 10, 12}));
  EXPECT_EQ(again.channels[2].values[0], scene.clips[0].channels[2].values[2]);
}

TEST(DopeSheet, EachEditIsOneUndoStepThatRestoresTheClipExactly) {
  Document doc(testScene());
  const Clip original = doc.scene().clips[0];
  KeyColumnSelection s;
  s.set({{0, at(10)}, {1, at(10)}});
  ASSERT_EQ(moveKeysEdit(doc, 0, s, 5.4), "");
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{0, at(15)}, {1, at(15)}}));
  const Clip moved = doc.scene().clips[0];
  EXPECT_EQ(framesOf(moved.channels[2]), (std::vector<double>{5, 12, 15}));
  EXPECT_EQ(doc.historyPosition(), 1);

  ASSERT_EQ(deleteKeysEdit(doc, 0, s), "");
  EXPECT_TRUE(s.empty());
  const Clip deleted = doc.scene().clips[0];
  EXPECT_EQ(doc.historyPosition(), 2);

  s.set({{1, at(5)}});
  const KeyClipboard copied = copyKeyColumns(doc.scene().clips[0], ownFrameGrid(doc.scene().clips[0]), s.columns());
  ASSERT_EQ(pasteKeysEdit(doc, 0, s, copied, 40, {}), "");
  EXPECT_EQ(framesOf(doc.scene().clips[0].channels[2]), (std::vector<double>{5, 12, 40}));
  const Clip pastedClip = doc.scene().clips[0];
  EXPECT_EQ(doc.historyPosition(), 3);

  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(sameClip(doc.scene().clips[0], deleted));
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(sameClip(doc.scene().clips[0], moved));
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(sameClip(doc.scene().clips[0], original));
  ASSERT_TRUE(doc.redo());
  EXPECT_TRUE(sameClip(doc.scene().clips[0], moved));
  ASSERT_TRUE(doc.redo());
  EXPECT_TRUE(sameClip(doc.scene().clips[0], deleted));
  ASSERT_TRUE(doc.redo());
  EXPECT_TRUE(sameClip(doc.scene().clips[0], pastedClip));
  // Nothing selected: no step.
  s.clear();
  EXPECT_NE(moveKeysEdit(doc, 0, s, 1.0), "");
  EXPECT_EQ(doc.historyPosition(), 3);
}

TEST(DopeSheet, AMoveDragIsOneStepAndCancelRestores) {
  Document doc(testScene());
  const Clip original = doc.scene().clips[0];
  KeyColumnSelection s;
  s.set({{0, at(10)}});
  KeyMoveDrag drag;
  ASSERT_EQ(drag.begin(doc, 0, s), "");
  ASSERT_EQ(drag.update(doc, s, 3.2), "");
  EXPECT_EQ(framesOf(doc.scene().clips[0].channels[0]), (std::vector<double>{0, 13, 20}));
  ASSERT_EQ(drag.update(doc, s, 5.4), "");  // from the start, not from 13
  EXPECT_EQ(framesOf(doc.scene().clips[0].channels[0]), (std::vector<double>{0, 15, 20}));
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{0, at(15)}}));
  drag.commit(doc);
  EXPECT_EQ(doc.historyPosition(), 1);
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(sameClip(doc.scene().clips[0], original));

  s.set({{1, at(12)}});
  ASSERT_EQ(drag.begin(doc, 0, s), "");
  ASSERT_EQ(drag.update(doc, s, -9.0), "");
  drag.cancel(doc, s);
  EXPECT_TRUE(sameClip(doc.scene().clips[0], original));
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{1, at(12)}}));
  EXPECT_EQ(doc.historyPosition(), 0);
}

TEST(DopeSheet, SelectionPruneDropsColumnsThatLostTheirKeys) {
  const Clip clip = testScene().clips[0];
  KeyColumnSelection s;
  s.set({{0, at(10)}, {0, at(11)}, {5, at(0)}, {2, at(10.3) + 2e-6f}});
  s.prune(clip);
  EXPECT_EQ(s.columns(), (std::vector<KeyColumn>{{0, at(10)}, {2, at(10.3)}}));
}

// Regression (issue 17): the dope sheet's columns used 1e-5 s where keying used 1e-4 s, so
// two channels keyed 5e-5 s apart on one frame showed two diamonds that Alt+I deleted
// together. Now one tolerance (kKeyTimeTolerance): one column, and deleting it takes both.
TEST(DopeSheet, ColumnsAndKeyingShareOneKeyTimeTolerance) {
  Clip clip;
  clip.frameTime = kFt;
  const float t = at(10), off = t + 0.5f * kKeyTimeTolerance;
  clip.channels.emplace_back(0, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{t},
                             std::vector<glm::vec4>{{1, 0, 0, 0}});
  clip.channels.emplace_back(0, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{off},
                             std::vector<glm::vec4>{{0, 0, 0, 1}});
  const std::vector<DopeSheetRow> rows = dopeSheetRows(clip);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].times.size(), 1u);  // one diamond
  EXPECT_EQ(columnsOfCell(rows, 1, t).size(), 1u);
  Clip deleted = clip;
  deleteKeyColumns(deleted, columnsOfCell(rows, 1, t));
  EXPECT_TRUE(deleted.channels.empty());  // both keys went with the one column
  EXPECT_EQ(deleteJointKeys(clip, {0}, t), 2);  // Alt+I takes the same two
}

}  // namespace
}  // namespace kinema
