// End-to-end tests of the editor window: the real `kinema edit` under xvfb-run with Mesa's
// llvmpipe, driven by --script replay (and once by xdotool, through the X server), checked
// in --dump-state. Expected values are derived by hand from the pixels the script moves:
// the test projects joints itself (its own pinhole camera from the dumped eye/target/fov,
// seen through the dumped viewport rectangle, which one test checks against the panels'
// windows). Panel widgets are clicked by name (e2e_harness.h).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "io/gltf_writer.h"
#include "io/image.h"
#include "editor/e2e_harness.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using json = nlohmann::json;
using e2e::DumpCamera;
using e2e::itemRect;
using e2e::readJson;
using e2e::vec3;
using e2e::viewportRect;

// The script builder shared by the editor e2e suites.
using e2e::Script;
using e2e::FrontViewSuite;
using e2e::runEditor;

class EditorE2e : public FrontViewSuite<EditorE2e> {
 public:
  static constexpr const char* kShotFolder = "editor_e2e";

 protected:
  // Runs the script on the default character (or `file`); the last frame goes to the build
  // dir as editor_e2e/NAME.png. Returns the dumped state.
  static json runScript(const std::string& dir, const Script& script, const std::string& name,
                        const std::string& file = "") {
    return runEditor(dir, FrontViewSuite::shotDir(), script, name, file);
  }

  static glm::dvec3 joint(const json& d, const std::string& name, const char* field = "world_position") {
    for (const json& j : d["joints"])
      if (j["name"] == name) return vec3(j[field]);
    ADD_FAILURE() << "no joint " << name;
    return glm::dvec3(NAN);
  }
  static glm::dquat rotation(const json& d, const std::string& name) {
    for (const json& j : d["joints"])
      if (j["name"] == name) return glm::dquat(j["rotation"][3], j["rotation"][0], j["rotation"][1], j["rotation"][2]);
    return glm::dquat(NAN, NAN, NAN, NAN);
  }
  static std::vector<std::string> selection(const json& d) { return d["selection"].get<std::vector<std::string>>(); }
  DumpCamera camera() const { return DumpCamera(front_); }
  glm::dvec2 pixelOf(const std::string& name) const { return camera().pixel(joint(front_, name)); }
  glm::dvec2 midpoint(const std::string& a, const std::string& b) const { return (pixelOf(a) + pixelOf(b)) * 0.5; }
  // The rotate gizmo's ring radius on `name` in the front view (rotate_gizmo.h): 80 px, but
  // the view ring (1.2 times wider) plus its 6 px grab tolerance within half the distance to
  // the nearest joint the rotation does not carry (neither the joint, its parent nor a
  // descendant); never under 12 px.
  static double gizmoRingPixels(const json& d, const std::string& name) {
    const DumpCamera cam(d);
    auto pixelOf = [&](const std::string& n) { return cam.pixel(joint(d, n)); };
    std::vector<std::string> names;
    std::vector<int> parents;
    for (const json& j : d["joints"]) {
      names.push_back(j["name"]);
      parents.push_back(j["parent"]);
    }
    const int self = int(std::find(names.begin(), names.end(), name) - names.begin());
    double r = 80.0;
    for (size_t k = 0; k < names.size(); ++k) {
      bool carried = false;
      for (int a = int(k); a >= 0; a = parents[a]) carried = carried || a == self;
      if (carried || int(k) == parents[self]) continue;
      const double d = glm::length(pixelOf(names[k]) - pixelOf(name));
      if (d >= 1.0) r = std::min(r, (0.5 * d - 6.0) / 1.2);
    }
    return std::max(r, 12.0);
  }
};

