#pragma once
// The editor's physics (issue 23), window-free: marking a chain dynamic and editing its
// settings, ragdolls, and baking them into the clip, each one undo step; and the spring
// bones played live at the playhead. The simulations are simulate/'s (the ones `kinema
// simulate` runs).
#include <climits>
#include <string>
#include <vector>

#include "evaluation/scene_evaluation_job.h"
#include "sim/simulation_bake.h"

namespace kinema {

class Document;

// The chain "Make Chain Dynamic" takes from a selection: the selected joints when they run
// parent to child; a single joint and its first children down to a leaf (a tail from its
// root); otherwise the path from the topmost selected joint down to the active one. Empty
// when nothing is selected.
std::vector<int> dynamicChainFrom(const Skeleton& skeleton, const std::vector<int>& selected, int active);

// Settings for a new chain or ragdoll scaled to the skeleton's units: gravity 9.81 m/s^2 in
// them (a character taller than 20 units is read as centimetres), radii from its size.
SpringBoneChain defaultSpringChain(const Skeleton& skeleton, const std::vector<int>& joints);
RagdollSettings defaultRagdoll(const Skeleton& skeleton, int root, long long startFrame);
// The joint a ragdoll of the whole character hangs from: the humanoid's hips, else the
// first joint with children.
int characterRoot(const Skeleton& skeleton);

// "Make chain dynamic": adds the chain (its joints leave any chain they were in).
std::string addSpringChainEdit(Document& doc, const SpringBoneChain& chain);
std::string removeSpringChainEdit(Document& doc, int index);
std::string setSpringChainEdit(Document& doc, int index, const SpringBoneChain& chain);
std::string setRagdollEdit(Document& doc, int index, const RagdollSettings& ragdoll);
std::string removeRagdollEdit(Document& doc, int index);
// A collision capsule on `joint` (joint space): along its bone, from the joint to its first
// child, radius a quarter of that bone's length; a leaf gets a sphere of 3 % of the
// character's rest size at the joint.
SpringCollider defaultCollider(const Skeleton& skeleton, int joint);
// "Add collision capsule": `collider` joins every dynamic chain that does not hold its joint
// (a chain does not collide with itself): one undo step; an error when no chain can take it.
std::string addColliderEdit(Document& doc, const SpringCollider& collider);
// Removes capsule `collider` of chain `chain`: one undo step.
std::string removeColliderEdit(Document& doc, int chain, int collider);
// The chain holding `joint`, or -1.
int springChainOf(const Document& doc, int joint);

// Bakes the document's chains and ragdolls into clip `clip` over frames first..last, then
// thins the baked keys: one undo step "Bake simulation". `result` gets the parts.
std::string bakeSimulationEdit(Document& doc, int clip, long long first, long long last, SimulationBake* result = nullptr);
// "Ragdoll from current frame": the subtree of `root` becomes a ragdoll at `frame` (replacing
// a ragdoll it overlaps) and falls until `last`, baked into the clip: one undo step. Without
// a clip (`clip` names none) the pose on screen is keyed at `frame` into a new "Action",
// which the fall is baked into and which becomes the active clip.
std::string ragdollFromFrameEdit(Document& doc, int clip, int root, long long frame, long long last,
                                 SimulationBake* result = nullptr);

// Spring bones played live: the evaluation's dynamics stage (evaluation/dynamics_stage.h),
// whose state this context carries from frame to frame; off, the clip plays without them.
// Owned by the editor state.
struct LiveSprings {
  bool enabled = true;
  EvaluationContext context;
};

}  // namespace kinema
