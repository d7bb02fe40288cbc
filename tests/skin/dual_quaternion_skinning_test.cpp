// DualQuaternionSkinningJob: the candy-wrapper case (a twisted cylinder keeps its
// cross-section where linear blend collapses), agreement with linear blend where the two
// must agree, and the two-phase treatment of scale.
#include "skin/dual_quaternion_skinning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "skin/linear_blend_skinning.h"
#include "skin/skinning_reference.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr float kPi = 3.14159265358979f;

struct Rig {
  std::vector<glm::vec3> positions, normals;
  std::vector<uint16_t> joints;
  std::vector<float> weights;
  std::vector<glm::mat4> matrices;
  int stride = 2;

  template <class Job>
  Job job(std::vector<glm::vec3>& outP, std::vector<glm::vec3>* outN) const {
    outP.assign(positions.size(), glm::vec3(0.0f));
    Job j;
    j.positions = positions.data();
    j.vertexCount = static_cast<int>(positions.size());
    j.influenceJoints = joints.data();
    j.influenceWeights = weights.data();
    j.influencesPerVertex = stride;
    j.jointMatrices = matrices.data();
    j.jointCount = static_cast<int>(matrices.size());
    j.outPositions = outP.data();
    if (outN) {
      outN->assign(normals.size(), glm::vec3(0.0f));
      j.normals = normals.data();
      j.outNormals = outN->data();
    }
    return j;
  }
};

constexpr int kRingVertices = 32;
constexpr int kRings = 17;  // x = 0, 0.125, ..., 2

// A unit-radius cylinder along X from 0 to 2, joint 0 at the origin and joint 1 at
// (1, 0, 0); joint 1's weight ramps smoothly from 0 at x = 0.5 to 1 at x = 1.5
// (smoothstep), so the middle ring (x = 1) is exactly 50/50. Joint 1 twists by `angle`
// about X (its own axis, which is the cylinder's), joint 0 stays.
Rig twistedCylinder(float angle) {
  Rig r;
  for (int ring = 0; ring < kRings; ++ring) {
    const float x = 2.0f * ring / (kRings - 1);
    const float t = glm::clamp(x - 0.5f, 0.0f, 1.0f);
    const float w1 = t * t * (3 - 2 * t);
    for (int k = 0; k < kRingVertices; ++k) {
      const float a = 2 * kPi * k / kRingVertices;
      r.positions.push_back({x, std::cos(a), std::sin(a)});
      r.normals.push_back({0, std::cos(a), std::sin(a)});
      // Largest weight first.
      r.joints.insert(r.joints.end(), w1 > 0.5f ? std::initializer_list<uint16_t>{1, 0} : std::initializer_list<uint16_t>{0, 1});
      r.weights.insert(r.weights.end(), {std::max(w1, 1 - w1), std::min(w1, 1 - w1)});
    }
  }
  const glm::mat4 bind1 = glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0));
  const glm::mat4 world1 = bind1 * glm::rotate(glm::mat4(1.0f), angle, glm::vec3(1, 0, 0));
  r.matrices = {glm::mat4(1.0f), world1 * glm::inverse(bind1)};
  return r;
}

// The area of the polygon a ring makes in the YZ plane (shoelace formula).
double ringArea(const std::vector<glm::vec3>& p, int ring) {
  double area = 0;
  for (int k = 0; k < kRingVertices; ++k) {
    const glm::vec3& a = p[ring * kRingVertices + k];
    const glm::vec3& b = p[ring * kRingVertices + (k + 1) % kRingVertices];
    area += static_cast<double>(a.y) * b.z - static_cast<double>(b.y) * a.z;
  }
  return std::abs(area) / 2;
}

