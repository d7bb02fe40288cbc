// The input layer without a window: script parsing, key names, and the viewport tools fed
// events on an EditorState with a hand-built camera (through the same EditorInput as the
// window, so keys reach the tools as commands).
#include <GLFW/glfw3.h>

#include "core/default_character.h"
#include "editor/commands/editor_input.h"
#include "editor/model/input_events.h"
#include "editor/viewport/viewport_tools.h"
#include "editor/model/document.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(InputScript, ParsesJsonLinesAndArraysSortedByFrame) {
  const std::string lines =
      "# a comment\n"
      "{\"frame\": 5, \"type\": \"key\", \"key\": \"KP_1\", \"mods\": [\"ctrl\"]}\n"
      "\n"
      "{\"frame\": 2, \"type\": \"mouse_move\", \"x\": 10.5, \"y\": 20}\n"
      "{\"frame\": 3, \"type\": \"click\", \"button\": \"middle\"}\n";
  Result<std::vector<InputEvent>> r = parseInputScript(lines, "s.jsonl");
  ASSERT_TRUE(r.ok()) << r.error();
  const std::vector<InputEvent>& e = r.value();
  ASSERT_EQ(e.size(), 5u);  // key and click expand into a down and an up
  EXPECT_EQ(e[0].type, InputEventType::MouseMove);
  EXPECT_FLOAT_EQ(e[0].x, 10.5f);
  EXPECT_EQ(e[1].type, InputEventType::ButtonDown);
  EXPECT_EQ(e[1].button, 2);
  EXPECT_EQ(e[2].type, InputEventType::ButtonUp);
  EXPECT_EQ(e[3].type, InputEventType::KeyDown);
  EXPECT_EQ(e[3].key, GLFW_KEY_KP_1);
  EXPECT_EQ(e[3].mods, kModCtrl);
  EXPECT_EQ(e[4].type, InputEventType::KeyUp);
  EXPECT_EQ(e[4].frame, 5);

  r = parseInputScript("[{\"frame\":1,\"type\":\"scroll\",\"y\":-2},{\"frame\":0,\"type\":\"text\",\"text\":\"45\"}]", "a.json");
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r.value().size(), 2u);
  EXPECT_EQ(r.value()[0].text, "45");
  EXPECT_FLOAT_EQ(r.value()[1].y, -2.0f);
}

TEST(InputScript, ErrorsNameTheFileTheLineAndTheField) {
  auto error = [](const std::string& text) {
    Result<std::vector<InputEvent>> r = parseInputScript(text, "s.jsonl");
    return r.ok() ? std::string("ok") : r.error();
  };
  EXPECT_EQ(error("{\"frame\":1,\"type\":\"key\",\"key\":\"R\"}\n{\"frame\":2,\"type\":\"key\",\"key\":\"WHAT\"}"),
            "s.jsonl: line 2: 'key' \"WHAT\" is not a GLFW key name");
  EXPECT_NE(error("{\"frame\":-1,\"type\":\"key\",\"key\":\"R\"}").find("line 1: 'frame'"), std::string::npos);
  EXPECT_NE(error("{\"frame\":1,\"type\":\"jump\"}").find("unknown 'type' \"jump\""), std::string::npos);
  EXPECT_NE(error("{\"frame\":1,\"type\":\"mouse_move\",\"x\":\"a\"}").find("'x' must be a number"), std::string::npos);
  EXPECT_NE(error("[{\"frame\":1,\"type\":\"click\",\"button\":\"nose\"}]").find("event 0: 'button'"), std::string::npos);
  EXPECT_NE(error("{\"frame\":1,").find("line 1: not valid JSON"), std::string::npos);
  EXPECT_NE(error(std::string(100000, '[')).find("nested deeper"), std::string::npos);
  EXPECT_NE(error("[1, 2").find("not valid JSON"), std::string::npos);
}

TEST(InputScript, KeyNamesRoundTripThroughGlfwCodes) {
  for (const char* name : {"A", "Z", "0", "9", "KP_0", "KP_7", "F1", "F12", "LEFT_SHIFT", "ESCAPE", "HOME", "ENTER"})
    EXPECT_EQ(keyNameFromCode(keyCodeFromName(name)), name);
  EXPECT_EQ(keyCodeFromName("R"), GLFW_KEY_R);
  EXPECT_EQ(keyCodeFromName("KP_5"), GLFW_KEY_KP_5);
  EXPECT_EQ(keyCodeFromName("r"), -1);
  EXPECT_EQ(keyCodeFromName("F0"), -1);
  EXPECT_EQ(keyCodeFromName(""), -1);
}

