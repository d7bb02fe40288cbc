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
}

void JointSelection::keepActiveSelected(const std::vector<int>& preferred) {
  if (isSelected(active_)) return;
  active_ = -1;
  for (int j : preferred)  // nearest the root among what the change selected
    if (isSelected(j) && (active_ < 0 || j < active_)) active_ = j;
  if (active_ < 0 && !joints_.empty()) active_ = joints_.front();  // sorted: nearest the root
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
    keepActiveSelected({});
    return;
  }
  add(joint);
  active_ = joint;
}

void JointSelection::selectAll(int jointCount) {
  joints_.clear();
  for (int i = 0; i < jointCount; ++i) joints_.push_back(i);
  keepActiveSelected({});
}

void JointSelection::clear() {
  joints_.clear();
  active_ = -1;
}

void JointSelection::box(const std::vector<int>& joints, BoxSelectMode mode) {
  if (mode == BoxSelectMode::Replace) joints_.clear();
  for (int j : joints) {
    if (j < 0) continue;
    if (mode == BoxSelectMode::Subtract)
      remove(j);
    else
      add(j);
  }
  keepActiveSelected(mode == BoxSelectMode::Subtract ? std::vector<int>{} : joints);
}

}  // namespace kinema
