// The clip list (issue 18): choose, new, duplicate, rename and delete are one undo step
// each, undo and redo bring back the clips and which one was active, the active clip is
// saved in .kinema and restored on open, the views follow it, and export writes every
// clip to glTF (BVH: the active one, and the report says so).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "editor/model/clip_list.h"
#include "editor/model/document_files.h"
#include "editor/model/editor_state.h"
#include "editor/model/keying.h"
#include "editor/model/pose_edits.h"
#include "editor/model/timeline.h"
#include "io/gltf_reader.h"
#include "io/scene_files.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// Three clips on a two-joint skeleton, each moving the root along its own axis over 1 s
// (linear, 24 fps grid): "A" along X, "B" along Y, "C" along Z, 2 units at t = 1.
Scene threeClipScene() {
  Scene scene;
  scene.skeleton.addJoint("Root", -1, Transform{});
  scene.skeleton.addJoint("Tip", 0, Transform{glm::vec3(0, 1, 0)});
  const char* names[] = {"A", "B", "C"};
  for (int c = 0; c < 3; ++c) {
    Clip clip;
    clip.name = names[c];
    clip.frameTime = 1.0 / 24.0;
    glm::vec4 end(0.0f);
    end[c] = 2.0f;
    clip.channels.push_back(
        Channel{0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f}, {glm::vec4(0.0f), end}});
    scene.clips.push_back(clip);
  }
  return scene;
}

std::vector<std::string> clipNames(const Document& doc) {
  std::vector<std::string> names;
  for (const Clip& c : doc.scene().clips) names.push_back(c.name);
  return names;
}

bool sameClipBits(const Clip& a, const Clip& b) {
  if (a.channels.size() != b.channels.size() || a.frameTime != b.frameTime || a.hasRange != b.hasRange) return false;
  for (size_t i = 0; i < a.channels.size(); ++i) {
    const Channel &x = a.channels[i], &y = b.channels[i];
    if (x.joint != y.joint || x.target != y.target || x.times != y.times || x.values.size() != y.values.size() ||
        std::memcmp(x.values.data(), y.values.data(), x.values.size() * sizeof(glm::vec4)) != 0)
      return false;
  }
  return true;
}

// An editor state on `scene`, opened as File > Open opens it.
EditorState opened(Scene scene) {
  EditorState s;
  s.doc = Document(std::move(scene));
  resetTimeline(s);
  return s;
}

TEST(ClipList, FoxHasSurveyWalkAndRunInFileOrder) {
  KINEMA_REQUIRE_SHARED_DATA();
  Result<Document> fox = openDocument(test::sharedDataDir() + "/gltf/Fox.glb");
  ASSERT_TRUE(fox.ok()) << fox.error();
  EXPECT_EQ(clipNames(fox.value()), (std::vector<std::string>{"Survey", "Walk", "Run"}));
  EXPECT_EQ(fox->activeClip(), 0);  // a glTF file opens on its first clip
}

