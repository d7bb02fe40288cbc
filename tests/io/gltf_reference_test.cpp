// The glTF reader on the real files in ../shared/data/gltf: every file loads, every clip
// evaluates to finite world matrices, world matrices match three.js
// (../shared/data/reference, see its README), and single channels match values derived
// by tests/tools/gltf_channel_values.py (numpy, reading the files itself). Skips when
// ../shared/data is absent.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "io/gltf_reader.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

namespace fs = std::filesystem;
using test::sharedDataDir;

std::vector<std::string> gltfFiles() {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(sharedDataDir() + "/gltf")) {
    const std::string ext = e.path().extension().string();
    if (ext == ".gltf" || ext == ".glb") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

const Scene& loaded(const std::string& stem) {
  static std::map<std::string, Scene> cache;
  auto it = cache.find(stem);
  if (it == cache.end()) {
    std::string path;
    for (const std::string& f : gltfFiles())
      if (fs::path(f).stem() == stem) path = f;
    Result<Scene> r = loadGltf(path);
    EXPECT_TRUE(r.ok()) << r.error();
    it = cache.emplace(stem, r.ok() ? std::move(r).value() : Scene{}).first;
  }
  return it->second;
}

int jointOfNode(const Scene& s, int node) {
  for (int j = 0; j < static_cast<int>(s.nodeOfJoint.size()); ++j)
    if (s.nodeOfJoint[j] == node) return j;
  return -1;
}

std::vector<glm::mat4> worldAt(const Scene& s, int clip, float time) {
  Pose pose = Pose::rest(s.skeleton);
  if (clip < static_cast<int>(s.clips.size())) sampleClip(s.clips[clip], time, pose);
  return computeWorld(s.skeleton, pose);
}

const Channel* findChannel(const Scene& s, int clip, int node, ChannelTarget target, const std::string& property = "") {
  const int joint = jointOfNode(s, node);
  for (const Channel& c : s.clips.at(clip).channels)
    if (c.joint == joint && c.target == target && c.property == property) return &c;
  return nullptr;
}

TEST(GltfReference, EveryFileLoadsAndEvaluatesFinite) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::vector<std::string> files = gltfFiles();
  ASSERT_GE(files.size(), 7u);
  for (const std::string& f : files) {
    Result<Scene> r = loadGltf(f);
    ASSERT_TRUE(r.ok()) << r.error();
    const Scene& s = r.value();
    EXPECT_EQ(s.skeleton.validate(), "") << f;
    ASSERT_EQ(s.nodeOfJoint.size(), static_cast<size_t>(s.skeleton.size())) << f;
    std::vector<int> nodes = s.nodeOfJoint;  // a permutation of 0..n-1
    std::sort(nodes.begin(), nodes.end());
    for (int i = 0; i < static_cast<int>(nodes.size()); ++i) EXPECT_EQ(nodes[i], i) << f;
    EXPECT_FALSE(s.clips.empty()) << f;
    EXPECT_FALSE(s.meshes.empty()) << f;
    for (int c = 0; c < static_cast<int>(s.clips.size()); ++c) {
      EXPECT_EQ(s.clips[c].validate(s.skeleton), "") << f;
      const float d = s.clips[c].duration();
      for (float t : {-1.0f, 0.0f, 0.1f * d, 0.37f * d, 0.5f * d, 0.93f * d, d, d + 1.0f})
        for (const glm::mat4& m : worldAt(s, c, t))
          for (int k = 0; k < 16; ++k) ASSERT_TRUE(std::isfinite(m[k / 4][k % 4])) << f << " clip " << c << " t " << t;
    }
  }
}

