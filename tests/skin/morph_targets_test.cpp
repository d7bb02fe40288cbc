// MorphTargetsJob on hand-made primitives, and morph weights sampled from the Khronos
// samples (SimpleMorph, AnimatedMorphCube) deformed through SceneDeformationJob; expected
// values come from the files' keys by hand or from tests/tools/morph_values.py (numpy).
#include "skin/morph_targets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/forward_kinematics.h"
#include "io/scene_files.h"
#include "evaluation/scene_deformation.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

MeshPrimitive twoTargetTriangle() {
  MeshPrimitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  MorphTarget a, b;
  a.positionDeltas = {{0, 0, 1}, {0, 0, 0}, {0, 0, 0}};
  a.normalDeltas = {{1, 0, 0}, {0, 0, 0}, {0, 0, -1}};
  b.positionDeltas = {{0, 0, 0}, {2, 0, 0}, {0, 0, 0}};
  p.targets = {a, b};
  return p;
}

// p = bind + 0.5 * a + 0.25 * b; normals likewise, renormalised.
TEST(MorphTargets, AddsWeightedDeltas) {
  const MeshPrimitive prim = twoTargetTriangle();
  const float weights[] = {0.5f, 0.25f};
  std::vector<glm::vec3> pos, nrm;
  MorphTargetsJob job;
  job.primitive = &prim;
  job.weights = weights;
  job.weightCount = 2;
  job.outPositions = &pos;
  job.outNormals = &nrm;
  ASSERT_EQ(job.validate(), "");
  ASSERT_TRUE(job.run());
  ASSERT_EQ(pos.size(), 3u);
  EXPECT_VEC3_NEAR(pos[0], glm::vec3(0, 0, 0.5f), 1e-7f);
  EXPECT_VEC3_NEAR(pos[1], glm::vec3(1.5f, 0, 0), 1e-7f);
  EXPECT_VEC3_NEAR(pos[2], glm::vec3(0, 1, 0), 1e-7f);
  // (0,0,1) + 0.5 (1,0,0) = (0.5, 0, 1) -> /sqrt(1.25)
  EXPECT_VEC3_NEAR(nrm[0], glm::vec3(0.5f, 0, 1) / std::sqrt(1.25f), 1e-6f);
  EXPECT_VEC3_NEAR(nrm[1], glm::vec3(0, 0, 1), 1e-7f);
  // (0,0,1) + 0.5 (0,0,-1) = (0,0,0.5) -> (0,0,1)
  EXPECT_VEC3_NEAR(nrm[2], glm::vec3(0, 0, 1), 1e-7f);
}

// glTF: weights past the target count are ignored, missing ones count as 0.
TEST(MorphTargets, ExtraWeightsIgnoredMissingWeightsZero) {
  const MeshPrimitive prim = twoTargetTriangle();
  std::vector<glm::vec3> pos;
  MorphTargetsJob job;
  job.primitive = &prim;
  job.outPositions = &pos;
  const float one[] = {1.0f};
  job.weights = one;
  job.weightCount = 1;
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(pos[0], glm::vec3(0, 0, 1), 1e-7f);
  EXPECT_VEC3_NEAR(pos[1], glm::vec3(1, 0, 0), 1e-7f);
  const float many[] = {0.0f, 1.0f, 5.0f, 7.0f};
  job.weights = many;
  job.weightCount = 4;
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(pos[0], glm::vec3(0, 0, 0), 1e-7f);
  EXPECT_VEC3_NEAR(pos[1], glm::vec3(3, 0, 0), 1e-7f);
  job.weightCount = 0;
  job.weights = nullptr;
  ASSERT_TRUE(job.run());
  EXPECT_EQ(pos, prim.positions);
}

TEST(MorphTargets, ValidateNamesWhatIsWrong) {
  MeshPrimitive prim = twoTargetTriangle();
  std::vector<glm::vec3> pos = {{9, 9, 9}};
  const float weights[] = {1.0f, std::nanf("")};
  MorphTargetsJob job;
  EXPECT_NE(job.validate().find("primitive"), std::string::npos);
  job.primitive = &prim;
  EXPECT_NE(job.validate().find("outPositions"), std::string::npos);
  job.outPositions = &pos;
  job.weightCount = 2;
  EXPECT_NE(job.validate().find("weights is null"), std::string::npos);
  job.weights = weights;
  EXPECT_NE(job.validate().find("morph weight 1 is not finite"), std::string::npos);
  job.weightCount = 1;
  EXPECT_EQ(job.validate(), "");
  prim.targets[1].positionDeltas.pop_back();
  EXPECT_NE(job.validate().find("morph target 1"), std::string::npos);
  EXPECT_FALSE(job.run());
  EXPECT_EQ(pos.size(), 1u);  // untouched
}

