// SceneDeformationJob: every *.skin.json reference (three.js, ../shared/data/reference)
// through the job itself, glTF semantics on a hand-built scene (the skinned node's own
// transform ignored, unskinned instances moved by their node, per-instance method),
// and validate().
#include "evaluation/scene_deformation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <regex>

#include "core/forward_kinematics.h"
#include "test_support.h"
#include "io/scene_files.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

namespace fs = std::filesystem;

std::string findGltf(const std::string& stem) {
  for (const auto& e : fs::recursive_directory_iterator(test::sharedDataDir() + "/gltf")) {
    const std::string ext = e.path().extension().string();
    if ((ext == ".gltf" || ext == ".glb") && e.path().stem() == stem) return e.path().string();
  }
  return {};
}

std::vector<DeformedPrimitive> deform(const Scene& s, int clip, double time, bool skinnedOnly) {
  Pose pose = Pose::rest(s.skeleton);
  if (clip >= 0 && clip < static_cast<int>(s.clips.size())) sampleClip(s.clips[clip], static_cast<float>(time), pose);
  const std::vector<glm::mat4> world = computeWorld(s.skeleton, pose);
  const std::vector<std::vector<float>> weights = sampleMorphWeights(s, clip, time);
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &s;
  job.world = &world;
  job.morphWeights = &weights;
  job.skinnedOnly = skinnedOnly;
  job.out = &out;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return out;
}

TEST(SceneDeformation, SkinnedVerticesMatchThreeJsReferences) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::regex pattern(R"((.+)\.clip(\d+)\.t([0-9.]+)\.skin\.json)");
  int files = 0, compared = 0;
  for (const auto& e : fs::directory_iterator(test::sharedDataDir() + "/reference")) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (!std::regex_match(name, m, pattern)) continue;
    ++files;
    Result<Scene> loaded = loadScene(findGltf(m[1]));
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const Scene& s = loaded.value();
    std::ifstream in(e.path());
    const nlohmann::json ref = nlohmann::json::parse(in);
    const std::vector<DeformedPrimitive> out = deform(s, std::stoi(m[2]), std::stod(m[3]), true);
    ASSERT_EQ(out.size(), ref["meshes"].size()) << name;
    for (size_t i = 0; i < out.size(); ++i) {
      const auto& rm = ref["meshes"][i];
      const MeshInstance& inst = s.meshInstances[out[i].instance];
      ASSERT_EQ(s.fileIndexOf(inst.joint), rm["node"].get<int>()) << name;
      ASSERT_EQ(inst.mesh, rm["mesh"].get<int>()) << name;
      ASSERT_EQ(out[i].primitive, rm["primitive"].get<int>()) << name;
      ASSERT_EQ(out[i].positions.size(), rm["positions"].size()) << name;
      double scale = 0.0;
      for (const auto& q : rm["positions"])
        for (double x : q) scale = std::max(scale, std::abs(x));
      for (size_t v = 0; v < out[i].positions.size(); ++v) {
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(out[i].positions[v][c], rm["positions"][v][c].get<double>(), 1e-4 * scale)
              << name << " vertex " << v;
        ++compared;
      }
      for (const glm::vec3& n : out[i].normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << name;
    }
  }
  EXPECT_GE(files, 6);
  EXPECT_GT(compared, 8000);
}

// Joints: 0 "Root" at (0, 0, 0), 1 "Bone" at (0, 1, 0) (child of Root), 2 "Body" (child of
// Root, translated to (10, 0, 0): the node that shows the skinned mesh) and 3 "Prop" at
// (0, 0, 5) showing an unskinned mesh. The skinned mesh is two vertices, one on each joint.
Scene handScene() {
  Scene s;
  s.skeleton.names = {"Root", "Bone", "Body", "Prop"};
  s.skeleton.parents = {-1, 0, 0, 0};
  s.skeleton.rest.resize(4);
  s.skeleton.rest[1].translation = {0, 1, 0};
  s.skeleton.rest[2].translation = {10, 0, 0};
  s.skeleton.rest[3].translation = {0, 0, 5};
  Mesh skinned;
  MeshPrimitive p;
  p.positions = {{1, 0, 0}, {1, 1, 0}};
  p.normals = {{1, 0, 0}, {1, 0, 0}};
  p.influenceJoints.assign(2 * kMaxInfluences, 0);
  p.influenceWeights.assign(2 * kMaxInfluences, 0.0f);
  p.influenceWeights[0] = 1.0f;  // vertex 0 on skin joint 0 (Root)
  p.influenceJoints[kMaxInfluences] = 1;
  p.influenceWeights[kMaxInfluences] = 1.0f;  // vertex 1 on skin joint 1 (Bone)
  skinned.primitives = {p};
  Mesh prop;
  MeshPrimitive q;
  q.positions = {{0, 0, 1}};
  q.normals = {{0, 1, 0}};
  prop.primitives = {q};
  s.meshes = {skinned, prop};
  Skin skin;
  skin.joints = {0, 1};
  skin.inverseBind = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, -1, 0))};
  s.skins = {skin};
  MeshInstance a;
  a.joint = 2;
  a.mesh = 0;
  a.skin = 0;
  MeshInstance b;
  b.joint = 3;
  b.mesh = 1;
  s.meshInstances = {a, b};
  return s;
}

