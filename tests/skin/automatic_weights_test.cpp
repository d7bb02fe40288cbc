// Automatic weights: hand-derived capsule and inverse-distance cases, and the default
// character's body checked against an independent nearest-bone computation.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "core/mesh.h"
#include "skin/automatic_weights.h"
#include "skin/default_body_mesh.h"
#include "scene/default_character_scene.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// Joints at given world positions (identity rotations), parents as listed.
struct Rig {
  Skeleton skeleton;
  std::vector<glm::mat4> world;
};

Rig rigOf(const std::vector<glm::vec3>& at, const std::vector<int>& parents) {
  Rig rig;
  for (size_t j = 0; j < at.size(); ++j) {
    const glm::vec3 from = parents[j] < 0 ? glm::vec3(0.0f) : at[parents[j]];
    rig.skeleton.addJoint("j" + std::to_string(j), parents[j], Transform::fromTranslation(at[j] - from));
  }
  rig.world = computeWorld(rig.skeleton, Pose::rest(rig.skeleton));
  return rig;
}

struct Weights {
  std::vector<uint16_t> joints;
  std::vector<float> weights;
};

Weights runJob(const Rig& rig, const std::vector<glm::vec3>& points, AutomaticWeightsMethod method,
               std::vector<float> radii = {}, int maxInfluences = 4, float power = 4.0f) {
  Weights out;
  AutomaticWeightsJob job;
  job.skeleton = &rig.skeleton;
  job.bindWorld = &rig.world;
  job.positions = &points;
  job.method = method;
  job.capsuleRadius = std::move(radii);
  job.maxInfluences = maxInfluences;
  job.inverseDistancePower = power;
  job.outJoints = &out.joints;
  job.outWeights = &out.weights;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return out;
}

// Non-zero influences of vertex v as (joint, weight).
std::vector<std::pair<int, float>> influencesOf(const Weights& w, int v) {
  std::vector<std::pair<int, float>> r;
  for (int k = 0; k < kMaxInfluences; ++k)
    if (w.weights[v * kMaxInfluences + k] != 0.0f) r.push_back({w.joints[v * kMaxInfluences + k], w.weights[v * kMaxInfluences + k]});
  return r;
}

// One bone from the origin to (1, 0, 0); joint 1 is childless, so a point at the tip.
TEST(AutomaticWeights, CapsuleOnOneStraightBone) {
  const Rig rig = rigOf({{0, 0, 0}, {1, 0, 0}}, {-1, 0});
  const float r = 0.2f;
  // Beside the middle at d = 0, r/2, r, 2r: the tip is 0.5 or more further than the bone,
  // past its radius, so the bone alone (weight 1); at 2r no capsule reaches: still the bone.
  const std::vector<glm::vec3> middle = {{0.5f, 0, 0}, {0.5f, r / 2, 0}, {0.5f, r, 0}, {0.5f, 2 * r, 0}};
  const Weights w = runJob(rig, middle, AutomaticWeightsMethod::Capsule, {r, r});
  for (int v = 0; v < 4; ++v) {
    const auto inf = influencesOf(w, v);
    ASSERT_EQ(inf.size(), 1u) << "d index " << v;
    EXPECT_EQ(inf[0].first, 0);
    EXPECT_EQ(inf[0].second, 1.0f);
  }
  // Near the tip: (0.7, 0.4) is 0.4 from the bone and 0.5 from the tip joint; the excess
  // 0.1 over a radius 0.2 gives the tip 1 - 0.1/0.2 = 0.5 against the bone's 1: 2/3, 1/3.
  // Past the tip both are equally near: 1/2 each, the bone (the nearer-listed) first.
  const Weights tip = runJob(rig, {{0.7f, 0.4f, 0}, {1.3f, 0.1f, 0}}, AutomaticWeightsMethod::Capsule, {r, r});
  auto a = influencesOf(tip, 0);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].first, 0);
  EXPECT_NEAR(a[0].second, 2.0f / 3.0f, 1e-6f);
  EXPECT_EQ(a[1].first, 1);
  EXPECT_NEAR(a[1].second, 1.0f / 3.0f, 1e-6f);
  auto b = influencesOf(tip, 1);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].first, 0);
  EXPECT_NEAR(b[0].second, 0.5f, 1e-6f);
  EXPECT_NEAR(b[1].second, 0.5f, 1e-6f);
}

