#pragma once
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/math.h"

namespace kinema {

class Document;

// Motion control (seed 003, 16.2.1; the keyframe engine's arc-length control): keep a joint's
// translation path P(u) through its keys, but choose how fast it is travelled: p(t) = P(u(s(t)))
// with s(t) a distance-time curve. Constant speed covers equal arc lengths in equal times; the
// eases start and stop slowly.
enum class MotionControlProfile { ConstantSpeed, SineEase, ParabolicEase };
const char* toString(MotionControlProfile profile);  // "constant-speed", "sine-ease", "parabolic-ease"

struct MotionControlSettings {
  bool windowOpen = false;
  bool showTicks = true;  // tick marks at equal times along the selected joint's path
  MotionControlProfile profile = MotionControlProfile::ConstantSpeed;
  // Where the window put its widgets last frame (window pixels x, y, w, h): e2e scripts click them.
  glm::vec4 profileRects[3]{};
  glm::vec4 applyRect{0.0f};
};

// The index of `joint`'s Translation channel in `clip`, -1 when it has none.
int translationChannelIndex(const Clip& clip, int joint);

// Inputs of the re-timing, ozz-job style: the path (a Translation channel with >= 2 keys),
// the profile and the frame step of the baked keys.
struct MotionControlJob {
  const Channel* path = nullptr;
  MotionControlProfile profile = MotionControlProfile::ConstantSpeed;
  double frameTime = 1.0 / kDefaultFrameRate;  // seconds per baked key: the clip's (Clip::secondsPerFrame)
  // Empty when usable; otherwise one line saying what is wrong.
  std::string validate() const;
  // Times from the path's first key to its last, one per frame step (the last key's time
  // included exactly), and p(t - t0) at each. False (outputs empty) when validate() fails.
  bool run(std::vector<float>& times, std::vector<glm::vec3>& positions) const;
  // The re-timed channel: a Linear key at every time of run(). Same joint and target.
  bool bake(Channel& out) const;
};

// Positions at `count` + 1 equal time steps from the path's first key to its last (the
// viewport's tick marks): equal spacing shows constant speed, bunching at the ends an ease.
std::vector<glm::vec3> equalTimeTicks(const Channel& path, MotionControlProfile profile, int count);

// Applies the job to `joint`'s Translation channel of clip `clip` as one undo step
// ("Motion Control"). Returns "" or a one-line error (nothing changed).
std::string applyMotionControl(Document& doc, int clip, int joint, MotionControlProfile profile);

}  // namespace kinema
