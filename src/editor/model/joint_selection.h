#pragma once
#include <vector>

namespace kinema {

enum class BoxSelectMode { Replace, Extend, Subtract };

// The selected joints and the active one (Blender pose mode): the selection is what R, G,
// I and the other tools act on; the active joint is the one the properties panel, the
// status bar, the gizmo and the IK target of the active joint refer to. Selection changes
// are NOT undo steps here (Blender records them; keeping them out keeps the history to
// edits of the document). Indices are joint indices; the joint count never changes in a
// document.
//
// One rule keeps the two in step: whenever a joint is selected, one of the selected joints
// is active, and the active joint is always selected (-1 only with an empty selection).
// An operation that leaves the active joint selected keeps it; otherwise the active joint
// becomes the one it selected nearest the skeleton's root (the lowest index: parents come
// before their children), else the selected joint nearest the root. So after a box select
// or select all (A) there is an active joint, as the properties panel and status bar need.
class JointSelection {
 public:
  // A plain click: only `joint` selected and active (-1: clears).
  void click(int joint);
  // Shift-click (Blender): an unselected or inactive joint becomes selected and active;
  // clicking the active joint again deselects it (another selected joint becomes active).
  void shiftClick(int joint);
  void selectAll(int jointCount);  // the active joint kept; without one the root (joint 0)
  void clear();
  // Box select with the joints the viewport found inside the box.
  void box(const std::vector<int>& joints, BoxSelectMode mode);

  bool isSelected(int joint) const;
  int active() const { return active_; }  // -1 when (and only when) nothing is selected
  // Selected joints in ascending order.
  const std::vector<int>& joints() const { return joints_; }
  bool empty() const { return joints_.empty(); }

 private:
  void add(int joint);
  void remove(int joint);
  // Restores the rule above after a change; `preferred`: the joints the change selected.
  void keepActiveSelected(const std::vector<int>& preferred);
  std::vector<int> joints_;  // sorted, unique
  int active_ = -1;
};

}  // namespace kinema
