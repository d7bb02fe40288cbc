#include "sim/simulation_bake.h"

#include <algorithm>

#include "anim/sampling.h"
#include "sim/baked_keys.h"
#include "sim/ragdoll.h"

namespace kinema {

namespace {

// The input's poses with what an earlier part baked (its joints' keys in `baked`) over them:
// the motion a ragdoll after the spring chains moves on.
class BakedKeysOver final : public PoseSource {
 public:
  BakedKeysOver(PoseSource& under, const Clip& baked, const std::vector<int>& joints) : under_(under) {
    for (const Channel& c : baked.channels)
      if (std::find(joints.begin(), joints.end(), c.joint) != joints.end() &&
          (c.target == ChannelTarget::Rotation || c.target == ChannelTarget::Translation))
        channels_.push_back(&c);
  }
  void poseAt(double time, Pose& pose) override {
    under_.poseAt(time, pose);
    for (const Channel* c : channels_)
      applyChannelValue(*c, sampleChannel(*c, static_cast<float>(time)), pose.local[c->joint]);
  }

 private:
  PoseSource& under_;
  std::vector<const Channel*> channels_;
};

}  // namespace

Result<SimulationBake> bakeSimulation(const SimulationBakeInput& in) {
  using R = Result<SimulationBake>;
  if (!in.skeleton || !in.clip || !in.settings) return R::failure("bakeSimulation: skeleton, clip and settings are needed");
  const Skeleton& s = *in.skeleton;
  if (in.lastFrame < in.firstFrame) return R::failure("the last frame comes before the first");
  if (in.firstFrame < 0) return R::failure("frames start at 0");
  if (std::string e = in.settings->validate(s); !e.empty()) return R::failure(e);
  const IkRig noRig;
  const IkRig& rig = in.rig ? *in.rig : noRig;
  SimulationBake out;
  out.clip = *in.clip;
  out.clip.frameTime = frameGridOf(*in.clip, in.documentFrameRate).secondsPerFrame;  // what the bake counts in
  std::vector<int> keyed;

  // Spring chains first (one simulation; the chains do not touch each other).
  const std::vector<SpringBoneChain>& chains = in.settings->springChains;
  if (!chains.empty()) {
    Result<Clip> baked = bakeSpringBones(s, out.clip, chains, in.firstFrame, in.lastFrame, in.springSubsteps, in.poses);
    if (!baked) return R::failure(baked.error());
    for (const SpringBoneChain& c : chains) {
      SimulatedPart part;
      part.kind = "spring-chain";
      part.name = c.name;
      part.joints = c.joints;
      part.firstFrame = in.firstFrame;
      part.lastFrame = in.lastFrame;
      part.steps = (in.lastFrame - in.firstFrame + 1) * in.springSubsteps;
      // Spring bones follow no limits; where the rig has one, say how far past it they swung.
      SamplingCache cache;
      Pose pose = Pose::rest(s);
      for (long long f = in.firstFrame; f <= in.lastFrame; ++f) {
        if (std::none_of(c.joints.begin(), c.joints.end(), [&](int j) { return rig.limitOf(j) != nullptr; })) break;
        sampleClip(baked.value(), ownFrameGrid(baked.value()).frameToTime(f), pose, cache);
        for (int j : c.joints)
          if (const JointLimit* l = rig.limitOf(j))
            part.largestLimitExcess =
                std::max(part.largestLimitExcess, jointLimitViolation(*l, s.rest[j].rotation, pose.local[j].rotation));
      }
      if (in.progress) in.progress(part, in.lastFrame);
      keyed.insert(keyed.end(), c.joints.begin(), c.joints.end());
      out.parts.push_back(std::move(part));
    }
    out.clip = std::move(baked.value());
  }

  // Then each ragdoll, over the clip as the chains left it.
  for (const RagdollSettings& settings : in.settings->ragdolls) {
    ClipPoses bare(s, out.clip);
    BakedKeysOver over(in.poses ? *in.poses : bare, out.clip, keyed);
    PoseSource& poses = in.poses ? static_cast<PoseSource&>(over) : bare;
    Pose start = Pose::rest(s);
    poses.poseAt(ownFrameGrid(out.clip).frameToTime(std::max(in.firstFrame, settings.startFrame)), start);
    std::vector<RagdollBody> bodies;
    RagdollBodiesJob job;
    job.skeleton = &s;
    job.pose = &start;
    job.root = settings.root;
    job.totalMass = settings.mass;
    job.meshes = in.meshes;
    job.skins = in.skins;
    job.instances = in.instances;
    job.bodies = &bodies;
    if (std::string e = job.validate(); !e.empty()) return R::failure("ragdoll '" + settings.name + "': " + e);
    job.run();
    if (bodies.empty())
      return R::failure("ragdoll '" + settings.name + "': joint '" + s.names[settings.root] + "' has no bones below it to simulate");
    SimulatedPart part;
    part.kind = "ragdoll";
    part.name = settings.name;
    part.bodies = static_cast<int>(bodies.size());
    for (const RagdollBody& b : bodies) part.joints.push_back(b.joint);
    RagdollBakeReport report;
    std::function<void(long long)> frameDone;
    if (in.progress) frameDone = [&](long long f) { in.progress(part, f); };
    Result<Clip> baked = bakeRagdoll(s, out.clip, settings, bodies, ragdollJointLimits(s, rig), in.firstFrame,
                                     in.lastFrame, &report, frameDone, &poses);
    if (!baked) return R::failure(baked.error());
    out.clip = std::move(baked.value());
    part.firstFrame = report.firstFrame;
    part.lastFrame = report.lastFrame;
    part.steps = report.steps;
    part.largestLimitExcess = report.largestLimitExcess;
    part.worstJoint = report.worstJoint;
    keyed.insert(keyed.end(), part.joints.begin(), part.joints.end());
    out.parts.push_back(std::move(part));
  }

  std::sort(keyed.begin(), keyed.end());
  keyed.erase(std::unique(keyed.begin(), keyed.end()), keyed.end());
  for (const Channel& c : out.clip.channels)
    if (std::binary_search(keyed.begin(), keyed.end(), c.joint) &&
        (c.target == ChannelTarget::Rotation || c.target == ChannelTarget::Translation))
      out.keysBefore += c.keyCount();
  out.keysAfter = out.keysBefore;
  if (in.reduceKeys && !keyed.empty()) {
    KeyReductionReport report;
    if (std::string e = reduceBakedKeys(s, out.clip, keyed, in.reduction, &report); !e.empty()) return R::failure(e);
    out.keysAfter = report.keysAfter;
  }
  return out;
}

}  // namespace kinema
