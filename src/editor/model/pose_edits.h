#pragma once
#include <string>
#include <vector>

#include "editor/model/document.h"
#include "skin/automatic_weights.h"

namespace kinema {

// The editor's pose and rig edits, each one undo step on the document ("" or a one-line
// error; a refused edit changes nothing). Rotation edits honour Document::xMirror: the
// joint's mirror partner gets the X-mirrored rotation in the same step.

// Sets a joint's local rotation (normalised).
std::string setJointRotation(Document& doc, int joint, const glm::quat& local);
// Sets a joint's rotation given in global axes (its world rotation).
std::string setJointWorldRotation(Document& doc, int joint, const glm::quat& world);
// Sets a joint's local translation (G on a root joint moves the whole character).
std::string setJointTranslation(Document& doc, int joint, const glm::vec3& translation);
// Alt+R: the joints' rotations back to their rest rotations.
std::string clearRotations(Document& doc, const std::vector<int>& joints);
// Alt+G: the joints' translations back to rest.
std::string clearTranslations(Document& doc, const std::vector<int>& joints);
// Every joint back to its rest transform.
std::string resetToRestPose(Document& doc);
// Renames a joint: non-empty, unique (a clash is refused with the clashing joint's name).
std::string renameJoint(Document& doc, int joint, const std::string& name);

// Joint limits (a limit of type None removes it).
std::string setJointLimit(Document& doc, int joint, const JointLimit& limit);
// `local` clamped into the joint's limit (relative to its rest rotation, as the IK solvers
// do); unchanged when the joint has none. Every FK rotation edit and drag goes through it.
glm::quat limitedLocalRotation(const DocumentEdit& e, int joint, const glm::quat& local);
// How mesh instance `instance` is skinned (linear blend or dual quaternion); one undo step.
std::string setMeshSkinning(Document& doc, int instance, SkinningMethod method);
// Pose > Bind to Skeleton with Automatic Weights (Ctrl+P): every unskinned mesh instance
// bound to the skeleton at its rest pose (scene/default_character_scene.h), one undo step.
std::string bindUnskinnedMeshes(Document& doc, AutomaticWeightsMethod method = AutomaticWeightsMethod::Capsule);

// IK targets. The returned string is "" or the error; addIkTarget puts the new index in
// *index when given.
std::string addIkTarget(Document& doc, const PoseIkTarget& target, int* index = nullptr);
// A target on `effector` placed where the effector is now (the usual "add IK" action).
std::string addIkTargetAtEffector(Document& doc, int effector, int chainLength, IkSolver solver, int* index = nullptr);
std::string removeIkTarget(Document& doc, int target);
// Replaces every setting of a target at once (effector, root, chain length, solver,
// pole, pinned, active, position...).
std::string setIkTarget(Document& doc, int target, const PoseIkTarget& settings);

// Drags (one undo step each; commit/cancel through doc.commitDrag()/cancelDrag()).
// Rotate gizmo: each update gives the joint's local rotation for this frame.
std::string beginRotateDrag(Document& doc, int joint);
std::string updateRotateDrag(Document& doc, int joint, const glm::quat& local);
// R on several joints: each its local rotation (same length as joints), X-mirror honoured;
// a selected joint keeps its own rotation over its selected partner's mirror.
std::string updateRotateDrag(Document& doc, const std::vector<int>& joints, const std::vector<glm::quat>& locals);
// Translate (G): each update gives the joint's local translation.
std::string beginTranslateDrag(Document& doc, int joint);
std::string updateTranslateDrag(Document& doc, int joint, const glm::vec3& translation);

}  // namespace kinema
