#include "retarget/retarget_motion.h"

#include "retarget/retarget_clip.h"

namespace kinema {

Result<AutomaticBoneMap> automaticBoneMap(const Result<HumanoidReading>& source, const Result<HumanoidReading>& target,
                                          const std::string& sourceLabel, const std::string& targetLabel) {
  if (!source) return Result<AutomaticBoneMap>::failure(sourceLabel + ": " + source.error());
  if (!target) return Result<AutomaticBoneMap>::failure(targetLabel + ": " + target.error());
  AutomaticBoneMap out;
  out.map = mapThroughHumanoid(source->bones, target->bones);
  const bool names = source->source == HumanoidSource::Names && target->source == HumanoidSource::Names;
  const bool topology = source->source == HumanoidSource::Topology && target->source == HumanoidSource::Topology;
  out.mapBy = names ? "names" : (topology ? "topology" : "names and topology");
  return out;
}

Result<RetargetedMotion> retargetMotion(const RetargetMotionInput& in) {
  using R = Result<RetargetedMotion>;
  if (!in.source || !in.clip || !in.target || !in.map) return R::failure("retarget: missing input");
  const Skeleton& source = *in.source;
  const Skeleton& target = *in.target;
  const BoneMap& map = *in.map;
  if (const std::string bad = map.validate(source, target); !bad.empty())
    return R::failure((in.mapLabel.empty() ? in.sourceLabel + " onto " + in.targetLabel : in.mapLabel) + ": " + bad);
  if (map.pairs.empty()) return R::failure(in.sourceLabel + " onto " + in.targetLabel + ": the bone map is empty");

  RetargetedMotion out;
  RetargetJob job;
  job.source = &source;
  job.sourceClip = in.clip;
  job.sourcePoses = in.sourcePoses;
  job.target = &target;
  job.map = &map;
  job.inPlace = in.inPlace;
  const HumanoidReading* sh = in.sourceHuman;
  const HumanoidReading* th = in.targetHuman;
  if (sh && th && th->bones.has(HumanoidBone::Hips) &&
      map.sourceOf(th->bones[HumanoidBone::Hips]) == sh->bones[HumanoidBone::Hips]) {
    // Root motion between the hips, scaled by the hip heights.
    const Result<float> hs = restHipHeight(source, sh->bones);
    if (!hs) return R::failure(in.sourceLabel + ": " + hs.error());
    const Result<float> ht = restHipHeight(target, th->bones);
    if (!ht) return R::failure(in.targetLabel + ": " + ht.error());
    job.sourceRoot = sh->bones[HumanoidBone::Hips];
    job.targetRoot = th->bones[HumanoidBone::Hips];
    job.rootScale = ht.value() / hs.value();
    const Result<FootFloors> floors = footFloors(source, *in.clip, sh->bones, target, th->bones, in.sourcePoses);
    if (!floors) return R::failure(in.sourceLabel + " onto " + in.targetLabel + ": " + floors.error());
    job.sourceFloor = floors->source;
    job.targetFloor = floors->target;
    for (HumanoidBone b : {HumanoidBone::LeftFoot, HumanoidBone::RightFoot, HumanoidBone::LeftToes, HumanoidBone::RightToes})
      if (th->bones.has(b)) job.targetFeet.push_back(th->bones[b]);
  } else {
    // Without humanoid readings (a hand-written map): between the topmost mapped joints, unscaled.
    job.sourceRoot = map.pairs.front().source;
    job.targetRoot = map.pairs.front().target;  // pairs are in target order: the topmost
  }
  job.output = &out.clip;
  if (const std::string bad = job.validate(); !bad.empty()) return R::failure(in.sourceLabel + ": " + bad);
  job.run();
  out.rootScale = job.rootScale;
  out.sourceFloor = job.sourceFloor;
  out.targetFloor = job.targetFloor;
  return out;
}

}  // namespace kinema
