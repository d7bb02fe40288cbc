// Lattice edit mode's model (issue 22): selecting control points, a move that is one undo
// step (or none when cancelled), keys written where auto-key is on or the points are
// animated, and the mode leaving when its lattice goes. Expected values are the lattice's
// own rest points plus the offset applied, worked out from the fitted box.
#include <gtest/gtest.h>

#include "anim/scalar_property.h"
#include "editor/model/deformer_edits.h"
#include "editor/model/editor_state.h"
#include "editor/model/lattice_editing.h"
#include "scene/default_character_scene.h"
#include "evaluation/scene_deformation.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

struct LatticeFixture : ::testing::Test {
  EditorState state;
  void SetUp() override {
    state.doc = Document(makeDefaultCharacterScene());
    ASSERT_EQ(addDeformer(state.doc, 0, DeformerType::Lattice), "");
  }
  const FfdLattice& saved() const { return state.doc.scene().deformers[0].deformers[0].lattice; }
  const Channel* channel(const std::string& parameter) const {
    if (state.doc.scene().clips.empty()) return nullptr;
    for (const Channel& ch : state.doc.scene().clips[state.clip].channels)
      if (ch.target == ChannelTarget::Scalar && ch.property == deformerParameterProperty("lattice", parameter)) return &ch;
    return nullptr;
  }
};

TEST_F(LatticeFixture, EntersOnTheScenesLatticeAndLeavesWhenItIsGone) {
  EXPECT_EQ(enterLatticeEdit(state), "");
  EXPECT_TRUE(state.lattice.active);
  ASSERT_NE(editedLattice(state), nullptr);
  EXPECT_EQ(editedLattice(state)->name, "lattice");
  // The world-parented lattice is shown where it is stored, one point per grid node.
  const std::vector<glm::vec3> points = latticeWorldPoints(state);
  ASSERT_EQ(points.size(), 27u);
  EXPECT_EQ(points[saved().index(2, 1, 0)], saved().restPoint(2, 1, 0));
  clickLatticePoint(state.lattice, 3, false);
  ASSERT_EQ(beginLatticeMove(state), "");
  state.tool.mode = ModalTool::LatticeGrab;  // as the viewport's G sets it
  state.doc.undo();  // the lattice's Add
  keepLatticeEditValid(state);
  EXPECT_FALSE(state.lattice.active);
  EXPECT_FALSE(state.lattice.moving);
  EXPECT_EQ(state.tool.mode, ModalTool::None) << "the move ends with the mode";
  EXPECT_NE(enterLatticeEdit(state), "") << "no lattice left to edit";
}

TEST(LatticeEditing, TheCageJoinsNeighboursAlongEachAxis) {
  const int counts[3] = {3, 2, 4};
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const FfdLattice l = makeLattice(counts, glm::vec3(0.0f), axes);
  const std::vector<std::pair<int, int>> edges = latticeEdges(l);
  // Along S: (3-1)*2*4, along T: 3*(2-1)*4, along U: 3*2*(4-1).
  EXPECT_EQ(edges.size(), 16u + 12u + 18u);
  for (const auto& [a, b] : edges) EXPECT_NEAR(glm::length(l.points[a] - l.points[b]), 1.0f / 3.0f, 0.7f);
}

TEST_F(LatticeFixture, ClickToggleBoxAllAndNoneSelectPoints) {
  ASSERT_EQ(enterLatticeEdit(state), "");
  LatticeEditState& e = state.lattice;
  clickLatticePoint(e, 5, false);
  EXPECT_EQ(e.selected, (std::vector<int>{5}));
  clickLatticePoint(e, 2, true);
  EXPECT_EQ(e.selected, (std::vector<int>{2, 5}));
  clickLatticePoint(e, 5, true);  // Shift+click on a selected point takes it out
  EXPECT_EQ(e.selected, (std::vector<int>{2}));
  boxSelectLatticePoints(e, {9, 7, 2}, BoxSelectMode::Extend);
  EXPECT_EQ(e.selected, (std::vector<int>{2, 7, 9}));
  boxSelectLatticePoints(e, {7}, BoxSelectMode::Subtract);
  EXPECT_EQ(e.selected, (std::vector<int>{2, 9}));
  boxSelectLatticePoints(e, {4, 3}, BoxSelectMode::Replace);
  EXPECT_EQ(e.selected, (std::vector<int>{3, 4}));
  selectAllLatticePoints(state);
  EXPECT_EQ(e.selected.size(), 27u);
  selectNoLatticePoints(e);
  EXPECT_TRUE(e.selected.empty());
  clickLatticePoint(e, 26, false);
  clickLatticePoint(e, -1, false);  // a click on nothing
  EXPECT_TRUE(e.selected.empty());
}

