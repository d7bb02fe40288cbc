// Deformer stacks in a scene (issue 22): evaluated after morph targets and skinning, their
// parameters animated by Scalar channels "deformers/NAME/PARAM", the shading normals
// following the deformed surface. Expected values are derived by hand in each test.
#include <gtest/gtest.h>

#include <cmath>

#include "anim/scalar_property.h"
#include "core/forward_kinematics.h"
#include "bake/bake_deformers.h"
#include "evaluation/scene_deformation.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// One joint at (0, 0.5, 0) showing an unskinned triangle with one morph target, so the
// instance moves rigidly by +0.5 in y.
Scene triangleScene() {
  Scene scene;
  scene.skeleton.addJoint("Root", -1, Transform::fromTranslation({0, 0.5f, 0}));
  Mesh mesh;
  MeshPrimitive prim;
  prim.positions = {{1, 0, 0}, {0, 0, 1}, {0, 0, 0}};
  prim.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  prim.indices = {0, 1, 2};
  MorphTarget up;
  up.positionDeltas = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  prim.targets.push_back(up);
  mesh.primitives.push_back(prim);
  mesh.morphWeights = {0.5f};
  scene.meshes.push_back(mesh);
  MeshInstance inst;
  inst.joint = 0;
  inst.mesh = 0;
  scene.meshInstances.push_back(inst);
  return scene;
}

// Taper along world Y over [0, 2]: the scale of x and z is 1 + (factor - 1) * y / 2.
Deformer taper(float factor) {
  Deformer d;
  d.name = "taper";
  d.type = DeformerType::Taper;
  d.axis.kind = AxisDeformerKind::Taper;
  d.axis.axis = DeformAxis::Y;
  d.axis.low = 0.0f;
  d.axis.high = 2.0f;
  d.axis.amount = factor;
  return d;
}

std::vector<DeformedPrimitive> deform(const Scene& scene, const std::vector<DeformerStack>* stacks = nullptr) {
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.deformers = stacks;
  job.out = &out;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return out;
}

TEST(SceneDeformers, MorphThenSkinThenDeformers) {
  Scene scene = triangleScene();
  scene.editDeformerStack(0).deformers.push_back(taper(3.0f));
  const std::vector<DeformedPrimitive> out = deform(scene);
  ASSERT_EQ(out.size(), 1u);
  // Vertex 0: (1,0,0) + 0.5 (0,1,0) morph = (1,0.5,0); + joint (0,0.5,0) = (1,1,0); the taper
  // at y = 1 scales x by 1 + 2 * 1/2 = 2: (2,1,0). Tapering before the joint's move would
  // give 1.5, before the morph 1.
  EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(2, 1, 0), 1e-6f);
  EXPECT_VEC3_NEAR(out[0].positions[1], glm::vec3(0, 1, 2), 1e-6f);
  EXPECT_VEC3_NEAR(out[0].positions[2], glm::vec3(0, 1, 0), 1e-6f);
  // The triangle stays flat at y = 1: its normal is still +-Y (area-weighted normals of
  // the deformed triangle, whose winding (x, z, 0) gives -Y).
  for (const glm::vec3& n : out[0].normals) EXPECT_VEC3_NEAR(glm::abs(n), glm::vec3(0, 1, 0), 1e-6f);
}

TEST(SceneDeformers, DisabledStackLeavesTheSkinnedMesh) {
  Scene scene = triangleScene();
  const std::vector<DeformedPrimitive> plain = deform(scene);
  Deformer d = taper(3.0f);
  d.enabled = false;
  scene.editDeformerStack(0).deformers.push_back(d);
  const std::vector<DeformedPrimitive> off = deform(scene);
  for (int v = 0; v < 3; ++v) {
    EXPECT_EQ(off[0].positions[v], plain[0].positions[v]);
    EXPECT_EQ(off[0].normals[v], plain[0].normals[v]);
  }
}

