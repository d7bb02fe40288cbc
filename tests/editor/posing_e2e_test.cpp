// End-to-end tests of the posing features the other e2e files leave out: X-mirror editing,
// the two-bone pole target, pinned IK targets, IK target drags along an axis, and the
// orthographic toggle with frame selected from the View menu. The real `kinema edit` runs
// under xvfb-run (e2e_harness.h: 1280x720 or KINEMA_E2E_SIZE) on --script replay and is
// checked in --dump-state. Expected values are derived by hand (triangle geometry for the
// two-bone chain, quaternion algebra for the mirror) or computed here from the dumped camera
// (e2e_harness.h); panel widgets are clicked by name, the IK panel scrolled down first where
// its lower widgets may be below its bottom.
#include <cmath>

#include "editor/e2e_harness.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class PosingE2e : public FrontViewSuite<PosingE2e> {
 public:
  static constexpr const char* kShotFolder = "posing_e2e";

 protected:
  DumpCamera camera() const { return DumpCamera(front_); }
  glm::dvec3 rest(const std::string& name) const { return jointIn(front_, name); }
  glm::dvec2 pixelOf(const std::string& name) const { return camera().pixel(rest(name)); }
  glm::dvec2 midpoint(const std::string& a, const std::string& b) const { return (pixelOf(a) + pixelOf(b)) * 0.5; }
};

// The point of the line p + s * axis nearest to the ray o + t * d (both directions unit).
glm::dvec3 closestOnLine(glm::dvec3 p, glm::dvec3 axis, glm::dvec3 o, glm::dvec3 d) {
  const glm::dvec3 w = p - o;
  const double b = glm::dot(axis, d), denom = 1 - b * b;
  const double s = (b * glm::dot(d, w) - glm::dot(axis, w)) / denom;
  return p + s * axis;
}

TEST_F(PosingE2e, TheDefaultCharacterRestsWithIdentityRotations) {
  // The premise of the hand derivations below: every rest rotation is the identity, so a
  // world turn of a joint is also its local rotation; the arms lie along X at one height.
  for (const json& j : front_["joints"]) {
    const std::string name = j["name"];
    expectRotation(rotationIn(front_, name), glm::dquat(1, 0, 0, 0), 1e-9, name);
  }
  EXPECT_NEAR(glm::length(rest("LowerArm.L") - rest("UpperArm.L")), 0.28, 1e-6);
  EXPECT_NEAR(glm::length(rest("Hand.L") - rest("LowerArm.L")), 0.26, 1e-6);
  // The timeline is always there: the 3D view ends where it begins.
  EXPECT_EQ(viewportRect(front_).bottom(), itemRect(front_, "Timeline").y);
}