// The default character seen from the front (azimuth 0, elevation 0) at distance 5 on
// the point (0, 1, 0), 35 degrees vertical field in 800x600 pixels.
struct FrontView {
  EditorState state;
  ViewportView view;
  SkeletonDrawList list;
  ViewportTools tools;
  EditorInput input;
  Keymap keymap;
  FrontView() {
    Scene scene;
    scene.skeleton = makeDefaultCharacter();
    state.doc = Document(scene);
    state.camera.azimuthDeg = 0;
    state.camera.elevationDeg = 0;
    state.camera.distance = 5;
    state.camera.target = glm::vec3(0, 1, 0);
    state.camera.fovYDeg = 35;
    view = ViewportView::of(state.camera, glm::vec2(800, 600));
    refresh();
  }
  void refresh() {
    evaluateEditorPose(state);
    SkeletonDrawJob job;
    job.parents = &state.doc.skeleton().parents;
    job.world = &state.world();
    job.run(list);
  }
  int joint(const char* name) const { return state.doc.skeleton().find(name); }
  glm::vec3 position(const char* name) const { return glm::vec3(state.world()[joint(name)][3]); }
  // Pixel of a world point by hand: focal length 300 / tan(17.5 deg) pixels at depth 5 - z.
  glm::vec2 pixel(glm::vec3 p) const {
    const float f = 300.0f / std::tan(glm::radians(17.5f));
    return glm::vec2(400 + f * p.x / (5 - p.z), 300 - f * (p.y - 1) / (5 - p.z));
  }
  glm::vec2 pixelOf(const char* name) const { return pixel(position(name)); }
  void send(InputEventType type, float x = 0, float y = 0, int key = -1, int button = 0) {
    InputEvent e;
    e.type = type;
    e.x = x;
    e.y = y;
    e.key = key;
    e.button = button;
    CommandContext ctx(state);
    ctx.tools = &tools;
    ctx.view = view;
    ctx.keymap = &keymap;
    input.handle(ctx, e, list, false, false);
    refresh();
  }
  void move(glm::vec2 p) { send(InputEventType::MouseMove, p.x, p.y); }
  void click(glm::vec2 p) {
    move(p);
    send(InputEventType::ButtonDown);
    send(InputEventType::ButtonUp);
  }
  void key(int k) {
    send(InputEventType::KeyDown, 0, 0, k);
    send(InputEventType::KeyUp, 0, 0, k);
  }
};

TEST(ViewportTools, ClickOnABoneSelectsItsHeadJoint) {
  FrontView v;
  const glm::vec2 mid = (v.pixelOf("Hand.L") + v.pixelOf("Fingertip.L")) * 0.5f;
  v.click(mid);
  EXPECT_EQ(v.state.doc.selection.joints(), std::vector<int>{v.joint("Hand.L")});
  v.click(mid + glm::vec2(0, 120));  // nothing there (beyond the gizmo): a click clears
  EXPECT_TRUE(v.state.doc.selection.empty());
}

TEST(ViewportTools, BoxSelectAndShiftClick) {
  FrontView v;
  const glm::vec2 a = v.pixelOf("LowerArm.L") + glm::vec2(-10, -20), b = v.pixelOf("Fingertip.L") + glm::vec2(10, 20);
  v.move(a);
  v.send(InputEventType::ButtonDown);
  v.move((a + b) * 0.5f);
  EXPECT_EQ(v.state.tool.mode, ModalTool::BoxSelect);
  v.move(b);
  v.send(InputEventType::ButtonUp);
  EXPECT_EQ(v.state.doc.selection.joints(),
            (std::vector<int>{v.joint("LowerArm.L"), v.joint("Hand.L"), v.joint("Fingertip.L")}));
  v.send(InputEventType::KeyDown, 0, 0, GLFW_KEY_LEFT_SHIFT);
  v.click(v.pixelOf("LowerArm.R"));  // Shift-click adds
  v.send(InputEventType::KeyUp, 0, 0, GLFW_KEY_LEFT_SHIFT);
  EXPECT_TRUE(v.state.doc.selection.isSelected(v.joint("LowerArm.R")));
  EXPECT_EQ(v.state.doc.selection.joints().size(), 4u);
}

