// Undo/redo of the document: single edits, drags as one step, cancel, dirty tracking,
// history jumps, and a property test over random edit sequences (bitwise exact).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "core/default_character.h"
#include "editor/model/document_files.h"
#include "editor/model/ik_posing.h"
#include "editor/model/pose_clipboard.h"
#include "editor/model/pose_edits.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// Everything an edit may change, as bytes: two documents compare equal exactly when their
// names, pose, limits and IK targets are bitwise the same.
std::string contentBytes(const Document& d) {
  std::string b;
  auto raw = [&b](const void* p, size_t n) { b.append(static_cast<const char*>(p), n); };
  for (const std::string& n : d.skeleton().names) b += n + '\0';
  raw(d.pose().local.data(), d.pose().local.size() * sizeof(Transform));
  raw(d.rig().limits.data(), d.rig().limits.size() * sizeof(JointLimit));
  for (const PoseIkTarget& t : d.ikTargets()) {
    const IkTarget& x = t.target;
    const int ints[] = {x.effector, x.root, x.mid, x.hasOrientation, x.hasPole, t.chainLength,
                        static_cast<int>(t.solver), t.active, t.pinned};
    raw(ints, sizeof ints);
    raw(&x.position, sizeof x.position);
    raw(&x.orientation, sizeof x.orientation);
    raw(&x.pole, sizeof x.pole);
    raw(&x.weight, sizeof x.weight);
  }
  return b;
}

int joint(const Document& d, const char* name) { return d.skeleton().find(name); }

TEST(DocumentHistory, EditUndoRedoRestoreExactly) {
  Document doc = newDocument();
  const int arm = joint(doc, "UpperArm.L");
  const std::string start = contentBytes(doc);
  EXPECT_FALSE(doc.dirty());
  EXPECT_FALSE(doc.canUndo());
  const glm::quat q = glm::angleAxis(0.7f, glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f)));
  ASSERT_EQ(setJointRotation(doc, arm, q), "");
  EXPECT_TRUE(doc.dirty());
  EXPECT_TRUE(doc.needsConfirmationToDiscard());
  const std::string after = contentBytes(doc);
  EXPECT_NE(after, start);
  EXPECT_EQ(doc.historyLabels(), std::vector<std::string>{"Rotate UpperArm.L"});
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(contentBytes(doc), start);
  EXPECT_FALSE(doc.dirty());  // back at the saved (new) state
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(contentBytes(doc), after);
  EXPECT_FALSE(doc.redo());
}

TEST(DocumentHistory, ARefusedEditChangesNothingAndAddsNoStep) {
  Document doc = newDocument();
  const std::string start = contentBytes(doc);
  EXPECT_NE(renameJoint(doc, joint(doc, "Hand.L"), "Hand.R"), "");  // clash
  EXPECT_NE(renameJoint(doc, joint(doc, "Hand.L"), ""), "");
  EXPECT_NE(setJointRotation(doc, 999, glm::quat(1, 0, 0, 0)), "");
  EXPECT_NE(setJointRotation(doc, 0, glm::quat(0, 0, 0, 0)), "");
  EXPECT_NE(setJointTranslation(doc, 0, glm::vec3(NAN, 0, 0)), "");
  EXPECT_EQ(contentBytes(doc), start);
  EXPECT_FALSE(doc.canUndo());
  // An edit whose change function fails is rolled back.
  EXPECT_EQ(doc.edit("bad", [](DocumentEdit& e) {
    e.pose.local[0].translation.x = 5.0f;
    return std::string("nope");
  }),
            "nope");
  EXPECT_EQ(contentBytes(doc), start);
  // An edit may not break the invariants (duplicate names).
  EXPECT_NE(doc.edit("dup", [](DocumentEdit& e) {
    e.names[1] = e.names[0];
    return std::string();
  }),
            "");
  EXPECT_EQ(contentBytes(doc), start);
  EXPECT_FALSE(doc.canUndo());
}

