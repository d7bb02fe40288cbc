#pragma once
// When each foot is planted: frame intervals found from the ankle's and toe's height and
// horizontal speed, with hysteresis so a contact neither flickers on nor off.
#include <string>
#include <vector>

#include "anim/clip.h"
#include "anim/foot_contact_intervals.h"
#include "anim/pose_source.h"
#include "retarget/humanoid_bones.h"

namespace kinema {

// The joints of one leg (toes may be -1).
struct LegJoints {
  int upperLeg = -1, lowerLeg = -1, foot = -1, toes = -1;
  bool valid(int jointCount) const;
};
// [left, right] from a humanoid reading.
void legsOf(const HumanoidMap& humanoid, LegJoints out[2]);
// |hip - knee| + |knee - ankle| in the rest pose (file units).
float restLegLength(const Skeleton& skeleton, const LegJoints& leg);

// Thresholds as shares of the leg length (heights) and leg lengths per second (speeds). A
// contact starts on a frame where the ankle or the toe is within enterHeight of its lowest
// height over the clip and moves slower than enterSpeed horizontally; it lasts while one of
// them stays within exitHeight and below exitSpeed. Contacts shorter than minFrames go.
struct FootContactSettings {
  float enterHeight = 0.05f, exitHeight = 0.09f;
  float enterSpeed = 0.5f, exitSpeed = 1.0f;
  int minFrames = 3;
};

// ContactInterval (frames first..last of the clip's grid): anim/foot_contact_intervals.h.

struct FootContactJob {
  const Skeleton* skeleton = nullptr;
  const Clip* clip = nullptr;  // sampled at its frames (clipFrameCount)
  PoseSource* poses = nullptr;  // optional: the clip's poses (null: its keys alone; see anim/pose_source.h)
  LegJoints legs[2];           // left, right
  FootContactSettings settings;
  std::vector<ContactInterval>* output[2] = {nullptr, nullptr};  // written: per foot, in order

  std::string validate() const;
  bool run() const;
};

// World positions (Y up) of `joints` at every frame of the clip: tracks[k][frame]; the poses
// from `poses` when given, else the clip's keys alone.
std::vector<std::vector<glm::vec3>> jointTracks(const Skeleton& skeleton, const Clip& clip, const std::vector<int>& joints,
                                                PoseSource* poses = nullptr);

// Foot skate: the mean horizontal slide of the foot (ankle) joint per frame while in contact
// (every frame of an interval after its first), as a share of the leg length, over both
// feet; 0 when there are no contact frames.
float footSkate(const Skeleton& skeleton, const Clip& clip, const LegJoints legs[2],
                const std::vector<ContactInterval> contacts[2]);

}  // namespace kinema