std::vector<glm::mat4> bentWorld(const Scene& s) {
  Pose pose = Pose::rest(s.skeleton);
  pose.local[1].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));  // Bone turns a quarter about Z
  pose.local[3].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(1, 0, 0));  // Prop a quarter about X
  return computeWorld(s.skeleton, pose);
}

TEST(SceneDeformation, GltfSemanticsOnAHandBuiltScene) {
  const Scene s = handScene();
  const std::vector<glm::mat4> world = bentWorld(s);
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &s;
  job.world = &world;
  job.out = &out;
  ASSERT_TRUE(job.run());
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].instance, 0);
  EXPECT_EQ(out[0].primitive, 0);
  // Vertex 0 follows Root (identity): (1, 0, 0) — Body's (10, 0, 0) is ignored.
  EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(1, 0, 0), 1e-6f);
  // Vertex 1 is (1, 0, 0) from Bone's pivot (0, 1, 0); the quarter turn about Z takes that
  // offset to (0, 1, 0): (0, 2, 0). Its normal (1, 0, 0) turns to (0, 1, 0).
  EXPECT_VEC3_NEAR(out[0].positions[1], glm::vec3(0, 2, 0), 1e-6f);
  EXPECT_VEC3_NEAR(out[0].normals[1], glm::vec3(0, 1, 0), 1e-6f);
  // The prop follows its node: (0, 0, 5) + Rx(90) (0, 0, 1) = (0, -1, 5); normal (0,1,0) -> (0,0,1).
  EXPECT_EQ(out[1].instance, 1);
  EXPECT_VEC3_NEAR(out[1].positions[0], glm::vec3(0, -1, 5), 1e-6f);
  EXPECT_VEC3_NEAR(out[1].normals[0], glm::vec3(0, 0, 1), 1e-6f);

  // skinnedOnly: what `kinema skin` prints.
  job.skinnedOnly = true;
  ASSERT_TRUE(job.run());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].instance, 0);
}

// Each instance's method: a vertex half on Root, half on Bone turned 120 degrees about Y
// (Bone's axis through its pivot (0, 1, 0) is the Y axis). The vertex (1, 1, 0): Bone maps
// it to (cos120, 1, -sin120), so linear blend gives the midpoint ((1 + cos120)/2, 1,
// -sin120/2) = (0.25, 1, -0.433) (pulled towards the axis) while dual quaternions turn it by
// 60 degrees: (cos60, 1, -sin60).
TEST(SceneDeformation, DualQuaternionInstancesUseDualQuaternions) {
  Scene s = handScene();
  MeshPrimitive& p = s.meshes[0].primitives[0];
  p.positions = {{1, 1, 0}};
  p.normals.clear();
  p.influenceJoints.assign(kMaxInfluences, 0);
  p.influenceWeights.assign(kMaxInfluences, 0.0f);
  p.influenceJoints[1] = 1;
  p.influenceWeights[0] = p.influenceWeights[1] = 0.5f;
  Pose pose = Pose::rest(s.skeleton);
  pose.local[1].rotation = glm::angleAxis(glm::radians(120.0f), glm::vec3(0, 1, 0));
  const std::vector<glm::mat4> world = computeWorld(s.skeleton, pose);
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &s;
  job.world = &world;
  job.out = &out;
  job.skinnedOnly = true;
  ASSERT_TRUE(job.run());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].normals.empty());
  const float s60 = std::sqrt(3.0f) / 2;
  EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(0.25f, 1, -s60 / 2), 1e-6f);
  s.meshInstances[0].skinning = SkinningMethod::DualQuaternion;
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(0.5f, 1, -s60), 1e-6f);
}

TEST(SceneDeformation, ValidateNamesWhatIsWrong) {
  Scene s = handScene();
  std::vector<glm::mat4> world = bentWorld(s);
  std::vector<DeformedPrimitive> out(3);
  SceneDeformationJob job;
  EXPECT_NE(job.validate().find("scene"), std::string::npos);
  job.scene = &s;
  job.world = &world;
  job.out = &out;
  EXPECT_EQ(job.validate(), "");
  world.pop_back();
  EXPECT_NE(job.validate().find("3 transforms for 4 joints"), std::string::npos) << job.validate();
  world = bentWorld(s);
  world[2][0][0] = INFINITY;
  EXPECT_NE(job.validate().find("world transform 2 is not finite"), std::string::npos) << job.validate();
  world = bentWorld(s);
  std::vector<std::vector<float>> weights(1);
  job.morphWeights = &weights;
  EXPECT_NE(job.validate().find("morphWeights"), std::string::npos);
  job.morphWeights = nullptr;
  s.meshes[0].primitives[0].influenceJoints[kMaxInfluences] = 2;
  EXPECT_NE(job.validate().find("mesh instance 0: mesh 0 primitive 0: vertex 1 uses skin joint 2"), std::string::npos)
      << job.validate();
  EXPECT_FALSE(job.run());
  EXPECT_EQ(out.size(), 3u);  // untouched
  s = handScene();
  s.meshInstances[1].mesh = 5;
  EXPECT_NE(job.validate().find("mesh instance 1: mesh 5 does not exist"), std::string::npos) << job.validate();
}

}  // namespace
}  // namespace kinema
