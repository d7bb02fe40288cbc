// Lattice edit mode through the viewport's input (issue 22): a click picks the control point
// under the mouse (the nearer one where two project together), a box selects the points
// inside it, and G with X moves the selection along world X only, confirmed as one undo step.
// The camera is the hand-derivation one (viewport_test_views.h): eye at (0, 0, 10) looking
// down -Z, so a point projects to pixel (100 + 100 x / (10 - z), 100 - 100 y / (10 - z)).
#include <gtest/gtest.h>

#include <algorithm>

#include "editor/commands/command_registry.h"
#include "editor/commands/editor_input.h"
#include "editor/model/deformer_edits.h"
#include "editor/model/key_codes.h"
#include "editor/viewport/lattice_cage.h"
#include "editor/viewport/viewport_tools.h"
#include "scene/default_character_scene.h"
#include "viewport_test_views.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

glm::vec2 pixelOf(const glm::vec3& p) { return {100 + 100 * p.x / (10 - p.z), 100 - 100 * p.y / (10 - p.z)}; }

struct LatticeTools : ::testing::Test {
  EditorState state;
  ViewportTools tools;
  SkeletonDrawList list;
  ViewportView view = test::handView(false);
  void SetUp() override {
    state.doc = Document(makeDefaultCharacterScene());
    ASSERT_EQ(addDeformer(state.doc, 0, DeformerType::Lattice), "");
    ASSERT_EQ(enterLatticeEdit(state), "");
  }
  void send(InputEventType type, glm::vec2 at = glm::vec2(0.0f), int key = -1, int button = 0) {
    InputEvent e;
    e.type = type;
    e.x = at.x;
    e.y = at.y;
    e.key = key;
    e.button = button;
    tools.handle(state, e, view, list, false);
  }
  void move(glm::vec2 at) { send(InputEventType::MouseMove, at); }
  void click(glm::vec2 at) {
    move(at);
    send(InputEventType::ButtonDown, at);
    send(InputEventType::ButtonUp, at);
  }
  const FfdLattice& saved() const { return state.doc.scene().deformers[0].deformers[0].lattice; }
};

TEST_F(LatticeTools, AClickPicksTheNearerOfPointsSeenEndOn) {
  const int front = saved().index(2, 2, 2), back = saved().index(2, 2, 0);
  // Both corners project about a pixel apart (the cage is thin next to 10 m away): a click
  // half way between is as near to both, and the one nearer the eye is picked.
  const glm::vec2 a = pixelOf(saved().points[front]), b = pixelOf(saved().points[back]);
  EXPECT_LT(glm::length(a - b), 2.0f);
  click(0.5f * (a + b));
  EXPECT_EQ(state.lattice.selected, (std::vector<int>{front}));
  EXPECT_TRUE(state.doc.selection.empty()) << "no joint picked in lattice edit mode";
  click(glm::vec2(2.0f, 2.0f));  // nothing there: deselects
  EXPECT_TRUE(state.lattice.selected.empty());
}

TEST_F(LatticeTools, ABoxSelectsThePointsInside) {
  // The top layer (j = 2) lies above every other: a box over the top of the view takes it alone.
  const float top = pixelOf(saved().points[saved().index(0, 2, 0)]).y;
  const float below = pixelOf(saved().points[saved().index(0, 1, 0)]).y;
  const glm::vec2 a(0.0f, top - 5.0f), b(199.0f, 0.5f * (top + below));
  move(a);
  send(InputEventType::ButtonDown, a);
  move(b);
  EXPECT_EQ(state.tool.mode, ModalTool::BoxSelect);
  send(InputEventType::ButtonUp, b);
  std::vector<int> expected;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) expected.push_back(saved().index(i, 2, k));
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(state.lattice.selected, expected);
}