TEST(DocumentHistory, RenameIsUndoable) {
  Document doc = newDocument();
  const int hand = joint(doc, "Hand.L");
  ASSERT_EQ(renameJoint(doc, hand, "Paw.L"), "");
  EXPECT_EQ(doc.skeleton().names[hand], "Paw.L");
  EXPECT_EQ(doc.skeleton().find("Hand.L"), -1);
  doc.undo();
  EXPECT_EQ(doc.skeleton().names[hand], "Hand.L");
}

TEST(DocumentHistory, ADragIsOneStepAndCancelRestoresTheStart) {
  Document doc = newDocument();
  const int arm = joint(doc, "LowerArm.L");
  const std::string start = contentBytes(doc);
  ASSERT_EQ(beginRotateDrag(doc, arm), "");
  for (int i = 1; i <= 10; ++i) ASSERT_EQ(updateRotateDrag(doc, arm, glm::angleAxis(0.1f * i, glm::vec3(0, 0, 1))), "");
  EXPECT_TRUE(doc.dragging());
  EXPECT_NE(setJointRotation(doc, 0, glm::quat(1, 0, 0, 0)), "");  // no edits during a drag
  doc.cancelDrag();
  EXPECT_EQ(contentBytes(doc), start);
  EXPECT_FALSE(doc.canUndo());

  ASSERT_EQ(beginRotateDrag(doc, arm), "");
  for (int i = 1; i <= 10; ++i) ASSERT_EQ(updateRotateDrag(doc, arm, glm::angleAxis(0.1f * i, glm::vec3(0, 0, 1))), "");
  doc.commitDrag();
  EXPECT_EQ(doc.historyLabels().size(), 1u);
  // Each update starts from the drag's start: the result is the last update's rotation.
  EXPECT_EQ(doc.pose().local[arm].rotation, glm::normalize(glm::angleAxis(1.0f, glm::vec3(0, 0, 1))));
  doc.undo();
  EXPECT_EQ(contentBytes(doc), start);
}

TEST(DocumentHistory, JumpToEntryAndDirtyAfterSave) {
  Document doc = newDocument();
  std::vector<std::string> states{contentBytes(doc)};
  for (int i = 0; i < 5; ++i) {
    ASSERT_EQ(setJointTranslation(doc, 0, glm::vec3(0.1f * (i + 1), 0.95f, 0.0f)), "");
    states.push_back(contentBytes(doc));
  }
  ASSERT_TRUE(doc.jumpToHistory(2));
  EXPECT_EQ(contentBytes(doc), states[2]);
  doc.markSaved();
  EXPECT_FALSE(doc.dirty());
  ASSERT_TRUE(doc.jumpToHistory(5));
  EXPECT_TRUE(doc.dirty());
  ASSERT_TRUE(doc.jumpToHistory(2));
  EXPECT_FALSE(doc.dirty());
  ASSERT_TRUE(doc.jumpToHistory(0));
  EXPECT_EQ(contentBytes(doc), states[0]);
  EXPECT_FALSE(doc.jumpToHistory(6));
  // A new edit from position 1 drops the redo tail that held the saved state: dirty for good.
  doc.jumpToHistory(1);
  ASSERT_EQ(setJointTranslation(doc, 0, glm::vec3(9.0f, 0.95f, 0.0f)), "");
  ASSERT_EQ(setJointTranslation(doc, 0, glm::vec3(8.0f, 0.95f, 0.0f)), "");
  EXPECT_EQ(doc.historyPosition(), 3);
  EXPECT_TRUE(doc.dirty());
}