// The middle ring at 50/50. Linear blend: 0.5 (v + R_theta v) = cos(theta/2) R_(theta/2) v,
// so the ring shrinks by cos(theta/2) and its area by cos^2(theta/2): 1/2 at 90 degrees,
// 0 at 180 (the candy wrapper). Dual quaternions blend to the rotation by theta/2 itself:
// the ring turns rigidly and keeps its area.
void checkTwist(float degrees) {
  const float angle = glm::radians(degrees);
  const Rig rig = twistedCylinder(angle);
  const int middle = kRings / 2;
  std::vector<glm::vec3> bind = rig.positions, lbs, dqs, dqsNormals;
  ASSERT_TRUE(rig.job<LinearBlendSkinningJob>(lbs, nullptr).run());
  ASSERT_TRUE(rig.job<DualQuaternionSkinningJob>(dqs, &dqsNormals).run());
  const double bindArea = ringArea(bind, middle);
  const double lbsRatio = ringArea(lbs, middle) / bindArea;
  const double dqsRatio = ringArea(dqs, middle) / bindArea;
  const double expectedLbs = std::pow(std::cos(angle / 2), 2.0);
  EXPECT_NEAR(lbsRatio, expectedLbs, 1e-5) << degrees << " degrees";
  EXPECT_LT(lbsRatio, 0.51) << degrees << " degrees";
  EXPECT_NEAR(dqsRatio, 1.0, 0.01) << degrees << " degrees";
  // Every DQS vertex of the middle ring: its bind point turned by theta/2 about X, and its
  // normal turned with it. (At exactly 180 degrees +90 and -90 are equally short: either.)
  for (const float sign : {1.0f, -1.0f}) {
    if (sign < 0 && degrees < 180.0f) break;
    const glm::mat3 half = glm::mat3(glm::rotate(glm::mat4(1.0f), sign * angle / 2, glm::vec3(1, 0, 0)));
    int matching = 0;
    for (int k = 0; k < kRingVertices; ++k) {
      const int v = middle * kRingVertices + k;
      matching += glm::distance(dqs[v], half * bind[v]) < 1e-5f && glm::distance(dqsNormals[v], half * rig.normals[v]) < 1e-5f;
    }
    if (matching == kRingVertices || sign < 0) {
      EXPECT_EQ(matching, kRingVertices) << degrees << " degrees";
    }
    if (matching == kRingVertices) break;
  }
  // The ends follow their joints rigidly under both.
  for (int k = 0; k < kRingVertices; ++k) {
    EXPECT_VEC3_NEAR(dqs[k], bind[k], 1e-6f);
    const int last = (kRings - 1) * kRingVertices + k;
    EXPECT_VEC3_NEAR(dqs[last], glm::vec3(rig.matrices[1] * glm::vec4(bind[last], 1)), 1e-5f);
    EXPECT_VEC3_NEAR(lbs[last], glm::vec3(rig.matrices[1] * glm::vec4(bind[last], 1)), 1e-5f);
  }
}

TEST(DualQuaternionSkinning, QuarterTwistKeepsCrossSectionWhereLinearBlendHalvesIt) { checkTwist(90.0f); }
TEST(DualQuaternionSkinning, HalfTurnTwistKeepsCrossSectionWhereLinearBlendCollapses) { checkTwist(180.0f); }