TEST(GltfReference, WorldMatricesMatchThreeJs) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::regex pattern(R"((.+)\.clip(\d+)\.t([0-9.]+)\.pose\.json)");
  int compared = 0;
  for (const auto& e : fs::directory_iterator(sharedDataDir() + "/reference")) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (!std::regex_match(name, m, pattern)) continue;
    const Scene& s = loaded(m[1]);
    ASSERT_FALSE(s.skeleton.empty()) << name;
    std::ifstream in(e.path());
    const nlohmann::json ref = nlohmann::json::parse(in);
    const std::vector<glm::mat4> world = worldAt(s, std::stoi(m[2]), std::stof(m[3]));
    ASSERT_EQ(ref["joints"].size(), world.size()) << name;
    double scale = 1.0;  // three.js keeps floats: 1e-4 relative to the model's size
    for (const auto& j : ref["joints"])
      for (double x : j["world"]) scale = std::max(scale, std::abs(x));
    for (const auto& j : ref["joints"]) {
      const int joint = jointOfNode(s, j["node"]);
      ASSERT_GE(joint, 0) << name;
      for (int k = 0; k < 16; ++k)
        EXPECT_NEAR(world[joint][k / 4][k % 4], j["world"][k].get<double>(), 1e-4 * scale)
            << name << " node " << j["node"] << " element " << k;
      ++compared;
    }
  }
  EXPECT_GE(compared, 100);  // all 18 reference poses of the 7 files
}

// Values from: tests/tools/gltf_channel_values.py CesiumMan.glb 0 CHANNEL 0.25 0.5208333
// (channel 0 = node 3 translation, 1 = node 3 rotation, both LINEAR; keys every 1/24 s,
// 0.25 is key 5, 0.5208333 midway between the keys at 0.5 and 0.541666).
TEST(GltfReference, CesiumManLinearChannelsAtKeysAndMidpoints) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Scene& s = loaded("CesiumMan");
  const Channel* move = findChannel(s, 0, 3, ChannelTarget::Translation);
  const Channel* turn = findChannel(s, 0, 3, ChannelTarget::Rotation);
  ASSERT_TRUE(move && turn);
  EXPECT_EQ(move->interpolation, Interpolation::Linear);
  EXPECT_EQ(turn->keyCount(), 48);
  EXPECT_VEC3_NEAR(glm::vec3(sampleChannel(*move, 0.25f)), glm::vec3(2.98417007e-08f, -0.0200001206f, 0.695000231f), 1e-6f);
  EXPECT_VEC3_NEAR(glm::vec3(sampleChannel(*move, 0.5208333f)), glm::vec3(2.94742525e-08f, -0.022809719f, 0.674914157f),
                   1e-6f);
  const glm::vec4 atKey = sampleChannel(*turn, 0.25f), between = sampleChannel(*turn, 0.5208333f);
  EXPECT_SAME_ROTATION(glm::quat(atKey.w, atKey.x, atKey.y, atKey.z),
                       glm::quat(-0.999560058f, -0.00501359859f, -0.0292298608f, -0.000480920571f), 1e-6f);
  EXPECT_SAME_ROTATION(glm::quat(between.w, between.x, between.y, between.z),
                       glm::quat(-0.999697699f, -0.0116599186f, -0.0215826762f, -0.00165658951f), 1e-6f);
  // The pose uses them: node 3's local transform at the midpoint.
  Pose pose = Pose::rest(s.skeleton);
  sampleClip(s.clips[0], 0.5208333f, pose);
  EXPECT_VEC3_NEAR(pose.local[jointOfNode(s, 3)].translation, glm::vec3(2.94742525e-08f, -0.022809719f, 0.674914157f), 1e-6f);
}