TEST(DocumentHistory, XMirrorSetsThePartnerInTheSameStep) {
  Document doc = newDocument();
  doc.xMirror = true;
  const int l = joint(doc, "UpperArm.L"), r = joint(doc, "UpperArm.R");
  const glm::quat q = glm::normalize(glm::quat(0.9f, 0.1f, 0.2f, 0.3f));
  ASSERT_EQ(setJointRotation(doc, l, q), "");
  EXPECT_EQ(doc.historyLabels().size(), 1u);
  const glm::quat m = doc.pose().local[r].rotation;
  EXPECT_EQ(m.w, doc.pose().local[l].rotation.w);
  EXPECT_EQ(m.x, doc.pose().local[l].rotation.x);
  EXPECT_EQ(m.y, -doc.pose().local[l].rotation.y);
  EXPECT_EQ(m.z, -doc.pose().local[l].rotation.z);
  doc.undo();
  EXPECT_EQ(doc.pose().local[r].rotation, glm::quat(1, 0, 0, 0));
  EXPECT_EQ(doc.pose().local[l].rotation, glm::quat(1, 0, 0, 0));
}

TEST(DocumentHistory, ClearRotationAndResetToRest) {
  Document doc = newDocument();
  const int a = joint(doc, "Hand.L"), b = joint(doc, "Head");
  ASSERT_EQ(setJointRotation(doc, a, glm::angleAxis(0.5f, glm::vec3(1, 0, 0))), "");
  ASSERT_EQ(setJointRotation(doc, b, glm::angleAxis(0.5f, glm::vec3(0, 1, 0))), "");
  ASSERT_EQ(setJointTranslation(doc, 0, glm::vec3(1, 2, 3)), "");
  ASSERT_EQ(clearRotations(doc, {a}), "");
  EXPECT_EQ(doc.pose().local[a].rotation, doc.skeleton().rest[a].rotation);
  EXPECT_NE(doc.pose().local[b].rotation, doc.skeleton().rest[b].rotation);
  ASSERT_EQ(resetToRestPose(doc), "");
  for (int i = 0; i < doc.skeleton().size(); ++i) EXPECT_EQ(doc.pose().local[i], doc.skeleton().rest[i]);
  EXPECT_EQ(doc.historyLabels().back(), "Reset all joints to the rest pose");
  EXPECT_EQ(doc.historyLabels()[doc.historyLabels().size() - 2], "Clear rotation of Hand.L");
}

TEST(DocumentHistory, GlobalAxesRotationBecomesTheJointsWorldRotation) {
  Document doc = newDocument();
  const int shoulder = joint(doc, "UpperArm.L"), elbow = joint(doc, "LowerArm.L");
  const glm::quat parent = glm::angleAxis(0.6f, glm::vec3(0, 0, 1));
  ASSERT_EQ(setJointRotation(doc, shoulder, parent), "");
  const glm::quat world = glm::angleAxis(-0.4f, glm::vec3(0, 1, 0));
  ASSERT_EQ(setJointWorldRotation(doc, elbow, world), "");
  // Hand-derived: the parent chain above UpperArm.L is unrotated, so local = parent^-1 * world.
  EXPECT_SAME_ROTATION(doc.pose().local[elbow].rotation, glm::inverse(parent) * world, 1e-6f);
}

