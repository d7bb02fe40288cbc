#pragma once
#include <vector>

namespace kinema {

class Document;

// The IK target the editor acts on (Pose menu, Shift+I, the IK panel's settings, the
// highlighted handle): the target whose effector is the active joint, the first in
// doc.ikTargets() when several share it. Derived from the selection, so the menu, the
// keys and the panel cannot disagree. Index into doc.ikTargets(), -1 when none.
int activeIkTarget(const Document& doc);
// Every target whose effector is `joint`, in doc.ikTargets() order (empty when none).
std::vector<int> ikTargetsOnJoint(const Document& doc, int joint);

}  // namespace kinema