Scene loadShared(const std::string& relative) {
  Result<Scene> r = loadScene(test::sharedDataDir() + "/gltf/" + relative);
  EXPECT_TRUE(r.ok()) << r.error();
  return r.ok() ? std::move(r).value() : Scene{};
}

std::vector<DeformedPrimitive> deformAt(const Scene& s, int clip, double time) {
  Pose pose = Pose::rest(s.skeleton);
  if (clip >= 0 && clip < static_cast<int>(s.clips.size())) sampleClip(s.clips[clip], static_cast<float>(time), pose);
  const std::vector<glm::mat4> world = computeWorld(s.skeleton, pose);
  const std::vector<std::vector<float>> weights = sampleMorphWeights(s, clip, time);
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &s;
  job.world = &world;
  job.morphWeights = &weights;
  job.out = &out;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return out;
}

// SimpleMorph: weights keys (t: w0, w1) 0: (0,0), 1: (0,1), 2: (1,1), 3: (1,0), 4: (0,0),
// LINEAR; mesh defaults (0.5, 0.5). Vertex 2 is (0.5, 0.5, 0) with deltas (-1, 1, 0) and
// (1, 1, 0); the node has no transform.
//   t = 1.5: w = (0.5, 1)  -> (0.5 - 0.5 + 1, 0.5 + 0.5 + 1) = (1, 2, 0)
//   t = 2.5: w = (1, 0.5)  -> (0.5 - 1 + 0.5, 0.5 + 1 + 0.5) = (0, 2, 0)
//   no clip: w = (0.5, 0.5) -> (0.5, 1.5, 0)
//   t = 9 (past the end) holds the last key (0, 0): the bind position.
TEST(MorphTargets, SimpleMorphWeightsFromTheClip) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Scene s = loadShared("SimpleMorph/SimpleMorph.gltf");
  ASSERT_EQ(s.meshInstances.size(), 1u);
  const std::vector<std::vector<float>> w = sampleMorphWeights(s, 0, 1.5);
  ASSERT_EQ(w.size(), 1u);
  ASSERT_EQ(w[0].size(), 2u);
  EXPECT_NEAR(w[0][0], 0.5f, 1e-6f);
  EXPECT_NEAR(w[0][1], 1.0f, 1e-6f);
  struct Case {
    int clip;
    double time;
    glm::vec3 vertex2;
  };
  for (const Case& c : {Case{0, 1.5, {1, 2, 0}}, Case{0, 2.5, {0, 2, 0}}, Case{-1, 0.0, {0.5f, 1.5f, 0}},
                        Case{0, 9.0, {0.5f, 0.5f, 0}}, Case{0, -1.0, {0.5f, 0.5f, 0}}}) {
    const std::vector<DeformedPrimitive> out = deformAt(s, c.clip, c.time);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_VEC3_NEAR(out[0].positions[2], c.vertex2, 1e-6f);
    EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(0, 0, 0), 1e-6f);  // no deltas
  }
}

// AnimatedMorphCube (node: rotation, scale 100; two targets, 127 LINEAR keys). From
//   tests/tools/morph_values.py AnimatedMorphCube.gltf 0 1.05 2 5 6   and ... 0 2.1 2 5 6
TEST(MorphTargets, AnimatedMorphCubeMatchesNumpy) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Scene s = loadShared("AnimatedMorphCube/AnimatedMorphCube.gltf");
  struct Case {
    double time;
    float w0, w1;
    glm::vec3 v2, v5, v6;
  };
  const Case cases[] = {
      {1.05, 0.726643807f, 0.0f, {-1.00000007f, -1.00000003f, -0.375720682f}, {0.999999326f, 0.999999925f, -0.375720084f},
       {-1.00000035f, 0.999999925f, -0.375721151f}},
      {2.1, 0.723307311f, 0.27669266f, {-1.00000007f, -1.00000003f, -0.36940385f}, {0.999999326f, 0.999999848f, -0.919768071f},
       {-1.00000035f, 0.999999848f, -0.919769137f}},
  };
  for (const Case& c : cases) {
    const std::vector<std::vector<float>> w = sampleMorphWeights(s, 0, c.time);
    ASSERT_EQ(w.size(), 1u);
    ASSERT_EQ(w[0].size(), 2u);
    EXPECT_NEAR(w[0][0], c.w0, 1e-6f) << c.time;
    EXPECT_NEAR(w[0][1], c.w1, 1e-6f) << c.time;
    const std::vector<DeformedPrimitive> out = deformAt(s, 0, c.time);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_VEC3_NEAR(out[0].positions[2], c.v2, 1e-5f);
    EXPECT_VEC3_NEAR(out[0].positions[5], c.v5, 1e-5f);
    EXPECT_VEC3_NEAR(out[0].positions[6], c.v6, 1e-5f);
    ASSERT_EQ(out[0].normals.size(), out[0].positions.size());
    for (const glm::vec3& n : out[0].normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  }
}

}  // namespace
}  // namespace kinema