void expectNear(glm::dvec3 a, glm::dvec3 b, double tol, const std::string& what) {
  EXPECT_LE(glm::length(a - b), tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", "
                                     << b.y << ", " << b.z << ")";
}

TEST_F(EditorE2e, FrontViewFramesTheCharacter) {
  // The window has the size the suite asked for (--size wins).
  EXPECT_EQ(int(front_["window"]["width"]), e2e::windowPixels().x);
  EXPECT_EQ(int(front_["window"]["height"]), e2e::windowPixels().y);
  // The 3D view is the free area between the panels, not the whole window: right of the
  // outliner and history column, left of the properties and IK column, from the panels' top
  // (under the menu bar) down to the timeline (there whenever a skeleton is).
  const e2e::Rect view = viewportRect(front_), outliner = itemRect(front_, "Outliner"),
                  history = itemRect(front_, "History"), properties = itemRect(front_, "Properties"),
                  ik = itemRect(front_, "IK Targets"), timeline = itemRect(front_, "Timeline");
  EXPECT_EQ(view.x, outliner.right());
  EXPECT_EQ(view.x, history.right());
  EXPECT_EQ(view.right(), properties.x);
  EXPECT_EQ(view.right(), ik.x);
  EXPECT_EQ(view.y, outliner.y);
  EXPECT_EQ(view.y, properties.y);
  EXPECT_GT(view.y, 0.0);  // the menu bar above
  EXPECT_EQ(view.bottom(), timeline.y);
  EXPECT_EQ(view.x, timeline.x);
  EXPECT_EQ(view.width, timeline.width);
  EXPECT_LT(view.width, double(front_["window"]["width"]));
  EXPECT_LT(timeline.bottom(), double(front_["window"]["height"]));  // the status bar below
  // Numpad 1 looks from +Z; the T-posed arms span x = -0.89..0.89 in the middle of the view,
  // and Home frames all of the skeleton inside the view (not under the panels).
  EXPECT_NEAR(double(front_["camera"]["azimuth"]), 0.0, 1e-6);
  EXPECT_NEAR(double(front_["camera"]["elevation"]), 0.0, 1e-6);
  const glm::dvec2 l = pixelOf("Fingertip.L"), r = pixelOf("Fingertip.R");
  const double centre = view.x + view.width / 2;
  EXPECT_GT(l.x, centre + 100);
  EXPECT_LT(r.x, centre - 100);
  EXPECT_NEAR(l.x - centre, centre - r.x, 2.0);
  EXPECT_NEAR(l.y, r.y, 0.5);
  for (const json& j : front_["joints"]) {
    const glm::dvec2 p = camera().pixel(vec3(j["world_position"]));
    EXPECT_GT(p.x, view.x) << j["name"];
    EXPECT_LT(p.x, view.right()) << j["name"];
    EXPECT_GT(p.y, view.y) << j["name"];
    EXPECT_LT(p.y, view.bottom()) << j["name"];
  }
}

TEST_F(EditorE2e, ClickSelectsTheHandAndShiftClickAdds) {
  // The hand's bone runs from Hand.L to Fingertip.L: a click on its middle selects the hand.
  json d = run(Script().click(midpoint("Hand.L", "Fingertip.L")), "click_select_hand");
  EXPECT_EQ(selection(d), std::vector<std::string>{"Hand.L"});
  EXPECT_EQ(d["active"], "Hand.L");
  d = run(Script()
              .click(midpoint("Hand.L", "Fingertip.L"))
              .keyDown("LEFT_SHIFT")
              .click(pixelOf("LowerArm.R"))
              .keyUp("LEFT_SHIFT"),
          "shift_click");
  EXPECT_EQ(selection(d), (std::vector<std::string>{"Hand.L", "LowerArm.R"}));
  // A click on empty space (well below the arm, beside the legs) clears the selection.
  const glm::dvec2 empty = pixelOf("Hand.L") + glm::dvec2(0, 120);
  d = run(Script().click(midpoint("Hand.L", "Fingertip.L")).click(empty), "click_empty");
  EXPECT_TRUE(selection(d).empty());
}

TEST_F(EditorE2e, ScriptedClicksReachThePanelsAndNotTheViewport) {
  // The outliner (left column) lists Head: a click on its row selects it through ImGui.
  // Then a drag that starts on the History panel (empty there, below its one row) and ends
  // in the viewport past the left hand: had the viewport seen the press, it would have
  // box-selected most of the skeleton.
  const glm::dvec2 panel = itemRect(front_, "History").at(0.5, 0.9), past = pixelOf("Fingertip.L") + glm::dvec2(20, 20);
  ASSERT_GT(panel.y, itemRect(front_, "History/0").bottom()) << "the press is below the history's rows";
  json d = run(Script().clickItem("Outliner/Head").move(panel).down().path(panel, past).up(), "click_outliner");
  EXPECT_EQ(selection(d), std::vector<std::string>{"Head"});
  EXPECT_EQ(d["title"], "Kinema - untitled");
}

TEST_F(EditorE2e, HoverHighlightsTheJointUnderTheMouse) {
  json d = run(Script().move(pixelOf("Head")), "hover");
  EXPECT_EQ(d["hovered"], "Head");
  EXPECT_TRUE(selection(d).empty());
}

TEST_F(EditorE2e, BoxSelectTakesTheJointsInsideTheBox) {
  const glm::dvec2 a = pixelOf("LowerArm.L") + glm::dvec2(-15, -25), b = pixelOf("Fingertip.L") + glm::dvec2(15, 25);
  json d = run(Script().move(a).down().path(a, b).up(), "box_select");
  EXPECT_EQ(selection(d), (std::vector<std::string>{"LowerArm.L", "Hand.L", "Fingertip.L"}));
}

TEST_F(EditorE2e, RWithTheMouseRotatesTheForearmByTheAngleSwept) {
  // Mouse from 100 px right of the elbow to 100 px above it: a quarter turn counter-clockwise
  // on screen, i.e. +90 degrees about the line from the elbow to the eye (it projects onto
  // the elbow's pixel, so the bone follows the cursor). Rodrigues with cos = 0, sin = 1 takes
  // the forearm f = (0.26, 0, 0) to (u.f) u + u x f.
  const glm::dvec2 p = pixelOf("LowerArm.L");
  Script s;
  s.click(midpoint("LowerArm.L", "Hand.L")).move(p + glm::dvec2(100, 0)).key("R");
  for (int k = 1; k <= 9; ++k) s.move(p + 100.0 * glm::dvec2(std::cos(k * M_PI / 18), -std::sin(k * M_PI / 18)));
  s.down().up();
  json d = run(s, "rotate_r_mouse");
  const glm::dvec3 elbow = joint(front_, "LowerArm.L");
  const glm::dvec3 u = glm::normalize(camera().eye - elbow), f(0.26, 0, 0);
  expectNear(joint(d, "Hand.L"), elbow + glm::dot(u, f) * u + glm::cross(u, f), 2e-3, "Hand.L after R + 90 degrees");
  expectNear(joint(d, "LowerArm.L"), elbow, 1e-5, "the elbow stays");
  EXPECT_EQ(int(d["undo_depth"]), 1);
  EXPECT_TRUE(bool(d["dirty"]));
  EXPECT_EQ(d["title"], "Kinema - untitled*");  // the dirty marker
}

TEST_F(EditorE2e, RThenAxisKeysConstrainAndTypedDegreesAreExact) {
  // R Z 45 Enter: 45 degrees about world Z.
  json d = run(Script().click(midpoint("LowerArm.L", "Hand.L")).key("R").key("Z").key("4").key("5").key("ENTER"),
               "rotate_r_z45");
  const glm::dvec3 elbow = joint(front_, "LowerArm.L");
  const double c = std::cos(M_PI / 4), s = std::sin(M_PI / 4);
  expectNear(joint(d, "Hand.L"), elbow + 0.26 * glm::dvec3(c, s, 0), 1e-4, "R Z 45");
  // R X 90: the forearm turns about its own length (X): the hand stays, the local rotation
  // is 90 degrees about X = (sin 45, 0, 0, cos 45).
  d = run(Script().click(midpoint("LowerArm.L", "Hand.L")).key("R").key("X").key("9").key("0").key("ENTER"),
          "rotate_r_x90");
  expectNear(joint(d, "Hand.L"), joint(front_, "Hand.L"), 1e-4, "R X 90");
  const glm::dquat q = rotation(d, "LowerArm.L");
  EXPECT_NEAR(std::abs(q.x), s, 1e-4);
  EXPECT_NEAR(std::abs(q.w), c, 1e-4);
  EXPECT_NEAR(q.y, 0, 1e-5);
  // Esc cancels: nothing changes, nothing to undo.
  d = run(Script().click(midpoint("LowerArm.L", "Hand.L")).key("R").key("9").key("0").key("ESCAPE"), "rotate_cancel");
  expectNear(joint(d, "Hand.L"), joint(front_, "Hand.L"), 1e-6, "cancelled");
  EXPECT_EQ(int(d["undo_depth"]), 0);
}

TEST_F(EditorE2e, GizmoRingDragRotatesAboutItsAxis) {
  // In the front view the Z ring (radius gizmoRingPixels, at most 80 px) is a whole circle
  // around the joint (its axis is the view axis); X and Y are edge-on lines. Press on the Z
  // ring at 240 degrees (lower left) and, in a second run, at 60 degrees (upper right, the
  // half that used to be culled), sweep 90 degrees counter-clockwise: +90 degrees about Z,
  // the forearm points up.
  const glm::dvec2 p = pixelOf("LowerArm.L");
  const double ring = gizmoRingPixels(front_, "LowerArm.L");
  for (double startDegrees : {240.0, 60.0}) {
    Script s;
    s.click(midpoint("LowerArm.L", "Hand.L"));
    const double a0 = startDegrees * M_PI / 180;
    s.move(p + ring * glm::dvec2(std::cos(a0), -std::sin(a0))).down();
    for (int k = 1; k <= 8; ++k) {
      const double a = a0 + k * M_PI / 16;
      s.move(p + ring * glm::dvec2(std::cos(a), -std::sin(a)));
    }
    s.up();
    json d = run(s, "gizmo_ring_drag_" + std::to_string(int(startDegrees)));
    const glm::dvec3 elbow = joint(front_, "LowerArm.L");
    expectNear(joint(d, "Hand.L"), elbow + glm::dvec3(0, 0.26, 0), 2e-3,
               "Hand.L after the Z ring's quarter turn from " + std::to_string(int(startDegrees)) + " degrees");
    EXPECT_EQ(int(d["undo_depth"]), 1);
  }
}

TEST_F(EditorE2e, RotationsStopAtTheJointLimitAndTheLimitArcIsDrawn) {
  // An arm whose forearm (LowerArm.L, rest rotation identity, bone 0.26 along +X) may only
  // bend 0..45 degrees about Z. R Z 90 and a 90-degree sweep of the gizmo's Z ring both stop
  // at 45: rotation (0, 0, sin 22.5, cos 22.5), the hand at elbow + 0.26 (cos 45, sin 45, 0).
  const std::string file = dir_ + "/arm.kinema";
  std::ofstream(file) << R"({"format": "kinema", "version": 1, "skeleton": {"joints": [
    {"name": "Hips", "parent": -1, "translation": [0, 1, 0]},
    {"name": "UpperArm.L", "parent": 0, "translation": [0.2, 0.4, 0]},
    {"name": "LowerArm.L", "parent": 1, "translation": [0.3, 0, 0]},
    {"name": "Hand.L", "parent": 2, "translation": [0.26, 0, 0]},
    {"name": "Fingertip.L", "parent": 3, "translation": [0.1, 0, 0]}]},
  "ik": {"limits": [{"joint": "LowerArm.L", "type": "hinge", "axis": [0, 0, 1], "min_deg": 0, "max_deg": 45}]}})";
  const json front = runScript(dir_, Script(), "limit_front", file);
  ASSERT_TRUE(front.is_object());
  const DumpCamera cam(front);
  const glm::dvec3 elbow = joint(front, "LowerArm.L");
  expectNear(elbow, {0.5, 1.4, 0}, 1e-6, "the elbow in the file");
  const glm::dvec2 forearm = (cam.pixel(elbow) + cam.pixel(joint(front, "Hand.L"))) * 0.5;
  const double c = std::cos(M_PI / 4), s = std::sin(M_PI / 4);
  const glm::dvec3 limited = elbow + 0.26 * glm::dvec3(c, s, 0);

  json d = runScript(dir_, Script().click(forearm).key("R").key("Z").key("9").key("0").key("ENTER"), "limit_r_z90", file);
  EXPECT_EQ(selection(d), std::vector<std::string>{"LowerArm.L"});
  const glm::dquat q = rotation(d, "LowerArm.L");
  EXPECT_NEAR(std::abs(q.z), std::sin(M_PI / 8), 1e-4);
  EXPECT_NEAR(std::abs(q.w), std::cos(M_PI / 8), 1e-4);
  EXPECT_NEAR(q.x, 0, 1e-5);
  EXPECT_NEAR(q.y, 0, 1e-5);
  expectNear(joint(d, "Hand.L"), limited, 1e-4, "R Z 90 stops at 45");

  // The Z ring from 240 to 330 degrees (a quarter turn counter-clockwise): also 45.
  const glm::dvec2 p = cam.pixel(elbow);
  const double radius = gizmoRingPixels(front, "LowerArm.L");
  Script ring;
  ring.click(forearm);
  ring.move(p + radius * glm::dvec2(std::cos(4 * M_PI / 3), -std::sin(4 * M_PI / 3))).down();
  for (int k = 1; k <= 8; ++k) {
    const double a = 4 * M_PI / 3 + k * M_PI / 16;
    ring.move(p + radius * glm::dvec2(std::cos(a), -std::sin(a)));
  }
  ring.up();
  d = runScript(dir_, ring, "limit_ring_drag", file);
  expectNear(joint(d, "Hand.L"), limited, 2e-3, "the Z ring's quarter turn stops at 45");
  EXPECT_EQ(int(d["undo_depth"]), 1);

  // The screenshot of the R run shows the hinge arc (OverlayStyle::limit, cyan): radius the
  // bone's length about the elbow from the rest direction +X, 0..45 degrees. Look for it
  // (2 px wide) at 10, 22.5 and 35 degrees, away from the bone (drawn along 45).
  const auto shot = loadPng(shotDir() + "/limit_r_z90.png");
  ASSERT_TRUE(shot.ok()) << shot.error();
  const Image& img = shot.value();
  for (double deg : {10.0, 22.5, 35.0}) {
    const double a = deg * M_PI / 180;
    const glm::dvec2 px = cam.pixel(elbow + 0.26 * glm::dvec3(std::cos(a), std::sin(a), 0));
    bool found = false;
    for (int dy = -2; dy <= 2 && !found; ++dy)
      for (int dx = -2; dx <= 2 && !found; ++dx) {
        const int x = int(std::lround(px.x)) + dx, y = int(std::lround(px.y)) + dy;
        if (x < 0 || y < 0 || x >= img.width || y >= img.height) continue;
        const unsigned char* rgba = &img.rgba[(size_t(y) * img.width + x) * 4];
        found = rgba[0] < 140 && rgba[1] > 160 && rgba[2] > 160;
      }
    EXPECT_TRUE(found) << "no limit arc pixel near (" << px.x << ", " << px.y << ") at " << deg << " degrees";
  }
}

