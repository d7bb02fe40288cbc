#include "sim/spring_bones.h"

#include <algorithm>
#include <cmath>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "core/rotation.h"

namespace kinema {
namespace {

bool finite(float v) { return std::isfinite(v); }

// The rotation of an affine matrix whose columns may carry a uniform scale.

// Where joint `i` of the chain has its tail, in the joint's own space: the next chain joint,
// else the first child, else the joint's own bone (from its parent) continued as far again.
glm::vec3 tailOffset(const Skeleton& s, const Pose& pose, const SpringBoneChain& chain, size_t i) {
  const int j = chain.joints[i];
  if (i + 1 < chain.joints.size()) return pose.local[chain.joints[i + 1]].translation;
  for (int c = j + 1; c < s.size(); ++c)
    if (s.parents[c] == j) return pose.local[c].translation;
  const Transform& t = pose.local[j];
  return glm::inverse(t.rotation) * t.translation / t.scale;
}

glm::vec3 closestOnSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return a + t * ab;
}

}  // namespace

std::string SpringBoneChain::validate(const Skeleton& s) const {
  const std::string who = "spring chain '" + name + "': ";
  if (joints.empty()) return who + "has no joints";
  for (size_t i = 0; i < joints.size(); ++i) {
    if (joints[i] < 0 || joints[i] >= s.size()) return who + "joint " + std::to_string(joints[i]) + " is not in the skeleton";
    if (i > 0 && s.parents[joints[i]] != joints[i - 1])
      return who + "'" + s.names[joints[i]] + "' is not a child of '" + s.names[joints[i - 1]] + "' (a chain runs parent to child)";
  }
  if (!finite(stiffness) || stiffness < 0.0f) return who + "stiffness must be a finite number >= 0";
  if (!finite(damping) || damping < 0.0f) return who + "damping must be a finite number >= 0";
  if (!isFinite(gravity)) return who + "gravity is not finite";
  if (!finite(drag) || drag < 0.0f) return who + "drag must be a finite number >= 0";
  if (!finite(radius) || radius < 0.0f) return who + "radius must be a finite number >= 0";
  for (size_t c = 0; c < colliders.size(); ++c) {
    const SpringCollider& k = colliders[c];
    if (k.joint < -1 || k.joint >= s.size()) return who + "collider " + std::to_string(c) + " names no joint of the skeleton";
    if (!isFinite(k.a) || !isFinite(k.b) || !finite(k.radius) || k.radius <= 0.0f)
      return who + "collider " + std::to_string(c) + " needs finite ends and a radius above 0";
  }
  return "";
}

std::string SpringBoneJob::validate() const {
  if (!skeleton || !chains || !pose || !state) return "SpringBoneJob: skeleton, chains, pose and state are needed";
  if (!(dt > 0.0f) || !finite(dt)) return "SpringBoneJob: dt must be above 0";
  if (substeps < 1 || substeps > 64) return "SpringBoneJob: substeps must be 1 to 64";
  if (std::string e = pose->validate(*skeleton); !e.empty()) return "SpringBoneJob: " + e;
  for (const SpringBoneChain& c : *chains)
    if (std::string e = c.validate(*skeleton); !e.empty()) return "SpringBoneJob: " + e;
  return "";
}