TEST(ViewportTools, RSweepRotatesTheForearmAndIsOneUndoStep) {
  FrontView v;
  const glm::vec2 p = v.pixelOf("LowerArm.L");
  v.click((p + v.pixelOf("Hand.L")) * 0.5f);
  ASSERT_EQ(v.state.doc.selection.active(), v.joint("LowerArm.L"));
  v.move(p + glm::vec2(0, -80));  // straight above the elbow
  v.key(GLFW_KEY_R);
  EXPECT_EQ(v.state.tool.mode, ModalTool::Rotate);
  v.move(p + glm::vec2(-80, -80));
  v.move(p + glm::vec2(-80, 0));  // a quarter turn counter-clockwise on screen
  v.send(InputEventType::ButtonDown);
  v.send(InputEventType::ButtonUp);
  // Free R turns about the line from the elbow to the eye (it projects to the elbow's pixel,
  // so the bone follows the cursor): +90 degrees about u takes the forearm f = (0.26, 0, 0)
  // to (u.f) u + u x f (Rodrigues with cos = 0, sin = 1).
  const glm::vec3 e = v.position("LowerArm.L");
  const glm::vec3 u = glm::normalize(glm::vec3(0, 1, 5) - e), f(0.26f, 0, 0);
  EXPECT_VEC3_NEAR(v.position("Hand.L"), e + glm::dot(u, f) * u + glm::cross(u, f), 1e-4f);
  EXPECT_EQ(v.state.doc.historyPosition(), 1);
  ASSERT_TRUE(v.state.doc.undo());
  v.refresh();
  EXPECT_VEC3_NEAR(v.position("Hand.L"), glm::vec3(0.71f, 1.45f, 0), 1e-5f);
}

TEST(ViewportTools, RThenZAndTypedDegreesAndEscapeCancels) {
  FrontView v;
  v.click((v.pixelOf("LowerArm.L") + v.pixelOf("Hand.L")) * 0.5f);
  v.key(GLFW_KEY_R);
  v.key(GLFW_KEY_Z);
  EXPECT_EQ(v.state.tool.axis, AxisConstraint::Z);
  v.key(GLFW_KEY_3);
  v.key(GLFW_KEY_0);
  v.key(GLFW_KEY_ENTER);
  const float c = std::cos(glm::radians(30.0f)), s = std::sin(glm::radians(30.0f));
  EXPECT_VEC3_NEAR(v.position("Hand.L"), v.position("LowerArm.L") + 0.26f * glm::vec3(c, s, 0), 1e-5f);
  const glm::vec3 before = v.position("Hand.L");
  v.key(GLFW_KEY_R);
  v.key(GLFW_KEY_9);
  v.key(GLFW_KEY_ESCAPE);
  EXPECT_VEC3_NEAR(v.position("Hand.L"), before, 1e-6f);
  EXPECT_EQ(v.state.doc.historyPosition(), 1);
  EXPECT_EQ(v.state.tool.mode, ModalTool::None);
}

TEST(ViewportTools, GMovesTheRootWithTheCursorInTheViewPlane) {
  FrontView v;
  const glm::vec2 m(600, 450);
  v.move(m);
  v.key(GLFW_KEY_G);
  v.move(m + glm::vec2(60, 0));
  v.key(GLFW_KEY_ENTER);
  // 60 px at the hips' depth (5 from the eye): 60 * 10 tan(17.5 deg) / 600 units along +X.
  EXPECT_VEC3_NEAR(v.position("Hips"), glm::vec3(60 * 10 * std::tan(glm::radians(17.5f)) / 600, 0.95f, 0), 1e-5f);
}

TEST(ViewportTools, CameraKeys) {
  FrontView v;
  v.key(GLFW_KEY_KP_3);
  EXPECT_FLOAT_EQ(v.state.camera.azimuthDeg, 90.0f);
  v.key(GLFW_KEY_KP_5);
  EXPECT_TRUE(v.state.camera.orthographic);
  v.send(InputEventType::KeyDown, 0, 0, GLFW_KEY_LEFT_CONTROL);
  v.key(GLFW_KEY_KP_1);
  EXPECT_FLOAT_EQ(v.state.camera.azimuthDeg, 180.0f);
  v.key(GLFW_KEY_I);
  EXPECT_TRUE(v.state.view.autoIk);
}

}  // namespace
}  // namespace kinema::test
