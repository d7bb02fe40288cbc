#pragma once
#include <string>

#include "deform/deformer_stack.h"
#include "editor/model/document.h"
#include "editor/model/key_preferences.h"

namespace kinema {

// The Deformers panel's edits of a mesh instance's stack (issue 22), each one undo step
// (Document::editMeshes). Deformers act in world space after skinning (io/scene.h).

// Adds a deformer of `type` at the end of the instance's stack, placed around the mesh as it
// stands at the rest pose (world space): a 3x3x3 lattice fitted around it; a bend, twist or
// taper along +Y over its height (bend 0, twist 0, taper 1: no change until a parameter is
// set); a soft pull centred on its highest vertex with a tenth of its height as radius.
// Named after the type, made unique ("twist", "twist.001"...), as Blender names modifiers.
std::string addDeformer(Document& doc, int instance, DeformerType type);
std::string removeDeformer(Document& doc, int instance, int deformer);
// A deformer's placement and scope (not keyable), each one undo step:
// - a lattice of `counts` points (2..8 each way) over the same rest box, every point back at
//   rest (as Blender resets a lattice whose resolution changes);
std::string setLatticeResolution(Document& doc, int instance, int deformer, const int counts[3]);
// - the lattice refitted at rest, same resolution, around the rest-pose vertices whose
//   heaviest joint is one of `joints` (all the mesh's vertices when `joints` is empty);
std::string fitLatticeToJoints(Document& doc, int instance, int deformer, const std::vector<int>& joints);
// - parented to skeleton joint `joint` (-1: the world): placed at the rest pose, it then
//   follows that joint's motion;
std::string setDeformerParent(Document& doc, int instance, int deformer, int joint);
// - limited to the vertices `joint` weighs, each moved by that skin weight (a vertex group
//   from the skin; -1: every vertex in full);
std::string limitDeformerToJoint(Document& doc, int instance, int deformer, int joint);
// - a bend, twist or taper's axis and its range along it (metres from its origin, low < high).
std::string setAxisRange(Document& doc, int instance, int deformer, DeformAxis axis, float low, float high);
// Moves deformer `deformer` one place up (-1) or down (+1) the stack.
std::string moveDeformer(Document& doc, int instance, int deformer, int step);
std::string setDeformerEnabled(Document& doc, int instance, int deformer, bool enabled);
// A soft pull's centre (world space, metres: the point picked on the body), radius (> 0) and
// falloff; its offset (the keyable displacement) stays. One undo step.
std::string setSoftPullShape(Document& doc, int instance, int deformer, const glm::vec3& center, float radius,
                             Falloff falloff);
// Sets a keyable parameter by name (deformerParameters: "angle", "factor", "offset.y",
// "point.12.x"...).
std::string setDeformerValue(Document& doc, int instance, int deformer, const std::string& parameter, float value);
// The parameter's value at `time` in `clip` (its channel "deformers/NAME/PARAM" on the
// instance's joint where animated, else the stack's); 0 for an unknown one.
float deformerValueAt(const Document& doc, int clip, double time, int instance, int deformer, const std::string& parameter);
// Keys the parameter's value at `time` (keyScalarProperty; one undo step).
std::string keyDeformerValue(Document& doc, int& clip, int instance, int deformer, const std::string& parameter,
                             float time, float value, const KeyPreferences& preferences);

}  // namespace kinema