TEST_F(PosingE2e, XMirrorEditingRotatesTheMirrorPartnerInTheSameUndoStep) {
  // R Z 30 on the left forearm: local rotation Rz(30) = (x, y, z, w) = (0, 0, sin 15, cos 15);
  // with X-mirror (Edit menu) the right forearm gets (x, -y, -z, w) = (0, 0, -sin 15, cos 15),
  // which puts the right hand at the left hand's place mirrored across X = 0.
  const double c = std::cos(M_PI / 12), s = std::sin(M_PI / 12);
  const glm::dquat left(c, 0, 0, s), right(c, 0, 0, -s);
  const auto rotate = [&](Script& script) {
    return script.select("LowerArm.L").move(pixelOf("Hips") + glm::dvec2(0, 150))
        .key("R").key("Z").key("3").key("0").key("ENTER");
  };
  Script on;
  on.menu("Edit", "X-Mirror");
  rotate(on);
  json d = run(on, "x_mirror_on");
  const glm::dvec3 elbow = rest("LowerArm.L"), hand = elbow + 0.26 * glm::dvec3(std::cos(M_PI / 6), std::sin(M_PI / 6), 0);
  expectRotation(rotationIn(d, "LowerArm.L"), left, 1e-5, "LowerArm.L");
  expectRotation(rotationIn(d, "LowerArm.R"), right, 1e-5, "LowerArm.R, mirrored");
  expectNear(jointIn(d, "Hand.L"), hand, 1e-4, "Hand.L");
  expectNear(jointIn(d, "Hand.R"), glm::dvec3(-hand.x, hand.y, hand.z), 1e-4, "Hand.R, mirrored");
  EXPECT_EQ(int(d["undo_depth"]), 1);  // one step for both sides

  // One Ctrl+Z undoes both sides.
  on.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL");
  d = run(on, "x_mirror_undo");
  expectRotation(rotationIn(d, "LowerArm.L"), glm::dquat(1, 0, 0, 0), 1e-6, "LowerArm.L undone");
  expectRotation(rotationIn(d, "LowerArm.R"), glm::dquat(1, 0, 0, 0), 1e-6, "LowerArm.R undone");
  expectNear(jointIn(d, "Hand.R"), rest("Hand.R"), 1e-6, "Hand.R undone");
  EXPECT_EQ(int(d["undo_depth"]), 0);
  EXPECT_EQ(int(d["redo_depth"]), 1);

  // Off (the default), the partner stays.
  Script off;
  rotate(off);
  d = run(off, "x_mirror_off");
  expectRotation(rotationIn(d, "LowerArm.L"), left, 1e-5, "LowerArm.L");
  expectRotation(rotationIn(d, "LowerArm.R"), glm::dquat(1, 0, 0, 0), 1e-6, "LowerArm.R without X-mirror");
  expectNear(jointIn(d, "Hand.R"), rest("Hand.R"), 1e-6, "Hand.R without X-mirror");
}

TEST_F(PosingE2e, PoleTargetBendsTheElbowTowardsThePole) {
  // A two-bone target on the left hand (IK panel, 2 bones), a pole 0.5 in front of or behind
  // the elbow, then the target typed 0.21 nearer the shoulder: the arm must bend. With the
  // shoulder S, upper arm a = 0.28, forearm b = 0.26 and d = |T - S|, the elbow lies
  // s = (a^2 - b^2 + d^2) / 2d along the line S->T and h = sqrt(a^2 - s^2) off it, on the
  // pole's side: along the part of P - S perpendicular to the line.
  const glm::dvec3 S = rest("UpperArm.L"), hand = rest("Hand.L");
  const double a = glm::length(rest("LowerArm.L") - S), b = glm::length(hand - rest("LowerArm.L"));
  const glm::dvec3 T(0.5, hand.y, hand.z);
  for (double poleZ : {0.5, -0.5}) {
    const glm::dvec3 P = rest("LowerArm.L") + glm::dvec3(0, 0, poleZ);
    Script script;
    script.select("Hand.L").clickItem("IK Targets/Add IK Target to Selected").wait(2);
    script.scrollPanel("IK Targets", -10).clickItem("IK Targets/Pole target").wait(2);
    script.scrollPanel("IK Targets", -10);  // the pole's fields came in below
    script.doubleClickItem("IK Targets/Pole/2").wait(1).type(poleZ > 0 ? "0.5" : "-0.5").key("ENTER").wait(2);
    script.doubleClickItem("IK Targets/Position/0").wait(1).type("0.5").key("ENTER").wait(3);
    const json d = run(script, poleZ > 0 ? "pole_in_front" : "pole_behind");
    ASSERT_EQ(d["ik_targets"].size(), 1u);
    const json& t = d["ik_targets"][0];
    EXPECT_EQ(t["solver"], "two-bone");
    expectNear(vec3(t["pole"]), P, 1e-6, "the pole");
    expectNear(vec3(t["position"]), T, 1e-6, "the typed target");

    const double dist = glm::length(T - S), s = (a * a - b * b + dist * dist) / (2 * dist), h = std::sqrt(a * a - s * s);
    const glm::dvec3 n = (T - S) / dist, off = (P - S) - glm::dot(P - S, n) * n;
    const glm::dvec3 elbow = S + s * n + h * glm::normalize(off);
    expectNear(jointIn(d, "LowerArm.L"), elbow, 2e-3, "the elbow, pole z " + std::to_string(poleZ));
    EXPECT_GT(jointIn(d, "LowerArm.L").z * poleZ, 0.2 * 0.5) << "the elbow bends towards the pole";
    expectNear(jointIn(d, "Hand.L"), T, 2e-3, "the hand reaches the target");
    expectNear(jointIn(d, "UpperArm.L"), S, 1e-6, "the shoulder stays");
  }
}

