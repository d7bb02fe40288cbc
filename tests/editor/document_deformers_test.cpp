// The editor's document carries the scene's deformer stacks (issue 22): an edit of the
// meshes may change them as one undo step, invalid stacks are refused, and a save keeps them.
#include <gtest/gtest.h>

#include "core/forward_kinematics.h"
#include "editor/model/deformer_edits.h"
#include "editor/model/document.h"
#include "scene/default_character_scene.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Deformer twist(const std::string& name, float angle) {
  Deformer d;
  d.name = name;
  d.type = DeformerType::Twist;
  d.axis.kind = AxisDeformerKind::Twist;
  d.axis.low = 1.0f;
  d.axis.high = 1.6f;
  d.axis.amount = angle;
  return d;
}

TEST(DocumentDeformers, AddingADeformerIsOneUndoStep) {
  Document doc(makeDefaultCharacterScene());
  const long long revision = doc.meshRevision();
  ASSERT_EQ(doc.editMeshes("Add Twist", [](Scene& s) {
    s.editDeformerStack(0).deformers.push_back(twist("twist", 0.5f));
    return std::string();
  }), "");
  EXPECT_GT(doc.meshRevision(), revision);  // the renderers see a new mesh state
  ASSERT_NE(doc.scene().deformerStack(0), nullptr);
  EXPECT_EQ(doc.scene().deformerStack(0)->deformers[0].axis.amount, 0.5f);
  EXPECT_EQ(doc.sceneForSaving().deformers.size(), 1u);
  doc.undo();
  EXPECT_EQ(doc.scene().deformerStack(0), nullptr);
  doc.redo();
  ASSERT_NE(doc.scene().deformerStack(0), nullptr);
  EXPECT_EQ(doc.scene().deformerStack(0)->deformers[0].name, "twist");
}

TEST(DocumentDeformers, InvalidStacksAreRefusedAndChangeNothing) {
  Document doc(makeDefaultCharacterScene());
  const std::string error = doc.editMeshes("Add Twists", [](Scene& s) {
    s.editDeformerStack(0).deformers = {twist("t", 0.1f), twist("t", 0.2f)};
    return std::string();
  });
  EXPECT_EQ(error, "mesh instance 0: deformer 1 ('t'): the name is used by deformer 0 too");
  EXPECT_TRUE(doc.scene().deformers.empty());
  EXPECT_FALSE(doc.dirty());
}

TEST(DocumentDeformers, PanelEditsAreUndoSteps) {
  Document doc(makeDefaultCharacterScene());
  ASSERT_EQ(addDeformer(doc, 0, DeformerType::Twist), "");
  ASSERT_EQ(addDeformer(doc, 0, DeformerType::Twist), "");
  ASSERT_EQ(addDeformer(doc, 0, DeformerType::Lattice), "");
  const DeformerStack* stack = doc.scene().deformerStack(0);
  ASSERT_NE(stack, nullptr);
  ASSERT_EQ(stack->deformers.size(), 3u);
  EXPECT_EQ(stack->deformers[0].name, "twist");
  EXPECT_EQ(stack->deformers[1].name, "twist.001");
  // A new lattice sits at rest around the body: every point at its rest place.
  const FfdLattice& lattice = stack->deformers[2].lattice;
  EXPECT_EQ(lattice.pointCount(), 27);
  EXPECT_EQ(lattice.points[13], lattice.restPoint(1, 1, 1));
  // The twist spans the body's height, upwards from its lowest point.
  EXPECT_EQ(stack->deformers[0].axis.low, 0.0f);
  EXPECT_GT(stack->deformers[0].axis.high, 1.5f);

  ASSERT_EQ(setDeformerValue(doc, 0, 1, "angle", 0.5f), "");
  EXPECT_EQ(doc.scene().deformers[0].deformers[1].axis.amount, 0.5f);
  EXPECT_NE(setDeformerValue(doc, 0, 1, "factor", 2.0f), "");
  ASSERT_EQ(moveDeformer(doc, 0, 1, -1), "");
  EXPECT_EQ(doc.scene().deformers[0].deformers[0].name, "twist.001");
  EXPECT_NE(moveDeformer(doc, 0, 0, -1), "");
  ASSERT_EQ(setDeformerEnabled(doc, 0, 0, false), "");
  EXPECT_FALSE(doc.scene().deformers[0].deformers[0].enabled);
  ASSERT_EQ(removeDeformer(doc, 0, 2), "");
  EXPECT_EQ(doc.scene().deformers[0].deformers.size(), 2u);
  // Undo walks back through remove, disable, move and set.
  for (int k = 0; k < 4; ++k) doc.undo();
  EXPECT_EQ(doc.scene().deformers[0].deformers[1].name, "twist.001");
  EXPECT_EQ(doc.scene().deformers[0].deformers[1].axis.amount, 0.0f);
  EXPECT_TRUE(doc.scene().deformers[0].deformers[1].enabled);
  EXPECT_EQ(doc.scene().deformers[0].deformers.size(), 3u);
}

