// The deformer stack: order, enabling, vertex-group weights, joint parenting, keyable
// parameters, and "apply as shape" reproducing the deformation through MorphTargetsJob.
#include "deform/deformer_stack.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "skin/morph_targets.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Deformer twist(float angle) {
  Deformer d;
  d.name = "twist";
  d.type = DeformerType::Twist;
  d.axis.kind = AxisDeformerKind::Twist;
  d.axis.axis = DeformAxis::Y;
  d.axis.low = 0.0f;
  d.axis.high = 1.0f;
  d.axis.amount = angle;
  return d;
}

Deformer taper(float factor) {
  Deformer d = twist(0.0f);
  d.name = "taper";
  d.type = DeformerType::Taper;
  d.axis.kind = AxisDeformerKind::Taper;
  d.axis.amount = factor;
  return d;
}

std::vector<glm::vec3> run(const DeformerStack& stack, std::vector<glm::vec3> pts,
                           const std::vector<glm::mat4>* world = nullptr, int primitive = 0) {
  DeformerStackJob job;
  job.stack = &stack;
  job.positions = pts.data();
  job.count = static_cast<int>(pts.size());
  job.outPositions = pts.data();
  job.world = world;
  job.primitive = primitive;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return pts;
}

TEST(DeformerStack, AppliesInOrderSkipsDisabledAndBlendsByWeights) {
  const std::vector<glm::vec3> pts = {{1, 1, 0}, {0.5f, 0.5f, 0.5f}, {0, 0, 1}};
  DeformerStack stack;
  stack.deformers = {twist(1.0f), taper(0.5f)};
  const std::vector<glm::vec3> both = run(stack, pts);
  // By hand: the point (1, 1, 0) at the top is turned by 1 rad about +Y then scaled by 0.5.
  const float c = std::cos(1.0f), s = std::sin(1.0f);
  // Twist: (z, x) = (0, 1) turns to (-sin 1, cos 1); taper halves both.
  EXPECT_VEC3_NEAR(both[0], glm::vec3(0.5f * c, 1.0f, -0.5f * s), 1e-6f);
  // Disabled: only the taper.
  stack.deformers[0].enabled = false;
  const std::vector<glm::vec3> taperOnly = run(stack, pts);
  EXPECT_VEC3_NEAR(taperOnly[0], glm::vec3(0.5f, 1.0f, 0.0f), 1e-6f);
  // A vertex group at 0 / 0.5 / 1 on primitive 1 (primitive 0 keeps full effect).
  stack.deformers[1].weights = {{}, {0.0f, 0.5f, 1.0f}};
  const std::vector<glm::vec3> grouped = run(stack, pts, nullptr, 1);
  EXPECT_VEC3_NEAR(grouped[0], pts[0], 1e-7f);
  // (0.5, 0.5, 0.5) tapers to scale 0.75: halfway there is scale 0.875.
  EXPECT_VEC3_NEAR(grouped[1], glm::vec3(0.4375f, 0.5f, 0.4375f), 1e-6f);
  EXPECT_VEC3_NEAR(grouped[2], pts[2], 1e-7f);  // at height 0 the taper is 1
  // Order matters for non-commuting deformers: bend then taper differs from taper then bend.
  Deformer bend = twist(0.0f);
  bend.type = DeformerType::Bend;
  bend.axis.kind = AxisDeformerKind::Bend;
  bend.axis.amount = 1.2f;
  DeformerStack a, b;
  a.deformers = {bend, taper(0.5f)};
  b.deformers = {taper(0.5f), bend};
  const glm::vec3 p(0.3f, 0.8f, 0.2f);
  EXPECT_GT(glm::length(run(a, {p})[0] - run(b, {p})[0]), 1e-3f);
}

TEST(DeformerStack, AParentedDeformerFollowsItsJoint) {
  Deformer d = twist(0.8f);
  d.parentJoint = 1;
  d.parentRest = glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 0));
  DeformerStack stack;
  stack.deformers = {d};
  const glm::mat4 moved = glm::translate(glm::mat4(1.0f), glm::vec3(2, 1, 0)) *
                          glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0, 0, 1));
  const std::vector<glm::mat4> restWorld = {glm::mat4(1.0f), d.parentRest};
  const std::vector<glm::mat4> movedWorld = {glm::mat4(1.0f), moved};
  const std::vector<glm::vec3> pts = {{0.3f, 1.5f, 0.1f}, {-0.2f, 1.9f, 0.3f}};
  const std::vector<glm::vec3> atRest = run(stack, pts, &restWorld);
  // The points carried by the joint's motion, then deformed, land where the rest result is carried.
  const glm::mat4 delta = moved * glm::inverse(d.parentRest);
  std::vector<glm::vec3> carried;
  for (const glm::vec3& p : pts) carried.push_back(glm::vec3(delta * glm::vec4(p, 1.0f)));
  const std::vector<glm::vec3> followed = run(stack, carried, &movedWorld);
  for (size_t i = 0; i < pts.size(); ++i)
    EXPECT_VEC3_NEAR(followed[i], glm::vec3(delta * glm::vec4(atRest[i], 1.0f)), 1e-5f);
  // A parent the skeleton does not have is refused.
  DeformerStackJob job;
  job.stack = &stack;
  job.world = &restWorld;
  stack.deformers[0].parentJoint = 5;
  EXPECT_NE(job.validate().find("parent joint 5"), std::string::npos);
}