// Random edit sequences: after every step the document equals the state recorded for its
// history position; undoing everything gives the start bit for bit, redoing the end.
TEST(DocumentHistory, RandomEditSequencesUndoAndRedoExactly) {
  const int cases = test::propertyCases(40);
  for (int c = 0; c < cases; ++c) {
    std::mt19937 rng(1000 + c);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::uniform_int_distribution<int> pick(0, 15);
    Document doc = newDocument();
    const int n = doc.skeleton().size();
    std::uniform_int_distribution<int> anyJoint(0, n - 1);
    std::vector<std::string> states{contentBytes(doc)};
    PoseClipboard clipboard;
    auto record = [&] {
      states.resize(doc.historyPosition());
      states.push_back(contentBytes(doc));
      ASSERT_EQ(static_cast<int>(states.size()), doc.historyPosition() + 1);
    };
    for (int step = 0; step < 30; ++step) {
      const int j = anyJoint(rng);
      const int before = doc.historyPosition();
      std::string error;
      switch (pick(rng)) {
        case 0: error = setJointRotation(doc, j, test::randomRotation(rng)); break;
        case 1: error = setJointWorldRotation(doc, j, test::randomRotation(rng)); break;
        case 2: error = setJointTranslation(doc, j, glm::vec3(u(rng), u(rng), u(rng))); break;
        case 3: error = clearRotations(doc, {j, anyJoint(rng)}); break;
        case 4: error = rng() % 4 == 0 ? resetToRestPose(doc) : renameJoint(doc, j, "j" + std::to_string(rng() % 40)); break;
        case 5: error = addIkTargetAtEffector(doc, j, 1 + static_cast<int>(rng() % 3),
                                              rng() % 2 ? IkSolver::Ccd : IkSolver::JacobianDls); break;
        case 6:
          if (!doc.ikTargets().empty()) error = removeIkTarget(doc, static_cast<int>(rng() % doc.ikTargets().size()));
          break;
        case 7:
          if (!doc.ikTargets().empty()) {
            const int t = static_cast<int>(rng() % doc.ikTargets().size());
            PoseIkTarget s = doc.ikTargets()[t];
            s.pinned = !s.pinned;
            s.solver = rng() % 2 ? IkSolver::Fabrik : IkSolver::Ccd;
            s.target.position += glm::vec3(0.1f * u(rng), 0.1f * u(rng), 0.0f);
            error = setIkTarget(doc, t, s);
          }
          break;
        case 8: error = setJointLimit(doc, j, JointLimit::hinge({0, 0, 1}, -0.5f, 0.5f * (1.0f + u(rng)))); break;
        case 9: clipboard = copyPose(doc, {j, anyJoint(rng), 0}); break;
        case 10: error = pastePose(doc, clipboard, rng() % 2 == 0); break;
        case 11: doc.xMirror = !doc.xMirror; break;
        case 12:
        case 13: {
          const bool commit = rng() % 3 != 0;
          if (!doc.ikTargets().empty() && rng() % 2) {
            const int t = static_cast<int>(rng() % doc.ikTargets().size());
            ASSERT_EQ(beginIkTargetDrag(doc, t), "");
            for (int k = 0; k < 3; ++k)
              updateIkTargetDrag(doc, t, doc.ikTargets()[t].target.position + glm::vec3(0.05f * u(rng), 0.05f, 0.0f));
          } else if (doc.skeleton().parents[j] >= 0 && rng() % 2) {
            ASSERT_EQ(beginAutoIkDrag(doc, j, 2), "");
            for (int k = 0; k < 3; ++k) updateAutoIkDrag(doc, effectorPosition(doc, j) + glm::vec3(0.02f, 0.03f * u(rng), 0.0f));
          } else {
            ASSERT_EQ(beginRotateDrag(doc, j), "");
            for (int k = 0; k < 3; ++k) updateRotateDrag(doc, j, test::randomRotation(rng));
          }
          if (commit) {
            doc.commitDrag();
          } else {
            doc.cancelDrag();
            ASSERT_EQ(contentBytes(doc), states[doc.historyPosition()]) << "case " << c << " step " << step;
          }
          break;
        }
        case 14:
          if (doc.undo()) {
            ASSERT_EQ(contentBytes(doc), states[doc.historyPosition()]) << "case " << c << " step " << step;
            continue;
          }
          break;
        case 15:
          if (doc.redo()) {
            ASSERT_EQ(contentBytes(doc), states[doc.historyPosition()]) << "case " << c << " step " << step;
            continue;
          }
          break;
      }
      if (!error.empty() || doc.historyPosition() == before) {
        ASSERT_EQ(doc.historyPosition(), before);
        ASSERT_EQ(contentBytes(doc), states[before]) << "a refused or empty edit changed the document: " << error;
      } else {
        record();
      }
    }
    // The sequence did edit (refused edits are a minority of the 30 steps).
    EXPECT_GE(doc.historyLabels().size(), 5u) << "case " << c;
    const int end = doc.historyPosition();
    const std::string endState = contentBytes(doc);
    while (doc.undo()) {
    }
    EXPECT_EQ(contentBytes(doc), states[0]) << "case " << c;
    while (doc.redo()) {
    }
    EXPECT_EQ(doc.historyPosition(), static_cast<int>(doc.historyLabels().size()));
    ASSERT_TRUE(doc.jumpToHistory(end));
    EXPECT_EQ(contentBytes(doc), endState) << "case " << c;
  }
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

// Same rotation (either sign of the quaternion).
void expectSameRotation(const glm::quat& a, const glm::quat& b, const char* what) {
  EXPECT_NEAR(std::abs(glm::dot(glm::normalize(a), glm::normalize(b))), 1.0f, 1e-6f) << what;
}

TEST(DocumentLimits, FkRotationsAndDragsStayWithinTheJointLimit) {
  // A hinge about the rest frame's Z, 0..45 degrees, on the left forearm: 90 degrees about Z
  // stops at 45; -30 stops at 0; a turn about X (off the hinge) has no Z twist, so the joint
  // stays at rest. Limits are relative to the rest rotation: expected = rest * R_z(angle).
  Document doc = newDocument();
  const int elbow = joint(doc, "LowerArm.L");
  const glm::quat rest = doc.skeleton().rest[elbow].rotation;
  const glm::vec3 z(0, 0, 1);
  ASSERT_EQ(setJointLimit(doc, elbow, JointLimit::hinge(z, 0.0f, glm::radians(45.0f))), "");
  ASSERT_EQ(setJointRotation(doc, elbow, rest * glm::angleAxis(glm::radians(90.0f), z)), "");
  expectSameRotation(doc.pose().local[elbow].rotation, rest * glm::angleAxis(glm::radians(45.0f), z), "90 -> 45");
  ASSERT_EQ(setJointRotation(doc, elbow, rest * glm::angleAxis(glm::radians(-30.0f), z)), "");
  expectSameRotation(doc.pose().local[elbow].rotation, rest, "-30 -> 0");
  ASSERT_EQ(setJointRotation(doc, elbow, rest * glm::angleAxis(glm::radians(20.0f), z)), "");
  expectSameRotation(doc.pose().local[elbow].rotation, rest * glm::angleAxis(glm::radians(20.0f), z), "20 inside");
  ASSERT_EQ(setJointRotation(doc, elbow, rest * glm::angleAxis(glm::radians(30.0f), glm::vec3(1, 0, 0))), "");
  expectSameRotation(doc.pose().local[elbow].rotation, rest, "off the hinge");
  // A gizmo drag is clamped each frame, and the committed step holds the clamped rotation.
  ASSERT_EQ(beginRotateDrag(doc, elbow), "");
  ASSERT_EQ(updateRotateDrag(doc, elbow, rest * glm::angleAxis(glm::radians(120.0f), z)), "");
  expectSameRotation(doc.pose().local[elbow].rotation, rest * glm::angleAxis(glm::radians(45.0f), z), "drag 120 -> 45");
  doc.commitDrag();
  expectSameRotation(doc.pose().local[elbow].rotation, rest * glm::angleAxis(glm::radians(45.0f), z), "committed");
  // limitedLocalRotation on a joint without a limit changes nothing.
  const int hand = joint(doc, "Hand.L");
  ASSERT_EQ(setJointRotation(doc, hand, glm::angleAxis(2.5f, z)), "");
  expectSameRotation(doc.pose().local[hand].rotation, glm::angleAxis(2.5f, z), "no limit");
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(DocumentSkinning, TheSkinningMethodIsAnUndoableEditOfTheMeshInstance) {
  Document doc = newDocument();  // the default character: one skinned body
  ASSERT_FALSE(doc.scene().meshInstances.empty());
  ASSERT_EQ(doc.scene().meshInstances[0].skinning, SkinningMethod::LinearBlend);
  ASSERT_EQ(setMeshSkinning(doc, 0, SkinningMethod::DualQuaternion), "");
  EXPECT_EQ(doc.scene().meshInstances[0].skinning, SkinningMethod::DualQuaternion);
  EXPECT_EQ(doc.historyLabels(), std::vector<std::string>{"Set skinning of mesh 0 to dual quaternion"});
  EXPECT_TRUE(doc.dirty());
  EXPECT_EQ(doc.sceneForSaving().meshInstances[0].skinning, SkinningMethod::DualQuaternion);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().meshInstances[0].skinning, SkinningMethod::LinearBlend);
  EXPECT_FALSE(doc.dirty());
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.scene().meshInstances[0].skinning, SkinningMethod::DualQuaternion);
  // Setting the same method again is no step; a missing instance is refused.
  ASSERT_EQ(setMeshSkinning(doc, 0, SkinningMethod::DualQuaternion), "");
  EXPECT_EQ(doc.historyPosition(), 1);
  EXPECT_NE(setMeshSkinning(doc, 99, SkinningMethod::LinearBlend), "");
  EXPECT_NE(setMeshSkinning(doc, -1, SkinningMethod::LinearBlend), "");
  EXPECT_EQ(doc.historyPosition(), 1);
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(DocumentSkinning, BindingAnUnskinnedMeshIsOneUndoStep) {
  // A two-bone chain up +Y and a 4-vertex quad along it on the root, not skinned.
  Scene s;
  Transform up;
  up.translation = {0, 1, 0};
  s.skeleton.addJoint("Root", -1, Transform{});
  s.skeleton.addJoint("Mid", 0, up);
  s.skeleton.addJoint("Tip", 1, up);
  MeshPrimitive p;
  p.positions = {{-0.1f, 0.2f, 0}, {0.1f, 0.2f, 0}, {-0.1f, 1.8f, 0}, {0.1f, 1.8f, 0}};
  p.indices = {0, 1, 3, 0, 3, 2};
  Mesh m;
  m.primitives.push_back(p);
  s.meshes.push_back(m);
  MeshInstance i;
  i.joint = 0;
  i.mesh = 0;
  s.meshInstances.push_back(i);
  Document doc(s);
  const long long revision = doc.meshRevision();
  ASSERT_EQ(bindUnskinnedMeshes(doc), "");
  ASSERT_EQ(doc.scene().skins.size(), 1u);
  EXPECT_EQ(doc.scene().meshInstances[0].skin, 0);
  const MeshPrimitive& bound = doc.scene().meshes[doc.scene().meshInstances[0].mesh].primitives[0];
  ASSERT_EQ(bound.influenceWeights.size(), 4u * kMaxInfluences);
  for (int v = 0; v < 4; ++v) {  // every vertex weighted, the weights summing to 1
    float sum = 0;
    for (int k = 0; k < kMaxInfluences; ++k) sum += bound.influenceWeights[v * kMaxInfluences + k];
    EXPECT_NEAR(sum, 1.0f, 1e-5f) << v;
  }
  EXPECT_EQ(doc.historyLabels(), std::vector<std::string>{"Bind meshes to the skeleton"});
  EXPECT_GT(doc.meshRevision(), revision);
  EXPECT_NE(bindUnskinnedMeshes(doc), "");  // nothing left to bind: refused, no step
  EXPECT_EQ(doc.historyPosition(), 1);
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().skins.empty());
  EXPECT_EQ(doc.scene().meshInstances[0].skin, -1);
  EXPECT_FALSE(doc.scene().meshes[0].primitives[0].skinned());
  EXPECT_FALSE(doc.dirty());
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.scene().meshInstances[0].skin, 0);
  // The bound scene is what Save writes.
  EXPECT_EQ(doc.sceneForSaving().skins.size(), 1u);
}

}  // namespace
}  // namespace kinema