// Where every influence of a vertex has the same matrix (or there is one influence), the
// blend is that matrix under both methods: DQS must reproduce linear blend, for rigid
// matrices, uniformly scaled ones (an IBM that scales by 0.01, as many exporters write)
// and general affine ones (rotation, non-uniform scale, shear: the stretch phase).
void checkAgreesWithLinearBlend(int stride, int kind, std::mt19937& rng) {
  Rig r;
  r.stride = stride;
  for (int j = 0; j < 6; ++j) {
    if (kind == 0) r.matrices.push_back(test::randomSimilarity(rng, 1.0f));
    if (kind == 1) {
      const glm::mat4 ibm = glm::scale(glm::mat4(1.0f), glm::vec3(0.01f)) *
                            glm::translate(glm::mat4(1.0f), test::randomPoint(rng, 50.0f));
      r.matrices.push_back(test::randomSimilarity(rng, 1.0f) * ibm);
    }
    if (kind == 2) r.matrices.push_back(test::randomAffine(rng));
  }
  std::vector<float> w(stride);
  for (int v = 0; v < 40; ++v) {
    r.positions.push_back(test::randomPoint(rng, kind == 1 ? 100.0f : 2.0f));
    r.normals.push_back(glm::normalize(test::randomPoint(rng, 1.0f) + glm::vec3(0, 2, 0)));
    test::randomWeights(rng, stride, w.data());
    const uint16_t joint = static_cast<uint16_t>(rng() % 6);
    for (int k = 0; k < stride; ++k) {
      r.joints.push_back(joint);
      r.weights.push_back(w[k]);
    }
  }
  std::vector<glm::vec3> lbs, lbsN, dqs, dqsN;
  ASSERT_TRUE(r.job<LinearBlendSkinningJob>(lbs, &lbsN).run());
  ASSERT_TRUE(r.job<DualQuaternionSkinningJob>(dqs, &dqsN).run());
  for (int v = 0; v < 40; ++v) {
    const float scale = 1.0f + glm::length(lbs[v]) + (kind == 1 ? 1.0f : 0.0f);
    ASSERT_NEAR(glm::distance(dqs[v], lbs[v]), 0.0f, 4e-6f * scale) << "kind " << kind << " stride " << stride << " vertex " << v;
    ASSERT_NEAR(glm::distance(dqsN[v], lbsN[v]), 0.0f, 1e-5f) << "kind " << kind << " stride " << stride << " normal " << v;
  }
}

TEST(DualQuaternionSkinning, EqualsLinearBlendWhenInfluencesShareOneMatrix) {
  std::mt19937 rng(99);
  for (int kind = 0; kind < 3; ++kind)
    for (int stride : {1, 2, 3, 4, 5, 8}) {
      checkAgreesWithLinearBlend(stride, kind, rng);
      if (HasFatalFailure()) return;
    }
}

// Two-phase scale (Kavan 2008): M_0 = S, M_1 = Rx(90) S with S = diag(1, 2, 1). The
// polar decomposition gives the rotations I and Rx(90) and the stretch S for both; at 50/50
// the stretch blends to S and the rotation to Rx(45). The point (0, 1, 0) stretches to
// (0, 2, 0) and turns to (0, 2 cos45, 2 sin45) = (0, sqrt2, sqrt2). The normal (1, 1, 0)/sqrt2
// goes through inverse(S)^T = diag(1, 1/2, 1) to (2, 1, 0)/sqrt5, then Rx(45):
// (2, cos45, sin45)/sqrt5.
TEST(DualQuaternionSkinning, ScaleIsBlendedFirstThenTheRotation) {
  Rig r;
  const glm::mat4 s = glm::scale(glm::mat4(1.0f), glm::vec3(1, 2, 1));
  r.matrices = {s, glm::rotate(glm::mat4(1.0f), kPi / 2, glm::vec3(1, 0, 0)) * s};
  r.positions = {{0, 1, 0}};
  r.normals = {glm::vec3(1, 1, 0) / std::sqrt(2.0f)};
  r.joints = {0, 1};
  r.weights = {0.5f, 0.5f};
  std::vector<glm::vec3> p, n;
  ASSERT_TRUE(r.job<DualQuaternionSkinningJob>(p, &n).run());
  const float c = std::sqrt(0.5f);
  EXPECT_VEC3_NEAR(p[0], glm::vec3(0, std::sqrt(2.0f), std::sqrt(2.0f)), 1e-5f);
  EXPECT_VEC3_NEAR(n[0], glm::vec3(2, c, c) / std::sqrt(5.0f), 1e-5f);
}

// A quarter turn about Z around the pivot (1, 0, 0) blended 50/50 with the identity: the
// screw motion halfway is the eighth turn about the same pivot, so (2, 0, 0) lands at
// (1 + cos45, sin45, 0) — on the circle of radius 1 round the pivot, where linear blend
// cuts the chord to (1.5, 0.5, 0).
TEST(DualQuaternionSkinning, RotationAboutAnOffsetPivotBlendsAsAScrew) {
  Rig r;
  const glm::mat4 pivot = glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0));
  r.matrices = {glm::mat4(1.0f), pivot * glm::rotate(glm::mat4(1.0f), kPi / 2, glm::vec3(0, 0, 1)) * glm::inverse(pivot)};
  r.positions = {{2, 0, 0}};
  r.joints = {0, 1};
  r.weights = {0.5f, 0.5f};
  std::vector<glm::vec3> p;
  ASSERT_TRUE(r.job<DualQuaternionSkinningJob>(p, nullptr).run());
  const float c = std::sqrt(0.5f);
  EXPECT_VEC3_NEAR(p[0], glm::vec3(1 + c, c, 0), 1e-6f);
}

