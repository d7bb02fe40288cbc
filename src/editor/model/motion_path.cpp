#include "editor/model/motion_path.h"

#include <algorithm>
#include <cmath>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "editor/model/onion_skin.h"
#include "evaluation/scene_evaluation_job.h"

namespace kinema {

void motionPathRange(const MotionPathSettings& s, const Clip& clip, const FrameGrid& grid, long long current, long long& first,
                     long long& last) {
  const long long count = grid.nearestFrame(clip.duration()) + 1;
  if (s.wholeClip) {
    first = grid.nearestFrame(clip.playStart());
    last = grid.nearestFrame(clip.playEnd());
  } else {
    first = current - std::max(s.before, 0);
    last = current + std::max(s.after, 0);
  }
  first = std::clamp(first, 0LL, count - 1);
  last = std::clamp(last, 0LL, count - 1);
}

MotionPath computeMotionPath(const Scene& scene, int clip, int joint, long long first, long long last,
                             const IkRig* rig) {
  MotionPath path;
  if (clip < 0 || clip >= static_cast<int>(scene.clips.size()) || joint < 0 || joint >= scene.skeleton.size() ||
      last < first)
    return path;
  const Clip& c = scene.clips[clip];
  const FrameGrid grid = scene.frameGrid(clip);
  const double dt = grid.secondsPerFrame;
  // A key "is at" a frame when it is within half a frame of it (keys of frame-based clips are exact).
  std::vector<float> keyTimes;
  for (const Channel& ch : c.channels)
    if (ch.joint == joint) keyTimes.insert(keyTimes.end(), ch.times.begin(), ch.times.end());
  std::sort(keyTimes.begin(), keyTimes.end());
  path.joint = joint;
  EvaluationContext context;  // the dynamics stage steps forward through the frames once
  Pose pose;
  std::vector<glm::mat4> world;
  for (long long f = first; f <= last; ++f) {
    const double t = grid.frameToTime(f);
    SceneEvaluationJob job;  // every stage, over the rest pose (evaluation/scene_evaluation_job.h)
    job.scene = &scene;
    job.clip = clip;
    job.time = t;
    job.rig = rig;
    job.context = &context;
    job.pose = &pose;
    job.world = &world;
    job.run();
    path.frames.push_back(f);
    path.points.push_back(glm::vec3(world[joint][3]));
    const auto k = std::lower_bound(keyTimes.begin(), keyTimes.end(), static_cast<float>(t - 0.5 * dt));
    path.keyed.push_back(k != keyTimes.end() && *k < t + 0.5 * dt ? 1 : 0);
  }
  return path;
}

}  // namespace kinema
