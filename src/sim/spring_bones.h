#pragma once
#include <string>
#include <vector>

#include "anim/clip.h"
#include "anim/pose_source.h"
#include "core/pose.h"
#include "core/result.h"

namespace kinema {

// A capsule the spring bones' tails stay out of: the segment a-b in `joint`'s space (the
// world when joint is -1) swept by `radius`, metres.
struct SpringCollider {
  int joint = -1;
  glm::vec3 a{0.0f}, b{0.0f};
  float radius = 0.05f;
  bool operator==(const SpringCollider& o) const { return joint == o.joint && a == o.a && b == o.b && radius == o.radius; }
};

// A chain of joints that swings behind its animation (a tail, ears, hair, a belly): each
// joint's bone (from the joint to its tail: the next joint of the chain, else the joint's
// first child, else its own bone from its parent continued) is a point mass at the tail,
// pulled towards where the animation puts it, under gravity and damping, kept at the bone's
// length, pushed out of the colliders. The chain's first joint hangs from an animated parent.
struct SpringBoneChain {
  std::string name;
  std::vector<int> joints;   // root to tip, each the parent of the next
  float stiffness = 100.0f;  // 1/s^2 (acceleration per metre away from the animated tail)
  float damping = 5.0f;      // 1/s (velocity lost per second, as a fraction)
  glm::vec3 gravity{0.0f};   // m/s^2 in world space, e.g. (0, -9.81, 0)
  float drag = 0.0f;         // 1/m: air drag, an acceleration -drag |v| v against the tails' world velocity v
  float radius = 0.02f;      // the tails' own radius against the colliders (m)
  std::vector<SpringCollider> colliders;

  // Empty when usable on `skeleton`; otherwise one sentence naming the problem.
  std::string validate(const Skeleton& skeleton) const;
  bool operator==(const SpringBoneChain& o) const {
    return name == o.name && joints == o.joints && stiffness == o.stiffness && damping == o.damping &&
           gravity == o.gravity && drag == o.drag && radius == o.radius && colliders == o.colliders;
  }
};

// What a simulation carries from step to step: each chain's tail positions now and one step
// earlier (world space, metres). Empty: the next step starts from the animated pose at rest.
struct SpringBoneState {
  std::vector<std::vector<glm::vec3>> tails, previousTails;
  void reset() { tails.clear(), previousTails.clear(); }
};

// Advances the chains by one step of `dt` seconds, in `substeps` equal parts (position
// Verlet: deterministic, bit for bit, for the same inputs). `pose` holds the animated local
// pose on input (it drives the chains' parents and their targets) and the chains' simulated
// local rotations on output; other joints are left as they were. Assumes no non-uniform
// scale along the chains.
struct SpringBoneJob {
  const Skeleton* skeleton = nullptr;
  const std::vector<SpringBoneChain>* chains = nullptr;
  float dt = 1.0f / 30.0f;  // s, > 0
  int substeps = 4;         // 1..64
  Pose* pose = nullptr;
  SpringBoneState* state = nullptr;

  std::string validate() const;
  bool run() const;
};

// Bakes the chains into a copy of `clip`: the clip is sampled at every frame from firstFrame
// to lastFrame on its frame grid (Clip::frameToTime), simulated from firstFrame at rest, and each
// chain joint gets a linear rotation channel with a key per frame (replacing its own rotation
// channels). What the editor and `kinema simulate` write; the result edits like any clip.
// The chains move on `poses` (the clip's motion, e.g. through the pipeline: evaluation/
// scene_poses.h, dynamics off); null: the clip's keys alone.
Result<Clip> bakeSpringBones(const Skeleton& skeleton, const Clip& clip, const std::vector<SpringBoneChain>& chains,
                             long long firstFrame, long long lastFrame, int substeps = 4, PoseSource* poses = nullptr);

}  // namespace kinema
