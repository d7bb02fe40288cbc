#pragma once
// A crowd of animated characters (issue 24; the seed's chapter 003, 16.7): the members are
// boids (sim/boids.h) on the ground plane, each an instance of one character that plays its
// clip from its own phase, turned to face its velocity, the clip's playback rate scaled to the
// member's ground speed so the feet keep pace with the ground. Deterministic for a seed.
// Model space, metres, seconds; Y is up; yaw is the angle about +Y measured from +Z
// (yaw = atan2(vx, vz)).
#include <string>
#include <vector>

#include "anim/clip.h"
#include "anim/pose_source.h"
#include "core/pose.h"
#include "core/result.h"
#include "core/skeleton.h"
#include "sim/crowd_settings.h"

namespace kinema {

// What a crowd needs of its character's clip.
struct CrowdClipMotion {
  float start = 0.0f, duration = 0.0f;  // the clip's looped range, seconds (duration 0: a still pose)
  glm::vec3 drift{0.0f};                // the clip's own ground velocity (m/s, y = 0); removed so it loops in place
  float naturalSpeed = 1.0f;            // the ground speed at which the clip plays at rate 1 (m/s, > 0)
  float forwardYaw = 0.0f;              // radians: which way the character faces in its clip
};
// Measures the clip's ground drift from the centroid of its joints at the first and last key
// (a walk with root motion); a clip that moves less than 1 mm/s walks in place and uses
// `settings`' stride speed (or its cruise speed) and forward angle.
CrowdClipMotion analyseCrowdClip(const Skeleton& skeleton, const Clip& clip, const CrowdSettings& settings,
                                 PoseSource* poses = nullptr);

struct CrowdMemberState {
  glm::vec3 position{0.0f}, velocity{0.0f};
  float yaw = 0.0f;       // radians: atan2(vx, vz), held while the member stands still
  double clipTime = 0.0;  // seconds into the character's clip, in [start, start + duration)
};

// The whole crowd, every frame: frame 0 is the start layout, each later frame one boids step.
struct CrowdRun {
  int members = 0;
  long long frames = 0;
  double dt = 1.0 / 30.0;
  std::vector<CrowdMemberState> states;  // frame-major: states[frame * members + member]
  std::vector<BoidDebug> debug;          // per frame: the impulses the settings' debug member felt there

  const CrowdMemberState& at(long long frame, int member) const {
    return states[static_cast<size_t>(frame) * static_cast<size_t>(members) + static_cast<size_t>(member)];
  }
};

// The start layout: members on a square lattice 2.5 separation distances apart (the nearest
// lattice points to the spawn centre), jittered by up to a quarter of the separation
// distance, heading a random way (towards the goal, give or take 30 degrees, when there is
// one) at the cruise speed; each clip phase uniform over the clip.
std::vector<CrowdMemberState> crowdStartLayout(const CrowdSettings& settings, const CrowdClipMotion& motion);

// Runs `frames` frames (>= 1) at `dt` seconds a frame (0, 1].
Result<CrowdRun> runCrowd(const CrowdSettings& settings, const CrowdClipMotion& motion, double dt, long long frames);

// The clip time after a step: advanced by dt * groundSpeed / naturalSpeed and wrapped into
// the clip's range.
double advanceCrowdClipTime(double clipTime, double dt, float groundSpeed, const CrowdClipMotion& motion);

// A member's pose: the clip sampled at its clip time, its drift taken out, and each root joint
// turned by (yaw - forwardYaw) about +Y and moved to the member's position. Here and in
// analyseCrowdClip and bakeCrowdMember, `poses` gives the clip's poses (the character's scene
// through the pipeline: evaluation/scene_poses.h); null: the clip's keys alone.
void crowdMemberPose(const Skeleton& skeleton, const Clip& clip, const CrowdClipMotion& motion,
                     const CrowdMemberState& state, Pose& pose, PoseSource* poses = nullptr);

// One member as a clip of its own: a linear key per frame (frames first..last of the run, at
// frame * frameTime seconds) on the translation and rotation of every root joint and every joint
// the clip animates (and the scale where the clip animates it).
Clip bakeCrowdMember(const Skeleton& skeleton, const Clip& clip, const CrowdClipMotion& motion, const CrowdRun& run,
                     int member, long long first, long long last, const std::string& name, PoseSource* poses = nullptr);

// "crowd_0007": the name of a member (its baked clip, its joints' prefix in a glTF of the crowd).
std::string crowdMemberName(const std::string& crowdName, int member);

}  // namespace kinema