TEST_F(PosingE2e, APinnedTargetHoldsItsEffectorWhileAnotherIsDragged) {
  // A two-bone target on the elbow (Shift+I, 2 bones, up to Shoulder.L), pinned from the
  // Pose menu; a 3-bone target on the hand (IK panel, damped least squares). The hand's
  // handle is dragged along a circle of radius 0.26 (the forearm) around the elbow, 50
  // degrees down: every point is reachable with the elbow where it is, so pinned it holds;
  // unpinned, the elbow's target follows the elbow wherever the hand's solve puts it.
  const DumpCamera cam = camera();
  const glm::dvec3 elbow = rest("LowerArm.L"), hand = rest("Hand.L");
  const double upp = cam.unitsPerPixel(hand), radius = 0.26 / upp;
  const glm::dvec2 e = pixelOf("LowerArm.L"), h = pixelOf("Hand.L");
  for (bool pinned : {true, false}) {
    Script script;
    script.select("LowerArm.L").keyDown("LEFT_SHIFT").key("I").keyUp("LEFT_SHIFT").wait(1);
    if (pinned) script.menu("Pose", "Pin IK Target");
    script.select("Hand.L").clickItem("IK Targets/Bones/+").wait(1).clickItem("IK Targets/Add IK Target to Selected").wait(2);
    script.move(h).down();
    glm::dvec2 last = h;
    for (int k = 1; k <= 10; ++k) {
      const double angle = -50.0 * M_PI / 180 * k / 10;
      last = e + radius * glm::dvec2(std::cos(angle), -std::sin(angle));
      script.move(last);
    }
    script.up();
    const json d = run(script, pinned ? "pin_held" : "pin_off_follows");
    ASSERT_EQ(d["ik_targets"].size(), 2u);
    const json &elbowTarget = d["ik_targets"][0], &handTarget = d["ik_targets"][1];
    EXPECT_EQ(elbowTarget["effector"], "LowerArm.L");
    EXPECT_EQ(elbowTarget["pinned"], pinned);
    EXPECT_EQ(handTarget["effector"], "Hand.L");
    EXPECT_EQ(handTarget["chain_length"], 3);
    // The dropped target: the pixel offset at the hand's depth.
    const glm::dvec3 goal = hand + upp * glm::dvec3(last.x - h.x, -(last.y - h.y), 0);
    expectNear(goal, elbow + 0.26 * glm::dvec3(std::cos(-5 * M_PI / 18), std::sin(-5 * M_PI / 18), 0), 1e-4, "goal on the circle");
    expectNear(vec3(handTarget["position"]), goal, 1e-4, "the hand's target");
    expectNear(jointIn(d, "Hand.L"), goal, 2e-3, "the hand reaches its target");
    if (pinned) {
      expectNear(vec3(elbowTarget["position"]), elbow, 1e-6, "the pinned target stays");
      expectNear(jointIn(d, "LowerArm.L"), elbow, 2e-3, "the pinned elbow holds");
    } else {
      expectNear(vec3(elbowTarget["position"]), jointIn(d, "LowerArm.L"), 1e-5, "the unpinned target follows the elbow");
      EXPECT_GT(glm::length(jointIn(d, "LowerArm.L") - elbow), 1e-2) << "unpinned, the elbow moves";
    }
    EXPECT_NEAR(glm::length(jointIn(d, "Hand.L") - jointIn(d, "LowerArm.L")), 0.26, 1e-4);
    EXPECT_NEAR(glm::length(jointIn(d, "LowerArm.L") - jointIn(d, "UpperArm.L")), 0.28, 1e-4);
    // The last solve's report per solved target (shown in the status bar): the dragged
    // one, and the pinned one too; each error is its effector's distance to its target.
    ASSERT_TRUE(handTarget.contains("iterations"));
    EXPECT_GE(int(handTarget["iterations"]), 1);
    EXPECT_GE(double(handTarget["milliseconds"]), 0.0);
    EXPECT_NEAR(double(handTarget["error"]), glm::length(jointIn(d, "Hand.L") - goal), 1e-4);
    EXPECT_EQ(elbowTarget.contains("error"), pinned) << "only a pinned target is solved while another is dragged";
    if (pinned) {
      EXPECT_NEAR(double(elbowTarget["error"]), glm::length(jointIn(d, "LowerArm.L") - elbow), 1e-4);
    }
  }
}

