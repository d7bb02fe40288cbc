#pragma once
#include <vector>

namespace kinema {

enum class BoxSelectMode { Replace, Extend, Subtract };

// The selected joints and the active one (Blender pose mode). Selection changes are NOT
// undo steps here (Blender records them; keeping them out keeps the history to edits of
// the document). Indices are joint indices; the joint count never changes in a document.
class JointSelection {
 public:
  // A plain click: only `joint` selected and active (-1: clears).
  void click(int joint);
  // Shift-click (Blender): an unselected or inactive joint becomes selected and active;
  // clicking the active joint again deselects it.
  void shiftClick(int joint);
  void selectAll(int jointCount);  // active joint kept when there is one
  void clear();
  // Box select with the joints the viewport found inside the box.
  void box(const std::vector<int>& joints, BoxSelectMode mode);

  bool isSelected(int joint) const;
  int active() const { return active_; }  // -1 when none
  // Selected joints in ascending order.
  const std::vector<int>& joints() const { return joints_; }
  bool empty() const { return joints_.empty(); }

 private:
  void add(int joint);
  void remove(int joint);
  std::vector<int> joints_;  // sorted, unique
  int active_ = -1;
};

}  // namespace kinema
