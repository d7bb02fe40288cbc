// kinema pose and kinema convert on a .kinema clip with a channel modifier: the CLI shows
// the modified motion (closed form), clamps time to the clip, and glTF carries it.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/kinema_file.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// The root's translation is keyed at (0, 1, 0) at 0 s and 1 s; a wave adds
// 0.2 cos(3 t + 0.5) to y only (k = 0: x plays no part). The arm hangs 0.3 m along x.
Scene waveScene() {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform::fromTranslation({0, 1, 0}));
  scene.skeleton.addJoint("arm", 0, Transform::fromTranslation({0.3f, 0, 0}));
  Clip clip;
  clip.frameTime = 0.1;
  clip.channels.emplace_back(0, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{{0, 1, 0, 0}, {0, 1, 0, 0}});
  ChannelModifier wave;
  wave.kind = ChannelModifierKind::Wave;
  wave.components = 0x2;
  wave.wave.amplitude = 0.2f;
  wave.wave.omega = 3.0f;
  wave.wave.phi = 0.5f;
  clip.channels[0].modifiers = {wave};
  scene.clips.push_back(clip);
  return scene;
}

double armY(const nlohmann::json& report) { return report["joints"][1]["world"][13].get<double>(); }

TEST(ModifiersCli, PoseShowsTheModifiedMotionAndClampsTime) {
  const std::string dir = makeTempDir();
  ASSERT_FALSE(dir.empty());
  const std::string file = dir + "/wave.kinema";
  ASSERT_EQ(saveKinemaFile(file, waveScene()), "");
  std::string out, err;
  for (double t : {0.0, 0.25, 0.7}) {
    ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " pose '" + file + "' --time " + std::to_string(t) + " --json", &out, &err), 0) << err;
    EXPECT_NEAR(armY(nlohmann::json::parse(out)), 1.0 + 0.2 * std::cos(3.0 * t + 0.5), 1e-5) << t;
  }
  // Past the last key the clip holds its end: the wave at 1 s, not at 5 s.
  ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " pose '" + file + "' --time 5 --json", &out, &err), 0) << err;
  EXPECT_NEAR(armY(nlohmann::json::parse(out)), 1.0 + 0.2 * std::cos(3.0 + 0.5), 1e-5);
  // Converted to glTF (baked at the clip's 10 fps): frame 3 plays the same closed form.
  const std::string gltf = dir + "/wave.gltf";
  ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " convert '" + file + "' '" + gltf + "'", &out, &err), 0) << err;
  EXPECT_NE(err.find("channel modifiers baked to keys at 10 fps"), std::string::npos) << err;
  ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " pose '" + gltf + "' --time 0.3 --json", &out, &err), 0) << err;
  EXPECT_NEAR(armY(nlohmann::json::parse(out)), 1.0 + 0.2 * std::cos(0.9 + 0.5), 1e-5);
  std::system(("rm -rf '" + dir + "'").c_str());
}

}  // namespace
}  // namespace kinema::test
