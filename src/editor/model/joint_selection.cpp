#include "editor/model/joint_selection.h"

#include <algorithm>

namespace kinema {

void JointSelection::add(int joint) {
  auto it = std::lower_bound(joints_.begin(), joints_.end(), joint);
  if (it == joints_.end() || *it != joint) joints_.insert(it, joint);
}

void JointSelection::remove(int joint) {
  auto it = std::lower_bound(joints_.begin(), joints_.end(), joint);
  if (it != joints_.end() && *it == joint) joints_.erase(it);
  if (active_ == joint) active_ = -1;
}

bool JointSelection::isSelected(int joint) const {
  return std::binary_search(joints_.begin(), joints_.end(), joint);
}

void JointSelection::click(int joint) {
  clear();
  if (joint < 0) return;
  add(joint);
  active_ = joint;
}

void JointSelection::shiftClick(int joint) {
  if (joint < 0) return;
  if (isSelected(joint) && active_ == joint) {
    remove(joint);
    return;
  }
  add(joint);
  active_ = joint;
}

void JointSelection::selectAll(int jointCount) {
  joints_.clear();
  for (int i = 0; i < jointCount; ++i) joints_.push_back(i);
  if (active_ >= jointCount) active_ = -1;
}

void JointSelection::clear() {
  joints_.clear();
  active_ = -1;
}

void JointSelection::box(const std::vector<int>& joints, BoxSelectMode mode) {
  if (mode == BoxSelectMode::Replace) {
    joints_.clear();
    if (std::find(joints.begin(), joints.end(), active_) == joints.end()) active_ = -1;
  }
  for (int j : joints) {
    if (j < 0) continue;
    if (mode == BoxSelectMode::Subtract)
      remove(j);
    else
      add(j);
  }
}

}  // namespace kinema