TEST(ClipList, ChoosingIsOneUndoStepAndTheViewsFollow) {
  EditorState s = opened(threeClipScene());
  goToFrame(s, 12);  // t = 0.5: A puts the root at x = 1
  ASSERT_NEAR(s.world()[0][3].x, 1.0f, 1e-6f);
  ASSERT_EQ(chooseClip(s.doc, 2), "");
  EXPECT_EQ(s.doc.activeClip(), 2);
  EXPECT_EQ(s.doc.historyLabels(), std::vector<std::string>{"Choose clip C"});
  EXPECT_TRUE(s.doc.dirty());  // a save writes it
  followDocumentClip(s);
  EXPECT_EQ(s.clip, 2);
  EXPECT_EQ(currentFrame(s), 12);  // the frame stays, as in Blender
  // C's pose at t = 0.5 over A's: the root at z = 1, and x back to C's 0 (C keys all of it).
  EXPECT_NEAR(s.world()[0][3].z, 1.0f, 1e-6f);
  EXPECT_NEAR(s.world()[0][3].x, 0.0f, 1e-6f);
  // Choosing the active clip again changes nothing; a clip that does not exist is refused.
  EXPECT_EQ(chooseClip(s.doc, 2), "");
  EXPECT_EQ(s.doc.historyLabels().size(), 1u);
  EXPECT_NE(chooseClip(s.doc, 3), "");
  EXPECT_NE(chooseClip(s.doc, -1), "");
  EXPECT_EQ(s.doc.historyLabels().size(), 1u);

  ASSERT_TRUE(s.doc.undo());
  EXPECT_EQ(s.doc.activeClip(), 0);
  EXPECT_FALSE(s.doc.dirty());
  followDocumentClip(s);
  EXPECT_EQ(s.clip, 0);
  EXPECT_NEAR(s.world()[0][3].x, 1.0f, 1e-6f);
  EXPECT_NEAR(s.world()[0][3].z, 0.0f, 1e-6f);
  ASSERT_TRUE(s.doc.redo());
  evaluateEditorPose(s);  // the frame loop follows as well
  EXPECT_EQ(s.clip, 2);
  EXPECT_NEAR(s.world()[0][3].z, 1.0f, 1e-6f);
}

TEST(ClipList, NewAppendsAnEmptyActiveClipAndUndoRestoresTheOldOne) {
  EditorState s = opened(threeClipScene());
  ASSERT_EQ(chooseClip(s.doc, 1), "");
  ASSERT_EQ(newClip(s.doc), "");
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "C", "Action"}));
  EXPECT_EQ(s.doc.activeClip(), 3);
  const Clip& made = s.doc.scene().clips[3];
  EXPECT_TRUE(made.channels.empty());
  EXPECT_DOUBLE_EQ(s.doc.scene().frameGrid(3).framesPerSecond(), 24.0);
  EXPECT_EQ(s.doc.scene().frameGrid(3).nearestFrame(made.playStart()), kNewClipStartFrame);
  EXPECT_EQ(s.doc.scene().frameGrid(3).nearestFrame(made.playEnd()), kNewClipEndFrame);
  EXPECT_EQ(s.doc.historyLabels().back(), "New clip Action");
  ASSERT_EQ(newClip(s.doc), "");
  EXPECT_EQ(s.doc.scene().clips[4].name, "Action.001");

  ASSERT_TRUE(s.doc.undo());
  ASSERT_TRUE(s.doc.undo());
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_EQ(s.doc.activeClip(), 1);
  ASSERT_TRUE(s.doc.redo());
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "C", "Action"}));
  EXPECT_EQ(s.doc.activeClip(), 3);
}

TEST(ClipList, DuplicateInsertsAnEqualCopyAfterTheActiveClip) {
  EditorState s = opened(threeClipScene());
  ASSERT_EQ(chooseClip(s.doc, 1), "");
  const Clip original = s.doc.scene().clips[1];
  ASSERT_EQ(duplicateClip(s.doc), "");
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "B.001", "C"}));
  EXPECT_EQ(s.doc.activeClip(), 2);
  EXPECT_TRUE(sameClipBits(s.doc.scene().clips[2], original));
  EXPECT_EQ(s.doc.historyLabels().back(), "Duplicate clip B");
  // A copy of the copy counts on: B.002, not B.001.001.
  ASSERT_EQ(duplicateClip(s.doc), "");
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "B.001", "B.002", "C"}));

  ASSERT_TRUE(s.doc.undo());
  ASSERT_TRUE(s.doc.undo());
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_EQ(s.doc.activeClip(), 1);
  ASSERT_TRUE(s.doc.redo());
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "B.001", "C"}));
  EXPECT_EQ(s.doc.activeClip(), 2);
  EXPECT_TRUE(sameClipBits(s.doc.scene().clips[2], original));
}

