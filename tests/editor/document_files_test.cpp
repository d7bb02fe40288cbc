// New / open / save / save as / export and the recent-files list.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "anim/clip.h"
#include "core/forward_kinematics.h"
#include "editor/model/document_files.h"
#include "editor/model/pose_edits.h"
#include "test_support.h"
#include "io/scene_files.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

namespace fs = std::filesystem;

TEST(DocumentFiles, NewIsTheDefaultCharacterAtRest) {
  Document doc = newDocument();
  EXPECT_EQ(doc.skeleton().size(), 27);
  EXPECT_TRUE(doc.path().empty());
  EXPECT_FALSE(doc.dirty());
  EXPECT_FALSE(canSaveInPlace(doc));
  EXPECT_NE(saveDocument(doc), "");  // needs Save As
  EXPECT_EQ(documentTitle(doc), "untitled - Kinema");
  ASSERT_EQ(setJointTranslation(doc, 0, glm::vec3(0, 1, 0)), "");
  doc.setPath("/some/dir/walk.kinema");
  EXPECT_EQ(documentTitle(doc), "walk.kinema* - Kinema");
}

TEST(DocumentFiles, SaveAsThenOpenKeepsThePoseNamesAndTargets) {
  const std::string dir = test::makeTempDir();
  Document doc = newDocument();
  const int arm = doc.skeleton().find("UpperArm.L");
  ASSERT_EQ(setJointRotation(doc, arm, glm::angleAxis(0.75f, glm::vec3(0, 0, 1))), "");
  ASSERT_EQ(renameJoint(doc, doc.skeleton().find("Head"), "Skull"), "");
  ASSERT_EQ(addIkTargetAtEffector(doc, doc.skeleton().find("Hand.R"), 2, IkSolver::TwoBone), "");
  EXPECT_TRUE(doc.dirty());
  EXPECT_NE(saveDocumentAs(doc, dir + "/pose.gltf"), "");  // projects are .kinema
  ASSERT_EQ(saveDocumentAs(doc, dir + "/pose.kinema"), "");
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(doc.path(), dir + "/pose.kinema");
  EXPECT_TRUE(canSaveInPlace(doc));
  Result<Document> back = openDocument(dir + "/pose.kinema");
  ASSERT_TRUE(back) << back.error();
  EXPECT_FALSE(back->dirty());
  EXPECT_EQ(back->skeleton().names, doc.skeleton().names);
  ASSERT_EQ(back->pose().size(), doc.pose().size());
  for (int i = 0; i < doc.pose().size(); ++i)
    EXPECT_EQ(std::memcmp(&back->pose().local[i], &doc.pose().local[i], sizeof(Transform)), 0) << i;
  ASSERT_EQ(back->ikTargets().size(), 1u);
  EXPECT_EQ(back->ikTargets()[0].target.effector, doc.skeleton().find("Hand.R"));
  EXPECT_EQ(back->ikTargets()[0].target.root, doc.skeleton().find("UpperArm.R"));  // chain length 2 saved as its root
  // Save in place after another edit.
  ASSERT_EQ(setJointTranslation(doc, 0, glm::vec3(0, 1, 0)), "");
  ASSERT_EQ(saveDocument(doc), "");
  EXPECT_FALSE(doc.dirty());
  fs::remove_all(dir);
}

TEST(DocumentFiles, OpenErrorsAreOneLine) {
  const std::string dir = test::makeTempDir();
  Result<Document> missing = openDocument(dir + "/nope.kinema");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().find('\n'), std::string::npos);
  EXPECT_NE(missing.error().find("nope.kinema"), std::string::npos);
  test::writeFile(dir + "/bad.kinema", "{\"format\": \"kinema\", \"version\": 1, \"skeleton\": 3}");
  Result<Document> bad = openDocument(dir + "/bad.kinema");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("skeleton"), std::string::npos);
  fs::remove_all(dir);
}