TEST_F(PosingE2e, IkTargetDragAlongAnAxisChangesOnlyThatCoordinate) {
  // X (then Y) pressed during the handle drag: the target moves along the world axis
  // through where it was, by as much as the line's nearest point to the cursor's ray moved
  // (computed here from the dumped camera); the other two coordinates stay.
  const DumpCamera cam = camera();
  const glm::dvec3 hand = rest("Hand.L"), S = rest("UpperArm.L");
  const glm::dvec2 h = pixelOf("Hand.L");
  struct Case {
    const char* key;
    int axis;
    glm::dvec2 offset;
  };
  for (const Case& c : {Case{"X", 0, {-60, 40}}, Case{"Y", 1, {35, -50}}}) {
    Script script;
    script.select("Hand.L").keyDown("LEFT_SHIFT").key("I").keyUp("LEFT_SHIFT").wait(1);
    script.move(h).down().key(c.key).path(h, h + c.offset, 8).up();
    const json d = run(script, std::string("ik_axis_drag_") + c.key);
    ASSERT_EQ(d["ik_targets"].size(), 1u);
    const glm::dvec3 t = vec3(d["ik_targets"][0]["position"]);
    glm::dvec3 axis(0), o, dir;
    axis[c.axis] = 1;
    cam.ray(h, o, dir);
    const glm::dvec3 grabbed = closestOnLine(hand, axis, o, dir);
    cam.ray(h + c.offset, o, dir);
    const glm::dvec3 expected = hand + (closestOnLine(hand, axis, o, dir) - grabbed);
    for (int k = 0; k < 3; ++k) {
      if (k == c.axis) continue;
      EXPECT_NEAR(t[k], hand[k], 1e-5) << c.key << " drag moved coordinate " << k;
    }
    EXPECT_NEAR(t[c.axis], expected[c.axis], 2e-4) << c.key;
    EXPECT_GT(std::abs(t[c.axis] - hand[c.axis]), 0.1) << c.key << " the target moved";
    if (c.axis == 0) {
      // 0.26 towards the shoulder: within reach.
      expectNear(jointIn(d, "Hand.L"), t, 2e-3, "the hand reaches the X-dragged target");
    } else {
      // Straight up from the outstretched hand is out of reach: the arm points at it.
      expectNear(jointIn(d, "Hand.L"), S + 0.54 * glm::normalize(t - S), 2e-3, "the arm points at the Y-dragged target");
    }
  }
}