TEST_F(LatticeTools, GThenXMovesAlongXOnlyAsOneUndoStep) {
  const int corner = saved().index(2, 2, 2);
  const glm::vec3 before = saved().points[corner];
  click(pixelOf(before));
  ASSERT_EQ(state.lattice.selected.size(), 1u);
  const int history = state.doc.historyPosition();
  ASSERT_TRUE(tools.startLatticeGrab(state));
  EXPECT_EQ(state.tool.mode, ModalTool::LatticeGrab);
  send(InputEventType::KeyDown, {}, keys::X);
  const glm::vec2 start = pixelOf(before);
  move(start + glm::vec2(20.0f, 15.0f));  // off the axis: still along X only
  EXPECT_GT(state.lattice.offset.x, 0.0f);
  EXPECT_NEAR(state.lattice.offset.y, 0.0f, 1e-6f);
  EXPECT_NEAR(state.lattice.offset.z, 0.0f, 1e-6f);
  move(start + glm::vec2(20.0f, 0.0f));
  // 20 pixels along the axis at depth 10 - z (a move along X keeps the depth): 20 (10 - z) / 100 m.
  const float expected = 20.0f * (10.0f - before.z) / 100.0f;
  EXPECT_NEAR(state.lattice.offset.x, expected, 1e-3f);
  EXPECT_NEAR(state.lattice.offset.y, 0.0f, 1e-6f);
  EXPECT_EQ(saved().points[corner], before) << "not in the document before it is confirmed";
  send(InputEventType::KeyDown, {}, keys::ENTER);
  EXPECT_EQ(state.tool.mode, ModalTool::None);
  EXPECT_EQ(state.doc.historyPosition(), history + 1);
  EXPECT_NEAR(saved().points[corner].x, before.x + expected, 1e-3f);
  EXPECT_EQ(saved().points[corner].y, before.y);
  EXPECT_EQ(saved().points[corner].z, before.z);
  // Esc cancels a second move: nothing recorded.
  ASSERT_TRUE(tools.startLatticeGrab(state));
  move(start + glm::vec2(-30.0f, 0.0f));
  send(InputEventType::KeyDown, {}, keys::ESCAPE);
  EXPECT_EQ(state.doc.historyPosition(), history + 1);
  EXPECT_FALSE(state.lattice.moving);
}

TEST_F(LatticeTools, KeysInLatticeEditGoToTheLatticeNotToThePose) {
  const Keymap keymap;
  CommandContext ctx(state);
  ctx.tools = &tools;
  ctx.view = view;
  const std::vector<CommandScope> scopes = keyScopes(state, glm::vec2(100.0f, 100.0f));
  ASSERT_EQ(scopes.front(), CommandScope::LatticeEdit);
  const Command* a = runChord(keymap, ctx, KeyChord{keys::A, 0}, scopes);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->id, "lattice.select_all");
  EXPECT_EQ(state.lattice.selected.size(), 27u);
  EXPECT_TRUE(state.doc.selection.empty()) << "the joints' select all did not run";
  const Command* i = runChord(keymap, ctx, KeyChord{keys::I, 0}, scopes);
  ASSERT_NE(i, nullptr);
  EXPECT_EQ(i->id, "lattice.insert_keyframe");
  ASSERT_EQ(state.doc.scene().clips.size(), 1u);
  EXPECT_EQ(state.doc.scene().clips[0].channels.size(), 81u);  // 27 points x 3 axes
  const Command* g = runChord(keymap, ctx, KeyChord{keys::G, 0}, scopes);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->id, "lattice.grab");
  EXPECT_EQ(state.tool.mode, ModalTool::LatticeGrab);
  send(InputEventType::KeyDown, {}, keys::ESCAPE);
  const Command* tab = runChord(keymap, ctx, KeyChord{keys::TAB, 0}, keyScopes(state, glm::vec2(100.0f, 100.0f)));
  ASSERT_NE(tab, nullptr);
  EXPECT_EQ(tab->id, "lattice.edit");
  EXPECT_FALSE(state.lattice.active);
  EXPECT_EQ(keyScopes(state, glm::vec2(100.0f, 100.0f)).front(), CommandScope::Viewport);
}

}  // namespace
}  // namespace kinema
