#include "test_support.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/default_character.h"
#include "core/forward_kinematics.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<glm::vec3> restPositions(const Skeleton& s) {
  std::vector<glm::vec3> p;
  for (const glm::mat4& m : computeWorld(s, Pose::rest(s))) p.push_back(glm::vec3(m[3]));
  return p;
}

TEST(DefaultCharacter, IsAValidSkeletonOfHumanSize) {
  const Skeleton s = makeDefaultCharacter();
  EXPECT_EQ(s.validate(), "");
  EXPECT_GE(s.size(), 20);
  EXPECT_LE(s.size(), 30);
}

TEST(DefaultCharacter, OneRootNamedHips) {
  const Skeleton s = makeDefaultCharacter();
  int roots = 0;
  for (int i = 0; i < s.size(); ++i)
    if (s.parents[i] == -1) ++roots;
  EXPECT_EQ(roots, 1);
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.parents[0], -1);
  EXPECT_EQ(s.names[0], "Hips");
  EXPECT_EQ(s.find("Hips"), 0);
}

TEST(DefaultCharacter, RestPoseIsTheTPoseWithIdentityRotationsAndUnitScale) {
  const Skeleton s = makeDefaultCharacter();
  for (int i = 0; i < s.size(); ++i) {
    EXPECT_EQ(s.rest[i].rotation, glm::quat(1, 0, 0, 0)) << s.names[i];
    EXPECT_EQ(s.rest[i].scale, glm::vec3(1.0f)) << s.names[i];
  }
}

TEST(DefaultCharacter, LeftAndRightMirrorAcrossTheYZPlane) {
  const Skeleton s = makeDefaultCharacter();
  const std::vector<glm::vec3> p = restPositions(s);
  int pairs = 0;
  for (int i = 0; i < s.size(); ++i) {
    const std::string& name = s.names[i];
    EXPECT_FALSE(endsWith(name, ".l") || endsWith(name, ".r") || endsWith(name, "_L") ||
                 endsWith(name, "_R"))
        << name << ": sides are spelled .L / .R";
    if (endsWith(name, ".L")) {
      const std::string mirror = name.substr(0, name.size() - 2) + ".R";
      const int j = s.find(mirror);
      ASSERT_GE(j, 0) << name << " has no " << mirror;
      ++pairs;
      // The character's left is +X.
      EXPECT_GT(p[i].x, 0.0f) << name;
      EXPECT_LT(p[j].x, 0.0f) << mirror;
      EXPECT_VEC3_NEAR(p[j], glm::vec3(-p[i].x, p[i].y, p[i].z), 1e-6f);
      // Parents mirror too (the mirror's parent is the parent's mirror, or the same centre
      // joint).
      const int pi = s.parents[i], pj = s.parents[j];
      ASSERT_GE(pi, 0);
      ASSERT_GE(pj, 0);
      std::string pn = s.names[pi];
      if (endsWith(pn, ".L")) pn = pn.substr(0, pn.size() - 2) + ".R";
      EXPECT_EQ(s.names[pj], pn) << name;
    } else if (endsWith(name, ".R")) {
      EXPECT_GE(s.find(name.substr(0, name.size() - 2) + ".L"), 0) << name << " has no .L";
    } else {
      // Centre joints lie on the plane of symmetry.
      EXPECT_NEAR(p[i].x, 0.0f, 1e-6f) << name;
    }
  }
  EXPECT_GE(pairs, 8);  // arms and legs at least
}

TEST(DefaultCharacter, StandsOnTheGroundAndIsOneEightyTall) {
  const Skeleton s = makeDefaultCharacter();
  const std::vector<glm::vec3> p = restPositions(s);
  float top = -1e9f, bottom = 1e9f;
  for (const glm::vec3& v : p) {
    top = std::max(top, v.y);
    bottom = std::min(bottom, v.y);
  }
  EXPECT_NEAR(top, 1.80f, 1e-4f);
  // Feet on y = 0: no joint below the ground, and the lowest joints (toes, a couple of
  // centimetres up inside the foot) within 3 cm of it.
  EXPECT_GE(bottom, -1e-6f);
  EXPECT_LE(bottom, 0.03f);
  // Y is up: the head is above the hips, the feet below.
  const int head = s.find("Head"), hips = s.find("Hips");
  ASSERT_GE(head, 0);
  EXPECT_GT(p[head].y, p[hips].y);
  for (int i = 0; i < s.size(); ++i)
    if (s.names[i].rfind("Foot", 0) == 0) {
      EXPECT_LT(p[i].y, 0.2f) << s.names[i];
    }
}

TEST(DefaultCharacter, ArmsStretchSidewaysInTPose) {
  // T-pose: the arm chain runs along the X axis at shoulder height.
  const Skeleton s = makeDefaultCharacter();
  const std::vector<glm::vec3> p = restPositions(s);
  for (int i = 0; i < s.size(); ++i) {
    const std::string& n = s.names[i];
    if (n.rfind("LowerArm", 0) == 0 || n.rfind("Hand", 0) == 0) {
      const glm::vec3 bone = p[i] - p[s.parents[i]];
      EXPECT_NEAR(bone.y, 0.0f, 1e-5f) << n;
      EXPECT_NEAR(bone.z, 0.0f, 1e-5f) << n;
      EXPECT_GT(std::abs(bone.x), 0.1f) << n;
    }
  }
}

}  // namespace
}  // namespace kinema