TEST_F(PosingE2e, OrthographicToggleAndFrameSelectedFromTheViewMenuAndKeys) {
  // View > Orthographic, then View > Frame Selected on the right forearm: an orthographic
  // camera centred on the joint; numpad 5 goes back to perspective.
  Script menus;
  menus.select("LowerArm.R").menu("View", "Orthographic").menu("View", "Frame Selected");
  json d = run(menus, "view_menu_ortho_frame_selected");
  EXPECT_TRUE(d["camera"]["orthographic"].get<bool>());
  expectNear(vec3(d["camera"]["target"]), rest("LowerArm.R"), 1e-4, "View > Frame Selected");
  EXPECT_LT(double(d["camera"]["distance"]), double(front_["camera"]["distance"]) / 2);
  // The joint is at the middle of the 3D view (between the panels' columns, from their top
  // down to the timeline), not of the window.
  const glm::dvec2 centre = DumpCamera(d).pixel(rest("LowerArm.R"));
  EXPECT_NEAR(centre.x, (itemRect(d, "Outliner").right() + itemRect(d, "Properties").x) / 2, 0.5);
  EXPECT_NEAR(centre.y, (itemRect(d, "Outliner").y + itemRect(d, "Timeline").y) / 2, 0.5);  // above the timeline
  menus.key("KP_5");
  d = run(menus, "view_menu_ortho_then_numpad5");
  EXPECT_FALSE(d["camera"]["orthographic"].get<bool>());

  // Numpad 5 and F: orthographic, centred on the left hand.
  Script keys;
  keys.select("Hand.L").move(pixelOf("Hips") + glm::dvec2(0, 150)).key("KP_5").key("F");
  d = run(keys, "numpad5_frame_selected");
  EXPECT_TRUE(d["camera"]["orthographic"].get<bool>());
  expectNear(vec3(d["camera"]["target"]), rest("Hand.L"), 1e-4, "F");
  // Perspective from the start: the front run.
  EXPECT_FALSE(front_["camera"]["orthographic"].get<bool>());
}

TEST_F(PosingE2e, OrthographicPickingFollowsTheOrthographicProjection) {
  // From the right (numpad 3) with numpad 5 the left arm, which points at the eye, projects
  // to a single point: every joint of it lies on one viewing ray, and a click there picks
  // the one nearest the eye, the fingertip (x = 0.89). Without numpad 5 the same pixel is
  // far from the fingertip's perspective image (the arm spreads along the view's height).
  Script ortho;
  ortho.key("KP_3").key("KP_5");
  const json view = run(ortho, "right_ortho");
  ASSERT_TRUE(view.is_object());
  ASSERT_TRUE(view["camera"]["orthographic"].get<bool>());
  const DumpCamera cam(view);
  const glm::dvec2 arm = cam.pixel(rest("Hand.L"));
  for (const char* j : {"Shoulder.L", "UpperArm.L", "LowerArm.L", "Fingertip.L"})
    EXPECT_LT(glm::length(cam.pixel(rest(j)) - arm), 0.01) << j << " on the same ray";
  json d = run(ortho.click(arm), "right_ortho_pick");
  EXPECT_EQ(d["selection"], json::array({"Fingertip.L"}));

  Script perspective;
  perspective.key("KP_3").wait(1).click(arm);
  d = run(perspective, "right_perspective_pick");
  EXPECT_FALSE(d["camera"]["orthographic"].get<bool>());
  EXPECT_GT(glm::length(DumpCamera(d).pixel(rest("Fingertip.L")) - arm), 20.0);
  EXPECT_NE(d["selection"], json::array({"Fingertip.L"}));
}