// RiggedSimple's STEP channels (gltf_channel_values.py RiggedSimple.glb 0 0/1: node 3,
// two keys at 0 and 6.6666665 s) hold their first key until the second.
TEST(GltfReference, RiggedSimpleStepChannelsHold) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Scene& s = loaded("RiggedSimple");
  const Channel* turn = findChannel(s, 0, 3, ChannelTarget::Rotation);
  const Channel* linear = findChannel(s, 0, 2, ChannelTarget::Rotation);
  ASSERT_TRUE(turn && linear);
  EXPECT_EQ(turn->interpolation, Interpolation::Step);
  EXPECT_EQ(linear->interpolation, Interpolation::Linear);
  const glm::vec4 q = sampleChannel(*turn, 3.0f);
  EXPECT_SAME_ROTATION(glm::quat(q.w, q.x, q.y, q.z), glm::quat(1.0f, -9.15739573e-09f, 2.42032421e-08f, 0.0f), 1e-6f);
  // Node 2 rotation (LINEAR, 161 keys) at t = 0.5: -0.160850063 0 0 0.986978889.
  const glm::vec4 r = sampleChannel(*linear, 0.5f);
  EXPECT_SAME_ROTATION(glm::quat(r.w, r.x, r.y, r.z), glm::quat(0.986978889f, -0.160850063f, 0.0f, 0.0f), 1e-5f);
}

// BoxAnimated (gltf_channel_values.py BoxAnimated.gltf 0 0/1): node 2 turns from
// (0,0,0,-1) at 1.25 s to (1,0,0,0) at 2.5 s; node 0 rises to y = 2.52 at 1.25 s.
TEST(GltfReference, BoxAnimatedNodesAtKeyTimes) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Scene& s = loaded("BoxAnimated");
  Pose pose = Pose::rest(s.skeleton);
  sampleClip(s.clips[0], 2.5f, pose);
  EXPECT_SAME_ROTATION(pose.local[jointOfNode(s, 2)].rotation, glm::quat(0.0f, 1.0f, 0.0f, 0.0f), 1e-6f);
  EXPECT_VEC3_NEAR(pose.local[jointOfNode(s, 0)].translation, glm::vec3(0.0f, 2.52f, 0.0f), 1e-6f);
  sampleClip(s.clips[0], 1.25f, pose);
  EXPECT_SAME_ROTATION(pose.local[jointOfNode(s, 2)].rotation, glm::quat(1.0f, 0.0f, 0.0f, 0.0f), 1e-6f);
  EXPECT_VEC3_NEAR(pose.local[jointOfNode(s, 0)].translation, glm::vec3(0.0f, 2.52f, 0.0f), 1e-6f);
  // Midway in time (1.5 s, u = 0.2): the script's slerp gives -0.309016994 0 0 -0.951056516.
  sampleClip(s.clips[0], 1.5f, pose);
  EXPECT_SAME_ROTATION(pose.local[jointOfNode(s, 2)].rotation, glm::quat(-0.951056516f, -0.309016994f, 0.0f, 0.0f), 1e-5f);
}

// AnimatedMorphCube's "weights" channel (gltf_channel_values.py AnimatedMorphCube.gltf 0 0
// 0.5 1.0; 127 LINEAR keys, two targets) as two Scalar channels "weights/0" and "weights/1".
TEST(GltfReference, AnimatedMorphCubeWeights) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Scene& s = loaded("AnimatedMorphCube");
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(s.meshes[0].morphWeights.size(), 2u);
  ASSERT_EQ(s.meshes[0].primitives[0].targets.size(), 2u);
  const Channel* w0 = findChannel(s, 0, 0, ChannelTarget::Scalar, "weights/0");
  const Channel* w1 = findChannel(s, 0, 0, ChannelTarget::Scalar, "weights/1");
  ASSERT_TRUE(w0 && w1);
  EXPECT_EQ(w0->keyCount(), 127);
  EXPECT_NEAR(sampleChannel(*w0, 0.0f).x, 0.0f, 1e-7f);
  EXPECT_NEAR(sampleChannel(*w0, 0.0333333351f).x, 0.00128399895f, 1e-6f);  // key 1
  EXPECT_NEAR(sampleChannel(*w0, 0.5f).x, 0.231933579f, 1e-6f);
  EXPECT_NEAR(sampleChannel(*w0, 1.0f).x, 0.683593671f, 1e-6f);
  EXPECT_NEAR(sampleChannel(*w1, 1.0f).x, 0.0f, 1e-7f);
}

