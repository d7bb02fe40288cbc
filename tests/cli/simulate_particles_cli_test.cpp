// `kinema simulate --render` and `kinema render` with particles (issue 24): one PNG a frame,
// particle-coloured pixels where a projection computed here puts the particles and none
// before the first is born, and the JSON report naming each system with its counts.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/image.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

constexpr int kSize = 96;

// Two joints from (0, 0, 0) to (0, 2, 0) and a magenta
// system whose particles stand still where they are born, at (0.5, 1.5, 0), one a frame.
Scene stillSparks() {
  Scene scene;
  scene.frameRate = 30.0;  // no clip: frames count at the document's rate
  scene.skeleton.addJoint("root", -1, Transform{});
  scene.skeleton.addJoint("top", 0, Transform::fromTranslation({0, 2, 0}));
  ParticleSystemSettings s;
  s.name = "dots";
  s.colour = {1.0f, 0.0f, 1.0f, 1.0f};
  s.size = 0.15f;
  s.forces.gravity = glm::vec3(0.0f);
  ParticleEmitter e;
  e.position = {0.5f, 1.5f, 0.0f};
  e.speed = {0.0f, 0.0f, RandomDistribution::Uniform};
  e.rate = {30.0f, 0.0f, RandomDistribution::Uniform};  // 30 fps frames: one a frame
  e.lifetime = {100.0f, 0.0f, RandomDistribution::Uniform};
  s.emitters.push_back(e);
  scene.simulation.particles.push_back(s);
  return scene;
}

bool magenta(const std::uint8_t* p) { return p[0] > 200 && p[1] < 60 && p[2] > 200; }
int countMagenta(const Image& img) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += magenta(img.pixel(x, y));
  return n;
}

// The camera (--camera 0,0,4) looks along -Z from 4 units in front of the centre of the box
// around the joints and the particles, (0..0.5, 0..2, 0): (0.25, 1, 0). (0.5, 1.5, 0) is then
// 0.25 right and 0.5 up at depth 4, with a 35° vertical field on a square image.
glm::ivec2 projected() {
  const float half = 4.0f * std::tan(glm::radians(17.5f));
  return {static_cast<int>((0.25f / half + 1.0f) * 0.5f * kSize), static_cast<int>((1.0f - 0.5f / half) * 0.5f * kSize)};
}

class SimulateParticlesCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = makeTempDir(); }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  int kinema(const std::string& args) { return runCommand(std::string(KINEMA_BINARY) + " " + args, &out_, &err_); }
  std::string dir_, out_, err_;
};

TEST_F(SimulateParticlesCli, RenderWritesAFramePerFrameWithTheParticlesWhereTheyProject) {
  const std::string in = dir_ + "/dots.kinema";
  ASSERT_EQ(saveKinemaFile(in, stillSparks()), "");
  const std::string size = std::to_string(kSize) + "x" + std::to_string(kSize);
  ASSERT_EQ(kinema("simulate '" + in + "' --frames 0:3 --render '" + dir_ + "/frames' --size " + size +
                   " --camera 0,0,4 --json"),
            0)
      << err_;
  const nlohmann::json j = nlohmann::json::parse(out_);
  ASSERT_EQ(j["parts"].size(), 1u);
  const nlohmann::json& part = j["parts"][0];
  EXPECT_EQ(part["kind"], "particles");
  EXPECT_EQ(part["name"], "dots");
  EXPECT_EQ(part["frames"], nlohmann::json::array({0, 3}));
  EXPECT_EQ(part["alive"], 3);
  EXPECT_EQ(part["emitted"], 3);
  EXPECT_EQ(j["render"], dir_ + "/frames");
  EXPECT_EQ(j["frames"], nlohmann::json::array({0, 3}));
  Result<Image> first = loadPng(dir_ + "/frames/frame_0000.png");
  Result<Image> last = loadPng(dir_ + "/frames/frame_0003.png");
  ASSERT_TRUE(first && last);
  EXPECT_TRUE(std::ifstream(dir_ + "/frames/frame_0001.png").good());
  EXPECT_EQ(countMagenta(first.value()), 0) << "frame 0 is before the first particle is born";
  const glm::ivec2 p = projected();
  EXPECT_TRUE(magenta(last->pixel(p.x, p.y))) << p.x << ", " << p.y;
  EXPECT_GT(countMagenta(last.value()), 4);

  // kinema render draws the same particles at the same frame.
  ASSERT_EQ(kinema("render '" + in + "' --frame 3 --size " + size + " --camera 0,0,4 --out '" + dir_ + "/one.png'"), 0) << err_;
  Result<Image> one = loadPng(dir_ + "/one.png");
  ASSERT_TRUE(one);
  EXPECT_TRUE(magenta(one->pixel(p.x, p.y)));
}

TEST_F(SimulateParticlesCli, ChainsAreBakedAndParticlesReportedInOneRun) {
  Scene scene = stillSparks();
  SpringBoneChain chain;
  chain.name = "stick";
  chain.joints = {0};
  scene.simulation.springChains.push_back(chain);
  const std::string in = dir_ + "/both.kinema", out = dir_ + "/baked.kinema";
  ASSERT_EQ(saveKinemaFile(in, scene), "");
  ASSERT_EQ(kinema("simulate '" + in + "' --frames 0:10 --out '" + out + "' --json"), 0) << err_;
  const nlohmann::json j = nlohmann::json::parse(out_);
  ASSERT_EQ(j["parts"].size(), 2u);
  EXPECT_EQ(j["parts"][0]["kind"], "spring-chain");
  EXPECT_EQ(j["parts"][1]["kind"], "particles");
  EXPECT_EQ(j["parts"][1]["alive"], 10);
  Result<Scene> back = loadScene(out);
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->simulation.particles.size(), 1u);
  EXPECT_TRUE(back->simulation.particles[0] == scene.simulation.particles[0]) << "the particles stay in the file";
}

TEST_F(SimulateParticlesCli, BadRenderOptionsAreUsageErrors) {
  const std::string in = dir_ + "/dots.kinema";
  ASSERT_EQ(saveKinemaFile(in, stillSparks()), "");
  EXPECT_EQ(kinema("simulate '" + in + "' --frames 0:3"), 2) << "neither --out nor --render";
  EXPECT_NE(err_.find("--out FILE, --render DIR or both"), std::string::npos) << err_;
  EXPECT_EQ(kinema("simulate '" + in + "' --render '" + dir_ + "/f' --size 64"), 2);
  EXPECT_NE(err_.find("--size takes WxH"), std::string::npos) << err_;
  EXPECT_EQ(kinema("simulate '" + in + "' --render '" + dir_ + "/f' --camera 1"), 2);
}

}  // namespace
}  // namespace kinema::test