TEST_F(PosingE2e, ViewMenuPresetsAltLeftOrbitAndShiftMiddlePan) {
  // View > Right looks from +X (azimuth 90), View > Top from above (elevation 90).
  json d = run(Script().menu("View", "Right"), "view_menu_right");
  EXPECT_NEAR(double(d["camera"]["azimuth"]), 90.0, 1e-4);
  EXPECT_NEAR(double(d["camera"]["elevation"]), 0.0, 1e-4);
  d = run(Script().menu("View", "Top"), "view_menu_top");
  EXPECT_NEAR(double(d["camera"]["elevation"]), 90.0, 1e-3);

  // Alt + left drag, starting on the hand's bone, orbits like a middle drag (0.4 degrees
  // per pixel, turntable): 100 px right and 50 px up; nothing gets selected.
  const glm::dvec2 a = midpoint("Hand.L", "Fingertip.L");
  d = run(Script().move(a).keyDown("LEFT_ALT").down().path(a, a + glm::dvec2(100, -50)).up().keyUp("LEFT_ALT"),
          "alt_left_orbit");
  EXPECT_NEAR(double(d["camera"]["azimuth"]), -40.0, 1e-3);
  EXPECT_NEAR(double(d["camera"]["elevation"]), -20.0, 1e-3);
  EXPECT_TRUE(d["selection"].empty());
  EXPECT_EQ(int(d["undo_depth"]), 0);

  // Shift + middle drag pans: the scene follows the cursor on the target's plane, so the
  // old target's point now projects 120 px right and 40 px below the view's centre. The drag
  // starts in the view's lower half.
  const glm::dvec2 m = viewportRect(front_).at(0.5, 0.67);
  d = run(Script().move(m).keyDown("LEFT_SHIFT").down("middle").path(m, m + glm::dvec2(120, 40)).up("middle").keyUp("LEFT_SHIFT"),
          "shift_middle_pan");
  const DumpCamera after(d);
  const glm::dvec2 centre(after.x0 + after.w / 2, after.y0 + after.h / 2);
  const glm::dvec2 moved = after.pixel(vec3(front_["camera"]["target"]));
  EXPECT_NEAR(moved.x, centre.x + 120, 0.05);
  EXPECT_NEAR(moved.y, centre.y + 40, 0.05);
  EXPECT_NEAR(double(d["camera"]["azimuth"]), 0.0, 1e-6);  // a pan does not turn
  EXPECT_NEAR(double(d["camera"]["distance"]), double(front_["camera"]["distance"]), 1e-5);
}

TEST_F(PosingE2e, RPressedAxisTwiceTurnsAboutTheJointsLocalAxis) {
  // The upper arm turned 90 degrees about Z points up; the forearm's local frame is that
  // turn, so its local Y is world -X. R Y Y 90 turns the forearm (now along +Y) about -X:
  // to -Z, the hand at elbow + 0.26 (0, 0, -1), local rotation (0, sin 45, 0, cos 45).
  // R Y 90 (global Y) turns it about its own length: the hand stays at elbow + (0, 0.26, 0).
  const glm::dvec3 elbow = rest("UpperArm.L") + glm::dvec3(0, 0.28, 0);
  const glm::dvec2 away = pixelOf("Hips") + glm::dvec2(0, 150);
  const auto script = [&](bool local) {
    Script s;
    s.select("UpperArm.L").move(away).key("R").key("Z").key("9").key("0").key("ENTER");
    s.select("LowerArm.L").move(away).key("R").key("Y");
    if (local) s.key("Y");
    return s.key("9").key("0").key("ENTER");
  };
  json d = run(script(true), "rotate_local_axis");
  expectNear(jointIn(d, "LowerArm.L"), elbow, 1e-4, "the elbow after the upper arm's turn");
  expectNear(jointIn(d, "Hand.L"), elbow + glm::dvec3(0, 0, -0.26), 1e-4, "R Y Y 90: about the local Y");
  const double h = std::sqrt(0.5);
  expectRotation(rotationIn(d, "LowerArm.L"), glm::dquat(h, 0, h, 0), 1e-5, "local rotation");
  d = run(script(false), "rotate_global_axis");
  expectNear(jointIn(d, "Hand.L"), elbow + glm::dvec3(0, 0.26, 0), 1e-4, "R Y 90: about the global Y");
  EXPECT_EQ(int(d["undo_depth"]), 2);
}