// The pixel (x, y) of a screenshot the test wrote (RGBA), or black outside it.
glm::ivec3 pixelAt(const Image& img, glm::dvec2 p) {
  const int x = int(std::lround(p.x)), y = int(std::lround(p.y));
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return glm::ivec3(0);
  const unsigned char* c = &img.rgba[(size_t(y) * img.width + x) * 4];
  return {c[0], c[1], c[2]};
}

TEST_F(EditorE2e, SkinnedCharacterWithXrayBonesWeightsAndDualQuaternionSkinning) {
  // The default character has a body now. Click the forearm (bones are picked through the
  // body), R Z 90 bends the elbow, Alt+Z turns the bones to x-ray, Alt+W shows the
  // forearm's weights, and the properties panel's Mesh section (its skinning combo, named
  // after the mesh, under the collapsed joint limit) switches the body to dual quaternions.
  const std::string combo = "Properties/Mesh/Body";  // the default character's mesh (default_character_scene.cpp)
  Script s;
  s.click(midpoint("LowerArm.L", "Hand.L")).key("R").key("Z").key("9").key("0").key("ENTER");
  s.keyDown("LEFT_ALT").key("Z").key("W").keyUp("LEFT_ALT");
  s.clickItem(combo).moveItem(combo + "/Dual quaternion").clickItem(combo + "/Dual quaternion");
  json d = run(s, "skinned_xray_weights_dq");
  EXPECT_EQ(selection(d), std::vector<std::string>{"LowerArm.L"});
  expectNear(joint(d, "Hand.L"), joint(front_, "LowerArm.L") + glm::dvec3(0, 0.26, 0), 1e-4, "the bent elbow");
  EXPECT_EQ(d["bones"], "x-ray");
  EXPECT_TRUE(bool(d["show_weights"]));
  ASSERT_EQ(d["mesh_skinning"].size(), 1u);
  EXPECT_EQ(d["mesh_skinning"][0], "dual-quaternion");
  EXPECT_EQ(int(d["undo_depth"]), 2);  // the rotation, then the skinning method
  // Ctrl+Z puts linear blend back (the skinning method is an undoable edit).
  s.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL");
  d = run(s, "skinned_dq_undone");
  EXPECT_EQ(d["mesh_skinning"][0], "linear");
  EXPECT_EQ(int(d["undo_depth"]), 1);

  // Weights without bones (Alt+Z twice from on: x-ray, none), rest pose: the forearm's own
  // vertices are hot (red), the chest's are cold (blue: weight 0 of the forearm).
  d = run(Script()
              .click(midpoint("LowerArm.L", "Hand.L"))
              .keyDown("LEFT_ALT").key("W").key("Z").key("Z").keyUp("LEFT_ALT"),
          "skinned_weights_no_bones");
  EXPECT_EQ(d["bones"], "none");
  const auto shot = loadPng(shotDir() + "/skinned_weights_no_bones.png");
  ASSERT_TRUE(shot.ok()) << shot.error();
  const glm::ivec3 forearm = pixelAt(shot.value(), midpoint("LowerArm.L", "Hand.L"));
  const glm::ivec3 chest = pixelAt(shot.value(), pixelOf("Chest"));
  EXPECT_GT(forearm.r, forearm.b + 60) << forearm.r << " " << forearm.g << " " << forearm.b;
  EXPECT_GT(chest.b, chest.r + 60) << chest.r << " " << chest.g << " " << chest.b;
}

