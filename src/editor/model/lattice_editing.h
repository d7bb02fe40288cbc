#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/math.h"
#include "deform/deformer_stack.h"
#include "editor/model/joint_selection.h"

namespace kinema {

struct EditorState;
class Document;

// Lattice edit mode (issue 22; Blender's lattice edit mode is the yardstick): the cage of
// one FFD lattice deformer is drawn over the mesh, its control points are selected and moved
// with G, and keyed with I. Window-free: the viewport (editor/viewport) picks points and
// turns the mouse into a world offset; everything else is here.
//
// Spaces: the lattice's points are stored in the deformer's own space (the world for a
// world-parented lattice, else its parent joint's, deform/deformer_stack.h deformerFrame);
// this file shows and moves them in world space (metres), at the playhead (their animated
// values where a channel keys them).
//
// A move is not written into the document until it is confirmed: while G runs, the offset
// lives here and the renderers add it to the sampled stacks (previewLatticeMove), so the
// confirmed move is exactly one undo step and a cancelled one none.
struct LatticeEditState {
  bool active = false;               // lattice edit mode is on
  // The lattice edited (or, while the mode is off, the one Tab enters: the active lattice,
  // set by the Properties panel; -1 or stale: the scene's first lattice).
  int instance = -1, deformer = -1;
  std::vector<int> selected;         // flat point indices (FfdLattice::index), ascending, unique
  int hovered = -1;                  // the point under the mouse (drawn lighter), -1 none
  bool moving = false;               // G runs: `offset` is added to the selected points
  glm::vec3 offset{0.0f};            // the move so far, world metres
};

// The lattice deformer `state.lattice` names, when it is one; else null.
const Deformer* editedLattice(const EditorState& state);
// The lattice Tab would edit: the active one when it still is a lattice, else the first
// lattice of the scene (instance order, then stack order). False when the scene has none.
bool latticeToEdit(const EditorState& state, int& instance, int& deformer);

// Enters the mode on the lattice latticeToEdit picks (or on instance / deformer when given,
// which must name a lattice); the point selection starts empty. Returns "" or why not.
std::string enterLatticeEdit(EditorState& state, int instance = -1, int deformer = -1);
// Leaves the mode; a running move is cancelled.
void exitLatticeEdit(EditorState& state);
// After any change of the document (undo, a removed deformer): leaves the mode when its
// lattice is gone, drops selected indices beyond the point count. Cheap; called per frame.
void keepLatticeEditValid(EditorState& state);

// The control points of the edited lattice in world space at the playhead, with a running
// move's offset on the selected ones. Empty when the mode is off.
std::vector<glm::vec3> latticeWorldPoints(const EditorState& state);
// The cage's edges: neighbouring points along S, T and U, as pairs of flat indices.
std::vector<std::pair<int, int>> latticeEdges(const FfdLattice& lattice);

// Selection (not undo steps, as the joints' selection): a click selects only `point`
// (-1 clears); toggle (Shift+click) adds it or takes it out; box with the points inside.
void clickLatticePoint(LatticeEditState& edit, int point, bool toggle);
void boxSelectLatticePoints(LatticeEditState& edit, const std::vector<int>& points, BoxSelectMode mode);
void selectAllLatticePoints(EditorState& state);
void selectNoLatticePoints(LatticeEditState& edit);
bool latticePointSelected(const LatticeEditState& edit, int point);

// G: starts moving the selected points (false and a reason when nothing is selected or the
// mode is off). setLatticeMoveOffset replaces the offset (world metres) of the running move.
std::string beginLatticeMove(EditorState& state);
void setLatticeMoveOffset(EditorState& state, const glm::vec3& offset);
// Confirms the move as one undo step: the selected points' parameters ("point.N.x|y|z") are
// keyed at the playhead when auto-key is on or one of them is animated in the clip (every
// axis of every selected point, so they stay where they were put), else the stack's saved
// points are set. Returns the status line (what was moved, or the error); a move by zero or
// without a selection records nothing and returns "".
std::string confirmLatticeMove(EditorState& state);
void cancelLatticeMove(EditorState& state);

// I: keys every axis of the selected points at the playhead with the values shown there (one
// undo step). Returns the status line.
std::string keyLatticePoints(EditorState& state);

// What the renderers and pickers use while a move runs: `stacks` (sampleDeformerStacks at
// the playhead, one per instance) with the offset added to the edited lattice's selected
// points, taken into the lattice's space by its frame (`world`: the joints' world
// matrices). Nothing changes when no move runs.
void previewLatticeMove(const EditorState& state, const std::vector<glm::mat4>& world, std::vector<DeformerStack>& stacks);

}  // namespace kinema