TEST_F(PosingE2e, AChosenIkRootSetsTheChain) {
  // A 3-bone target on the left hand (root Shoulder.L: Shoulder.L, UpperArm.L and LowerArm.L
  // turn) reaches at most 0.14 + 0.28 + 0.26 = 0.68 from Shoulder.L. The target typed at
  // (0.55, 0.95, 0) is sqrt(0.52^2 + 0.5^2) = 0.72 from it: out of reach. With the chain
  // length at 0 and UpperChest chosen as IK root, UpperChest turns too and the target is
  // 0.67 from it, inside its 0.12 + 0.68 reach: the hand gets there, UpperChest itself stays
  // where it is, and the joints above it (Chest, Spine, Hips) keep their rotations.
  const glm::dvec3 T(0.55, 0.95, 0.0);
  ASSERT_GT(glm::length(T - rest("Shoulder.L")), 0.68 + 0.02);
  const auto script = [&](bool chooseRoot) {
    Script s;
    s.select("Hand.L").clickItem("IK Targets/Bones/+").wait(1).clickItem("IK Targets/Add IK Target to Selected").wait(2);
    if (chooseRoot) {
      // With the chain length at 0 an "IK root" combo comes in under it (the effector's
      // ancestors from the parent up) and the rows below move down one.
      for (int k = 0; k < 3; ++k) s.clickItem("IK Targets/Chain length/-").wait(1);
      s.clickItem("IK Targets/IK root").wait(2).clickItem("IK Targets/IK root/UpperChest").wait(2);
    }
    s.scrollPanel("IK Targets", -10);
    s.doubleClickItem("IK Targets/Position/0").wait(1).type("0.55").key("ENTER").wait(3);
    return s.doubleClickItem("IK Targets/Position/1").wait(1).type("0.95").key("ENTER").wait(3);
  };
  json d = run(script(true), "ik_root_chosen");
  ASSERT_EQ(d["ik_targets"].size(), 1u);
  EXPECT_EQ(d["ik_targets"][0]["chain_length"], 0);
  EXPECT_EQ(d["ik_targets"][0]["root"], "UpperChest");
  EXPECT_EQ(d["ik_targets"][0]["solver"], "jacobian-dls");
  expectNear(vec3(d["ik_targets"][0]["position"]), T, 1e-6, "the typed target");
  expectNear(jointIn(d, "Hand.L"), T, 2e-3, "the hand reaches the target");
  expectNear(jointIn(d, "UpperChest"), rest("UpperChest"), 1e-5, "the IK root stays in place");
  EXPECT_LT(std::abs(rotationIn(d, "UpperChest").w), 0.9999) << "the IK root turns";
  for (const char* outside : {"Chest", "Spine", "Hips"})
    expectRotation(rotationIn(d, outside), glm::dquat(1, 0, 0, 0), 1e-6, outside);

  // The same target with the 3-bone chain: the hand stops short (root Shoulder.L).
  d = run(script(false), "ik_root_chain3");
  EXPECT_EQ(d["ik_targets"][0]["root"], "Shoulder.L");
  EXPECT_GT(glm::length(jointIn(d, "Hand.L") - T), 0.72 - 0.68 - 2e-3);
  expectNear(jointIn(d, "Shoulder.L"), rest("Shoulder.L"), 1e-5, "the 3-bone chain's root stays");
  expectRotation(rotationIn(d, "UpperChest"), glm::dquat(1, 0, 0, 0), 1e-6, "UpperChest outside the chain");
}

// A file with motion gets the timeline under the 3D view (which gives it the room), and its
// Play button plays the clip at the replay's fixed 1/60 s per frame.
TEST_F(PosingE2e, TimelinePlaysAFilesMotion) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string bvh = sharedDataDir() + "/bvh/cmu_01_01_first720.bvh";
  // Play is the timeline's third button (after |< and <).
  Script s;
  s.clickItem("Timeline/Play").wait(60).clickItem("Timeline/Play").wait(2);
  const json d = runEditor(dir_, shotDir(), s, "timeline_play", bvh);
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(viewportRect(d).bottom(), itemRect(d, "Timeline").y);
  EXPECT_EQ(d["playback"]["clip"], 0);
  EXPECT_EQ(d["playback"]["playing"], false);
  // Play takes effect with the first click's release (frame 5), Pause with the second's
  // (3 frames after the 60 waited): about 63 frames of 1/60 s, give or take the frame in
  // which ImGui reports each click.
  const double t = d["playback"]["time"];
  EXPECT_GT(t, 59.0 / 60.0);
  EXPECT_LT(t, 66.0 / 60.0);
}