TEST(ClipList, RenameRefusesEmptyAndTakenNamesAndUndoes) {
  EditorState s = opened(threeClipScene());
  for (const char* bad : {"", "   ", "B"}) {
    const std::string error = renameClip(s.doc, 0, bad);
    EXPECT_FALSE(error.empty()) << "'" << bad << "'";
  }
  EXPECT_NE(renameClip(s.doc, 0, "B").find("'B'"), std::string::npos);  // names the clash
  EXPECT_NE(renameClip(s.doc, 0, "").find("empty"), std::string::npos);
  EXPECT_NE(renameClip(s.doc, 0, std::string("\xff\xfe", 2)), "");  // not UTF-8
  EXPECT_NE(renameClip(s.doc, 7, "Z"), "");
  EXPECT_FALSE(s.doc.canUndo());
  EXPECT_EQ(renameClip(s.doc, 0, "A"), "");  // its own name: nothing to do
  EXPECT_FALSE(s.doc.canUndo());

  ASSERT_EQ(renameClip(s.doc, 2, "Sprint"), "");
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "Sprint"}));
  EXPECT_EQ(s.doc.historyLabels(), std::vector<std::string>{"Rename clip C to Sprint"});
  EXPECT_EQ(s.doc.activeClip(), 0);  // renaming chooses nothing
  ASSERT_TRUE(s.doc.undo());
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "C"}));
  ASSERT_TRUE(s.doc.redo());
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "Sprint"}));
}

TEST(ClipList, DeleteChoosesTheNextClipAndUndoBringsItBackActive) {
  EditorState s = opened(threeClipScene());
  ASSERT_EQ(chooseClip(s.doc, 1), "");
  const Clip b = s.doc.scene().clips[1];
  ASSERT_EQ(deleteClip(s.doc), "");
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "C"}));
  EXPECT_EQ(s.doc.activeClip(), 1);  // C, the one after it
  EXPECT_EQ(s.doc.historyLabels().back(), "Delete clip B");
  // The last clip of the list gone: the one before it.
  ASSERT_EQ(deleteClip(s.doc), "");
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A"}));
  EXPECT_EQ(s.doc.activeClip(), 0);

  ASSERT_TRUE(s.doc.undo());
  ASSERT_TRUE(s.doc.undo());
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_EQ(s.doc.activeClip(), 1);
  EXPECT_TRUE(sameClipBits(s.doc.scene().clips[1], b));
  ASSERT_TRUE(s.doc.redo());
  EXPECT_EQ(clipNames(s.doc), (std::vector<std::string>{"A", "C"}));
  EXPECT_EQ(s.doc.activeClip(), 1);
}

TEST(ClipList, DeletingTheOnlyClipLeavesTheRestPoseAndTheTimelineDefaults) {
  Scene scene = threeClipScene();
  scene.clips.resize(1);
  EditorState s = opened(scene);
  s.doc.autoKey.enabled = true;  // deleting is no posing edit: nothing is keyed back
  goToFrame(s, 12);
  ASSERT_NEAR(s.world()[0][3].x, 1.0f, 1e-6f);
  ASSERT_EQ(deleteClip(s.doc), "");
  followDocumentClip(s);
  EXPECT_TRUE(s.doc.scene().clips.empty());
  EXPECT_FALSE(s.hasMotion());
  EXPECT_EQ(s.doc.activeClip(), 0);
  EXPECT_EQ(s.doc.pose().local, Pose::rest(s.doc.skeleton()).local);
  EXPECT_EQ(rangeStartFrame(s), kNewClipStartFrame);
  EXPECT_EQ(rangeEndFrame(s), kNewClipEndFrame);
  EXPECT_EQ(deleteClip(s.doc), "there is no clip to delete");
  EXPECT_EQ(s.doc.historyLabels().size(), 1u);

  ASSERT_TRUE(s.doc.undo());  // the clip and the pose of frame 12 come back together
  followDocumentClip(s);
  ASSERT_EQ(s.doc.scene().clips.size(), 1u);
  EXPECT_TRUE(s.hasMotion());
  EXPECT_NEAR(s.world()[0][3].x, 1.0f, 1e-6f);
}

