// The editor's crowds without a window (issue 24): adding, editing, toggling the naive
// average, baking and removing are one undo step each and make the document dirty (its change
// detection sees crowd edits); the live preview runs the crowd once and poses every member at
// the playhead as the bake keys it; the debug vectors are the member's impulses.
#include <gtest/gtest.h>

#include "anim/sampling.h"
#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "editor/model/crowd_edits.h"
#include "editor/model/document.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// The default character walking 1.2 m along +Z in 1 s at 30 fps (its hips move).
Scene walker() {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  const Skeleton& s = scene.skeleton;
  Clip clip;
  clip.name = "walk";
  clip.frameTime = 1.0 / 30.0;
  const int hips = s.find("Hips");
  const glm::vec3 rest = s.rest[hips].translation;
  clip.channels.emplace_back(hips, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{{rest, 0}, {rest + glm::vec3(0, 0, 1.2f), 0}});
  scene.clips.push_back(clip);
  return scene;
}

TEST(CrowdEdits, EachEditIsOneUndoStepTheDocumentSees) {
  Document doc(walker());
  ASSERT_FALSE(doc.dirty());
  CrowdSettings crowd = defaultCrowd(doc);
  EXPECT_EQ(crowd.character, "") << "the document's own character";
  EXPECT_EQ(crowd.validate(), "");
  ASSERT_EQ(addCrowdEdit(doc, crowd), "");
  EXPECT_TRUE(doc.dirty()) << "document change detection notices a crowd";
  ASSERT_EQ(doc.scene().simulation.crowds.size(), 1u);
  crowd.members = 12;
  ASSERT_EQ(setCrowdEdit(doc, 0, crowd), "");
  ASSERT_EQ(toggleNaiveAverageEdit(doc, 0), "");
  EXPECT_EQ(doc.scene().simulation.crowds[0].boids.allocation, AccelerationAllocation::Average);
  EXPECT_EQ(doc.historyLabels(), (std::vector<std::string>{"Add crowd", "Crowd settings", "Naive average allocation"}));
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().simulation.crowds[0].boids.allocation, AccelerationAllocation::Priority);
  EXPECT_EQ(doc.scene().simulation.crowds[0].members, 12);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().simulation.crowds[0].members, 50);
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().simulation.crowds.empty());
  EXPECT_FALSE(doc.dirty());
  // Bad settings change nothing.
  crowd.boids.cruiseSpeed = 100.0f;
  EXPECT_NE(addCrowdEdit(doc, crowd), "");
  EXPECT_TRUE(doc.scene().simulation.crowds.empty());
}

TEST(CrowdEdits, BakeAddsAClipPerMemberInOneStepAndAgainReplacesThem) {
  Document doc(walker());
  CrowdSettings crowd = defaultCrowd(doc);
  crowd.members = 8;
  ASSERT_EQ(addCrowdEdit(doc, crowd), "");
  int clips = 0;
  ASSERT_EQ(bakeCrowdEdit(doc, 0, 0, 30, &clips), "");
  EXPECT_EQ(clips, 8);
  ASSERT_EQ(doc.scene().clips.size(), 9u);
  EXPECT_EQ(doc.scene().clips[8].name, "crowd_0007");
  ASSERT_EQ(bakeCrowdEdit(doc, 0, 0, 20), "");
  EXPECT_EQ(doc.scene().clips.size(), 9u) << "a second bake replaces the members' clips";
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().clips.size(), 1u);
  ASSERT_EQ(removeCrowdEdit(doc, 0), "");
  EXPECT_TRUE(doc.scene().simulation.crowds.empty());
  crowd.character = "elsewhere.glb";
  ASSERT_EQ(addCrowdEdit(doc, crowd), "");
  EXPECT_NE(bakeCrowdEdit(doc, 0, 0, 10).find("another file"), std::string::npos);
}

TEST(CrowdEdits, ThePreviewPosesEveryMemberAsTheBakeKeysIt) {
  Document doc(walker());
  CrowdSettings crowd = defaultCrowd(doc);
  crowd.members = 6;
  crowd.debugMember = 2;
  ASSERT_EQ(addCrowdEdit(doc, crowd), "");
  CrowdPreview p;
  const double frameTime = 1.0 / 30.0;
  ASSERT_TRUE(updateCrowdPreview(p, doc, 0, 10 * frameTime, 1.0f, 0.1f)) << p.error;
  EXPECT_EQ(p.runs, 1);
  EXPECT_EQ(p.frame, 10);
  ASSERT_EQ(p.world.size(), 6u);
  ASSERT_TRUE(updateCrowdPreview(p, doc, 0, 20 * frameTime));
  EXPECT_EQ(p.runs, 1) << "the run is kept while nothing changed";
  // The debug member's vectors: each non-zero desired acceleration x 0.1 s, from its position.
  ASSERT_TRUE(updateCrowdPreview(p, doc, 0, 10 * frameTime, 1.0f, 0.1f));
  const BoidDebug& d = p.run.debug[10];
  const glm::vec3 from = p.run.at(10, 2).position + glm::vec3(0, 1, 0);
  ASSERT_FALSE(p.vectors.empty());
  EXPECT_EQ(std::string(p.vectors.back().label), "acceleration");
  EXPECT_NEAR(glm::distance(p.vectors.back().to, from + d.acceleration * 0.1f), 0.0f, 1e-4f);
  for (const CrowdDebugVector& v : p.vectors) EXPECT_NEAR(glm::distance(v.from, from), 0.0f, 1e-5f);
  // The member's hips where the baked clip puts them.
  ASSERT_EQ(bakeCrowdEdit(doc, 0, 0, 30), "");
  ASSERT_TRUE(updateCrowdPreview(p, doc, 0, 10 * frameTime));
  EXPECT_EQ(p.runs, 2) << "the bake changed the document: run again";
  const Skeleton& s = doc.skeleton();
  Pose pose = Pose::rest(s);
  sampleClip(doc.scene().clips[1 + 4], static_cast<float>(10 * frameTime), pose);
  const std::vector<glm::mat4> world = computeWorld(s, pose);
  const int hips = s.find("Hips");
  EXPECT_NEAR(glm::distance(glm::vec3(world[hips][3]), glm::vec3(p.world[4][hips][3])), 0.0f, 1e-4f);
}

}  // namespace
}  // namespace kinema