TEST_F(PosingE2e, PinIkTargetPinsTheActiveJointsTargetNotTheRowHighlightedInTheIkPanel) {
  // Issue 17: Hand.R's target added with the IK panel's button (before the fix its row
  // stayed highlighted, PanelState::selectedIkTarget), then Foot.L selected and its target
  // added with Shift+I; Pose > Pin IK Target pinned Hand.R's target. It must pin the target
  // of the active joint, Foot.L, and leave Hand.R's alone.
  Script script;
  script.select("Hand.R").clickItem("IK Targets/Add IK Target to Selected").wait(2);
  script.select("Foot.L").keyDown("LEFT_SHIFT").key("I").keyUp("LEFT_SHIFT").wait(1);
  script.menu("Pose", "Pin IK Target");
  const json d = run(script, "pin_active_joints_target");
  EXPECT_EQ(d["active"], "Foot.L");
  ASSERT_EQ(d["ik_targets"].size(), 2u);
  const json &hand = d["ik_targets"][0], &foot = d["ik_targets"][1];
  EXPECT_EQ(hand["effector"], "Hand.R");
  EXPECT_EQ(foot["effector"], "Foot.L");
  EXPECT_TRUE(foot["pinned"].get<bool>()) << "the active joint's target is pinned";
  EXPECT_FALSE(hand["pinned"].get<bool>()) << "the other target stays free";
  // Pinning moved nothing: both targets sit where their effectors were.
  expectNear(vec3(foot["position"]), rest("Foot.L"), 1e-5, "Foot.L's target");
  expectNear(vec3(hand["position"]), rest("Hand.R"), 1e-5, "Hand.R's target");
}

TEST_F(PosingE2e, AKeymapFileRebindsKeysAndABadLineIsReportedByItsNumber) {
  // The user's keymap (XDG_CONFIG_HOME/kinema/keymap.txt): R freed from rotate and given to
  // select all, and a line naming no command. The bad line shows in the error popup (Enter
  // dismisses it); then R over the 3D view selects every joint and starts no rotation, and a
  // script's command event runs View > Orthographic by id.
  runCommand("mkdir -p '" + dir_ + "/kinema'");
  writeFile(dir_ + "/kinema/keymap.txt", "tool.rotate = none\nselect.all = R\nbogus.command = X\n");
  Script script;
  script.wait(2).key("ENTER").wait(2).move(pixelOf("Hips") + glm::dvec2(0, 150)).wait(1).key("R").wait(1);
  script.move(pixelOf("Hips") + glm::dvec2(40, 150)).wait(1);
  const json before = run(script, "keymap_file");
  EXPECT_EQ(before["tool"], "none") << "R no longer rotates";
  EXPECT_EQ(before["selection"].size(), front_["joints"].size()) << "R selects all";
  EXPECT_TRUE(before["errors"].empty()) << "Enter dismissed the keymap's error";
  // The error itself, left open.
  const json shown = run(Script().wait(2), "keymap_file_error");
  ASSERT_EQ(shown["errors"].size(), 1u);
  EXPECT_EQ(shown["errors"][0].get<std::string>().rfind("keymap: " + dir_ + "/kinema/keymap.txt:3: unknown command 'bogus.command'", 0),
            0u)
      << shown["errors"][0];
  // A command event in the script.
  std::ofstream(dir_ + "/kinema/keymap.txt") << "";
  const json ortho = run(Script().command("view.orthographic"), "command_event");
  EXPECT_TRUE(ortho["camera"]["orthographic"].get<bool>());
}

}  // namespace
}  // namespace kinema::test
