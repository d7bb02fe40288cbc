// The undo history's labels (model/edit_labels.h): every step says what it did and to what,
// in one style ("Rotate LowerArm.L", not "Rotate"; "Move 2 keys", not "Move Keys").
#include <gtest/gtest.h>

#include "editor/model/document_files.h"
#include "editor/model/dope_sheet.h"
#include "editor/model/editor_state.h"
#include "editor/model/edit_labels.h"
#include "editor/model/keying.h"
#include "editor/model/pose_edits.h"
#include "editor/model/timeline.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(EditLabels, JointsAndCountsReadAsWords) {
  const Document doc = newDocument();
  const Skeleton& s = doc.skeleton();
  const int a = s.find("Hand.L"), b = s.find("Hand.R"), c = s.find("Head");
  EXPECT_EQ(jointsPhrase(s, {a}), "Hand.L");
  EXPECT_EQ(jointsPhrase(s, {a, b}), "Hand.L and Hand.R");
  EXPECT_EQ(jointsPhrase(s, {a, b, c}), "3 joints");
  EXPECT_EQ(jointsPhrase(s, {}), "no joints");
  EXPECT_EQ(jointsPhrase(s, {s.size()}), "joint " + std::to_string(s.size()));
  EXPECT_EQ(countPhrase(1, "key"), "1 key");
  EXPECT_EQ(countPhrase(4, "key"), "4 keys");
  EXPECT_EQ(countPhrase(2, "mesh", "meshes"), "2 meshes");
}

TEST(EditLabels, EachStepNamesWhatItDidAndToWhat) {
  EditorState st;
  st.doc = newDocument();
  Document& doc = st.doc;
  const Skeleton& s = doc.skeleton();
  const int arm = s.find("LowerArm.L"), hand = s.find("Hand.L"), head = s.find("Head");
  ASSERT_EQ(setJointRotation(doc, arm, glm::angleAxis(0.4f, glm::vec3(0, 0, 1))), "");
  ASSERT_EQ(beginRotateDrag(doc, hand), "");
  ASSERT_EQ(updateRotateDrag(doc, hand, glm::angleAxis(0.2f, glm::vec3(1, 0, 0))), "");
  doc.commitDrag();
  ASSERT_EQ(clearRotations(doc, {arm, hand, head}), "");
  int clip = -1;
  ASSERT_EQ(insertKeys(doc, clip, 12.0f / 24.0f, {arm, hand}, KeyPreferences{}), "");
  ASSERT_EQ(setFrameRange(st, 1, 48), "");
  ASSERT_EQ(setFrameRate(st, 30.0), "");
  KeyColumnSelection keys;
  keys.set(allKeyColumns(doc.scene().clips[clip]));
  ASSERT_EQ(keys.columns().size(), 2u);  // the two joints' keys at frame 12
  ASSERT_EQ(moveKeysEdit(doc, clip, keys, 3.0), "");
  ASSERT_EQ(deleteKeysEdit(doc, clip, keys), "");
  EXPECT_EQ(doc.historyLabels(), (std::vector<std::string>{
                                     "Rotate LowerArm.L",
                                     "Rotate Hand.L",
                                     "Clear rotation of 3 joints",
                                     "Insert keys on LowerArm.L and Hand.L at frame 12",
                                     "Set frame range to 1-48",
                                     "Set document frame rate to 30 fps",  // the Action has no rate of its own
                                     "Move 2 keys",
                                     "Delete 2 keys",
                                 }));
}

}  // namespace
}  // namespace kinema
