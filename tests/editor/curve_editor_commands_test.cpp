// The curve editor's keys through the command registry and key dispatch (no window): A
// selects every key of the shown curves, Alt+A none, B arms a box; and the Esc that closes
// an open popup reaches no tool, while without a popup Esc still cancels the rotate tool.
#include "core/default_character.h"
#include "editor/commands/editor_input.h"
#include "editor/model/key_codes.h"
#include "editor/model/keying.h"
#include "editor/model/pose_edits.h"
#include "editor/viewport/viewport_tools.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

struct CurveEditorKeys {
  EditorState state;
  Keymap keymap;
  EditorInput input;
  ViewportTools tools;
  SkeletonDrawList list;
  const glm::vec2 overView{500, 200}, overCurves{500, 19 + 400 + 10};

  CurveEditorKeys() {
    Scene scene;
    scene.skeleton = makeDefaultCharacter();
    state.doc = Document(scene);
    state.viewportRect = glm::vec4(250, 19, 720, 400);
    state.animationEditor = AnimationEditorKind::CurveEditor;
    evaluateEditorPose(state);
  }
  CommandContext context() {
    CommandContext ctx(state);
    ctx.keymap = &keymap;
    ctx.tools = &tools;
    ctx.view = ViewportView::of(state.camera, glm::vec2(720, 400), glm::vec2(250, 19));
    return ctx;
  }
  void send(InputEventType type, int key = -1, glm::vec2 at = glm::vec2(0.0f)) {
    InputEvent e;
    e.type = type;
    e.key = key;
    e.x = at.x;
    e.y = at.y;
    CommandContext ctx = context();
    input.handle(ctx, e, list, false, false);
    evaluateEditorPose(state);
  }
  void mouse(glm::vec2 p) { send(InputEventType::MouseMove, -1, p); }
  void key(int k, int modifier = -1) {
    if (modifier >= 0) send(InputEventType::KeyDown, modifier);
    send(InputEventType::KeyDown, k);
    send(InputEventType::KeyUp, k);
    if (modifier >= 0) send(InputEventType::KeyUp, modifier);
  }
};

TEST(CurveEditorKeys, ASelectsEveryShownKeyAltADeselectsAndBArmsABox) {
  CurveEditorKeys e;
  const int arm = e.state.doc.skeleton().find("UpperArm.L");
  int clip = -1;
  ASSERT_EQ(insertKeys(e.state.doc, clip, 1.0f / 24, {arm}, KeyPreferences{}), "");
  ASSERT_EQ(setJointRotation(e.state.doc, arm, glm::angleAxis(0.5f, glm::vec3(0, 0, 1))), "");
  ASSERT_EQ(insertKeys(e.state.doc, clip, 11.0f / 24, {arm}, KeyPreferences{}), "");
  e.state.clip = clip;
  e.state.doc.selection.click(arm);
  // Over the 3D view A selects joints, not keys.
  e.mouse(e.overView);
  e.key(keys::A);
  EXPECT_TRUE(e.state.curveEditor.selected.empty());
  // Over the curve editor: location x y z and rotation X Y Z (Euler view), two keys each.
  e.state.doc.selection.click(arm);
  e.mouse(e.overCurves);
  e.key(keys::A);
  EXPECT_EQ(e.state.curveEditor.selected.size(), 12u);
  EXPECT_EQ(e.state.doc.selection.joints(), std::vector<int>{arm}) << "the joints stay as they were";
  e.key(keys::A, keys::LEFT_ALT);
  EXPECT_TRUE(e.state.curveEditor.selected.empty());
  e.key(keys::B);
  EXPECT_TRUE(e.state.curveEditor.boxArmed);
  // While the editor's own drag runs, its keys are not commands.
  e.state.curveEditor.boxArmed = false;
  e.state.curveEditor.drag = CurveEditorState::Drag::Box;
  e.key(keys::A);
  EXPECT_TRUE(e.state.curveEditor.selected.empty());
}

TEST(CurveEditorKeys, EscClosingAPopupCancelsNothingElse) {
  CurveEditorKeys e;
  e.state.doc.selection.click(e.state.doc.skeleton().find("UpperArm.L"));
  e.mouse(e.overView);
  e.key(keys::R);
  ASSERT_EQ(e.state.tool.mode, ModalTool::Rotate);
  // A combo is open (the panels say so at the end of each frame): its Esc closes it only.
  e.state.panels.popupOpen = true;
  e.key(keys::ESCAPE);
  EXPECT_EQ(e.state.tool.mode, ModalTool::Rotate);
  // No popup: Esc cancels the tool as before.
  e.state.panels.popupOpen = false;
  e.key(keys::ESCAPE);
  EXPECT_EQ(e.state.tool.mode, ModalTool::None);
}

}  // namespace
}  // namespace kinema::test
