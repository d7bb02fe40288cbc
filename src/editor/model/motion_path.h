#pragma once
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace kinema {

// Motion path of a joint (Blender's bone motion paths): where the joint is at every frame
// of a range, drawn as a polyline with a dot per frame, larger where the joint is keyed.
struct MotionPathSettings {
  bool enabled = false;
  bool wholeClip = true;     // the clip's playback range; else `before` / `after` frames around the current one
  int before = 15, after = 15;
  glm::vec4 color{1.0f, 0.85f, 0.25f, 1.0f};
};

struct MotionPath {
  int joint = -1;
  std::vector<long long> frames;   // consecutive clip frames
  std::vector<glm::vec3> points;   // the joint's world position at each frame
  std::vector<char> keyed;         // 1 where a channel of the joint has a key at that frame
};

// The frames the path covers: [first, last] clamped to the clip's frames 0 .. frameCount - 1.
void motionPathRange(const MotionPathSettings& settings, const Clip& clip, const FrameGrid& grid, long long current, long long& first,
                     long long& last);

// Samples the clip (over the rest pose, as playback does) at every frame from `first` to
// `last` and records `joint`'s world position by forward kinematics. Empty when the clip or
// the joint does not exist or the range is empty.
// Every stage of the evaluation at each frame; `rig` (null: scene.ik) holds the IK targets.
MotionPath computeMotionPath(const Scene& scene, int clip, int joint, long long first, long long last,
                             const IkRig* rig = nullptr);

}  // namespace kinema
