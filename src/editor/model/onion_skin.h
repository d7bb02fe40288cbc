#pragma once
#include <vector>

#include "core/math.h"
#include "scene/scene.h"
#include "evaluation/scene_evaluation_job.h"

namespace kinema {

// Onion skin (Blender's / Maya's ghosting): translucent poses of the edited clip a few frames
// before and after the current one, one tint for the past and another for the future,
// fading with the distance from the current frame.
// The defaults are chosen to read at a glance on a character with a body: ghosts 5 frames
// apart (at 24 fps a fifth of a second, far enough apart not to merge with the current pose)
// at 0.6 opacity for the nearest.
struct OnionSkinSettings {
  bool enabled = false;
  int before = 2, after = 2;  // ghosts on each side
  int step = 5;               // frames between ghosts (and from the current frame to the nearest)
  float opacity = 0.6f;       // alpha of the nearest ghosts; the farthest fade towards 0
  bool bodies = true;         // ghosts of the skinned body where the scene has meshes (else bones)
  glm::vec3 beforeColor{0.20f, 0.85f, 0.30f};  // green: frames already played
  glm::vec3 afterColor{0.25f, 0.50f, 1.00f};   // blue: frames to come
};

// One ghost: the clip frame it shows and how it is tinted.
struct GhostFrame {
  long long frame = 0;  // on the clip's frame grid (Clip::secondsPerFrame, the timeline's; 0 .. frameCount - 1)
  int offset = 0;       // signed distance in ghosts: -1 the nearest before, +1 the nearest after
  glm::vec4 color{1.0f};  // rgb tint, alpha = opacity faded with |offset|
};

// The ghosts around `current` (frames 0 .. frameCount - 1): before ones first, farthest to
// nearest, then after ones nearest to farthest. Ghosts that would fall outside the clip are
// dropped (not clamped onto its ends, where they would pile up). Nearest alpha = opacity,
// the k-th of n on a side has opacity * (n - k + 1) / n.
std::vector<GhostFrame> ghostFrames(const OnionSkinSettings& settings, long long current, long long frameCount);

// Whether the ghosts are drawn as the scene's meshes (translucent bodies) rather than as
// bones: settings.bodies and the scene has a mesh instance to draw.
bool ghostsShowBodies(const OnionSkinSettings& settings, const Scene& scene);

// World transforms of every joint at each ghost's frame: the evaluation pipeline over the rest
// pose (what playback shows; evaluation/scene_evaluation_job.h) with `stages` and the dynamics'
// start frame (LLONG_MIN: the clip's range start), scene revision and IK rig (null: scene.ik)
// as the timeline has them.
std::vector<std::vector<glm::mat4>> ghostPoses(const Scene& scene, int clip, const std::vector<GhostFrame>& ghosts,
                                               const EvaluationStages& stages = {},
                                               long long dynamicsStartFrame = LLONG_MIN, long long revision = 0,
                                               const IkRig* rig = nullptr);

}  // namespace kinema
