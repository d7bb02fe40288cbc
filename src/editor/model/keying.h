#pragma once
#include <string>
#include <utility>
#include <vector>

#include "anim/clip.h"
#include "editor/model/key_preferences.h"

namespace kinema {

class Document;

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

// The editor's commands, each one undo step. `clip` may name no clip yet: the first key
// creates "Action" and `clip` is set to its index.
std::string insertKeys(Document& doc, int& clip, float time, const std::vector<int>& joints,
                       const KeyPreferences& preferences);
std::string insertKeysOnAllJoints(Document& doc, int& clip, float time, const KeyPreferences& preferences);
std::string deleteKeys(Document& doc, int clip, float time, const std::vector<int>& joints);
// Keys `value` at `time` on the Scalar channel (`joint`, `property`) of clips[clip], made
// when missing (non-joint channels: morph weights "weights/K", deformer parameters
// "deformers/NAME/PARAM"; anim/scalar_property.h). One undo step named `label`; `clip`
// naming no clip yet creates "Action" (the active clip) and is set to it.
std::string keyScalarProperty(Document& doc, int& clip, int joint, const std::string& property, float time, float value,
                              const KeyPreferences& preferences, const std::string& label);
// Several Scalar properties of one joint keyed at `time` in one undo step (each pair: the
// property and its value), as keyScalarProperty does for one.
std::string keyScalarProperties(Document& doc, int& clip, int joint,
                                const std::vector<std::pair<std::string, float>>& values, float time,
                                const KeyPreferences& preferences, const std::string& label);

}  // namespace kinema
