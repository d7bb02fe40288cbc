// End-to-end: particles in the editor (issue 24). The real `kinema edit` under xvfb-run on
// the default character waving its right arm: Hand.R selected in the outliner, Simulate >
// Add Particle Emitter (its command), its restitution typed into the Particles window, 20
// frames stepped; the dump shows the system and its live counts, the screenshot shows sparks
// in the system's colour; Ctrl+Z twice undoes the edit and the emitter.
#include <algorithm>
#include <cmath>

#include "editor/e2e_harness.h"
#include "io/image.h"
#include "io/kinema_file.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

// The default emitter's colour (1, 0.55, 0.1): a bright orange nothing else in the view has.
bool spark(const std::uint8_t* p) { return p[0] > 230 && p[1] > 110 && p[1] < 170 && p[2] < 60; }

// Spark-coloured pixels in the dumped 3D viewport rectangle of a screenshot.
int sparks(const std::string& png, const json& d) {
  const Result<Image> img = loadPng(png);
  EXPECT_TRUE(img.ok()) << png;
  if (!img.ok()) return -1;
  const json& v = d["viewport"];
  const int x0 = v["x"], y0 = v["y"], w = v["width"], h = v["height"];
  int n = 0;
  for (int y = std::max(y0, 0); y < std::min(y0 + h, img->height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x0 + w, img->width); ++x) n += spark(img->pixel(x, y));
  return n;
}

TEST(ParticlesE2e, AnEmitterOnTheActiveJointIsEditedPlaysLiveAndCtrlZRemovesIt) {
  if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
  const std::string dir = makeTempDir(), file = dir + "/wave.kinema";
  // The default character, its right upper arm turning about z from 1.1 rad down to 0.7 up
  // and back over 3 s at 30 fps.
  Result<Scene> scene = loadKinemaFile(std::string(KINEMA_SOURCE_DIR) + "/assets/default_character.kinema");
  ASSERT_TRUE(scene.ok()) << scene.error();
  Clip clip;
  clip.name = "wave";
  clip.frameTime = 1.0 / 30.0;
  const auto z = [](float a) { return glm::vec4(0.0f, 0.0f, std::sin(a / 2), std::cos(a / 2)); };
  clip.channels.emplace_back(scene->skeleton.find("UpperArm.R"), ChannelTarget::Rotation, Interpolation::Linear,
                             std::vector<float>{0.0f, 1.5f, 3.0f}, std::vector<glm::vec4>{z(1.1f), z(-0.7f), z(1.1f)});
  scene->clips.push_back(clip);
  ASSERT_EQ(saveKinemaFile(file, scene.value()), "");
  const std::string shots = std::string(KINEMA_BUILD_DIR) + "/particles_e2e";
  runCommand("mkdir -p '" + shots + "'");

  Script added;
  // The Particles window opens on the new system: its restitution typed in (one more undo
  // step), then the window closed so the viewport shows whole.
  added.select("Hand.R").command("sim.add_particle_emitter").wait(3);
  added.clickItem("Particles/Restitution").wait(1).type("0.9").key("ENTER").wait(2);
  added.command("sim.particle_settings").wait(1);
  for (int i = 0; i < 20; ++i) added.command("timeline.step_forward");
  added.wait(3);
  const json d = runEditor(dir, shots, added, "particles_added", file);
  ASSERT_TRUE(d.is_object());
  const json& p = d["particles"];
  ASSERT_EQ(p["systems"].size(), 1u);
  EXPECT_EQ(p["systems"][0]["name"], "Hand.R sparks");
  EXPECT_EQ(p["systems"][0]["emitters"][0]["kind"], "joint");
  EXPECT_EQ(p["systems"][0]["emitters"][0]["joint"], "Hand.R");
  EXPECT_EQ(p["frame"], 20);
  // 60 a second at 30 fps: 2 a frame for 20 frames; none has reached its lifetime (1.5 ± 0.5 s).
  EXPECT_EQ(p["systems"][0]["emitted"], 40);
  EXPECT_EQ(p["systems"][0]["alive"], 40);
  EXPECT_TRUE(d["items"].contains("Particles/Emitter")) << "the Particles window was drawn";
  EXPECT_EQ(p["window"], false);
  EXPECT_NEAR(double(p["systems"][0]["restitution"]), 0.9, 1e-6);
  EXPECT_EQ(d["undo_depth"], 2) << "adding, then the restitution: one step each";
  EXPECT_GT(sparks(shots + "/particles_added.png", d), 20) << "sparks drawn in the viewport";

  Script undone = added;
  undone.chord("Z", {"ctrl"}).wait(2).chord("Z", {"ctrl"}).wait(3);
  const json u = runEditor(dir, shots, undone, "particles_undone", file);
  ASSERT_TRUE(u.is_object());
  EXPECT_EQ(u["particles"]["systems"].size(), 0u);
  EXPECT_EQ(u["undo_depth"], 0);
  EXPECT_EQ(sparks(shots + "/particles_undone.png", u), 0) << "no sparks once the emitter is undone";
  runCommand("rm -rf '" + dir + "'");
}

}  // namespace
}  // namespace kinema::test