TEST_F(EditorE2e, AClickOnTheBodyAwayFromTheBonesSelectsTheJointWeighingMostThere) {
  // 22 px right of the chest joint the ray crosses the torso but no bone (the spine's
  // octahedra are a few pixels wide, the fallback circle smaller): the joint with the
  // largest weight at the hit vertex is one of the torso's. Before, nothing was selected.
  const glm::dvec2 side = pixelOf("Chest") + glm::dvec2(22, 0);
  json d = run(Script().click(side), "click_body");
  ASSERT_EQ(selection(d).size(), 1u);
  const std::string j = selection(d)[0];
  EXPECT_TRUE(j == "Spine" || j == "Chest" || j == "UpperChest" || j == "Shoulder.L") << j;
  // The same click with the bones hidden (Alt+Z twice), and on the forearm: the body's
  // weights decide there too (the forearm's middle is its own).
  d = run(Script().keyDown("LEFT_ALT").key("Z").key("Z").keyUp("LEFT_ALT").click(midpoint("LowerArm.L", "Hand.L")),
          "click_body_no_bones");
  EXPECT_EQ(d["bones"], "none");
  EXPECT_EQ(selection(d), std::vector<std::string>{"LowerArm.L"});
}

// A bar 0.1 x 0.1 wide from the root (y = 1) up to the tip (y = 2), NOT skinned: one mesh
// instance on the root joint; Mid at y = 1.5 halfway. Written with the project's glTF writer.
std::string writeUnskinnedBar(const std::string& dir) {
  Scene s;
  Transform root, up;
  root.translation = {0, 1, 0};
  up.translation = {0, 0.5f, 0};
  s.skeleton.addJoint("Root", -1, root);
  s.skeleton.addJoint("Mid", 0, up);
  s.skeleton.addJoint("Tip", 1, up);
  MeshPrimitive p;
  const int rings = 9;  // every 0.125 up the bar, in the root's frame (y 0..1)
  const float corners[4][2] = {{-0.05f, -0.05f}, {0.05f, -0.05f}, {0.05f, 0.05f}, {-0.05f, 0.05f}};
  for (int r = 0; r < rings; ++r)
    for (const auto& c : corners) p.positions.push_back({c[0], r / float(rings - 1), c[1]});
  for (int r = 0; r + 1 < rings; ++r)
    for (int k = 0; k < 4; ++k) {
      const uint32_t a = r * 4 + k, b = r * 4 + (k + 1) % 4, c = a + 4, d = b + 4;
      p.indices.insert(p.indices.end(), {a, b, d, a, d, c});
    }
  Mesh m;
  m.name = "bar";
  m.primitives.push_back(p);
  s.meshes.push_back(m);
  MeshInstance i;
  i.joint = 0;
  i.mesh = 0;
  s.meshInstances.push_back(i);
  const std::string path = dir + "/bar.gltf";
  EXPECT_EQ(saveGltf(path, s, GltfWriteOptions{}), "");
  return path;
}

