// IK posing on the document: a dragged target is reached, a pinned target holds its
// effector while another target moves, unpinned targets follow, auto-IK drags a joint.
#include <gtest/gtest.h>

#include "core/forward_kinematics.h"
#include "editor/model/document_files.h"
#include "editor/model/ik_posing.h"
#include "editor/model/pose_edits.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

int joint(const Document& d, const char* name) { return d.skeleton().find(name); }

TEST(IkPosing, DraggingATargetReachesItInOneUndoStep) {
  for (IkSolver solver : {IkSolver::TwoBone, IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianDls}) {
    Document doc = newDocument();
    const int hand = joint(doc, "Hand.L");
    int t = -1;
    ASSERT_EQ(addIkTargetAtEffector(doc, hand, 2, solver, &t), "") << toString(solver);
    const Pose start = doc.pose();
    ASSERT_EQ(beginIkTargetDrag(doc, t), "");
    // Reachable: 0.54 from the shoulder (0.17, 1.45, 0), inside the 0.28 + 0.26 arm.
    const glm::vec3 goal(0.45f, 1.2f, 0.25f);
    for (int k = 1; k <= 5; ++k) ASSERT_EQ(updateIkTargetDrag(doc, t, glm::mix(doc.ikTargets()[t].target.position, goal, k / 5.0f)), "");
    doc.commitDrag();
    EXPECT_LT(glm::distance(effectorPosition(doc, hand), goal), 2e-3f) << toString(solver);
    ASSERT_EQ(doc.lastIkReports().size(), 1u);  // the last update's solve
    EXPECT_EQ(doc.lastIkReports()[0].target, t);
    doc.undo();
    EXPECT_EQ(doc.pose().local, start.local);
  }
}

TEST(IkPosing, ReportsNameTheTargetIterationsErrorAndTime) {
  Document doc = newDocument();
  const int hand = joint(doc, "Hand.L");
  PoseIkTarget t;
  t.target.effector = hand;
  t.target.position = {0.5f, 1.3f, 0.2f};
  t.chainLength = 2;
  t.solver = IkSolver::Ccd;
  ASSERT_EQ(addIkTarget(doc, t), "");
  ASSERT_EQ(doc.lastIkReports().size(), 1u);
  const IkTargetReport& r = doc.lastIkReports()[0];
  EXPECT_EQ(r.target, 0);
  EXPECT_GT(r.iterations, 0);
  EXPECT_GE(r.milliseconds, 0.0);
  EXPECT_NEAR(r.error, glm::distance(effectorPosition(doc, hand), t.target.position), 1e-6f);
  EXPECT_EQ(r.converged, r.error <= doc.ikSettings.tolerance);
}

// Drags the hand (DLS, chain of 3 from Shoulder.L) to a point the forearm can reach from
// the elbow's current place; returns how far the elbow moved.
float elbowDriftWhileDraggingTheHand(bool pinElbow, int pinChain) {
  Document doc = newDocument();
  const int hand = joint(doc, "Hand.L"), elbow = joint(doc, "LowerArm.L");
  int pin = -1, drag = -1;
  // Chain 2: the pin shares the hand chain's root (Shoulder.L); chain 1: its root
  // (UpperArm.L) is moved by the hand's chain, and the joint solve lets it use Shoulder.L.
  EXPECT_EQ(addIkTargetAtEffector(doc, elbow, pinChain, IkSolver::Ccd, &pin), "");
  PoseIkTarget p = doc.ikTargets()[pin];
  p.pinned = pinElbow;
  p.active = pinElbow;
  EXPECT_EQ(setIkTarget(doc, pin, p), "");
  const glm::vec3 elbowAt = effectorPosition(doc, elbow);
  EXPECT_EQ(addIkTargetAtEffector(doc, hand, 3, IkSolver::JacobianDls, &drag), "");
  EXPECT_EQ(beginIkTargetDrag(doc, drag), "");
  // The forearm is 0.26 long: a goal 0.26 from the elbow is reachable without moving it.
  const glm::vec3 goal = elbowAt + 0.26f * glm::normalize(glm::vec3(1, -1, 1));
  EXPECT_EQ(updateIkTargetDrag(doc, drag, goal), "");
  doc.commitDrag();
  EXPECT_LT(glm::distance(effectorPosition(doc, hand), goal), 2e-3f);
  return glm::distance(effectorPosition(doc, elbow), elbowAt);
}

