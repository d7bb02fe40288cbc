#pragma once
// The one evaluation pipeline: a scene at a time, in one order of stages, for every consumer
// (the CLI's pose / ik / skin / render / convert, the editor's display, onion skin and motion
// path, retargeting, simulation bakes, crowds). docs/evaluation.md lists the stages and who
// calls this.
//
//   1 clip         the clip's keys at the time, over the base pose (anim/sampling.h)
//   2 modifiers    channel modifiers (noise, cycles, wave) on the channels that carry them
//   3 layers       blending, NLA strips, additive layers: a slot, passed through (issue 41)
//   4 constraints  look-at, child-of: a slot, passed through (issue 42)
//   5 IK targets   saved targets whose position the clip keys, moved there and solved
//   6 dynamics     live dynamic chains (spring bones), simulated frame by frame
//   7 FK           model-space matrices of every joint
//   8 morphs       morph weights of every mesh instance
//   9 meshes       morph targets, skinning, then each instance's deformer stack (world space)
#include <climits>
#include <string>
#include <vector>

#include "anim/playback_sampling_job.h"
#include "anim/sampling.h"
#include "core/pose.h"
#include "evaluation/dynamics_stage.h"
#include "evaluation/scene_deformation.h"
#include "scene/scene.h"

namespace kinema {

// Which stages run (all by default). A stage that is off passes its input through.
struct EvaluationStages {
  bool ikTargets = true;  // 5
  bool dynamics = true;   // 6
  bool deformers = true;  // in 9: off, meshes are morphed and skinned only
};

// Working memory a caller keeps across evaluations (the editor keeps one per view): the
// sampling cursors, the live chains' state. Results never depend on it, except that the
// dynamics stage continues from the frame it last reached.
struct EvaluationContext {
  SamplingCache sampling;
  DynamicsState dynamics;
};

// Evaluates scene->clips[clip] at `time` seconds. Inputs are read only.
struct SceneEvaluationJob {
  const Scene* scene = nullptr;
  int clip = -1;          // an index into scene->clips; any other value: no animation (stages 1-6 keep the base)
  double time = 0.0;      // seconds, finite; each channel clamps to its keys, modifiers act at any time
  const Pose* base = nullptr;  // joints the clip does not animate keep this pose (one per joint); null: the rest pose
  EvaluationStages stages;
  const IkRig* rig = nullptr;  // the IK targets and limits stage 5 solves with; null: scene->ik
  // The frame the dynamic chains start from, at rest; LLONG_MIN: the clip's playback range
  // start (Clip::playStart on the clip's grid). They reach the frame nearest `time`.
  long long dynamicsStartFrame = LLONG_MIN;
  long long revision = 0;  // the caller's count of scene edits: a change restarts the dynamics
  EvaluationContext* context = nullptr;  // optional: null uses fresh working memory
  // Optional: stage 1's form for sequential playback, built once from scene->clips[clip]
  // (anim/playback_sampling_job.h; the same values to 1e-6), with its cursors.
  const PlaybackClip* playback = nullptr;
  PlaybackContext* playbackContext = nullptr;

  // Outputs; `pose` is required, the others are optional (null: that stage does not run).
  Pose* pose = nullptr;                      // local transforms, one per joint
  std::vector<glm::mat4>* world = nullptr;   // model space (the skeleton's root frame, file units)
  std::vector<std::vector<float>>* morphWeights = nullptr;  // per mesh instance
  std::vector<DeformedPrimitive>* meshes = nullptr;         // world space, one per instance x primitive
  bool skinnedOnly = false;  // meshes: only skinned instances (what `kinema skin` prints)

  std::string validate() const;
  bool run() const;  // false (nothing written) when validate() fails
};

// Stages 1 to 5 alone at `time`, from `base` (what the dynamics stage steps on each frame).
void evaluateAnimatedPose(const Scene& scene, int clip, double time, const EvaluationStages& stages, Pose& pose,
                          SamplingCache* cache = nullptr, const IkRig* rig = nullptr);

// The common case: the local pose of clip `clip` at `time`, every stage, from the rest pose.
Pose evaluatedPose(const Scene& scene, int clip, double time);

}  // namespace kinema