// An L: bone 0 along x from the origin to (1,0,0), bone 1 up to (1,1,0), joint 2 the tip.
TEST(AutomaticWeights, CapsuleOnTwoBonesMeetingAtAJoint) {
  const Rig rig = rigOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {-1, 0, 1});
  const std::vector<float> radii = {0.5f, 0.5f, 0.1f};
  // (0.7, 0.4): 0.4 from bone 0, 0.3 from bone 1 (nearest), 0.67 from the tip. Bone 0's
  // excess 0.1 over radius 0.5 gives 0.8; normalised 1/1.8 and 0.8/1.8.
  // (1.3, -0.3): outside the corner, 0.3*sqrt(2) from both bones: half each.
  // (0.2, 0.1): 0.1 from bone 0, 0.8 from bone 1 (excess 0.7 > 0.5): bone 0 alone.
  const Weights w = runJob(rig, {{0.7f, 0.4f, 0}, {1.3f, -0.3f, 0}, {0.2f, 0.1f, 0}}, AutomaticWeightsMethod::Capsule, radii);
  auto a = influencesOf(w, 0);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].first, 1);
  EXPECT_NEAR(a[0].second, 1.0f / 1.8f, 1e-6f);
  EXPECT_EQ(a[1].first, 0);
  EXPECT_NEAR(a[1].second, 0.8f / 1.8f, 1e-6f);
  auto b = influencesOf(w, 1);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_NEAR(b[0].second, 0.5f, 1e-6f);
  EXPECT_NEAR(b[1].second, 0.5f, 1e-6f);
  auto c = influencesOf(w, 2);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].first, 0);
}

TEST(AutomaticWeights, InverseDistanceKeepsTheLargestAndRenormalises) {
  const Rig rig = rigOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {-1, 0, 1});
  // (0.7, 0.4): d = 0.4, 0.3, sqrt(0.45). With power 2: 1/d^2 = 6.25, 11.111, 2.222;
  // normalised 0.3191, 0.5674, 0.1135; the top 2 renormalised: 0.36, 0.64.
  const Weights all = runJob(rig, {{0.7f, 0.4f, 0}}, AutomaticWeightsMethod::InverseDistance, {}, 4, 2.0f);
  auto a = influencesOf(all, 0);
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].first, 1);
  EXPECT_NEAR(a[0].second, 11.111111f / 19.583333f, 1e-5f);
  EXPECT_EQ(a[1].first, 0);
  EXPECT_NEAR(a[1].second, 6.25f / 19.583333f, 1e-5f);
  EXPECT_EQ(a[2].first, 2);
  EXPECT_NEAR(a[2].second, 2.2222222f / 19.583333f, 1e-5f);
  const Weights two = runJob(rig, {{0.7f, 0.4f, 0}}, AutomaticWeightsMethod::InverseDistance, {}, 2, 2.0f);
  auto b = influencesOf(two, 0);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_NEAR(b[0].second, 0.64f, 1e-6f);
  EXPECT_NEAR(b[1].second, 0.36f, 1e-6f);
  // On a bone (d = 0) the weight is that bone's alone, not a division by zero.
  const Weights on = runJob(rig, {{0.5f, 0, 0}}, AutomaticWeightsMethod::InverseDistance);
  auto c = influencesOf(on, 0);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].first, 0);
  EXPECT_EQ(c[0].second, 1.0f);
}

TEST(AutomaticWeights, NearestGivesExactlyOneInfluence) {
  const Rig rig = rigOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {-1, 0, 1});
  const Weights w = runJob(rig, {{0.7f, 0.4f, 0}, {0.2f, 0.1f, 0}, {1.1f, 1.5f, 0}, {5, 5, 5}}, AutomaticWeightsMethod::Nearest);
  const int expected[] = {1, 0, 2, 2};  // (1.1, 1.5) and (5,5,5) are nearest the tip at (1,1,0)
  for (int v = 0; v < 4; ++v) {
    auto inf = influencesOf(w, v);
    ASSERT_EQ(inf.size(), 1u);
    EXPECT_EQ(inf[0].second, 1.0f);
    if (v < 2) {
      EXPECT_EQ(inf[0].first, expected[v]);
    } else {
      EXPECT_TRUE(inf[0].first == 1 || inf[0].first == 2) << "the tip lies on bone 1's end";
    }
  }
}