TEST(SceneDeformers, NormalsFollowTheDeformedSurface) {
  Scene scene = triangleScene();
  // A bend along X tilts the triangle: every corner's normal must be the deformed face's
  // normal (one triangle: the area weighting has nothing else to mix in).
  Deformer bend = taper(1.0f);
  bend.name = "bend";
  bend.type = DeformerType::Bend;
  bend.axis.kind = AxisDeformerKind::Bend;
  bend.axis.axis = DeformAxis::X;
  bend.axis.low = -1.0f;
  bend.axis.high = 1.0f;
  bend.axis.amount = 1.0f;
  scene.editDeformerStack(0).deformers.push_back(bend);
  const std::vector<DeformedPrimitive> out = deform(scene);
  const std::vector<glm::vec3>& p = out[0].positions;
  const glm::vec3 face = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
  for (const glm::vec3& n : out[0].normals) EXPECT_VEC3_NEAR(n, face, 1e-5f);
}

TEST(SceneDeformers, ChannelsAnimateParametersByName) {
  Scene scene = triangleScene();
  scene.editDeformerStack(0).deformers.push_back(taper(1.0f));
  Clip clip;
  clip.name = "pulse";
  Channel ch(0, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 1.0f}, {glm::vec4(1.0f), glm::vec4(3.0f)});
  ch.property = deformerParameterProperty("taper", "factor");
  clip.channels.push_back(ch);
  // A channel naming a deformer the stack does not have changes nothing.
  Channel other = ch;
  other.property = deformerParameterProperty("missing", "factor");
  clip.channels.push_back(other);
  scene.clips.push_back(clip);
  ASSERT_EQ(clip.validate(scene.skeleton), "");

  const std::vector<DeformerStack> atHalf = sampleDeformerStacks(scene, 0, 0.5);
  ASSERT_EQ(atHalf.size(), 1u);
  EXPECT_FLOAT_EQ(atHalf[0].deformers[0].axis.amount, 2.0f);  // linear half way from 1 to 3
  EXPECT_FLOAT_EQ(sampleDeformerStacks(scene, 0, 5.0)[0].deformers[0].axis.amount, 3.0f);  // clamped
  EXPECT_FLOAT_EQ(sampleDeformerStacks(scene, -1, 0.5)[0].deformers[0].axis.amount, 1.0f);  // no clip: as saved
  // Factor 2 at y = 1: scale 1 + (2 - 1) / 2 = 1.5.
  const std::vector<DeformedPrimitive> out = deform(scene, &atHalf);
  EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(1.5f, 1, 0), 1e-6f);
}

TEST(SceneDeformers, ScalarPropertyPaths) {
  ScalarProperty p = parseScalarProperty("weights/12");
  EXPECT_EQ(p.kind, ScalarPropertyKind::MorphWeight);
  EXPECT_EQ(p.morphTarget, 12);
  p = parseScalarProperty(deformerParameterProperty("Lattice", "point.3.y"));
  EXPECT_EQ(p.kind, ScalarPropertyKind::DeformerParameter);
  EXPECT_EQ(p.deformer, "Lattice");
  EXPECT_EQ(p.parameter, "point.3.y");
  for (const char* other : {"weights/", "weights/x", "deformers/", "deformers//angle", "deformers/a/", "deformers/a",
                            "twist", ""})
    EXPECT_EQ(parseScalarProperty(other).kind, ScalarPropertyKind::Other) << other;
  EXPECT_EQ(parseScalarProperty(morphWeightProperty(7)).morphTarget, 7);
}

TEST(SceneDeformers, InvalidStacksAreRefusedByTheJob) {
  Scene scene = triangleScene();
  Deformer a = taper(2.0f), b = taper(2.0f);
  scene.editDeformerStack(0).deformers = {a, b};
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.out = &out;
  EXPECT_EQ(job.validate(), "mesh instance 0: deformer 1 ('taper'): the name is used by deformer 0 too");
  scene.deformers[0].deformers.resize(1);
  scene.deformers[0].deformers[0].weights = {{0.5f, 0.5f}};
  EXPECT_EQ(job.validate(), "mesh instance 0: deformer 0 ('taper'): 2 weights for primitive 0's 3 vertices");
  // Weights blend: vertex 0 with weight 0.5 moves half way, from (1,1,0) towards (2,1,0).
  scene.deformers[0].deformers[0].weights = {{0.5f, 1.0f, 0.0f}};
  scene.deformers[0].deformers[0].axis.amount = 3.0f;
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(1.5f, 1, 0), 1e-6f);
  EXPECT_VEC3_NEAR(out[0].positions[1], glm::vec3(0, 1, 2), 1e-6f);
}

