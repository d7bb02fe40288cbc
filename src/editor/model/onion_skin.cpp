#include "editor/model/onion_skin.h"

#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "anim/sampling.h"

namespace kinema {

namespace {
float fade(const OnionSkinSettings& s, int k, int count) {
  return s.opacity * static_cast<float>(count - k + 1) / static_cast<float>(std::max(count, 1));
}
}  // namespace

std::vector<GhostFrame> ghostFrames(const OnionSkinSettings& s, long long current, long long frameCount) {
  std::vector<GhostFrame> out;
  const int step = std::max(s.step, 1);
  const int before = std::clamp(s.before, 0, 64), after = std::clamp(s.after, 0, 64);
  for (int k = before; k >= 1; --k) {
    const long long f = current - static_cast<long long>(k) * step;
    if (f >= 0 && f < frameCount) out.push_back({f, -k, glm::vec4(s.beforeColor, fade(s, k, before))});
  }
  for (int k = 1; k <= after; ++k) {
    const long long f = current + static_cast<long long>(k) * step;
    if (f >= 0 && f < frameCount) out.push_back({f, k, glm::vec4(s.afterColor, fade(s, k, after))});
  }
  return out;
}

bool ghostsShowBodies(const OnionSkinSettings& s, const Scene& scene) {
  return s.bodies && !scene.meshInstances.empty();
}

std::vector<std::vector<glm::mat4>> ghostPoses(const Scene& scene, int clip, const std::vector<GhostFrame>& ghosts,
                                               const EvaluationStages& stages, long long dynamicsStartFrame,
                                               long long revision, const IkRig* rig) {
  std::vector<std::vector<glm::mat4>> out;
  if (clip < 0 || clip >= static_cast<int>(scene.clips.size())) return out;
  out.resize(ghosts.size());
  // Earliest frame first: the dynamics stage then steps forward through all of them once.
  std::vector<size_t> order(ghosts.size());
  for (size_t g = 0; g < order.size(); ++g) order[g] = g;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return ghosts[a].frame < ghosts[b].frame; });
  EvaluationContext context;
  Pose pose;
  for (size_t g : order) {
    SceneEvaluationJob job;
    job.scene = &scene;
    job.clip = clip;
    job.time = scene.frameGrid(clip).frameToTime(ghosts[g].frame);
    job.stages = stages;
    job.rig = rig;
    job.dynamicsStartFrame = dynamicsStartFrame;
    job.revision = revision;
    job.context = &context;
    job.pose = &pose;
    job.world = &out[g];
    job.run();
  }
  return out;
}

}  // namespace kinema
