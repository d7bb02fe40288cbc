#include "evaluation/scene_evaluation_job.h"

#include <cmath>

#include "core/forward_kinematics.h"
#include "evaluation/ik_target_stage.h"

namespace kinema {

namespace {
bool hasClip(const Scene& scene, int clip) { return clip >= 0 && clip < static_cast<int>(scene.clips.size()); }

// Stages 1 to 5 into `pose` (which holds the base): the playback form of stage 1 when given
// (it declines a clip it cannot sample), else the clip with the cache's cursors.
void animatedPose(const Scene& scene, const IkRig& rig, int clip, double time, const EvaluationStages& stages,
                  Pose& pose, SamplingCache* cache, const PlaybackClip* playback, PlaybackContext* playbackContext) {
  if (!hasClip(scene, clip)) return;
  // 1, 2: keys and channel modifiers (both forms play both).
  const Clip& c = scene.clips[clip];
  const bool played =
      playback && playbackContext && samplePlayback(*playback, static_cast<float>(time), pose, *playbackContext);
  if (!played && cache) sampleClip(c, static_cast<float>(time), pose, *cache);
  if (!played && !cache) sampleClip(c, static_cast<float>(time), pose);
  // 3, 4: layers and constraints have no data yet (issues 41 and 42): nothing to do.
  // 5: keyed IK targets.
  if (stages.ikTargets) solveKeyedIkTargets(scene, rig, clip, time, pose);
}
}  // namespace

void evaluateAnimatedPose(const Scene& scene, int clip, double time, const EvaluationStages& stages, Pose& pose,
                          SamplingCache* cache, const IkRig* rig) {
  animatedPose(scene, rig ? *rig : scene.ik, clip, time, stages, pose, cache, nullptr, nullptr);
}

std::string SceneEvaluationJob::validate() const {
  if (!scene || !pose) return "evaluation: missing scene or pose";
  if (!std::isfinite(time)) return "evaluation: the time is not a finite number";
  if (base && base->size() != scene->skeleton.size()) return "evaluation: the base pose does not fit the skeleton";
  return {};
}

bool SceneEvaluationJob::run() const {
  if (!validate().empty()) return false;
  const Scene& s = *scene;
  EvaluationContext fresh;
  EvaluationContext& ctx = context ? *context : fresh;
  *pose = base ? *base : Pose::rest(s.skeleton);
  const IkRig& ik = rig ? *rig : s.ik;
  animatedPose(s, ik, clip, time, stages, *pose, &ctx.sampling, playback, playbackContext);
  // 6: dynamic chains, stepped on stages 1-5 of each frame from the start frame.
  // A clip the chains are baked into plays its keys (Clip::dynamicsBaked).
  if (stages.dynamics && hasClip(s, clip) && !s.clips[clip].dynamicsBaked && !s.simulation.springChains.empty()) {
    const FrameGrid grid = s.frameGrid(clip);
    const long long start =
        dynamicsStartFrame != LLONG_MIN ? dynamicsStartFrame : grid.nearestFrame(s.clips[clip].playStart());
    SamplingCache stepCache;
    const auto animatedAt = [&](long long f, Pose& p) {
      animatedPose(s, ik, clip, grid.frameToTime(f), stages, p, &stepCache, nullptr, nullptr);
    };
    applyDynamicChains(s, clip, start, grid.nearestFrame(time), revision, animatedAt, ctx.dynamics, *pose);
  }
  // 7: forward kinematics.
  std::vector<glm::mat4> worldHere;
  std::vector<glm::mat4>* w = world ? world : (meshes ? &worldHere : nullptr);
  if (w) computeWorld(s.skeleton, *pose, *w);
  // 8: morph weights.
  std::vector<std::vector<float>> weightsHere;
  std::vector<std::vector<float>>* weights = morphWeights ? morphWeights : (meshes ? &weightsHere : nullptr);
  if (weights) *weights = sampleMorphWeights(s, hasClip(s, clip) ? clip : -1, time);
  // 9: morph targets, skinning, deformers.
  if (meshes) {
    std::vector<DeformerStack> stacks;
    if (stages.deformers) stacks = sampleDeformerStacks(s, hasClip(s, clip) ? clip : -1, time);
    else stacks.assign(s.meshInstances.size(), DeformerStack{});
    SceneDeformationJob deform;
    deform.scene = &s;
    deform.world = w;
    deform.morphWeights = weights;
    deform.deformers = &stacks;
    deform.skinnedOnly = skinnedOnly;
    deform.out = meshes;
    if (!deform.run()) return false;
  }
  return true;
}

Pose evaluatedPose(const Scene& scene, int clip, double time) {
  Pose pose;
  SceneEvaluationJob job;
  job.scene = &scene;
  job.clip = clip;
  job.time = time;
  job.pose = &pose;
  job.run();
  return pose;
}

}  // namespace kinema
