// Shape sliders (issue 22): the default character's face shapes set by hand (one undo step
// each) and keyed as "weights/K" channels whose value half way between two keys is the
// interpolated weight.
#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/shape_keys.h"
#include "core/forward_kinematics.h"
#include "scene/default_character_scene.h"
#include "evaluation/scene_deformation.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(ShapeKeys, TheDefaultCharacterHasNamedShapes) {
  Document doc(makeDefaultCharacterScene());
  ASSERT_EQ(shapeCount(doc, 0), 4);
  EXPECT_EQ(shapeName(doc, 0, 1), "smile");
  EXPECT_EQ(shapeCount(doc, 1), 0);  // no such instance
  EXPECT_EQ(shapeWeightAt(doc, -1, 0.0, 0, 1), 0.0f);
}

TEST(ShapeKeys, SettingAWeightIsOneUndoStep) {
  Document doc(makeDefaultCharacterScene());
  ASSERT_EQ(setShapeWeight(doc, 0, 2, 0.75f), "");
  EXPECT_EQ(shapeWeightAt(doc, -1, 0.0, 0, 2), 0.75f);
  EXPECT_EQ(doc.scene().meshInstances[0].morphWeights, (std::vector<float>{0, 0, 0.75f, 0}));
  doc.undo();
  EXPECT_EQ(shapeWeightAt(doc, -1, 0.0, 0, 2), 0.0f);
  EXPECT_NE(setShapeWeight(doc, 0, 9, 1.0f), "");
  EXPECT_NE(setShapeWeight(doc, 0, 1, std::nanf("")), "");
}

TEST(ShapeKeys, KeyedTwiceTheWeightIsInterpolatedBetween) {
  Document doc(makeDefaultCharacterScene());
  int clip = -1;
  KeyPreferences linear;
  linear.interpolation = Interpolation::Linear;
  ASSERT_EQ(keyShapeWeight(doc, clip, 0, 1, 0.0f, 0.0f, linear), "");
  ASSERT_EQ(clip, 0);  // "Action" made by the first key
  ASSERT_EQ(keyShapeWeight(doc, clip, 0, 1, 1.0f, 0.8f, linear), "");
  const Clip& c = doc.scene().clips[0];
  ASSERT_EQ(c.channels.size(), 1u);
  EXPECT_EQ(c.channels[0].property, "weights/1");
  EXPECT_EQ(c.channels[0].target, ChannelTarget::Scalar);
  EXPECT_EQ(c.channels[0].joint, doc.scene().meshInstances[0].joint);
  EXPECT_TRUE(shapeAnimated(doc, 0, 0, 1));
  EXPECT_FALSE(shapeAnimated(doc, 0, 0, 2));
  EXPECT_NEAR(shapeWeightAt(doc, 0, 0.5, 0, 1), 0.4f, 1e-6f);  // linear: half of 0.8
  EXPECT_NEAR(shapeWeightAt(doc, 0, 0.25, 0, 1), 0.2f, 1e-6f);
  // Each key is one undo step.
  doc.undo();
  EXPECT_EQ(doc.scene().clips[0].channels[0].times.size(), 1u);
}

std::vector<glm::vec3> restPositions(const Scene& scene) {
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.out = &out;
  EXPECT_TRUE(job.run()) << job.validate();
  return out.at(0).positions;
}

TEST(ShapeKeys, ApplyDeformerAsShapeReproducesItAtFullWeight) {
  Document doc(makeDefaultCharacterScene());
  Deformer twist;
  twist.name = "twist";
  twist.type = DeformerType::Twist;
  twist.axis.kind = AxisDeformerKind::Twist;
  twist.axis.low = 1.0f;
  twist.axis.high = 1.6f;
  twist.axis.amount = 0.6f;
  ASSERT_EQ(doc.editMeshes("Add twist", [&](Scene& s) {
    s.editDeformerStack(0).deformers.push_back(twist);
    return std::string();
  }), "");
  const std::vector<glm::vec3> twisted = restPositions(doc.scene());
  ASSERT_EQ(applyDeformerAsShape(doc, 0, 0), "");
  EXPECT_TRUE(doc.scene().deformers[0].empty());
  ASSERT_EQ(shapeCount(doc, 0), 5);
  EXPECT_EQ(shapeName(doc, 0, 4), "twist");
  EXPECT_EQ(shapeWeightAt(doc, -1, 0.0, 0, 4), 0.0f);  // Blender: the new shape starts at 0
  ASSERT_EQ(setShapeWeight(doc, 0, 4, 1.0f), "");
  const std::vector<glm::vec3> shaped = restPositions(doc.scene());
  ASSERT_EQ(shaped.size(), twisted.size());
  float worst = 0.0f;
  for (size_t v = 0; v < shaped.size(); ++v) worst = std::max(worst, glm::length(shaped[v] - twisted[v]));
  EXPECT_LT(worst, 1e-5f);
  // One step each: undoing the weight and the apply brings the deformer back.
  doc.undo();
  doc.undo();
  ASSERT_NE(doc.scene().deformerStack(0), nullptr);
  EXPECT_EQ(shapeCount(doc, 0), 4);
}

}  // namespace
}  // namespace kinema