TEST(IkPosing, APinnedTargetHoldsItsEffectorWhileAnotherMoves) {
  for (int chain : {1, 2}) {
    EXPECT_LT(elbowDriftWhileDraggingTheHand(true, chain), 2e-3f) << "pin chain " << chain;
    // Without the pin the same drag moves the elbow: the check above is not vacuous.
    EXPECT_GT(elbowDriftWhileDraggingTheHand(false, chain), 1e-2f) << "pin chain " << chain;
  }
}

TEST(IkPosing, UnpinnedTargetsFollowTheirEffector) {
  Document doc = newDocument();
  const int hand = joint(doc, "Hand.L"), shoulder = joint(doc, "UpperArm.L");
  int t = -1;
  ASSERT_EQ(addIkTargetAtEffector(doc, hand, 2, IkSolver::TwoBone, &t), "");
  ASSERT_EQ(setJointRotation(doc, shoulder, glm::angleAxis(-0.8f, glm::vec3(0, 0, 1))), "");
  // The target moved with the hand (FK edit), so the FK edit stands.
  EXPECT_EQ(doc.pose().local[shoulder].rotation, glm::normalize(glm::angleAxis(-0.8f, glm::vec3(0, 0, 1))));
  EXPECT_LT(glm::distance(doc.ikTargets()[t].target.position, effectorPosition(doc, hand)), 1e-6f);
  // Pinned, the same edit is pulled back by the solve: the hand stays at the target.
  PoseIkTarget s = doc.ikTargets()[t];
  s.pinned = true;
  ASSERT_EQ(setIkTarget(doc, t, s), "");
  const glm::vec3 held = s.target.position;
  ASSERT_EQ(setJointRotation(doc, shoulder, glm::angleAxis(0.3f, glm::vec3(0, 0, 1))), "");
  EXPECT_LT(glm::distance(effectorPosition(doc, hand), held), 2e-3f);
}

TEST(IkPosing, AutoIkDragsAJointWithATemporaryTarget) {
  Document doc = newDocument();
  const int hand = joint(doc, "Hand.L"), chest = joint(doc, "UpperChest");
  const glm::vec3 chestAt = effectorPosition(doc, chest);
  ASSERT_EQ(beginAutoIkDrag(doc, hand, 3), "");
  ASSERT_TRUE(doc.temporaryIkTarget().has_value());
  const glm::vec3 goal(0.5f, 1.1f, 0.3f);
  ASSERT_EQ(updateAutoIkDrag(doc, goal), "");
  ASSERT_FALSE(doc.lastIkReports().empty());
  EXPECT_EQ(doc.lastIkReports()[0].target, -1);
  doc.commitDrag();
  EXPECT_FALSE(doc.temporaryIkTarget().has_value());
  EXPECT_LT(glm::distance(effectorPosition(doc, hand), goal), 2e-3f);
  // Chain of 3 (hand's parent, grandparent, great-grandparent = Shoulder.L): the chest is outside it.
  EXPECT_EQ(effectorPosition(doc, chest), chestAt);
  EXPECT_EQ(doc.historyLabels().size(), 1u);
  EXPECT_NE(beginAutoIkDrag(doc, joint(doc, "Hips"), 2), "");  // a root has nothing to move
}

TEST(IkPosing, JointLimitsAreRespected) {
  Document doc = newDocument();
  const int elbow = joint(doc, "LowerArm.L"), hand = joint(doc, "Hand.L");
  // The elbow may bend only about +Y (the bone runs along +X), at most 0.5 rad.
  ASSERT_EQ(setJointLimit(doc, elbow, JointLimit::hinge({0, 1, 0}, 0.0f, 0.5f)), "");
  int t = -1;
  ASSERT_EQ(addIkTargetAtEffector(doc, hand, 2, IkSolver::Ccd, &t), "");
  ASSERT_EQ(beginIkTargetDrag(doc, t), "");
  ASSERT_EQ(updateIkTargetDrag(doc, t, glm::vec3(0.2f, 1.45f, 0.3f)), "");
  doc.commitDrag();
  EXPECT_LE(jointLimitViolation(doc.rig().limits[elbow], doc.skeleton().rest[elbow].rotation,
                                doc.pose().local[elbow].rotation),
            1e-4f);
}

}  // namespace
}  // namespace kinema
