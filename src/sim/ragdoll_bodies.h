#pragma once
// What a ragdoll is made of, before any physics (no Bullet here): one capsule per bone and
// the limit each joint is held to. sim/ragdoll.h turns these into Bullet bodies.
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/pose.h"
#include "core/result.h"
#include "ik/ik_rig.h"

namespace kinema {

// One rigid body: the bone of `joint`, from the joint (the head) to `tail`, a capsule of
// `radius` around that segment. `tail` is in the joint's own frame without its scale
// (rigid: rotation and translation only), file units; the centroid of the joint's
// children. `parentBody` indexes the body list (-1: the ragdoll's root, free in the world).
struct RagdollBody {
  int joint = -1;
  int parentBody = -1;
  glm::vec3 tail{0.0f};
  float radius = 0.0f;  // file units, > 0
  float mass = 0.0f;    // kg, > 0
};

// The bodies of the subtree under `root`: one per joint that has a child (leaves ride on
// their parent's body). Sizes come from the skin where the scene has one (the mean distance
// of the vertices a joint carries most to its bone), else a fifth of the bone's length;
// the mass is shared by volume, no body under 2 % of it (the solver cannot hold a toe a
// hundredth of its leg's mass to its limits). `pose` gives the bone shapes (its translations and scales).
struct RagdollBodiesJob {
  const Skeleton* skeleton = nullptr;
  const Pose* pose = nullptr;
  int root = 0;
  float totalMass = 70.0f;  // kg
  // Optional, for sizing by the skin (all three or none).
  const std::vector<Mesh>* meshes = nullptr;
  const std::vector<Skin>* skins = nullptr;
  const std::vector<MeshInstance>* instances = nullptr;
  std::vector<RagdollBody>* bodies = nullptr;  // written

  std::string validate() const;
  bool run() const;
};

// The limit each joint of `skeleton` is held to in a ragdoll: the rig's own where it has one;
// else, when the skeleton reads as a humanoid, default human ranges (knees bend back and
// elbows forward only, as hinges; hips, shoulders, spine, neck, wrists and ankles in
// cones); other joints (a tail, a non-humanoid's bones without stored limits) are free ball
// joints, held only by their bodies' collisions with the ground.
std::vector<JointLimit> ragdollJointLimits(const Skeleton& skeleton, const IkRig& rig);

}  // namespace kinema
