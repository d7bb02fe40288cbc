#pragma once
#include <functional>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/result.h"
#include "core/rotation.h"
#include "core/skeleton.h"
#include "evaluation/scene_evaluation_job.h"
#include "scene/scene.h"

namespace kinema {

struct BvhWriteOptions {
  EulerOrder order = EulerOrder::ZXY;  // rotation channel order of every joint
  // Frames per second; 0: the clip's own frame rate, else the grid its keys lie on
  // (keyGridFrameTime), else the document's rate below.
  double frameRate = 0.0;
  // The document's frame rate (Scene::frameRate): a clip's rate when it has none of its own
  // and its keys lie on no grid.
  double documentFrameRate = kDefaultFrameRate;
  // The scene `clip` is clips[clipIndex] of (optional): each frame is then evaluated through
  // the scene's pipeline (modifiers, keyed IK targets, dynamic chains), else `clip` is sampled.
  const Scene* scene = nullptr;
  int clipIndex = -1;
  EvaluationStages stages;  // the stages each frame goes through
  // Called every few hundred frames with (frames written, total), for progress lines.
  std::function<void(long long, long long)> progress;
};

// Skeleton + clip -> BVH text. OFFSETs are the rest translations; every joint gets
// rotation channels in `order` (rest rotations are folded into them, BVH has none);
// roots, and joints whose translation is animated, get position channels. Leaves named
// "<parent>_End" without animation (what our BVH reader makes of End Sites) are written
// back as End Sites; other leaves get a zero-length End Site. `clip` may be null (one
// frame of the rest pose). `report` gets one line for each thing BVH cannot hold
// (scale, scalar channels, renamed joints, resampled keys).
Result<std::string> bvhText(const Skeleton& skeleton, const Clip* clip, const BvhWriteOptions& options,
                            std::vector<std::string>* report = nullptr);
// Writes atomically; returns "" or the one-line error.
std::string saveBvh(const std::string& path, const Skeleton& skeleton, const Clip* clip,
                    const BvhWriteOptions& options, std::vector<std::string>* report = nullptr);

// The frame time bvhText uses for `clip` (see BvhWriteOptions::frameRate); `uniform` is
// false when the keys had to be resampled onto a grid.
double bvhFrameTime(const Clip* clip, const BvhWriteOptions& options, bool* uniform = nullptr);

}  // namespace kinema