TEST(GltfReference, SkinsAndMeshesOfCesiumMan) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Scene& s = loaded("CesiumMan");
  ASSERT_EQ(s.skins.size(), 1u);
  EXPECT_EQ(s.skins[0].joints.size(), 19u);
  ASSERT_EQ(s.meshInstances.size(), 1u);
  EXPECT_EQ(s.meshInstances[0].skin, 0);
  const MeshPrimitive& p = s.meshes[0].primitives[0];
  EXPECT_TRUE(p.skinned());
  EXPECT_EQ(p.influenceWeights.size(), static_cast<size_t>(p.vertexCount()) * kMaxInfluences);
  EXPECT_EQ(p.indices.size() % 3, 0u);
  for (int v = 0; v < p.vertexCount(); ++v) {
    float sum = 0;
    for (int k = 0; k < kMaxInfluences; ++k) {
      sum += p.influenceWeights[v * kMaxInfluences + k];
      if (k > 0) {
        EXPECT_LE(p.influenceWeights[v * kMaxInfluences + k], p.influenceWeights[v * kMaxInfluences + k - 1]);
      }
      EXPECT_LT(p.influenceJoints[v * kMaxInfluences + k], 19);
    }
    ASSERT_NEAR(sum, 1.0f, 1e-5f) << "vertex " << v;
  }
  ASSERT_EQ(s.materials.size(), 1u);
  ASSERT_GE(s.materials[0].baseColorImage, 0);
  const TextureImage& image = s.images[s.materials[0].baseColorImage];
  EXPECT_GT(image.width, 0);
  EXPECT_EQ(image.rgba.size(), static_cast<size_t>(image.width) * image.height * 4);
}

// The imported skins and influences, put through glTF's skinning formula here
// (v = sum w_i * world(joint_i) * IBM_i * v_bind), land where three.js puts the vertices
// (the *.skin.json references): checks joint remapping, inverse bind matrices and the
// 8-influence weights together.
TEST(GltfReference, SkinnedVerticesMatchThreeJs) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::regex pattern(R"((.+)\.clip(\d+)\.t([0-9.]+)\.skin\.json)");
  int compared = 0;
  for (const auto& e : fs::directory_iterator(sharedDataDir() + "/reference")) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (!std::regex_match(name, m, pattern)) continue;
    const Scene& s = loaded(m[1]);
    std::ifstream in(e.path());
    const nlohmann::json ref = nlohmann::json::parse(in);
    const std::vector<glm::mat4> world = worldAt(s, std::stoi(m[2]), std::stof(m[3]));
    for (const auto& rm : ref["meshes"]) {
      const int joint = jointOfNode(s, rm["node"]);
      const MeshInstance* inst = nullptr;
      for (const MeshInstance& i : s.meshInstances)
        if (i.joint == joint && i.mesh == rm["mesh"].get<int>()) inst = &i;
      ASSERT_TRUE(inst && inst->skin >= 0) << name;
      const Skin& skin = s.skins[inst->skin];
      const MeshPrimitive& p = s.meshes[inst->mesh].primitives.at(rm["primitive"].get<int>());
      ASSERT_EQ(rm["positions"].size(), static_cast<size_t>(p.vertexCount())) << name;
      double scale = 1.0;
      for (const auto& q : rm["positions"])
        for (double x : q) scale = std::max(scale, std::abs(x));
      for (int v = 0; v < p.vertexCount(); ++v) {
        glm::vec4 sum(0.0f);
        for (int k = 0; k < kMaxInfluences; ++k) {
          const float w = p.influenceWeights[v * kMaxInfluences + k];
          const int j = p.influenceJoints[v * kMaxInfluences + k];
          sum += w * (world[skin.joints[j]] * skin.inverseBind[j] * glm::vec4(p.positions[v], 1.0f));
        }
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(sum[c], rm["positions"][v][c].get<double>(), 1e-4 * scale) << name << " vertex " << v;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace kinema