TEST_F(LatticeFixture, AMoveIsOneUndoStepAndACancelledOneNone) {
  ASSERT_EQ(enterLatticeEdit(state), "");
  const glm::vec3 p4 = saved().points[4], p8 = saved().points[8];
  clickLatticePoint(state.lattice, 4, false);
  clickLatticePoint(state.lattice, 8, true);
  const int history = state.doc.historyPosition();
  ASSERT_EQ(beginLatticeMove(state), "");
  const glm::vec3 offset(0.1f, -0.05f, 0.02f);
  setLatticeMoveOffset(state, offset);
  // Shown moved, not yet in the document.
  EXPECT_EQ(latticeWorldPoints(state)[4], p4 + offset);
  EXPECT_EQ(saved().points[4], p4);
  std::vector<DeformerStack> stacks = sampleDeformerStacks(state.doc.scene(), -1, 0.0);
  previewLatticeMove(state, state.world(), stacks);
  EXPECT_EQ(stacks[0].deformers[0].lattice.points[8], p8 + offset);
  EXPECT_EQ(stacks[0].deformers[0].lattice.points[5], saved().points[5]);
  cancelLatticeMove(state);
  EXPECT_EQ(state.doc.historyPosition(), history);
  EXPECT_EQ(latticeWorldPoints(state)[4], p4);

  ASSERT_EQ(beginLatticeMove(state), "");
  setLatticeMoveOffset(state, offset * 0.5f);
  setLatticeMoveOffset(state, offset);  // the latest offset counts
  EXPECT_NE(confirmLatticeMove(state), "");
  EXPECT_EQ(state.doc.historyPosition(), history + 1);
  EXPECT_EQ(saved().points[4], p4 + offset);
  EXPECT_EQ(saved().points[8], p8 + offset);
  EXPECT_TRUE(state.doc.scene().clips.empty()) << "auto-key off, nothing animated: no keys";
  state.doc.undo();
  EXPECT_EQ(saved().points[4], p4);
  EXPECT_EQ(saved().points[8], p8);
}

TEST_F(LatticeFixture, NothingSelectedNothingMoves) {
  ASSERT_EQ(enterLatticeEdit(state), "");
  EXPECT_NE(beginLatticeMove(state), "");
  EXPECT_FALSE(state.lattice.moving);
  exitLatticeEdit(state);
  EXPECT_NE(beginLatticeMove(state), "");
}

TEST_F(LatticeFixture, AutoKeyKeysEveryAxisOfTheMovedPointsInTheSameStep) {
  ASSERT_EQ(enterLatticeEdit(state), "");
  state.doc.autoKey.enabled = true;
  state.doc.autoKey.preferences.interpolation = Interpolation::Linear;
  const glm::vec3 p0 = saved().points[0];
  clickLatticePoint(state.lattice, 0, false);
  const int history = state.doc.historyPosition();
  ASSERT_EQ(beginLatticeMove(state), "");
  setLatticeMoveOffset(state, glm::vec3(0.0f, 0.2f, 0.0f));
  confirmLatticeMove(state);
  EXPECT_EQ(state.doc.historyPosition(), history + 1);
  EXPECT_EQ(saved().points[0], p0) << "keyed, the saved point stays";
  for (int a = 0; a < 3; ++a) {
    const Channel* ch = channel(std::string("point.0.") + "xyz"[a]);
    ASSERT_NE(ch, nullptr) << a;
    ASSERT_EQ(ch->times.size(), 1u);
    EXPECT_EQ(ch->times[0], 0.0f);
    EXPECT_FLOAT_EQ(ch->values[0].x, p0[a] + (a == 1 ? 0.2f : 0.0f));
  }
  EXPECT_EQ(channel("point.1.x"), nullptr) << "only the selected point";
  EXPECT_FLOAT_EQ(latticeWorldPoints(state)[0].y, p0.y + 0.2f);  // shown from the channel
  state.doc.undo();
  EXPECT_TRUE(state.doc.scene().clips.empty() || channel("point.0.y") == nullptr);
}

TEST_F(LatticeFixture, KeyedPointsAreKeyedAgainWhenMovedAndPlayInBetween) {
  ASSERT_EQ(enterLatticeEdit(state), "");
  state.doc.autoKey.preferences.interpolation = Interpolation::Linear;
  const glm::vec3 p13 = saved().points[13];
  clickLatticePoint(state.lattice, 13, false);
  EXPECT_NE(keyLatticePoints(state), "");  // I at frame 0: the rest place
  ASSERT_NE(channel("point.13.z"), nullptr);
  ASSERT_TRUE(state.hasMotion());
  const double later = 1.0;
  state.time = later;
  const int history = state.doc.historyPosition();
  ASSERT_EQ(beginLatticeMove(state), "");
  setLatticeMoveOffset(state, glm::vec3(0.0f, 0.0f, 0.3f));
  confirmLatticeMove(state);  // auto-key is off, but the point is animated: keyed
  EXPECT_EQ(state.doc.historyPosition(), history + 1);
  EXPECT_EQ(saved().points[13], p13);
  const Channel* z = channel("point.13.z");
  ASSERT_NE(z, nullptr);
  ASSERT_EQ(z->times.size(), 2u);
  // Half way between the keys, linear: half the offset.
  state.time = 0.5 * later;
  EXPECT_NEAR(latticeWorldPoints(state)[13].z, p13.z + 0.15f, 1e-5f);
  EXPECT_NEAR(latticeWorldPoints(state)[13].x, p13.x, 1e-6f);
}

}  // namespace
}  // namespace kinema