TEST_F(EditorE2e, CtrlPBindsAnUnskinnedMeshWithAutomaticWeightsUndoably) {
  const std::string file = writeUnskinnedBar(dir_);
  const json front = runScript(dir_, Script(), "bind_front", file);
  ASSERT_TRUE(front.is_object());
  ASSERT_EQ(front["mesh_skins"].size(), 1u);
  EXPECT_EQ(int(front["mesh_skins"][0]), -1);
  const DumpCamera cam(front);
  const glm::dvec2 midBone = (cam.pixel(joint(front, "Mid")) + cam.pixel(joint(front, "Tip"))) * 0.5;
  // Ctrl+P binds (one undo step); Ctrl+Z unbinds.
  Script bind;
  bind.keyDown("LEFT_CONTROL").key("P").keyUp("LEFT_CONTROL");
  json d = runScript(dir_, bind, "bind_only", file);
  EXPECT_GE(int(d["mesh_skins"][0]), 0);
  EXPECT_EQ(int(d["undo_depth"]), 1);
  EXPECT_TRUE(bool(d["dirty"]));
  d = runScript(dir_, Script(bind).keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL"), "bind_undone", file);
  EXPECT_EQ(int(d["mesh_skins"][0]), -1);
  EXPECT_EQ(int(d["undo_depth"]), 0);

  // Then R Z 90 on Mid: bound, the bar's upper half turns with it to the left (Tip at
  // (-0.5, 1.5, 0)); unbound, the bar stays upright on the root. Bones hidden and nothing
  // selected for the screenshot, so only the body shows.
  auto pose = [&](bool withBind, const std::string& name) {
    Script s;
    if (withBind) s.keyDown("LEFT_CONTROL").key("P").keyUp("LEFT_CONTROL");
    s.click(midBone).key("R").key("Z").key("9").key("0").key("ENTER");
    s.keyDown("LEFT_ALT").key("A").key("Z").key("Z").keyUp("LEFT_ALT");
    json out = runScript(dir_, s, name, file);
    expectNear(joint(out, "Tip"), {-0.5, 1.5, 0}, 1e-4, name + ": Tip after R Z 90");
    const auto shot = loadPng(shotDir() + "/" + name + ".png");
    EXPECT_TRUE(shot.ok());
    return shot.ok() ? shot.value() : Image();
  };
  auto bright = [&](const Image& img, glm::dvec3 world) {
    const glm::ivec3 c = pixelAt(img, cam.pixel(world));
    return c.r + c.g + c.b > 3 * 100;  // the lit grey body; the background is 60, 60, 60
  };
  const glm::dvec3 oldTop(0, 1.85, 0), turned(-0.35, 1.5, 0), lower(0, 1.25, 0);
  const Image bound = pose(true, "bind_posed"), unbound = pose(false, "unbound_posed");
  EXPECT_TRUE(bright(bound, turned)) << "the bound bar's upper half turned left";
  EXPECT_FALSE(bright(bound, oldTop)) << "and left its old place";
  EXPECT_TRUE(bright(bound, lower)) << "its lower half stays on the root";
  EXPECT_FALSE(bright(unbound, turned));
  EXPECT_TRUE(bright(unbound, oldTop)) << "an unbound bar stays upright";
}

TEST_F(EditorE2e, GMovesTheRootInTheViewPlaneAndAlongAnAxis) {
  // 100 px right at the hips' depth is 100 * (2 depth tan(fov/2) / view height) world units along +X.
  const glm::dvec3 hips = joint(front_, "Hips");
  const double upp = camera().unitsPerPixel(hips);
  const glm::dvec2 m = pixelOf("Hips") + glm::dvec2(250, 60);
  json d = run(Script().move(m).key("G").path(m, m + glm::dvec2(100, 0)).down().up(), "grab_root");
  expectNear(joint(d, "Hips"), hips + glm::dvec3(100 * upp, 0, 0), 1e-4, "G 100 px right");
  expectNear(joint(d, "Hand.L") - joint(d, "Hips"), joint(front_, "Hand.L") - hips, 1e-5, "the body moves along");
  // G Y from below the hips: along the vertical line through them, which lies in the view
  // plane at their depth, so 50 px up is 50 * upp.
  const glm::dvec2 below = pixelOf("Hips") + glm::dvec2(0, 60);
  d = run(Script().move(below).key("G").key("Y").path(below, below + glm::dvec2(0, -50)).key("ENTER"), "grab_root_y");
  expectNear(joint(d, "Hips"), hips + glm::dvec3(0, 50 * upp, 0), 1e-4, "G Y 50 px up");
}

TEST_F(EditorE2e, AltRClearsTheRotation) {
  json d = run(Script()
                   .click(midpoint("LowerArm.L", "Hand.L"))
                   .key("R").key("Z").key("3").key("0").key("ENTER")
                   .keyDown("LEFT_ALT").key("R").keyUp("LEFT_ALT"),
               "alt_r");
  const glm::dquat q = rotation(d, "LowerArm.L");
  EXPECT_NEAR(std::abs(q.w), 1.0, 1e-6);
  expectNear(joint(d, "Hand.L"), joint(front_, "Hand.L"), 1e-5, "cleared");
  EXPECT_EQ(int(d["undo_depth"]), 2);
}

TEST_F(EditorE2e, DraggingTheHandsIkTargetMovesTheHandThereAndKeepsBoneLengths) {
  // Shift+I adds a target on the selected hand (two bones up: root UpperArm.L). Dragging its
  // handle 60 px left and 80 px down at the hand's depth puts it at hand + upp * (-60, -80, 0).
  const glm::dvec3 hand = joint(front_, "Hand.L");
  const double upp = camera().unitsPerPixel(hand);
  const glm::dvec2 h = pixelOf("Hand.L");
  json d = run(Script()
                   .click(midpoint("Hand.L", "Fingertip.L"))
                   .keyDown("LEFT_SHIFT").key("I").keyUp("LEFT_SHIFT")
                   .move(h).down().path(h, h + glm::dvec2(-60, 80), 10).up(),
               "ik_target_drag");
  const glm::dvec3 expected = hand + upp * glm::dvec3(-60, -80, 0);
  ASSERT_EQ(d["ik_targets"].size(), 1u);
  EXPECT_EQ(d["ik_targets"][0]["effector"], "Hand.L");
  expectNear(vec3(d["ik_targets"][0]["position"]), expected, 1e-4, "the dropped target");
  expectNear(joint(d, "Hand.L"), expected, 2e-3, "the hand reaches the target");
  EXPECT_LT(double(d["ik_targets"][0]["error"]), 2e-3);
  expectNear(joint(d, "UpperArm.L"), joint(front_, "UpperArm.L"), 1e-5, "the IK root stays");
  EXPECT_EQ(d["ik_targets"][0]["solver"], "two-bone");
  for (auto [a, b] : {std::pair{"UpperArm.L", "LowerArm.L"}, {"LowerArm.L", "Hand.L"}, {"Hand.L", "Fingertip.L"}})
    EXPECT_NEAR(glm::length(joint(d, b) - joint(d, a)), glm::length(joint(front_, b) - joint(front_, a)), 1e-4)
        << a << "-" << b;
  EXPECT_EQ(int(d["undo_depth"]), 2);  // adding the target, then the drag
  // Esc during the drag puts the target and the arm back.
  d = run(Script()
              .click(midpoint("Hand.L", "Fingertip.L"))
              .keyDown("LEFT_SHIFT").key("I").keyUp("LEFT_SHIFT")
              .move(h).down().path(h, h + glm::dvec2(-60, 80), 4).key("ESCAPE").up(),
          "ik_target_cancel");
  expectNear(vec3(d["ik_targets"][0]["position"]), hand, 1e-5, "cancelled target");
  expectNear(joint(d, "Hand.L"), hand, 1e-5, "cancelled hand");
}

TEST_F(EditorE2e, AutoIkDragsAJointDirectly) {
  const glm::dvec3 hand = joint(front_, "Hand.L");
  const double upp = camera().unitsPerPixel(hand);
  const glm::dvec2 h = pixelOf("Hand.L");
  json d = run(Script()
                   .keyDown("LEFT_CONTROL").key("I").keyUp("LEFT_CONTROL")
                   .move(h).down().path(h, h + glm::dvec2(-50, 70), 8).up(),
               "auto_ik");
  EXPECT_TRUE(bool(d["auto_ik"]));
  expectNear(joint(d, "Hand.L"), hand + upp * glm::dvec3(-50, -70, 0), 2e-3, "auto-IK hand");
  expectNear(joint(d, "UpperArm.L"), joint(front_, "UpperArm.L"), 1e-5, "chain root stays");
  EXPECT_NEAR(glm::length(joint(d, "Hand.L") - joint(d, "LowerArm.L")), 0.26, 1e-4);
}

TEST_F(EditorE2e, CameraKeysWheelAndMiddleDragChangeTheView) {
  const double d0 = front_["camera"]["distance"];
  json d = run(Script().scroll(2), "camera_zoom");
  EXPECT_NEAR(double(d["camera"]["distance"]), d0 / (1.2 * 1.2), 1e-4);
  d = run(Script().key("KP_3"), "camera_right");
  EXPECT_NEAR(double(d["camera"]["azimuth"]), 90.0, 1e-4);
  d = run(Script().keyDown("LEFT_CONTROL").key("KP_7").keyUp("LEFT_CONTROL").key("KP_5"), "camera_bottom_ortho");
  EXPECT_NEAR(double(d["camera"]["elevation"]), -90.0, 1e-3);
  EXPECT_TRUE(bool(d["camera"]["orthographic"]));
  // Middle drag 100 px right (from the view's lower right): turntable orbit of 0.4 degrees
  // per pixel, to the right.
  const glm::dvec2 m = viewportRect(front_).at(0.9, 0.75);
  d = run(Script().move(m).down("middle").path(m, m + glm::dvec2(100, 0)).up("middle"), "camera_orbit");
  EXPECT_NEAR(double(d["camera"]["azimuth"]), -40.0, 1e-3);
  // F frames the selected hand: the view centres on it.
  d = run(Script().click(midpoint("Hand.L", "Fingertip.L")).key("F"), "camera_frame_selected");
  expectNear(vec3(d["camera"]["target"]), joint(front_, "Hand.L"), 1e-4, "F centres the hand");
  EXPECT_LT(double(d["camera"]["distance"]), d0 / 2);
}

TEST_F(EditorE2e, CtrlZRestoresThePoseAndCtrlShiftZRedoes) {
  Script s;
  s.click(midpoint("LowerArm.L", "Hand.L")).key("R").key("Z").key("9").key("0").key("ENTER");
  s.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL");
  json d = run(s, "undo");
  expectNear(joint(d, "Hand.L"), joint(front_, "Hand.L"), 1e-6, "undone");
  EXPECT_EQ(int(d["undo_depth"]), 0);
  s.keyDown("LEFT_CONTROL").keyDown("LEFT_SHIFT").key("Z").keyUp("LEFT_SHIFT").keyUp("LEFT_CONTROL");
  d = run(s, "redo");
  expectNear(joint(d, "Hand.L"), joint(front_, "LowerArm.L") + glm::dvec3(0, 0.26, 0), 1e-4, "redone");
}

TEST_F(EditorE2e, XdotoolClickSelectsTheHandThroughTheXServer) {
  if (runCommand("command -v xdotool") != 0) GTEST_SKIP() << "SKIPPED: xdotool is not installed";
  // A real user's path: X events from the server, GLFW callbacks, the same handler.
  const glm::dvec2 hand = midpoint("Hand.L", "Fingertip.L");
  const std::string dump = dir_ + "/xdotool.json", sh = dir_ + "/drive.sh";
  char move[64];
  std::snprintf(move, sizeof move, "%d %d", int(std::lround(hand.x)), int(std::lround(hand.y)));
  std::ofstream(sh) << "set -e\n"
                    << e2e::editorEnvironment(dir_) << KINEMA_BINARY << " edit --size " << e2e::windowSize()
                    << " --frame-count 100000 --dump-state " << dump
                    << " --screenshot " << shotDir() << "/xdotool.png & pid=$!\n"
                    << "for i in $(seq 100); do w=$(xdotool search --name 'Kinema - ' | head -1) && [ -n \"$w\" ] && break; sleep 0.1; done\n"
                    << "xdotool windowfocus --sync $w || true\n"
                    << "sleep 0.5\nxdotool key --window $w KP_1 Home\nsleep 0.5\n"
                    << "xdotool mousemove --window $w " << move << "\nsleep 0.3\nxdotool click 1\nsleep 0.5\n"
                    << "xdotool key --window $w ctrl+q || true\nwait $pid\n";  // it may quit before the releases
  std::string out, err;
  ASSERT_EQ(runCommand(e2e::xvfb() + "sh " + sh, &out, &err), 0) << err;
  json d = readJson(dump);
  EXPECT_EQ(selection(d), std::vector<std::string>{"Hand.L"});
  EXPECT_NEAR(double(d["camera"]["azimuth"]), 0.0, 1e-6);
}

TEST_F(EditorE2e, XdotoolTapsOf12MsAtFiveFramesASecondAreAllHandled) {
  if (runCommand("command -v xdotool") != 0) GTEST_SKIP() << "SKIPPED: xdotool is not installed";
  // Real X events, tapped for 12 ms each at --max-fps 5 (200 ms frames), so most presses
  // and releases fall within one frame: A (select all), then 8 times I (insert keys) and
  // Right (next frame), which makes 8 undo steps on frames start..start+7, then Ctrl+Z 8
  // times. Every tap must count, and promptly: the 25 taps must not take 2 frames each
  // (presses waiting for the frame after their release, the old lag behind fast typing).
  const int steps = 8, taps = 1 + 3 * steps;
  const glm::dvec2 view = viewportRect(front_).at(0.5, 0.4);
  const std::string dump = dir_ + "/taps.json", sh = dir_ + "/taps.sh";
  std::string keys = "a", undos;
  for (int i = 0; i < steps; ++i) {
    keys += " i Right";
    undos += " ctrl+z";
  }
  char move[64];
  std::snprintf(move, sizeof move, "%d %d", int(std::lround(view.x)), int(std::lround(view.y)));
  std::ofstream(sh) << e2e::editorEnvironment(dir_) << KINEMA_BINARY << " edit --size " << e2e::windowSize()
                    << " --max-fps 5 --frame-count 300 --dump-state " << dump << " & pid=$!\n"
                    << "for i in $(seq 100); do w=$(xdotool search --name 'Kinema - ' | head -1) && [ -n \"$w\" ] && break; sleep 0.1; done\n"
                    << "xdotool windowfocus --sync $w || true\n"
                    << "xdotool mousemove --window $w " << move << "\nsleep 1\n"
                    << "xdotool key --delay 12 " << keys << "\nxdotool key --delay 12" << undos << "\n"
                    << "sleep 0.5\nxdotool key ctrl+q || true\nwait $pid\n";  // it may quit before the releases
  std::string out, err;
  ASSERT_EQ(runCommand(e2e::xvfb() + "sh " + sh, &out, &err), 0) << err;
  const json d = readJson(dump);
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(int(d["timeline"]["frame"]), int(front_["timeline"]["frame"]) + steps) << "Right taps lost";
  EXPECT_EQ(int(d["redo_depth"]), steps) << "I or Ctrl+Z taps lost";
  EXPECT_EQ(int(d["undo_depth"]), 0) << "Ctrl+Z taps lost";
  // Ctrl+Q quit right after the taps (the document is clean again), long before 2 frames a tap.
  EXPECT_LT(int(d["frames"]), 2 * taps) << "the taps lagged behind";
}

}  // namespace
}  // namespace kinema::test
