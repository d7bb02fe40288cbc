#pragma once
// A ragdoll in Bullet (library kinema_ragdoll; only what simulates links it): the bodies of
// sim/ragdoll_bodies.h as rigid capsules, each joint a Bullet constraint built from its
// limit (hinge -> one free axis of a 6-DOF joint, Euler ranges -> a 6-DOF joint in the same
// order, cone -> a 6-DOF joint holding swing and twist inside the cone), a ground plane, gravity. Bodies collide with the ground
// only, not with each other (a character's neighbouring capsules overlap at rest).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "anim/pose_source.h"
#include "core/pose.h"
#include "core/result.h"
#include "ik/joint_limits.h"
#include "sim/ragdoll_bodies.h"
#include "sim/ragdoll_settings.h"

namespace kinema {

// Physics steps per second: each step() is split into equal parts no longer than this.
constexpr int kRagdollStepsPerSecond = 240;

class Ragdoll {
 public:
  // Builds the ragdoll in `pose` (the animated local pose at the start), moving as it moved
  // from `previousPose` (`interval` seconds earlier; nullptr: at rest). `limits` holds one
  // limit per joint (ragdollJointLimits); a joint without an active limit turns freely.
  static Result<std::unique_ptr<Ragdoll>> create(const Skeleton& skeleton, const RagdollSettings& settings,
                                                 const std::vector<RagdollBody>& bodies,
                                                 const std::vector<JointLimit>& limits, const Pose& pose,
                                                 const Pose* previousPose = nullptr, float interval = 1.0f / 30.0f);
  ~Ragdoll();
  Ragdoll(const Ragdoll&) = delete;
  Ragdoll& operator=(const Ragdoll&) = delete;

  // Advances `dt` seconds (> 0) in ceil(dt * kRagdollStepsPerSecond) equal physics steps.
  void step(float dt);
  // Writes the ragdoll's joints into `pose`, which holds the animated pose of the rest of the
  // skeleton (the root's parent may move): the root body's joint gets rotation and
  // translation, the others rotation; leaves keep theirs.
  void writePose(Pose& pose) const;
  // How far the joints of `pose` (as writePose left it) lie outside their limits, radians.
  // `joint` (optional) gets the joint that is furthest out, or -1.
  float largestLimitExcess(const Pose& pose, int* joint = nullptr) const;
  long long stepsTaken() const { return steps_; }
  int bodyCount() const { return static_cast<int>(bodies_.size()); }
  // Largest speed of any body (file units / s): near 0 once the ragdoll lies still.
  float largestSpeed() const;

 private:
  struct World;
  Ragdoll() = default;
  const Skeleton* skeleton_ = nullptr;
  std::vector<RagdollBody> bodies_;
  std::vector<JointLimit> limits_;
  std::vector<glm::mat4> bodyFromJoint_;  // each body's frame in its joint's rigid frame, inverted
  std::unique_ptr<World> world_;
  long long steps_ = 0;
};

// What bakeRagdoll did, for the CLI's report.
struct RagdollBakeReport {
  int bodies = 0;
  long long steps = 0;               // physics steps
  float largestLimitExcess = 0.0f;   // radians, over every baked frame
  int worstJoint = -1;               // where it was
  long long firstFrame = 0, lastFrame = -1;  // the frames the ragdoll moved (empty when last < first)
};

// Bakes a ragdoll into a copy of `clip`: frames firstFrame..lastFrame on the clip's frame grid
// are sampled; from max(firstFrame, settings.startFrame) on, the ragdoll drives its joints.
// Each body's joint gets a linear rotation channel (the root's also a translation channel)
// with a key per frame over firstFrame..lastFrame, replacing its own channels of that kind.
Result<Clip> bakeRagdoll(const Skeleton& skeleton, const Clip& clip, const RagdollSettings& settings,
                         const std::vector<RagdollBody>& bodies, const std::vector<JointLimit>& limits,
                         long long firstFrame, long long lastFrame, RagdollBakeReport* report = nullptr,
                         const std::function<void(long long frame)>& frameDone = {}, PoseSource* poses = nullptr);

}  // namespace kinema
