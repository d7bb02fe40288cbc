// X-mirror on the R tool's several-joint rotate drag (updateRotateDrag for a joint list):
// each partner gets the mirrored rotation (x, -y, -z, w) in the same undo step, and a
// partner that is itself in the list keeps its own rotation.
#include <gtest/gtest.h>

#include "editor/model/document_files.h"
#include "editor/model/pose_edits.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

glm::quat rotZ(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(0, 0, 1)); }

// 0 for the same rotation (q and -q alike), growing as they part.
float rotationGap(const glm::quat& a, const glm::quat& b) { return 1.0f - std::abs(glm::dot(a, b)); }

TEST(PoseEditsMirror, SeveralJointRotateDragMirrorsOntoPartnersInOneStep) {
  Document doc = newDocument();
  const int l = doc.skeleton().find("LowerArm.L"), r = doc.skeleton().find("LowerArm.R");
  const int head = doc.skeleton().find("Head");
  ASSERT_GE(l, 0);
  ASSERT_GE(r, 0);
  doc.xMirror = true;
  ASSERT_EQ(doc.beginDrag("Rotate"), "");
  ASSERT_EQ(updateRotateDrag(doc, {l, head}, {rotZ(30), rotZ(10)}), "");
  doc.commitDrag();
  // Rz(30) = (0, 0, sin 15, cos 15) -> (0, 0, -sin 15, cos 15) = Rz(-30).
  EXPECT_LT(rotationGap(doc.pose().local[r].rotation, rotZ(-30)), 1e-6f);
  EXPECT_LT(rotationGap(doc.pose().local[l].rotation, rotZ(30)), 1e-6f);
  EXPECT_LT(rotationGap(doc.pose().local[head].rotation, rotZ(10)), 1e-6f);  // a centre joint: no partner
  EXPECT_EQ(doc.historyLabels().size(), 1u);
  doc.undo();
  EXPECT_LT(rotationGap(doc.pose().local[r].rotation, glm::quat(1, 0, 0, 0)), 1e-6f);

  // Both sides in the list: each keeps its own rotation, whatever the order.
  ASSERT_EQ(doc.beginDrag("Rotate"), "");
  ASSERT_EQ(updateRotateDrag(doc, {r, l}, {rotZ(5), rotZ(40)}), "");
  doc.commitDrag();
  EXPECT_LT(rotationGap(doc.pose().local[l].rotation, rotZ(40)), 1e-6f);
  EXPECT_LT(rotationGap(doc.pose().local[r].rotation, rotZ(5)), 1e-6f);

  // Off, only the listed joints turn; a mismatched list is refused.
  doc.xMirror = false;
  ASSERT_EQ(doc.beginDrag("Rotate"), "");
  ASSERT_EQ(updateRotateDrag(doc, std::vector<int>{l}, std::vector<glm::quat>{rotZ(-20)}), "");
  doc.commitDrag();
  EXPECT_LT(rotationGap(doc.pose().local[r].rotation, rotZ(5)), 1e-6f);
  ASSERT_EQ(doc.beginDrag("Rotate"), "");
  EXPECT_NE(updateRotateDrag(doc, {l, r}, {rotZ(1)}), "");
  doc.cancelDrag();
}

}  // namespace
}  // namespace kinema