TEST(DocumentDeformers, KeyedParametersAreInterpolatedChannels) {
  Document doc(makeDefaultCharacterScene());
  ASSERT_EQ(addDeformer(doc, 0, DeformerType::Lattice), "");
  int clip = -1;
  KeyPreferences linear;
  linear.interpolation = Interpolation::Linear;
  const float y0 = doc.scene().deformers[0].deformers[0].lattice.points[26].y;
  ASSERT_EQ(keyDeformerValue(doc, clip, 0, 0, "point.26.y", 0.0f, y0, linear), "");
  ASSERT_EQ(keyDeformerValue(doc, clip, 0, 0, "point.26.y", 2.0f, y0 + 0.2f, linear), "");
  EXPECT_EQ(clip, 0);
  const Channel& ch = doc.scene().clips[0].channels.at(0);
  EXPECT_EQ(ch.property, "deformers/lattice/point.26.y");
  EXPECT_NEAR(deformerValueAt(doc, 0, 1.0, 0, 0, "point.26.y"), y0 + 0.1f, 1e-6f);  // half way
  EXPECT_NEAR(deformerValueAt(doc, -1, 1.0, 0, 0, "point.26.y"), y0, 0.0f);  // no clip: as placed
  EXPECT_NE(keyDeformerValue(doc, clip, 0, 0, "angle", 0.0f, 1.0f, linear), "");
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(DocumentDeformers, ASoftPullsCentreRadiusAndFalloffAreOneUndoStepAndKeepItsOffset) {
  Document doc(makeDefaultCharacterScene());
  ASSERT_EQ(addDeformer(doc, 0, DeformerType::SoftPull), "");
  ASSERT_EQ(setDeformerValue(doc, 0, 0, "offset.y", 0.05f), "");
  const size_t steps = doc.historyLabels().size();
  const SoftPull before = doc.scene().deformers[0].deformers[0].pull;
  ASSERT_EQ(setSoftPullShape(doc, 0, 0, glm::vec3(0.1f, 1.2f, 0.1f), 0.2f, Falloff::Linear), "");
  EXPECT_EQ(doc.historyLabels().size(), steps + 1);
  const SoftPull& pull = doc.scene().deformers[0].deformers[0].pull;
  EXPECT_EQ(pull.center, glm::vec3(0.1f, 1.2f, 0.1f));
  EXPECT_EQ(pull.radius, 0.2f);
  EXPECT_EQ(pull.falloff, Falloff::Linear);
  EXPECT_EQ(pull.offset, glm::vec3(0.0f, 0.05f, 0.0f)) << "the keyable offset stays";
  EXPECT_NE(setSoftPullShape(doc, 0, 0, glm::vec3(0.0f), -1.0f, Falloff::Smooth), "") << "a radius must be positive";
  EXPECT_EQ(doc.historyLabels().size(), steps + 1);
  ASSERT_EQ(addDeformer(doc, 0, DeformerType::Bend), "");
  EXPECT_NE(setSoftPullShape(doc, 0, 1, glm::vec3(0.0f), 0.1f, Falloff::Smooth), "") << "not a soft pull";
  ASSERT_TRUE(doc.undo());  // the bend
  ASSERT_TRUE(doc.undo());  // the centre, radius and falloff
  const SoftPull& undone = doc.scene().deformers[0].deformers[0].pull;
  EXPECT_EQ(undone.center, before.center);
  EXPECT_EQ(undone.radius, before.radius);
  EXPECT_EQ(undone.falloff, before.falloff);
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(DocumentDeformers, PlacementAndScopeEditsAreUndoStepsThatChangeWhatTheyName) {
  Document doc(makeDefaultCharacterScene());
  const Skeleton& sk = doc.skeleton();
  ASSERT_EQ(addDeformer(doc, 0, DeformerType::Lattice), "");
  const FfdLattice before = doc.scene().deformers[0].deformers[0].lattice;
  const size_t steps = doc.historyLabels().size();

  // Resolution: a 4x2x3 grid over the same rest box, every point at rest.
  const int counts[3] = {4, 2, 3};
  ASSERT_EQ(setLatticeResolution(doc, 0, 0, counts), "");
  const FfdLattice& res = doc.scene().deformers[0].deformers[0].lattice;
  EXPECT_EQ(res.pointCount(), 24);
  EXPECT_EQ(res.origin, before.origin);
  EXPECT_EQ(res.points[static_cast<size_t>(res.index(3, 1, 2))], before.origin + before.axes[0] + before.axes[1] + before.axes[2]);
  const int tooMany[3] = {9, 2, 2};
  EXPECT_NE(setLatticeResolution(doc, 0, 0, tooMany), "");
  EXPECT_EQ(doc.historyLabels().size(), steps + 1);

  // Fitted around the head: the box holds the head's vertices and is far shorter than the body's.
  const int head = sk.find("Head");
  ASSERT_EQ(fitLatticeToJoints(doc, 0, 0, {head}), "");
  const FfdLattice& fitted = doc.scene().deformers[0].deformers[0].lattice;
  EXPECT_LT(glm::length(fitted.axes[1]), 0.5f * glm::length(before.axes[1]));
  EXPECT_GT(fitted.origin.y, before.origin.y + 1.0f) << "up at the head";

  // Parented to the chest: its rest matrix is the chest's at the rest pose.
  const int chest = sk.find("Chest");
  ASSERT_EQ(setDeformerParent(doc, 0, 0, chest), "");
  EXPECT_EQ(doc.scene().deformers[0].deformers[0].parentJoint, chest);
  EXPECT_EQ(doc.scene().deformers[0].deformers[0].parentRest, computeWorld(sk, Pose::rest(sk))[chest]);

  // Limited to the head's skin weights: each vertex's weight is the sum of its head influences.
  ASSERT_EQ(limitDeformerToJoint(doc, 0, 0, head), "");
  const Scene& scene = doc.scene();
  const Deformer& limited = scene.deformers[0].deformers[0];
  const MeshInstance& mi = scene.meshInstances[0];
  const std::vector<MeshPrimitive>& prims = scene.meshes[static_cast<size_t>(mi.mesh)].primitives;
  ASSERT_EQ(limited.weights.size(), prims.size());
  int weighted = 0;
  for (size_t p = 0; p < prims.size(); ++p)
    for (int v = 0; v < prims[p].vertexCount(); ++v) {
      float expected = 0.0f;
      for (int k = 0; k < kMaxInfluences; ++k) {
        const size_t at = static_cast<size_t>(v) * kMaxInfluences + static_cast<size_t>(k);
        if (scene.skins[static_cast<size_t>(mi.skin)].joints[prims[p].influenceJoints[at]] == head)
          expected += prims[p].influenceWeights[at];
      }
      EXPECT_FLOAT_EQ(limited.weights[p][static_cast<size_t>(v)], expected);
      weighted += expected > 0.0f;
    }
  EXPECT_GT(weighted, 10);
  ASSERT_EQ(limitDeformerToJoint(doc, 0, 0, -1), "");
  EXPECT_TRUE(doc.scene().deformers[0].deformers[0].weights.empty());

  // A twist's axis and range; a range that is empty is refused.
  ASSERT_EQ(addDeformer(doc, 0, DeformerType::Twist), "");
  ASSERT_EQ(setAxisRange(doc, 0, 1, DeformAxis::X, -0.2f, 0.3f), "");
  EXPECT_EQ(doc.scene().deformers[0].deformers[1].axis.axis, DeformAxis::X);
  EXPECT_EQ(doc.scene().deformers[0].deformers[1].axis.high, 0.3f);
  EXPECT_NE(setAxisRange(doc, 0, 1, DeformAxis::Y, 0.5f, 0.1f), "");
  EXPECT_NE(setAxisRange(doc, 0, 0, DeformAxis::Y, 0.0f, 1.0f), "") << "a lattice has no axis";
  // Every accepted change was one step: resolution, fit, parent, limit, unlimit, add, axis.
  EXPECT_EQ(doc.historyLabels().size(), steps + 7);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().deformers[0].deformers[1].axis.axis, DeformAxis::Y);
}

}  // namespace
}  // namespace kinema
