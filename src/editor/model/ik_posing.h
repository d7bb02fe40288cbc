#pragma once
#include <string>
#include <vector>

#include "editor/model/document.h"
#include "ik/ik_posing_job.h"

namespace kinema {

// The effector's world position in the document's working pose.
glm::vec3 effectorPosition(const Document& doc, int joint);

// Drags an existing IK target's handle: one undo step, each update moves the target and
// solves. Commit / cancel through doc.commitDrag() / doc.cancelDrag().
std::string beginIkTargetDrag(Document& doc, int target);
std::string updateIkTargetDrag(Document& doc, int target, const glm::vec3& position);

// Auto-IK: drag `joint` itself with a temporary target moving a chain of up to
// `chainLength` parents (fewer when the joint is nearer the root).
std::string beginAutoIkDrag(Document& doc, int joint, int chainLength, IkSolver solver = IkSolver::JacobianDls);
std::string updateAutoIkDrag(Document& doc, const glm::vec3& position);

}  // namespace kinema