TEST(AutomaticWeights, ValidateNamesTheProblem) {
  const Rig rig = rigOf({{0, 0, 0}, {1, 0, 0}}, {-1, 0});
  std::vector<glm::vec3> points = {{0, 0, 0}};
  std::vector<uint16_t> joints;
  std::vector<float> weights;
  AutomaticWeightsJob job;
  EXPECT_NE(job.validate(), "");
  EXPECT_FALSE(job.run());
  job.skeleton = &rig.skeleton;
  job.bindWorld = &rig.world;
  job.positions = &points;
  job.outJoints = &joints;
  job.outWeights = &weights;
  EXPECT_EQ(job.validate(), "");
  job.capsuleRadius = {0.1f};
  EXPECT_NE(job.validate().find("capsuleRadius"), std::string::npos);
  job.capsuleRadius = {0.1f, -1.0f};
  EXPECT_NE(job.validate().find("capsuleRadius[1]"), std::string::npos);
  job.capsuleRadius.clear();
  job.maxInfluences = 9;
  EXPECT_NE(job.validate().find("maxInfluences"), std::string::npos);
  job.maxInfluences = 4;
  points[0].x = std::nanf("");
  EXPECT_NE(job.validate().find("positions[0]"), std::string::npos);
  EXPECT_FALSE(job.run());
}

// The default character's segments, computed here from joint positions in double:
// parent -> child segments belong to the parent; a childless joint is a point.
double independentDistance(const Skeleton& s, const std::vector<glm::dvec3>& at, int joint, const glm::dvec3& p) {
  double best = std::numeric_limits<double>::infinity();
  bool hasChild = false;
  for (int c = 0; c < s.size(); ++c) {
    if (s.parents[c] != joint) continue;
    hasChild = true;
    const glm::dvec3 a = at[joint], ab = at[c] - at[joint];
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    best = std::min(best, glm::length(p - (a + t * ab)));
  }
  if (!hasChild) best = glm::length(p - at[joint]);
  return best;
}

void expectWellFormed(const MeshPrimitive& m, int maxInfluences) {
  ASSERT_EQ(m.influenceWeights.size(), m.positions.size() * kMaxInfluences);
  ASSERT_EQ(m.influenceJoints.size(), m.positions.size() * kMaxInfluences);
  for (int v = 0; v < m.vertexCount(); ++v) {
    double sum = 0.0;
    int nonZero = 0;
    for (int k = 0; k < kMaxInfluences; ++k) {
      const float w = m.influenceWeights[v * kMaxInfluences + k];
      ASSERT_GE(w, 0.0f);
      if (k > 0) {
        ASSERT_LE(w, m.influenceWeights[v * kMaxInfluences + k - 1]) << "vertex " << v << " not largest first";
      }
      sum += w;
      nonZero += w != 0.0f;
    }
    ASSERT_NEAR(sum, 1.0, 1e-6) << "vertex " << v;
    ASSERT_GE(nonZero, 1) << "vertex " << v;
    ASSERT_LE(nonZero, maxInfluences) << "vertex " << v;
  }
}

