#pragma once
// Keying poses into clips, window-free: what a first key creates, the settings new keys carry,
// keying and deleting joints' keys at a time. The editor's undoable commands over these are
// editor/model/keying.h.
#include <vector>

#include "anim/clip.h"
#include "anim/key_preferences.h"
#include "core/pose.h"
#include "core/skeleton.h"

namespace kinema {

constexpr const char* kNewClipName = "Action";  // Blender's name for a new action
constexpr long long kNewClipStartFrame = 1, kNewClipEndFrame = 250;  // Blender's default range

// The interpolation a rotation (quaternion) key gets for a preferred one. Clip::validate
// accepts Step, Linear, Nlerp, Squad, Hermite, Ease and Bezier (quaternion F-curves, as
// Blender keys them) on rotations; Catmull-Rom and TCB (splines through the keys) become
// Squad, the spherical spline through the keys.
Interpolation rotationInterpolation(Interpolation preferred);
// The settings a new key of `target` carries under `preferences`.
KeySettings keySettingsFor(const KeyPreferences& preferences, ChannelTarget target);

// A new empty clip as the first key creates it: "Action", without a rate of its own (it
// counts at the document's, Scene::frameRate), range frames 1..250 on `grid` (the document's).
Clip newActionClip(const FrameGrid& grid);

// Keys the joints' local transforms of `pose` at `time` into clips[clip]; when `clip` is
// not a clip of `clips`, a new "Action" (on `newClipGrid`, the document's) is appended and `clip` set to it. Translation and
// rotation always; scale where it differs from the rest pose or is keyed already (unless
// locRotOnly). Returns the number of keys written.
int keyJoints(std::vector<Clip>& clips, int& clip, const Skeleton& skeleton, const Pose& pose,
              const std::vector<int>& joints, float time, const KeyPreferences& preferences,
              const FrameGrid& newClipGrid);
// Deletes the keys of the joints' channels at `time` (findKey: within kKeyTimeTolerance).
// Returns how many.
int deleteJointKeys(Clip& clip, const std::vector<int>& joints, float time);
// Sorted times holding a key of any channel of the joints (the timeline's diamonds).
std::vector<float> jointKeyTimes(const Clip& clip, const std::vector<int>& joints);

}  // namespace kinema
