// Add Modifier in the curve editor's model (editor/model/channel_modifier_edits.h): which
// channels it acts on, the defaults, one undo step that restores the clip, and the refusal of
// a second Cycles modifier.
#include <gtest/gtest.h>

#include "anim/channel_modifiers.h"
#include "editor/model/channel_modifier_edits.h"
#include "editor/model/document.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// Root at (0, 1, 0); A 0.5 m above it. Channels: root translation, root rotation, A rotation.
Scene testScene() {
  Scene scene;
  const int root = scene.skeleton.addJoint("Root", -1, Transform::fromTranslation({0, 1, 0}));
  const int a = scene.skeleton.addJoint("A", root, Transform::fromTranslation({0, 0.5f, 0}));
  Clip clip;
  clip.frameTime = 1.0 / 24;
  clip.channels.emplace_back(root, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{{0, 1, 0, 0}, {1, 1, 0, 0}});
  clip.channels.emplace_back(root, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{{0, 0, 0, 1}, {0, 0.6f, 0, 0.8f}});
  clip.channels.emplace_back(a, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{{0, 0, 0, 1}, {0.6f, 0, 0, 0.8f}});
  scene.clips.push_back(clip);
  return scene;
}

TEST(ChannelModifierEdits, TargetsAreTheSelectedKeysChannelsElseEveryShownChannel) {
  const Scene scene = testScene();
  JointSelection selection;
  CurveEditorState state;
  EXPECT_TRUE(modifierTargetChannels(scene.clips[0], selection, state).empty());
  selection.click(0);
  EXPECT_EQ(modifierTargetChannels(scene.clips[0], selection, state), (std::vector<int>{0, 1}));
  state.selected = {{1, 0, 1}, {1, 2, 0}, {2, 0, 0}};  // channel 2 is not shown (joint A unselected)
  EXPECT_EQ(modifierTargetChannels(scene.clips[0], selection, state), (std::vector<int>{1}));
}

TEST(ChannelModifierEdits, AddIsOneUndoStepAndTheWaveKnowsTheJointsRestPosition) {
  Document doc(testScene());
  const Clip before = doc.scene().clips[0];
  ASSERT_EQ(addChannelModifierEdit(doc, 0, {0, 2}, ChannelModifierKind::Wave), "");
  const Clip& after = doc.scene().clips[0];
  ASSERT_EQ(after.channels[0].modifiers.size(), 1u);
  EXPECT_TRUE(after.channels[1].modifiers.empty());
  ASSERT_EQ(after.channels[2].modifiers.size(), 1u);
  EXPECT_EQ(after.channels[2].modifiers[0].kind, ChannelModifierKind::Wave);
  EXPECT_EQ(after.channels[2].modifiers[0].wave.position, glm::vec3(0, 1.5f, 0));  // 1 + 0.5
  EXPECT_EQ(after.channels[0].modifiers[0].wave.position, glm::vec3(0, 1, 0));
  EXPECT_EQ(after.channels[2].modifiers[0].wave.amplitude, 0.1f);  // an angle: 0.1 rad
  EXPECT_EQ(after.channels[0].modifiers[0].wave.amplitude, 0.05f);  // metres
  EXPECT_EQ(doc.historyLabels().back(), "Add Wave Modifier to 2 channels");
  // The modified clip plays differently from its keys.
  Pose moved = Pose::rest(doc.skeleton()), keyed = Pose::rest(doc.skeleton());
  sampleClip(after, 0.3f, moved);
  sampleClip(before, 0.3f, keyed);
  EXPECT_GT(glm::length(moved.local[0].translation - keyed.local[0].translation), 1e-3f);
  ASSERT_TRUE(doc.undo());
  for (const Channel& ch : doc.scene().clips[0].channels) EXPECT_TRUE(ch.modifiers.empty());
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.scene().clips[0].channels[2].modifiers.size(), 1u);
}

TEST(ChannelModifierEdits, ASecondCyclesModifierIsRefusedAndNothingChanges) {
  Document doc(testScene());
  ASSERT_EQ(addChannelModifierEdit(doc, 0, {1}, ChannelModifierKind::Cycles), "");
  const size_t steps = doc.historyLabels().size();
  EXPECT_EQ(addChannelModifierEdit(doc, 0, {0, 1}, ChannelModifierKind::Cycles),
            "Add Cycles Modifier: channel 1 already has a Cycles modifier (a channel takes one)");
  EXPECT_TRUE(doc.scene().clips[0].channels[0].modifiers.empty());  // reverted with the rest
  EXPECT_EQ(doc.historyLabels().size(), steps);
  EXPECT_EQ(addChannelModifierEdit(doc, 0, {}, ChannelModifierKind::Noise),
            "Add Noise Modifier: select a joint with animated channels (or keys in the curve editor) first");
  // Noise defaults: seeded by the joint, two octaves of half-second cells.
  ASSERT_EQ(addChannelModifierEdit(doc, 0, {2}, ChannelModifierKind::Noise), "");
  const ChannelModifier& n = doc.scene().clips[0].channels[2].modifiers[0];
  EXPECT_EQ(n.noise.seed, 1u);
  EXPECT_EQ(n.noise.octaves, 2);
  EXPECT_EQ(n.noise.scale, 0.5f);
  EXPECT_EQ(n.validate(), "");
}

TEST(ChannelModifierEdits, TheCurveEditorPlotsThePlayedCurve) {
  Document doc(testScene());
  const Channel plain = doc.scene().clips[0].channels[0];
  EXPECT_TRUE(modifiedCurvePoints(plain, 1, RotationView::Euler, EulerOrder::XYZ, 0.0f, 1.0f, 11).times.empty());
  ASSERT_EQ(addChannelModifierEdit(doc, 0, {0}, ChannelModifierKind::Noise), "");
  const Channel& ch = doc.scene().clips[0].channels[0];
  // Past the last key too: the played curve spans the asked range, point for point.
  const CurvePoints p = modifiedCurvePoints(ch, 1, RotationView::Euler, EulerOrder::XYZ, -0.5f, 2.0f, 26);
  ASSERT_EQ(p.times.size(), 26u);
  EXPECT_TRUE(p.keyTimes.empty());
  for (size_t i = 0; i < p.times.size(); ++i) {
    EXPECT_NEAR(p.times[i], -0.5f + 0.1f * i, 1e-6f);
    EXPECT_EQ(p.values[i], sampleModifiedChannel(ch, p.times[i]).y);  // metres, shown as stored
  }
}

}  // namespace
}  // namespace kinema