TEST(AutomaticWeights, DefaultCharacterLargestWeightIsTheNearestBone) {
  const Scene scene = makeDefaultCharacterScene();
  const Skeleton& s = scene.skeleton;
  const MeshPrimitive& body = scene.meshes.at(0).primitives.at(0);
  expectWellFormed(body, 4);
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  std::vector<glm::dvec3> at;
  for (const glm::mat4& m : world) at.push_back(glm::dvec3(m[3]));
  int checked = 0;
  for (int v = 0; v < body.vertexCount(); ++v) {
    const glm::dvec3 p(body.positions[v]);
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < s.size(); ++j) nearest = std::min(nearest, independentDistance(s, at, j, p));
    const int largest = body.influenceJoints[v * kMaxInfluences];
    // Ties (a tip joint and the bone ending there) may go either way.
    EXPECT_LE(independentDistance(s, at, largest, p), nearest + 1e-5)
        << "vertex " << v << " at (" << p.x << ", " << p.y << ", " << p.z << ") leans on " << s.names[largest];
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

// Random points in and around the default character's box, every method and the default
// radii: well formed, and the largest weight on the nearest bone.
TEST(AutomaticWeights, RandomPointsLeanOnTheirNearestBone) {
  const Skeleton s = makeDefaultCharacter();
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  std::vector<glm::dvec3> at;
  for (const glm::mat4& m : world) at.push_back(glm::dvec3(m[3]));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> x(-1.2f, 1.2f), y(-0.2f, 2.0f), z(-0.5f, 0.5f);
  MeshPrimitive points;
  for (int i = 0; i < propertyCases(2000); ++i) points.positions.push_back({x(rng), y(rng), z(rng)});
  for (AutomaticWeightsMethod method :
       {AutomaticWeightsMethod::Capsule, AutomaticWeightsMethod::InverseDistance, AutomaticWeightsMethod::Nearest}) {
    AutomaticWeightsJob job;
    job.skeleton = &s;
    job.bindWorld = &world;
    job.positions = &points.positions;
    job.method = method;
    job.maxInfluences = 3;
    job.outJoints = &points.influenceJoints;
    job.outWeights = &points.influenceWeights;
    ASSERT_TRUE(job.run());
    expectWellFormed(points, method == AutomaticWeightsMethod::Nearest ? 1 : 3);
    for (int v = 0; v < points.vertexCount(); ++v) {
      const glm::dvec3 p(points.positions[v]);
      double nearest = std::numeric_limits<double>::infinity();
      for (int j = 0; j < s.size(); ++j) nearest = std::min(nearest, independentDistance(s, at, j, p));
      ASSERT_LE(independentDistance(s, at, points.influenceJoints[v * kMaxInfluences], p), nearest + 1e-5)
          << "method " << static_cast<int>(method) << ", point " << v;
    }
  }
}

TEST(AutomaticWeights, DefaultCharacterHandsAndForearmsFeelOnlyTheirArm) {
  const Scene scene = makeDefaultCharacterScene();
  const Skeleton& s = scene.skeleton;
  const MeshPrimitive& body = scene.meshes.at(0).primitives.at(0);
  int handVertices = 0;
  for (int v = 0; v < body.vertexCount(); ++v) {
    const float x = body.positions[v].x;
    if (std::abs(x) < 0.55f) continue;  // past the elbow (0.45) by more than its blend band
    const std::string side = x > 0 ? ".L" : ".R";
    for (int k = 0; k < kMaxInfluences; ++k) {
      if (body.influenceWeights[v * kMaxInfluences + k] == 0.0f) continue;
      const std::string& name = s.names[body.influenceJoints[v * kMaxInfluences + k]];
      EXPECT_TRUE(name == "LowerArm" + side || name == "Hand" + side || name == "Fingertip" + side)
          << "vertex " << v << " at x = " << x << " is pulled by " << name;
    }
    ++handVertices;
  }
  EXPECT_GT(handVertices, 100);
}

TEST(AutomaticWeights, EveryMethodWeighsEveryBodyVertex) {
  const Skeleton s = makeDefaultCharacter();
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  for (AutomaticWeightsMethod method :
       {AutomaticWeightsMethod::Capsule, AutomaticWeightsMethod::InverseDistance, AutomaticWeightsMethod::Nearest}) {
    MeshPrimitive body = makeDefaultBodyMesh();
    AutomaticWeightsJob job;
    job.skeleton = &s;
    job.bindWorld = &world;
    job.positions = &body.positions;
    job.method = method;  // the default radii: 0.35 x bone length
    job.outJoints = &body.influenceJoints;
    job.outWeights = &body.influenceWeights;
    ASSERT_TRUE(job.run());
    expectWellFormed(body, method == AutomaticWeightsMethod::Nearest ? 1 : 4);
  }
}

}  // namespace
}  // namespace kinema::test
