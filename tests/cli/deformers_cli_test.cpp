// `kinema convert --bake-deformers` and glTF export of a scene with deformers (issue 22):
// the baked file plays the deformation as morph targets, the report names the largest
// error, and without the flag the dropped stack is one warning.
#include <gtest/gtest.h>

#include "anim/scalar_property.h"
#include "core/forward_kinematics.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "scene/default_character_scene.h"
#include "evaluation/scene_deformation.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

class DeformersCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = makeTempDir();
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  int kinema(const std::string& args) { return runCommand(std::string(KINEMA_BINARY) + " " + args, &out_, &err_); }
  std::string dir_, out_, err_;
};

// The default character with a taper of its upper body keyed from 1 to 1.5 over one second.
// A taper is linear in its factor, so blending the shapes at the two keys is exact in between.
Scene taperedCharacter() {
  Scene scene = makeDefaultCharacterScene();
  Deformer d;
  d.name = "chest";
  d.type = DeformerType::Taper;
  d.axis.kind = AxisDeformerKind::Taper;
  d.axis.axis = DeformAxis::Y;
  d.axis.origin = glm::vec3(0, 1.0f, 0);
  d.axis.low = 0.0f;
  d.axis.high = 0.5f;
  d.axis.amount = 1.0f;
  scene.editDeformerStack(0).deformers.push_back(d);
  Clip clip;
  clip.name = "breathe";
  Channel ch(scene.meshInstances[0].joint, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 1.0f},
             {glm::vec4(1.0f), glm::vec4(1.5f)});
  ch.property = deformerParameterProperty("chest", "factor");
  clip.channels.push_back(ch);
  scene.clips.push_back(clip);
  return scene;
}

std::vector<glm::vec3> positionsAt(const Scene& scene, double time) {
  Pose pose = Pose::rest(scene.skeleton);
  if (!scene.clips.empty()) sampleClip(scene.clips[0], static_cast<float>(time), pose);
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, pose);
  const std::vector<std::vector<float>> weights = sampleMorphWeights(scene, scene.clips.empty() ? -1 : 0, time);
  const std::vector<DeformerStack> stacks = sampleDeformerStacks(scene, scene.clips.empty() ? -1 : 0, time);
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.morphWeights = &weights;
  job.deformers = &stacks;
  job.out = &out;
  EXPECT_TRUE(job.run()) << job.validate();
  return out.empty() ? std::vector<glm::vec3>{} : out[0].positions;
}

TEST_F(DeformersCli, BakedGltfPlaysTheDeformationAsMorphTargets) {
  const Scene scene = taperedCharacter();
  const std::string in = dir_ + "/tapered.kinema";
  ASSERT_EQ(saveKinemaFile(in, scene), "");
  ASSERT_EQ(kinema("convert '" + in + "' '" + dir_ + "/baked.gltf' --bake-deformers"), 0) << err_;
  EXPECT_NE(err_.find("kinema convert: baked deformers: 2 morph target(s), largest error "), std::string::npos) << err_;
  EXPECT_EQ(err_.find("dropped"), std::string::npos) << err_;
  EXPECT_EQ(out_, "");

  Result<Scene> baked = loadScene(dir_ + "/baked.gltf");
  ASSERT_TRUE(baked) << baked.error();
  EXPECT_TRUE(baked->deformers.empty());
  ASSERT_EQ(baked->meshes.size(), 1u);
  // The face's four shapes, then one baked shape per key.
  EXPECT_EQ(baked->meshes[0].primitives[0].targets.size(), scene.meshes[0].primitives[0].targets.size() + 2);
  // At the keys and half way the glTF's morphed mesh is where the deformers put the body.
  for (double t : {0.0, 0.5, 1.0}) {
    const std::vector<glm::vec3> want = positionsAt(scene, t), got = positionsAt(baked.value(), t);
    ASSERT_EQ(want.size(), got.size());
    float worst = 0.0f;
    for (size_t v = 0; v < want.size(); ++v) worst = std::max(worst, glm::length(want[v] - got[v]));
    EXPECT_LT(worst, 1e-5f) << "t = " << t;
  }
}

TEST_F(DeformersCli, WithoutTheFlagTheStackIsReportedDropped) {
  const std::string in = dir_ + "/tapered.kinema";
  ASSERT_EQ(saveKinemaFile(in, taperedCharacter()), "");
  ASSERT_EQ(kinema("convert '" + in + "' '" + dir_ + "/plain.glb'"), 0) << err_;
  EXPECT_NE(err_.find("kinema convert: warning: mesh instance 0 (joint 'Hips'): 1 deformer(s) dropped (glTF has no "
                      "deformers; kinema convert --bake-deformers writes them as morph targets)"),
            std::string::npos)
      << err_;
  EXPECT_NE(err_.find("scalar channel 'deformers/chest/factor' dropped"), std::string::npos) << err_;
}

}  // namespace
}  // namespace kinema::test