// The active clip goes into .kinema's playhead and comes back on open, bit for bit, with
// the frame; the first frame drawn shows that clip's pose there.
TEST(ClipList, SaveAndReopenKeepTheActiveClip) {
  const std::string dir = test::makeTempDir();
  EditorState s = opened(threeClipScene());
  ASSERT_EQ(chooseClip(s.doc, 1), "");
  followDocumentClip(s);
  goToFrame(s, 6);
  const std::string path = dir + "/b.kinema";
  ASSERT_EQ(saveDocumentAs(s.doc, path), "");
  Result<Document> back = openDocument(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->activeClip(), 1);
  ASSERT_TRUE(back->savedPlayhead().has_value());
  EXPECT_EQ(back->savedPlayhead()->clip, 1);
  EXPECT_EQ(back->savedPlayhead()->time, s.time);
  EditorState r;
  r.doc = std::move(back.value());
  resetTimeline(r);
  EXPECT_EQ(r.clip, 1);
  EXPECT_EQ(currentFrame(r), 6);
  EXPECT_NEAR(r.world()[0][3].y, 2.0f * 6.0f / 24.0f, 1e-6f);  // B moves along Y
  EXPECT_FALSE(r.doc.dirty());
  // Saved again unchanged: the same playhead.
  const Scene again = r.doc.sceneForSaving();
  ASSERT_TRUE(again.playhead.has_value());
  EXPECT_EQ(*again.playhead, (ScenePlayhead{1, s.time}));
  test::runCommand("rm -rf '" + dir + "'");
}

// glTF export writes every clip in order, each sampling as it did; BVH holds one: the
// active clip, and the report says which.
TEST(ClipList, ExportWritesEveryClipToGlbAndTheActiveOneToBvh) {
  const std::string dir = test::makeTempDir();
  EditorState s = opened(threeClipScene());
  ASSERT_EQ(chooseClip(s.doc, 2), "");
  ASSERT_EQ(duplicateClip(s.doc), "");
  ASSERT_EQ(renameClip(s.doc, 3, "C copy"), "");
  ASSERT_EQ(chooseClip(s.doc, 1), "");
  const std::vector<std::string> names{"A", "B", "C", "C copy"};
  ASSERT_EQ(clipNames(s.doc), names);

  std::vector<std::string> report;
  ASSERT_EQ(exportDocument(s.doc, dir + "/all.glb", &report), "");
  Result<Scene> glb = loadGltf(dir + "/all.glb");
  ASSERT_TRUE(glb.ok()) << glb.error();
  ASSERT_EQ(glb->clips.size(), names.size());
  const Skeleton& sk = s.doc.skeleton();
  for (size_t c = 0; c < names.size(); ++c) {
    EXPECT_EQ(glb->clips[c].name, names[c]);
    for (float t : {0.0f, 0.25f, 0.5f, 1.0f}) {
      Pose expected = Pose::rest(sk), got = Pose::rest(glb->skeleton);
      sampleClip(s.doc.scene().clips[c], t, expected);
      sampleClip(glb->clips[c], t, got);
      const int root = glb->skeleton.find("Root");
      ASSERT_GE(root, 0);
      EXPECT_VEC3_NEAR(got.local[root].translation, expected.local[0].translation, 1e-6f);
    }
  }

  report.clear();
  ASSERT_EQ(exportDocument(s.doc, dir + "/active.bvh", &report), "");
  bool said = false;
  for (const std::string& line : report) said = said || line.find("'B'") != std::string::npos;
  EXPECT_TRUE(said) << "the report names the clip BVH got";
  Result<Scene> bvh = loadScene(dir + "/active.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.error();
  ASSERT_EQ(bvh->clips.size(), 1u);
  Pose at = Pose::rest(bvh->skeleton);
  sampleClip(bvh->clips[0], 0.5f, at);
  EXPECT_VEC3_NEAR(at.local[0].translation, glm::vec3(0.0f, 1.0f, 0.0f), 1e-4f);  // B: along Y
  test::runCommand("rm -rf '" + dir + "'");
}

}  // namespace
}  // namespace kinema