DeformerBakeReport bake(const Scene& scene, Scene& out) {
  DeformerBakeReport report;
  BakeDeformersJob job;
  job.scene = &scene;
  job.out = &out;
  job.report = &report;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return report;
}

TEST(BakeDeformers, StaticStackBecomesOneShapeAtFullWeight) {
  Scene scene = triangleScene();
  scene.editDeformerStack(0).deformers.push_back(taper(3.0f));
  Scene baked;
  const DeformerBakeReport report = bake(scene, baked);
  EXPECT_TRUE(baked.deformers.empty());
  EXPECT_EQ(report.targets, 1);
  const MeshPrimitive& prim = baked.meshes[0].primitives[0];
  ASSERT_EQ(prim.targets.size(), 2u);
  // The rigid joint only translates, so the bind-space delta is the world one: (2,1,0) - (1,1,0).
  EXPECT_VEC3_NEAR(prim.targets[1].positionDeltas[0], glm::vec3(1, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(prim.targets[1].positionDeltas[1], glm::vec3(0, 0, 1), 1e-6f);
  EXPECT_VEC3_NEAR(prim.targets[1].positionDeltas[2], glm::vec3(0, 0, 0), 1e-6f);
  EXPECT_EQ(baked.meshes[0].morphWeights, (std::vector<float>{0.5f, 1.0f}));
  EXPECT_EQ(baked.meshes[0].targetNames.back(), "deformers");
  EXPECT_LT(report.largestError, 1e-6);
}

// Twist keyed from 0 to pi over one second: at y = 1 (h/H = 1/2) the triangle turns by 0 and
// pi/2 at the keys. Between them the bake blends the two shapes linearly, so a point at
// distance r from the axis is off by r (1 - cos(pi/4)) half way, where the true point is on
// the arc and the baked one on the chord's midpoint.
TEST(BakeDeformers, AnimatedStackBecomesOneShapePerKey) {
  Scene scene = triangleScene();
  Deformer twist = taper(1.0f);
  twist.name = "twist";
  twist.type = DeformerType::Twist;
  twist.axis.kind = AxisDeformerKind::Twist;
  twist.axis.amount = 0.0f;
  scene.editDeformerStack(0).deformers.push_back(twist);
  Clip clip;
  clip.name = "turn";
  Channel ch(0, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 1.0f},
             {glm::vec4(0.0f), glm::vec4(static_cast<float>(M_PI))});
  ch.property = deformerParameterProperty("twist", "angle");
  clip.channels.push_back(ch);
  scene.clips.push_back(clip);

  Scene baked;
  const DeformerBakeReport report = bake(scene, baked);
  EXPECT_EQ(report.targets, 2);
  ASSERT_EQ(baked.meshes[0].primitives[0].targets.size(), 3u);
  EXPECT_EQ(baked.meshes[0].morphWeights, (std::vector<float>{0.5f, 0.0f, 0.0f}));
  // The deformer channel is gone; two weight channels: 1 at their own key, 0 at the other.
  ASSERT_EQ(baked.clips[0].channels.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const Channel& w = baked.clips[0].channels[k];
    EXPECT_EQ(w.property, morphWeightProperty(1 + k));
    EXPECT_EQ(w.times, (std::vector<float>{0.0f, 1.0f}));
    EXPECT_FLOAT_EQ(w.values[k].x, 1.0f);
    EXPECT_FLOAT_EQ(w.values[1 - k].x, 0.0f);
  }
  EXPECT_EQ(baked.clips[0].validate(baked.skeleton), "");
  EXPECT_NEAR(report.largestError, 1.0 - std::sqrt(0.5), 1e-5);
  EXPECT_EQ(report.errorClip, 0);
  EXPECT_NEAR(report.errorTime, 0.5, 1e-9);
  // The second shape is the quarter turn of the first: (1,1,0) goes to (0,1,-1).
  EXPECT_VEC3_NEAR(baked.meshes[0].primitives[0].targets[2].positionDeltas[0], glm::vec3(-1, 0, -1), 1e-6f);
}

}  // namespace
}  // namespace kinema
