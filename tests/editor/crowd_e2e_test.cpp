// End-to-end test of the crowd commands (issue 24) in the real `kinema edit` under Xvfb: on
// CesiumMan.glb the script adds a crowd (Simulate > Add Crowd...), types 200 members into the
// Crowd panel, plays (the flock is drawn and runs around the obstacle sphere), bakes a clip
// per member (Simulate > Bake Crowd) and saves .kinema; the file, opened again by the editor,
// has the crowd and its 200 baked walk clips, which the model's own bake (no window) computes.
#include "editor/e2e_harness.h"

#include "anim/sampling.h"
#include "editor/model/crowd_edits.h"
#include "editor/model/document.h"
#include "io/scene_files.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class CrowdE2e : public TempDirSuite<CrowdE2e> {
 public:
  static constexpr const char* kShotFolder = "crowd_e2e";
};

TEST_F(CrowdE2e, TwoHundredCesiumMenWalkAroundAnObstacleBakedSavedReopened) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string cesium = sharedDataDir() + "/gltf/CesiumMan.glb";
  const std::string saved = dir_ + "/crowd.kinema";
  Script s(Script::Start::AsOpened);
  s.wait(2);
  s.menu("Simulate", "Add Crowd...").wait(2);
  s.clickItem("Crowd/members").wait(1).chord("A", {"ctrl"}).type("200").key("ENTER").wait(2);
  s.clickItem("Timeline/Play").wait(10);
  s.clickItem("Timeline/Play").wait(2);
  s.menu("Simulate", "Bake Crowd").wait(3);
  s.saveAs(saved);
  const json d = runEditor(dir_, shotDir(), s, "crowd", cesium);
  ASSERT_TRUE(d.is_object());
  const json& crowds = d["crowds"];
  ASSERT_EQ(crowds["crowds"].size(), 1u) << crowds.dump();
  EXPECT_EQ(crowds["crowds"][0]["members"], 200);
  EXPECT_EQ(crowds["crowds"][0]["spheres"], 1);
  EXPECT_EQ(crowds["members_drawn"], 200) << "the flock was drawn";
  EXPECT_GT(crowds["debug_vectors"].get<int>(), 0) << "and its debug member's impulses";
  EXPECT_EQ(d["undo_depth"], 3) << "add, members, bake";
  EXPECT_TRUE(d["errors"].empty()) << d["errors"].dump();

  // Reopened in the editor: the crowd and its baked clips are there.
  const json again = runEditor(dir_, shotDir(), Script(Script::Start::AsOpened).wait(2), "crowd_reopened", saved);
  ASSERT_TRUE(again.is_object());
  EXPECT_EQ(again["crowds"]["crowds"].size(), 1u);
  ASSERT_EQ(again["clips"].size(), 201u);
  EXPECT_EQ(again["clips"][200], "crowd_0199");

  // The model's bake of the same crowd (no window) keys what the file holds.
  Result<Scene> loaded = loadScene(cesium), back = loadScene(saved);
  ASSERT_TRUE(loaded && back) << back.error();
  Document doc(loaded.value());
  CrowdSettings crowd = defaultCrowd(doc);
  crowd.members = 200;
  ASSERT_TRUE(crowd == back->simulation.crowds.at(0));
  ASSERT_EQ(addCrowdEdit(doc, crowd), "");
  const Clip walk = doc.scene().clips[0];  // a copy: the bake adds clips
  ASSERT_EQ(bakeCrowdEdit(doc, 0, 0, ownFrameGrid(walk).nearestFrame(walk.duration())), "");
  for (int m : {0, 77, 199}) {
    const Clip& expected = doc.scene().clips[1 + m];
    const Clip& got = back->clips[1 + m];
    ASSERT_EQ(got.name, expected.name);
    for (long long f = 0; f <= ownFrameGrid(walk).nearestFrame(walk.duration()); f += 7) {
      Pose pe = Pose::rest(doc.skeleton()), pb = Pose::rest(back->skeleton);
      sampleClip(expected, ownFrameGrid(expected).frameToTime(f), pe);
      sampleClip(got, ownFrameGrid(got).frameToTime(f), pb);
      for (int j = 0; j < doc.skeleton().size(); ++j)
        ASSERT_LT(glm::distance(pe.local[j].translation, pb.local[j].translation), 1e-4f) << m << " " << f << " " << j;
    }
  }
}

}  // namespace
}  // namespace kinema::test
