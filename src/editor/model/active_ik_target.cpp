#include "editor/model/active_ik_target.h"

#include "editor/model/document.h"

namespace kinema {

std::vector<int> ikTargetsOnJoint(const Document& doc, int joint) {
  std::vector<int> out;
  if (joint < 0) return out;
  const std::vector<PoseIkTarget>& targets = doc.ikTargets();
  for (int i = 0; i < static_cast<int>(targets.size()); ++i)
    if (targets[i].target.effector == joint) out.push_back(i);
  return out;
}

int activeIkTarget(const Document& doc) {
  const std::vector<int> onActive = ikTargetsOnJoint(doc, doc.selection.active());
  return onActive.empty() ? -1 : onActive.front();
}

}  // namespace kinema