bool SpringBoneJob::run() const {
  if (!validate().empty()) return false;
  const Skeleton& s = *skeleton;
  const std::vector<glm::mat4> world = computeWorld(s, *pose);  // the animated pose
  const bool fresh = state->tails.size() != chains->size();
  if (fresh) {
    state->tails.assign(chains->size(), {});
    state->previousTails.assign(chains->size(), {});
  }
  const float h = dt / static_cast<float>(substeps);
  for (size_t ci = 0; ci < chains->size(); ++ci) {
    const SpringBoneChain& chain = (*chains)[ci];
    const size_t n = chain.joints.size();
    std::vector<glm::vec3>& tails = state->tails[ci];
    std::vector<glm::vec3>& previous = state->previousTails[ci];
    std::vector<glm::vec3> offsets(n);
    for (size_t i = 0; i < n; ++i) offsets[i] = tailOffset(s, *pose, chain, i);
    const int rootParent = s.parents[chain.joints[0]];
    const glm::mat4 parentWorld = rootParent >= 0 ? world[rootParent] : glm::mat4(1.0f);
    const glm::quat parentRotation = rootParent >= 0 ? rotationOf(parentWorld) : glm::quat(1, 0, 0, 0);
    if (tails.size() != n) {  // start at the animated pose, at rest
      tails.resize(n);
      glm::mat4 p = parentWorld;
      for (size_t i = 0; i < n; ++i) {
        const glm::mat4 w = multiplyAffine(p, pose->local[chain.joints[i]].toMatrix());
        tails[i] = glm::vec3(w * glm::vec4(offsets[i], 1.0f));
        p = w;
      }
      previous = tails;
    }
    // The colliders in the world, from the animated pose.
    std::vector<std::pair<glm::vec3, glm::vec3>> capsules;
    for (const SpringCollider& k : chain.colliders) {
      const glm::mat4 m = k.joint >= 0 ? world[k.joint] : glm::mat4(1.0f);
      capsules.emplace_back(glm::vec3(m * glm::vec4(k.a, 1.0f)), glm::vec3(m * glm::vec4(k.b, 1.0f)));
    }
    std::vector<glm::quat> simulated(n);
    const float keep = std::max(0.0f, 1.0f - chain.damping * h);
    for (int sub = 0; sub < substeps; ++sub) {
      glm::mat4 p = parentWorld;
      glm::quat pq = parentRotation;
      for (size_t i = 0; i < n; ++i) {
        const Transform& local = pose->local[chain.joints[i]];
        const glm::mat4 w = multiplyAffine(p, local.toMatrix());  // animated rotation under the simulated parent
        const glm::vec3 head(w[3]);
        const glm::vec3 target(w * glm::vec4(offsets[i], 1.0f));
        const float length = glm::length(target - head);
        // Position Verlet: the last step's motion, damped, plus this step's acceleration.
        const glm::vec3 accel = chain.stiffness * (target - tails[i]) + chain.gravity;
        // Air drag -drag |v| v, taken implicitly in the speed (v' = v / (1 + drag |v| h)), so
        // no drag or step size can reverse the motion.
        const glm::vec3 motion = tails[i] - previous[i];
        const float dragKeep = chain.drag > 0.0f ? 1.0f / (1.0f + chain.drag * glm::length(motion)) : 1.0f;
        glm::vec3 next = tails[i] + (keep * dragKeep) * motion + accel * (h * h);
        auto keepLength = [&](glm::vec3& t) {
          const glm::vec3 d = t - head;
          const float len = glm::length(d);
          t = len > 0.0f ? head + d * (length / len) : target;
        };
        keepLength(next);
        // Pushing out of a capsule and back onto the bone's sphere can re-enter it a little:
        // a few rounds shrink that geometrically.
        for (int round = 0; round < 4; ++round) {
          bool touched = false;
          for (size_t k = 0; k < capsules.size(); ++k) {
            const glm::vec3 q = closestOnSegment(next, capsules[k].first, capsules[k].second);
            const float reach = chain.colliders[k].radius + chain.radius;
            const glm::vec3 d = next - q;
            const float dist = glm::length(d);
            if (dist < reach) {
              next = dist > 0.0f ? q + d * (reach / dist) : q + glm::vec3(0.0f, reach, 0.0f);
              keepLength(next);
              touched = true;
            }
          }
          if (!touched) break;
        }
        previous[i] = tails[i];
        tails[i] = next;
        // The joint turns its animated bone onto the simulated one.
        const glm::quat worldAnimated = pq * local.rotation;
        const glm::quat worldSimulated = fromToRotation(target - head, next - head) * worldAnimated;
        simulated[i] = glm::normalize(glm::inverse(pq) * worldSimulated);
        Transform moved = local;
        moved.rotation = simulated[i];
        p = multiplyAffine(p, moved.toMatrix());
        pq = glm::normalize(worldSimulated);
      }
    }
    for (size_t i = 0; i < n; ++i) pose->local[chain.joints[i]].rotation = simulated[i];
  }
  return true;
}

Result<Clip> bakeSpringBones(const Skeleton& skeleton, const Clip& clip, const std::vector<SpringBoneChain>& chains,
                             long long firstFrame, long long lastFrame, int substeps, PoseSource* poses) {
  if (lastFrame < firstFrame) return Result<Clip>::failure("the last frame is before the first");
  if (lastFrame - firstFrame > 1000000) return Result<Clip>::failure("more than 1,000,000 frames to bake");
  for (const SpringBoneChain& c : chains)
    if (std::string e = c.validate(skeleton); !e.empty()) return Result<Clip>::failure(e);
  std::vector<int> baked;
  for (const SpringBoneChain& c : chains) baked.insert(baked.end(), c.joints.begin(), c.joints.end());
  std::vector<Channel> channels(baked.size());
  for (size_t b = 0; b < baked.size(); ++b) {
    channels[b].joint = baked[b];
    channels[b].target = ChannelTarget::Rotation;
    channels[b].interpolation = Interpolation::Linear;
  }
  if (!hasOwnFrameRate(clip)) return Result<Clip>::failure("the clip has no frame rate of its own (frame_time)");
  SpringBoneState state;
  ClipPoses bare(skeleton, clip);
  PoseSource& source = poses ? *poses : bare;
  Pose pose = Pose::rest(skeleton);
  SpringBoneJob job;
  job.skeleton = &skeleton;
  job.chains = &chains;
  job.dt = static_cast<float>(ownFrameGrid(clip).secondsPerFrame);
  job.substeps = substeps;
  job.pose = &pose;
  job.state = &state;
  if (std::string e = job.validate(); !e.empty()) return Result<Clip>::failure(e);
  for (long long f = firstFrame; f <= lastFrame; ++f) {
    const float t = ownFrameGrid(clip).frameToTime(f);
    source.poseAt(t, pose);
    if (!job.run()) return Result<Clip>::failure("the simulation failed at frame " + std::to_string(f));
    for (size_t b = 0; b < baked.size(); ++b) {
      const glm::quat q = pose.local[baked[b]].rotation;
      channels[b].times.push_back(t);
      channels[b].values.emplace_back(q.x, q.y, q.z, q.w);
    }
  }
  Clip out = clip;
  if (out.frameTime <= 0.0) out.frameTime = ownFrameGrid(clip).secondsPerFrame;
  out.dynamicsBaked = true;  // played from its keys from now on, not simulated on top of them
  out.channels.erase(std::remove_if(out.channels.begin(), out.channels.end(),
                                    [&](const Channel& c) {
                                      return (c.target == ChannelTarget::Rotation || c.target == ChannelTarget::Euler) &&
                                             std::find(baked.begin(), baked.end(), c.joint) != baked.end();
                                    }),
                     out.channels.end());
  for (Channel& c : channels) out.channels.push_back(std::move(c));
  return out;
}

}  // namespace kinema
