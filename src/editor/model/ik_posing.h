#pragma once
#include <string>
#include <vector>

#include "editor/model/document.h"

namespace kinema {

// IK posing on the document. The rule every solve follows:
//  * the driven target (the one being edited or dragged; also the auto-IK temporary
//    target) and every active *pinned* target are solved, in a stable order: the
//    temporary one, the driven one, then pinned ones in list order, each with its own
//    solver, joint limits respected. When several are solved and that leaves one off
//    target (overlapping chains), they are solved once more all together by damped least
//    squares (up to kIkJointIterations steps), where a chain whose root lies inside
//    another target's chain extends up to that chain's root (the outer chain moves it anyway);
//  * every other active (unpinned) target then follows its effector (its position is set
//    to where the effector ended), so FK edits and other drags carry it along.
// So a pinned target keeps its effector where it is while other targets move.
constexpr int kIkJointIterations = 200;

struct IkPosingInput {
  const Skeleton* skeleton = nullptr;
  const std::vector<JointLimit>* limits = nullptr;  // may be empty
  std::vector<PoseIkTarget>* targets = nullptr;     // unpinned ones are moved to their effectors
  const PoseIkTarget* temporary = nullptr;          // auto-IK target, or null
  int driven = -1;                                  // index into *targets, or -1
  IkSettings settings;
};

// Solves as described above, editing `pose` in place; returns one report per solved
// target (driven / temporary first, then pinned ones). Invalid targets are skipped with
// converged = false.
std::vector<IkTargetReport> solveIkPosing(const IkPosingInput& input, Pose& pose);

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