// q and -q are the same rotation: a joint whose quaternion comes out on the far side must
// be flipped before blending, or the blend goes the long way round. Rx(-100 degrees) is
// (-sin50, 0, 0, cos50) or its negation (glm::quat_cast picks the one whose largest
// component, x here, is positive: the far side of the identity). Blended 50/50 with the
// identity the short way is Rx(-50): (0, 1, 0) -> (0, cos50, -sin50); the long way would
// be Rx(130).
TEST(DualQuaternionSkinning, BlendsAlongTheShortestArc) {
  Rig r;
  r.matrices = {glm::mat4(1.0f), glm::rotate(glm::mat4(1.0f), glm::radians(-100.0f), glm::vec3(1, 0, 0))};
  r.positions = {{0, 1, 0}};
  r.joints = {0, 1};
  r.weights = {0.5f, 0.5f};
  std::vector<glm::vec3> p;
  ASSERT_TRUE(r.job<DualQuaternionSkinningJob>(p, nullptr).run());
  EXPECT_VEC3_NEAR(p[0], glm::vec3(0, std::cos(glm::radians(50.0f)), -std::sin(glm::radians(50.0f))), 1e-6f);
  // Either joint first: the alignment is to the first influence, whichever it is.
  r.joints = {1, 0};
  ASSERT_TRUE(r.job<DualQuaternionSkinningJob>(p, nullptr).run());
  EXPECT_VEC3_NEAR(p[0], glm::vec3(0, std::cos(glm::radians(50.0f)), -std::sin(glm::radians(50.0f))), 1e-6f);
}

TEST(DualQuaternionSkinning, ValidateRejectsWhatLinearBlendRejects) {
  Rig r = twistedCylinder(1.0f);
  std::vector<glm::vec3> p(r.positions.size(), glm::vec3(-3.0f));
  DualQuaternionSkinningJob j = r.job<DualQuaternionSkinningJob>(p, nullptr);
  EXPECT_EQ(j.validate(), "");
  j.jointCount = 1;
  EXPECT_NE(j.validate().find("uses joint 1"), std::string::npos) << j.validate();
  std::fill(p.begin(), p.end(), glm::vec3(-3.0f));
  EXPECT_FALSE(j.run());
  EXPECT_EQ(p[0], glm::vec3(-3.0f));
  j = r.job<DualQuaternionSkinningJob>(p, nullptr);
  j.influencesPerVertex = 9;
  EXPECT_NE(j.validate().find("influencesPerVertex"), std::string::npos);
  j = r.job<DualQuaternionSkinningJob>(p, nullptr);
  j.outNormals = p.data();
  EXPECT_NE(j.validate().find("normals is null"), std::string::npos);
}

// Degenerate matrices (a joint scaled to zero) give finite output, never NaN.
TEST(DualQuaternionSkinning, ZeroScaleJointStaysFinite) {
  Rig r;
  r.matrices = {glm::scale(glm::mat4(1.0f), glm::vec3(0.0f)), glm::mat4(1.0f)};
  r.positions = {{1, 2, 3}};
  r.normals = {{0, 0, 1}};
  r.joints = {0, 1};
  r.weights = {0.5f, 0.5f};
  std::vector<glm::vec3> p, n;
  ASSERT_TRUE(r.job<DualQuaternionSkinningJob>(p, &n).run());
  EXPECT_VEC3_NEAR(p[0], glm::vec3(0.5f, 1.0f, 1.5f), 1e-6f);  // half the stretch, no rotation
  EXPECT_TRUE(isFinite(n[0]));
}

}  // namespace
}  // namespace kinema
