// Clips as part of the document: key edits go through edit() and drags like pose edits, in
// the same undo step; the animated pose of a frame change is not an undo step.
#include <gtest/gtest.h>

#include <cstring>

#include "editor/model/document.h"
#include "editor/model/document_files.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// A clip with one rotation channel on `joint`: keys at 0 s and 1 s.
Clip twoKeyClip(int joint, float angle) {
  Clip c;
  c.name = "Action";
  c.frameTime = 1.0 / 24.0;
  c.channels.push_back(Channel(joint, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 1.0f},
                               {glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, std::sin(angle / 2), std::cos(angle / 2))}));
  return c;
}

bool sameValues(const Clip& a, const Clip& b) {
  if (a.channels.size() != b.channels.size()) return false;
  for (size_t i = 0; i < a.channels.size(); ++i) {
    const Channel &x = a.channels[i], &y = b.channels[i];
    if (x.times != y.times || x.values.size() != y.values.size() ||
        std::memcmp(x.values.data(), y.values.data(), x.values.size() * sizeof(glm::vec4)) != 0)
      return false;
  }
  return a.name == b.name;
}

TEST(DocumentClips, PoseAndKeysChangeInOneUndoStep) {
  Document doc = newDocument();
  ASSERT_TRUE(doc.scene().clips.empty());
  const Clip expected = twoKeyClip(1, 0.5f);
  const glm::quat turned = glm::angleAxis(0.5f, glm::vec3(0, 0, 1));
  ASSERT_EQ(doc.edit("Key", [&](DocumentEdit& e) {
              e.pose.local[1].rotation = turned;
              e.clips.push_back(expected);
              return std::string();
            }),
            "");
  EXPECT_EQ(doc.historyLabels().size(), 1u);
  ASSERT_EQ(doc.scene().clips.size(), 1u);
  EXPECT_TRUE(sameValues(doc.scene().clips[0], expected));
  EXPECT_TRUE(doc.dirty());

  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().clips.empty());
  EXPECT_EQ(doc.pose().local[1].rotation, doc.skeleton().rest[1].rotation);
  ASSERT_TRUE(doc.redo());
  ASSERT_EQ(doc.scene().clips.size(), 1u);
  EXPECT_TRUE(sameValues(doc.scene().clips[0], expected));
  EXPECT_EQ(doc.pose().local[1].rotation, turned);
}

TEST(DocumentClips, EditingOneClipLeavesTheOtherAndUndoesExactly) {
  Document doc = newDocument();
  ASSERT_EQ(doc.edit("Two clips", [&](DocumentEdit& e) {
              e.clips = {twoKeyClip(1, 0.5f), twoKeyClip(2, 1.0f)};
              return std::string();
            }),
            "");
  const Clip first = doc.scene().clips[0], second = doc.scene().clips[1];
  ASSERT_EQ(doc.edit("Move key", [&](DocumentEdit& e) {
              moveKey(e.clips[1].channels[0], 1, 2.0f);
              return std::string();
            }),
            "");
  EXPECT_FLOAT_EQ(doc.scene().clips[1].channels[0].times[1], 2.0f);
  EXPECT_TRUE(sameValues(doc.scene().clips[0], first));
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(sameValues(doc.scene().clips[1], second));
  EXPECT_FLOAT_EQ(doc.scene().clips[1].channels[0].times[1], 1.0f);
  // Removing a clip and undoing brings it back in its place.
  ASSERT_EQ(doc.edit("Delete clip", [&](DocumentEdit& e) {
              e.clips.erase(e.clips.begin());
              return std::string();
            }),
            "");
  ASSERT_EQ(doc.scene().clips.size(), 1u);
  EXPECT_TRUE(sameValues(doc.scene().clips[0], second));
  ASSERT_TRUE(doc.undo());
  ASSERT_EQ(doc.scene().clips.size(), 2u);
  EXPECT_TRUE(sameValues(doc.scene().clips[0], first));
  EXPECT_TRUE(sameValues(doc.scene().clips[1], second));
}

TEST(DocumentClips, AnInvalidClipIsRefusedAndNothingChanges) {
  Document doc = newDocument();
  const std::string error = doc.edit("Bad", [&](DocumentEdit& e) {
    Clip c = twoKeyClip(1, 0.5f);
    c.channels[0].times = {1.0f, 0.0f};  // not increasing
    e.clips.push_back(c);
    e.pose.local[1].rotation = glm::angleAxis(0.3f, glm::vec3(1, 0, 0));
    return std::string();
  });
  EXPECT_NE(error.find("clip 0"), std::string::npos) << error;
  EXPECT_TRUE(doc.scene().clips.empty());
  EXPECT_EQ(doc.pose().local[1].rotation, doc.skeleton().rest[1].rotation);
  EXPECT_FALSE(doc.canUndo());
}

TEST(DocumentClips, DragUpdatesStartFromTheDragStartClips) {
  Document doc = newDocument();
  ASSERT_EQ(doc.beginDrag("Drag keys"), "");
  for (int update = 0; update < 3; ++update)
    ASSERT_EQ(doc.updateDrag([&](DocumentEdit& e) {
                e.clips.push_back(twoKeyClip(1, 0.1f * (update + 1)));
                return std::string();
              }),
              "");
  doc.commitDrag();
  ASSERT_EQ(doc.scene().clips.size(), 1u);  // not three: each update replaced the last
  EXPECT_TRUE(sameValues(doc.scene().clips[0], twoKeyClip(1, 0.3f)));
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().clips.empty());
}

TEST(DocumentClips, TheAnimatedPoseOfAFrameIsNotAnUndoStep) {
  Document doc = newDocument();
  Pose pose = doc.pose();
  pose.local[1].rotation = glm::angleAxis(0.7f, glm::vec3(0, 1, 0));
  EXPECT_TRUE(doc.setAnimatedPose(pose));
  EXPECT_EQ(doc.pose().local[1].rotation, pose.local[1].rotation);
  EXPECT_FALSE(doc.canUndo());
  EXPECT_FALSE(doc.dirty());
  Pose wrong;  // no joints
  EXPECT_FALSE(doc.setAnimatedPose(wrong));
  ASSERT_EQ(doc.beginDrag("drag"), "");
  EXPECT_FALSE(doc.setAnimatedPose(pose));  // a drag owns the pose until it ends
  doc.cancelDrag();
}

}  // namespace
}  // namespace kinema