TEST(DeformerStack, ParametersByName) {
  Deformer lattice;
  lattice.type = DeformerType::Lattice;
  const int counts[3] = {2, 3, 2};
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  lattice.lattice = makeLattice(counts, glm::vec3(0.0f), axes);
  const std::vector<std::string> names = deformerParameters(lattice);
  ASSERT_EQ(names.size(), 12u * 3u);
  EXPECT_EQ(names[3 * 7 + 1], "point.7.y");
  ASSERT_TRUE(setDeformerParameter(lattice, "point.7.y", 4.5f));
  EXPECT_EQ(lattice.lattice.points[7].y, 4.5f);
  float v = 0;
  ASSERT_TRUE(getDeformerParameter(lattice, "point.7.y", v));
  EXPECT_EQ(v, 4.5f);
  EXPECT_FALSE(setDeformerParameter(lattice, "point.12.x", 1.0f));  // 12 points: 0..11
  EXPECT_FALSE(setDeformerParameter(lattice, "point.7.w", 1.0f));
  EXPECT_FALSE(setDeformerParameter(lattice, "point..x", 1.0f));
  EXPECT_FALSE(setDeformerParameter(lattice, "angle", 1.0f));
  Deformer pull;
  pull.type = DeformerType::SoftPull;
  EXPECT_EQ(deformerParameters(pull), (std::vector<std::string>{"offset.x", "offset.y", "offset.z"}));
  ASSERT_TRUE(setDeformerParameter(pull, "offset.z", -0.25f));
  EXPECT_EQ(pull.pull.offset.z, -0.25f);
  Deformer t = taper(1.0f);
  EXPECT_EQ(deformerParameters(t), std::vector<std::string>{"factor"});
  EXPECT_FALSE(setDeformerParameter(t, "factor", std::nanf("")));
  DeformerType type;
  ASSERT_TRUE(fromString("soft_pull", type));
  EXPECT_EQ(type, DeformerType::SoftPull);
}

// A unit square in the XY plane: two triangles facing +Z.
TEST(DeformerStack, NormalsAndApplyAsShape) {
  const std::vector<glm::vec3> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<uint32_t> tris = {0, 1, 2, 0, 2, 3};
  std::vector<glm::vec3> normals;
  computeVertexNormals(quad, tris, normals);
  for (const glm::vec3& n : normals) EXPECT_VEC3_NEAR(n, glm::vec3(0, 0, 1), 1e-7f);
  // Bend the square's top about X (Y turns towards Z): the deformation baked as a shape and
  // replayed by MorphTargetsJob at weight 1 gives the deformed mesh back, at 0.5 halfway.
  Deformer bend = twist(0.0f);
  bend.type = DeformerType::Bend;
  bend.axis.kind = AxisDeformerKind::Bend;
  bend.axis.amount = 1.0f;
  DeformerStack stack;
  stack.deformers = {bend};
  const std::vector<glm::vec3> bent = run(stack, quad);
  MeshPrimitive prim;
  prim.positions = quad;
  prim.normals = normals;
  prim.indices = tris;
  prim.targets = {shapeFromDeformation(quad, bent, tris)};
  std::vector<glm::vec3> pos, nrm;
  const float one = 1.0f, half = 0.5f;
  MorphTargetsJob job;
  job.primitive = &prim;
  job.weights = &one;
  job.weightCount = 1;
  job.outPositions = &pos;
  job.outNormals = &nrm;
  ASSERT_TRUE(job.run());
  std::vector<glm::vec3> bentNormals;
  computeVertexNormals(bent, tris, bentNormals);
  for (size_t v = 0; v < quad.size(); ++v) {
    EXPECT_VEC3_NEAR(pos[v], bent[v], 1e-6f);
    EXPECT_VEC3_NEAR(nrm[v], bentNormals[v], 1e-6f);
  }
  job.weights = &half;
  ASSERT_TRUE(job.run());
  for (size_t v = 0; v < quad.size(); ++v) EXPECT_VEC3_NEAR(pos[v], 0.5f * (quad[v] + bent[v]), 1e-6f);
}

}  // namespace
}  // namespace kinema
