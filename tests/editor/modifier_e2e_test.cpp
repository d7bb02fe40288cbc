// End-to-end: a noise modifier added in the curve editor as a user would (issue 24): the
// real `kinema edit` under xvfb-run selects Hips in the outliner, opens the curve editor
// (Shift+F6), steps to frame 5, runs Animation > Add Modifier > Noise, saves a copy, then
// Ctrl+Z. The saved copy has the modifier and a pose moved off the keyed curve by less than
// the noise's strength; after the undo the modifier is gone and the pose is the keyed one.
#include <cmath>

#include "editor/e2e_harness.h"
#include "io/kinema_file.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

// Hips's translation y: 1 at frame 0, 2 at frame 10 (linear, 30 fps); x = z = 0. Frame 5 is
// halfway: (0, 1.5, 0).
const char* kFile = R"({"format": "kinema", "version": 1,
 "skeleton": {"joints": [
   {"name": "Hips", "parent": -1, "translation": [0, 1, 0]},
   {"name": "Spine", "parent": 0, "translation": [0, 0.3, 0]}]},
 "clips": [{"name": "rise", "frame_time": 0.0333333333333,
   "channels": [
     {"joint": "Hips", "target": "translation", "interpolation": "linear",
      "times": [0, 0.333333333333], "values": [[0, 1, 0], [0, 2, 0]]}]}]})";

TEST(ModifierE2e, ANoiseModifierFromTheCurveEditorMovesThePoseAndCtrlZRemovesIt) {
  if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
  const std::string dir = makeTempDir(), file = dir + "/rise.kinema", noisy = dir + "/noisy.kinema";
  std::ofstream(file) << kFile;
  const std::string shots = std::string(KINEMA_BUILD_DIR) + "/modifier_e2e";
  runCommand("mkdir -p '" + shots + "'");
  Script s;
  s.select("Hips").keyDown("LEFT_SHIFT").key("F6").keyUp("LEFT_SHIFT").wait(3);
  for (int i = 0; i < 5; ++i) s.command("timeline.step_forward");
  s.wait(2).command("curves.add_noise_modifier").wait(3);
  s.saveAs(noisy);
  s.chord("Z", {"ctrl"}).wait(3);
  const json d = runEditor(dir, shots, s, "modifier_undo", file);
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["curve_editor"]["open"], true);

  // The copy saved with the modifier: a noise modifier on the Hips channel, and the working
  // pose at frame 5 off the keyed (0, 1.5, 0) by a visible amount within the strength.
  const Result<Scene> saved = loadKinemaFile(noisy);
  ASSERT_TRUE(saved.ok()) << saved.error();
  ASSERT_EQ(saved->clips.size(), 1u);
  const Channel& ch = saved->clips[0].channels.at(0);
  ASSERT_EQ(ch.modifiers.size(), 1u);
  EXPECT_EQ(ch.modifiers[0].kind, ChannelModifierKind::Noise);
  const float strength = ch.modifiers[0].noise.strength;
  ASSERT_EQ(saved->pose.size(), 2);
  const glm::vec3 moved = saved->pose.local[0].translation - glm::vec3(0.0f, 1.5f, 0.0f);
  EXPECT_GT(glm::length(moved), 1e-4f) << "the noise moved the hips";
  for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(moved[k]), strength * 1.0001f) << k;

  // After Ctrl+Z: no modifier, the keyed pose, one step to redo.
  EXPECT_EQ(d["undo_depth"], 0);
  EXPECT_EQ(d["redo_depth"], 1);
  for (const json& curve : d["curve_editor"]["curves"]) EXPECT_EQ(curve["modifiers"], 0) << curve["label"];
  const glm::dvec3 hips = vec3(d["joints"][0]["translation"]);
  EXPECT_NEAR(hips.x, 0.0, 1e-6);
  EXPECT_NEAR(hips.y, 1.5, 1e-5);
  EXPECT_NEAR(hips.z, 0.0, 1e-6);
  runCommand("rm -rf '" + dir + "'");
}

}  // namespace
}  // namespace kinema::test
