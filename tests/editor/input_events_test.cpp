// The input layer without a window: script parsing, key names, and the viewport tools fed
// events on an EditorState with a hand-built camera.
#include <GLFW/glfw3.h>

#include "core/default_character.h"
#include "editor/input_events.h"
#include "editor/viewport_tools.h"
#include "test_support.h"

namespace kinema::test {
namespace {

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
  ViewportGeometry g;
  ViewportTools tools;
  FrontView() {
    state.scene.skeleton = makeDefaultCharacter();
    evaluateEditorPose(state);
    state.camera.azimuthDeg = 0;
    state.camera.elevationDeg = 0;
    state.camera.distance = 5;
    state.camera.target = glm::vec3(0, 1, 0);
    state.camera.fovYDeg = 35;
    g = viewportGeometry(state.camera, false, glm::vec2(800, 600));
  }
  // Pixel of a world point by hand: focal length 300 / tan(17.5 deg) pixels at depth 5 - z.
  glm::vec2 pixel(glm::vec3 p) const {
    const float f = 300.0f / std::tan(glm::radians(17.5f));
    return glm::vec2(400 + f * p.x / (5 - p.z), 300 - f * (p.y - 1) / (5 - p.z));
  }
  glm::vec2 pixelOf(const char* name) const {
    return pixel(glm::vec3(state.world[state.scene.skeleton.find(name)][3]));
  }
  void send(InputEventType type, float x = 0, float y = 0, int key = -1, int button = 0) {
    InputEvent e;
    e.type = type;
    e.x = x;
    e.y = y;
    e.key = key;
    e.button = button;
    tools.handle(state, e, g, false, false);
    evaluateEditorPose(state);
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

TEST(ViewportTools, ProjectionMatchesAHandPinhole) {
  FrontView v;
  glm::vec2 p;
  ASSERT_TRUE(v.g.toScreen(glm::vec3(0.71f, 1.45f, 0.0f), p));
  const glm::vec2 q = v.pixel(glm::vec3(0.71f, 1.45f, 0.0f));
  EXPECT_NEAR(p.x, q.x, 1e-2f);
  EXPECT_NEAR(p.y, q.y, 1e-2f);
  // At depth 5 one pixel is 2 * 5 * tan(17.5 deg) / 600 units.
  EXPECT_NEAR(v.g.unitsPerPixel(glm::vec3(0.3f, 0.2f, 0.0f)), 10 * std::tan(glm::radians(17.5f)) / 600, 1e-6);
}

TEST(ViewportTools, PickingPrefersJointsAndBonesPickTheirHead) {
  FrontView v;
  const glm::vec2 mid = (v.pixelOf("Hand.L") + v.pixelOf("Fingertip.L")) * 0.5f;
  EXPECT_EQ(pickJointOrBone(v.state, v.g, mid), v.state.scene.skeleton.find("Hand.L"));
  EXPECT_EQ(pickJointOrBone(v.state, v.g, v.pixelOf("Fingertip.L")), v.state.scene.skeleton.find("Fingertip.L"));
  EXPECT_EQ(pickJointOrBone(v.state, v.g, mid + glm::vec2(0, 40)), -1);
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
  const Skeleton& s = v.state.scene.skeleton;
  EXPECT_EQ(v.state.selection, (std::vector<int>{s.find("LowerArm.L"), s.find("Hand.L"), s.find("Fingertip.L")}));
  v.send(InputEventType::KeyDown, 0, 0, GLFW_KEY_LEFT_SHIFT);
  v.click(v.pixelOf("Hand.L"));  // Shift-click on a selected joint removes it
  v.send(InputEventType::KeyUp, 0, 0, GLFW_KEY_LEFT_SHIFT);
  EXPECT_EQ(v.state.selection, (std::vector<int>{s.find("LowerArm.L"), s.find("Fingertip.L")}));
}

TEST(ViewportTools, RotateSweptAngleUndoAndRedo) {
  FrontView v;
  const Skeleton& s = v.state.scene.skeleton;
  const int elbow = s.find("LowerArm.L"), hand = s.find("Hand.L");
  const glm::vec2 p = v.pixelOf("LowerArm.L");
  v.click((p + v.pixelOf("Hand.L")) * 0.5f);
  ASSERT_EQ(v.state.activeJoint, elbow);
  v.move(p + glm::vec2(0, -80));  // straight above the elbow
  v.key(GLFW_KEY_R);
  EXPECT_EQ(v.state.tool.mode, ModalTool::Rotate);
  v.move(p + glm::vec2(-80, -80));
  v.move(p + glm::vec2(-80, 0));  // a quarter turn counter-clockwise: the forearm points up
  v.send(InputEventType::ButtonDown);
  v.send(InputEventType::ButtonUp);
  const glm::vec3 e(v.state.world[elbow][3]);
  EXPECT_VEC3_NEAR(glm::vec3(v.state.world[hand][3]), e + glm::vec3(0, 0.26f, 0), 1e-4f);
  EXPECT_EQ(v.state.undoDepth, 1);
  v.send(InputEventType::KeyDown, 0, 0, GLFW_KEY_LEFT_CONTROL);
  v.key(GLFW_KEY_Z);
  EXPECT_VEC3_NEAR(glm::vec3(v.state.world[hand][3]), glm::vec3(0.71f, 1.45f, 0), 1e-5f);
  v.send(InputEventType::KeyDown, 0, 0, GLFW_KEY_LEFT_SHIFT);
  v.key(GLFW_KEY_Z);
  EXPECT_VEC3_NEAR(glm::vec3(v.state.world[hand][3]), e + glm::vec3(0, 0.26f, 0), 1e-4f);
}

TEST(ViewportTools, ViewPresetsAndFrameSelected) {
  FrontView v;
  setViewPreset(v.state, 3, false);
  EXPECT_FLOAT_EQ(v.state.camera.azimuthDeg, 90.0f);
  setViewPreset(v.state, 1, true);
  EXPECT_FLOAT_EQ(v.state.camera.azimuthDeg, 180.0f);
  setSelection(v.state, {v.state.scene.skeleton.find("Head")});
  frameSelection(v.state, 800.0f / 600.0f, false);
  EXPECT_VEC3_NEAR(v.state.camera.target, glm::vec3(0, 1.6f, 0.01f), 1e-5f);
}

TEST(ViewportTools, PasteFlippedMirrorsOntoTheOtherSide) {
  FrontView v;
  const Skeleton& s = v.state.scene.skeleton;
  const int l = s.find("LowerArm.L"), r = s.find("LowerArm.R");
  v.state.pose.local[l].rotation = glm::angleAxis(0.5f, glm::normalize(glm::vec3(1, 2, 3)));
  setSelection(v.state, {l});
  copySelectedPose(v.state);
  pastePose(v.state, true);
  // Mirroring across x = 0 turns an axis (x, y, z) into (x, -y, -z) for the same angle.
  const glm::quat m = v.state.pose.local[r].rotation;
  EXPECT_NEAR(glm::angle(m), 0.5f, 1e-5f);
  EXPECT_VEC3_NEAR(glm::axis(m), glm::normalize(glm::vec3(1, -2, -3)), 1e-5f);
}

}  // namespace
}  // namespace kinema::test
