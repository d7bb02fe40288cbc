// I over a Properties field (issue 22): the hovered shape slider or deformer parameter is
// keyed at the playhead with the value it shows there; nothing hovered keys nothing.
#include <gtest/gtest.h>

#include "anim/scalar_property.h"
#include "editor/model/deformer_edits.h"
#include "editor/model/editor_state.h"
#include "editor/model/property_keying.h"
#include "editor/model/shape_keys.h"
#include "scene/default_character_scene.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

const Channel* scalar(const EditorState& s, const std::string& property) {
  if (!s.hasMotion()) return nullptr;
  for (const Channel& ch : s.doc.scene().clips[s.clip].channels)
    if (ch.target == ChannelTarget::Scalar && ch.property == property) return &ch;
  return nullptr;
}

TEST(PropertyKeying, KeysTheHoveredShapeOrDeformerParameterAtThePlayhead) {
  EditorState state;
  state.doc = Document(makeDefaultCharacterScene());
  const int history = state.doc.historyPosition();
  EXPECT_NE(keyHoveredProperty(state), "");
  EXPECT_EQ(state.doc.historyPosition(), history) << "nothing hovered: nothing keyed";

  ASSERT_EQ(setShapeWeight(state.doc, 0, 1, 0.25f), "");
  state.hoveredProperty.kind = HoveredProperty::Kind::ShapeWeight;
  state.hoveredProperty.instance = 0;
  state.hoveredProperty.target = 1;
  keyHoveredProperty(state);
  const Channel* smile = scalar(state, morphWeightProperty(1));
  ASSERT_NE(smile, nullptr);
  ASSERT_EQ(smile->times.size(), 1u);
  EXPECT_EQ(smile->values[0].x, 0.25f);

  ASSERT_EQ(addDeformer(state.doc, 0, DeformerType::Twist), "");
  ASSERT_EQ(setDeformerValue(state.doc, 0, 0, "angle", 0.5f), "");
  state.hoveredProperty = HoveredProperty{};
  state.hoveredProperty.kind = HoveredProperty::Kind::DeformerParameter;
  state.hoveredProperty.instance = 0;
  state.hoveredProperty.deformer = 0;
  state.hoveredProperty.parameter = "angle";
  state.time = 0.5;
  const int before = state.doc.historyPosition();
  keyHoveredProperty(state);
  EXPECT_EQ(state.doc.historyPosition(), before + 1);
  const Channel* angle = scalar(state, deformerParameterProperty("twist", "angle"));
  ASSERT_NE(angle, nullptr);
  ASSERT_EQ(angle->times.size(), 1u);
  EXPECT_EQ(angle->times[0], 0.5f);
  EXPECT_EQ(angle->values[0].x, 0.5f);
}

}  // namespace
}  // namespace kinema