TEST(DocumentFiles, ExportWritesTheWorkingPoseAsAOneKeyClip) {
  const std::string dir = test::makeTempDir();
  Document doc = newDocument();
  const int arm = doc.skeleton().find("LowerArm.L");
  ASSERT_EQ(setJointRotation(doc, arm, glm::angleAxis(1.0f, glm::vec3(0, 1, 0))), "");
  ASSERT_EQ(setJointTranslation(doc, 0, glm::vec3(0.2f, 0.9f, 0.1f)), "");
  const std::vector<glm::mat4> expected = doc.worldTransforms();
  for (const char* name : {"/out.glb", "/out.gltf", "/out.bvh"}) {
    std::vector<std::string> report;
    ASSERT_EQ(exportDocument(doc, dir + name, &report), "") << name;
    Result<Scene> back = loadScene(dir + name);
    ASSERT_TRUE(back) << back.error();
    ASSERT_EQ(back->clips.size(), 1u) << name;
    Pose pose = Pose::rest(back->skeleton);
    sampleClip(back->clips[0], 0.0f, pose);
    const std::vector<glm::mat4> world = computeWorld(back->skeleton, pose);
    for (int i = 0; i < doc.skeleton().size(); ++i) {
      const int j = back->skeleton.find(doc.skeleton().names[i]);
      ASSERT_GE(j, 0) << name << " " << doc.skeleton().names[i];
      EXPECT_VEC3_NEAR(glm::vec3(world[j][3]), glm::vec3(expected[i][3]), 1e-4f);
    }
  }
  EXPECT_TRUE(doc.dirty());  // export is not a save
  EXPECT_NE(exportDocument(doc, dir + "/out.obj"), "");
  fs::remove_all(dir);
}

TEST(DocumentFiles, RenamingAJointOfAGltfSceneRenamesItsNode) {
  const std::string dir = test::makeTempDir();
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform{});
  scene.skeleton.addJoint("arm", 0, Transform::fromTranslation({1, 0, 0}));
  scene.nodeOfJoint = {1, 0};  // the file lists the arm first
  scene.nodeNames = {"arm", "root"};
  Document doc(scene, "");
  ASSERT_EQ(renameJoint(doc, 1, "wing"), "");
  const Scene saved = doc.sceneForSaving();
  EXPECT_EQ(saved.nodeNames, (std::vector<std::string>{"wing", "root"}));
  ASSERT_EQ(exportDocument(doc, dir + "/renamed.gltf"), "");
  Result<Scene> back = loadScene(dir + "/renamed.gltf");
  ASSERT_TRUE(back) << back.error();
  EXPECT_GE(back->skeleton.find("wing"), 0);
  EXPECT_EQ(back->skeleton.find("arm"), -1);
  fs::remove_all(dir);
}

TEST(DocumentFiles, RecentFilesKeepTenNewestFirstAndSurviveAReload) {
  const std::string dir = test::makeTempDir();
  const std::string file = dir + "/deep/er/kinema/recent.json";  // missing folders are created
  RecentFiles recent(file);
  EXPECT_EQ(recent.load(), "");
  for (int i = 0; i < 12; ++i) recent.add("/f" + std::to_string(i) + ".kinema");
  recent.add("/f5.kinema");  // again: moves to the front, no duplicate
  ASSERT_EQ(recent.entries().size(), 10u);
  EXPECT_EQ(recent.entries()[0], "/f5.kinema");
  EXPECT_EQ(recent.entries()[1], "/f11.kinema");
  EXPECT_EQ(recent.entries()[2], "/f10.kinema");
  EXPECT_EQ(recent.entries()[7], "/f4.kinema");  // f5 moved out from between f6 and f4
  EXPECT_EQ(recent.entries()[9], "/f2.kinema");  // f0 and f1 dropped
  ASSERT_EQ(recent.save(), "");
  RecentFiles again(file);
  EXPECT_EQ(again.load(), "");
  EXPECT_EQ(again.entries(), recent.entries());
  test::writeFile(file, "{\"recent\": [1, 2");
  RecentFiles corrupt(file);
  const std::string message = corrupt.load();
  EXPECT_NE(message, "");
  EXPECT_NE(message.find("recent.json"), std::string::npos);
  EXPECT_TRUE(corrupt.entries().empty());
  fs::remove_all(dir);
}

TEST(DocumentFiles, ConfigDirFollowsXdg) {
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string saved = old ? old : "";
  setenv("XDG_CONFIG_HOME", "/tmp/xdg-test", 1);
  EXPECT_EQ(RecentFiles::defaultFile(), "/tmp/xdg-test/kinema/recent.json");
  unsetenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  if (home) {
    EXPECT_EQ(kinemaConfigDir(), std::string(home) + "/.config/kinema");
  }
  if (old) setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
}

}  // namespace
}  // namespace kinema
