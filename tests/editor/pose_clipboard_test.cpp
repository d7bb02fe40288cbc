// Copy / paste / paste flipped on the default character. The mirror check runs its own
// forward kinematics (T * R per joint, parents first) instead of the library's.
#include <gtest/gtest.h>

#include "editor/model/document_files.h"
#include "editor/model/pose_clipboard.h"
#include "editor/model/pose_edits.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// World positions by a straightforward FK: M(joint) = M(parent) * T * R * S.
std::vector<glm::vec3> worldPositions(const Document& doc) {
  const Skeleton& s = doc.skeleton();
  std::vector<glm::mat4> m(s.size());
  std::vector<glm::vec3> p(s.size());
  for (int i = 0; i < s.size(); ++i) {
    const Transform& t = doc.pose().local[i];
    const glm::mat4 local = glm::translate(glm::mat4(1.0f), t.translation) * glm::mat4_cast(t.rotation) *
                            glm::scale(glm::mat4(1.0f), t.scale);
    m[i] = s.parents[i] < 0 ? local : m[s.parents[i]] * local;
    p[i] = glm::vec3(m[i][3]);
  }
  return p;
}

TEST(PoseClipboard, MirrorFormulas) {
  const glm::quat q(0.5f, 0.1f, 0.2f, 0.3f);
  const glm::quat m = mirrorRotationX(q);
  EXPECT_EQ(m.w, 0.5f);
  EXPECT_EQ(m.x, 0.1f);
  EXPECT_EQ(m.y, -0.2f);
  EXPECT_EQ(m.z, -0.3f);
  EXPECT_EQ(mirrorTranslationX({1, 2, 3}), glm::vec3(-1, 2, 3));
  // Independent check: mirroring a rotation is conjugating it by the reflection
  // S = diag(-1, 1, 1): S * R(q) * S equals R(mirror(q)).
  const glm::quat u = glm::normalize(glm::quat(0.8f, -0.3f, 0.4f, 0.2f));
  const glm::mat3 S(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
  const glm::mat3 expected = S * glm::mat3_cast(u) * S, got = glm::mat3_cast(mirrorRotationX(u));
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(got[c][r], expected[c][r], 1e-6f);
}

TEST(PoseClipboard, PasteFlippedMirrorsTheLeftArmOntoTheRight) {
  Document doc = newDocument();
  const char* arm[] = {"Shoulder", "UpperArm", "LowerArm", "Hand", "Fingertip"};
  std::vector<int> left;
  for (const char* a : arm) left.push_back(doc.skeleton().find(std::string(a) + ".L"));
  ASSERT_EQ(setJointRotation(doc, left[1], glm::angleAxis(0.9f, glm::normalize(glm::vec3(0.2f, 0.5f, -1.0f)))), "");
  ASSERT_EQ(setJointRotation(doc, left[2], glm::angleAxis(1.2f, glm::normalize(glm::vec3(0.0f, 1.0f, 0.3f)))), "");
  ASSERT_EQ(setJointRotation(doc, left[3], glm::angleAxis(-0.4f, glm::vec3(1, 0, 0))), "");
  const PoseClipboard clip = copyPose(doc, left);
  ASSERT_EQ(clip.entries.size(), 5u);
  ASSERT_EQ(pastePose(doc, clip, true), "");
  EXPECT_EQ(doc.historyLabels().back(), "Paste flipped pose onto 5 joints");
  const std::vector<glm::vec3> p = worldPositions(doc);
  for (const char* a : arm) {
    const glm::vec3 l = p[doc.skeleton().find(std::string(a) + ".L")];
    const glm::vec3 r = p[doc.skeleton().find(std::string(a) + ".R")];
    EXPECT_VEC3_NEAR(r, glm::vec3(-l.x, l.y, l.z), 1e-5f);
  }
  // The arm really moved (the check above is not the T-pose's own symmetry).
  EXPECT_GT(glm::distance(p[left[4]], glm::vec3(0.89f, 1.45f, 0.0f)), 0.1f);
}

TEST(PoseClipboard, PasteOntoSameNamesAndRootTranslation) {
  Document doc = newDocument();
  const int hips = doc.skeleton().find("Hips"), head = doc.skeleton().find("Head");
  ASSERT_EQ(setJointTranslation(doc, hips, glm::vec3(0.3f, 1.0f, -0.2f)), "");
  ASSERT_EQ(setJointRotation(doc, head, glm::angleAxis(0.3f, glm::vec3(0, 1, 0))), "");
  const PoseClipboard clip = copyPose(doc, {hips, head});
  EXPECT_TRUE(clip.entries[0].hasTranslation);
  EXPECT_FALSE(clip.entries[1].hasTranslation);
  Document other = newDocument();
  ASSERT_EQ(pastePose(other, clip), "");
  EXPECT_EQ(other.pose().local[hips].translation, glm::vec3(0.3f, 1.0f, -0.2f));
  EXPECT_EQ(other.pose().local[head].rotation, doc.pose().local[head].rotation);
  ASSERT_EQ(pastePose(other, clip, true), "");  // centre joints onto themselves, mirrored
  EXPECT_EQ(other.pose().local[hips].translation, glm::vec3(-0.3f, 1.0f, -0.2f));
  EXPECT_EQ(other.pose().local[head].rotation, mirrorRotationX(doc.pose().local[head].rotation));
  PoseClipboard stranger;
  stranger.entries.push_back({"Tail", glm::quat(1, 0, 0, 0), false, {}});
  EXPECT_NE(pastePose(other, stranger), "");
  EXPECT_NE(pastePose(other, PoseClipboard{}), "");
}

}  // namespace
}  // namespace kinema
