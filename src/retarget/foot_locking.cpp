#include "retarget/foot_locking.h"

#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "ik/ik_solver.h"
#include "retarget/retarget_clip.h"
#include "core/rotation.h"

namespace kinema {

namespace {


// How strongly frame f is locked by one of the contacts (smooth ramps outside them) and
// which contact it is locked to (-1: none).
float lockWeight(const std::vector<ContactInterval>& contacts, int f, int blend, int& which) {
  float best = 0.0f;
  which = -1;
  for (size_t i = 0; i < contacts.size(); ++i) {
    const ContactInterval& c = contacts[i];
    float w = 0.0f;
    if (f >= c.first && f <= c.last) w = 1.0f;
    else if (blend > 0 && f < c.first && f >= c.first - blend) w = 1.0f - float(c.first - f) / float(blend + 1);
    else if (blend > 0 && f > c.last && f <= c.last + blend) w = 1.0f - float(f - c.last) / float(blend + 1);
    w = w * w * (3.0f - 2.0f * w);  // smoothstep: no kink where the blend starts
    if (w > best) {
      best = w;
      which = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace

std::string FootLockJob::validate() const {
  if (!skeleton || !clip || !contacts[0] || !contacts[1] || !output) return "foot locking: missing input or output";
  if (!hasOwnFrameRate(*clip)) return "foot locking: the clip has no frame rate of its own";
  for (const LegJoints& l : legs)
    if (!l.valid(skeleton->size())) return "foot locking: a leg joint is missing";
  if (blendFrames < 0) return "foot locking: blendFrames must be >= 0";
  if (!std::isfinite(floorHeight)) return "foot locking: the floor height must be finite";
  const std::string c = clip->validate(*skeleton);
  if (!c.empty()) return "foot locking: " + c;
  return {};
}

bool FootLockJob::run() const {
  if (!validate().empty()) return false;
  const Skeleton& s = *skeleton;
  const int frames = clipFrameCount(*clip);
  // Where each contact holds the ankle: its horizontal position on the contact's first frame.
  std::vector<std::vector<glm::vec3>> lockAt(2);
  for (int side = 0; side < 2; ++side) {
    const std::vector<glm::vec3> track = jointTracks(s, *clip, {legs[side].foot})[0];
    for (const ContactInterval& c : *contacts[side]) lockAt[side].push_back(track[std::clamp(c.first, 0, frames - 1)]);
  }
  std::vector<int> edited;
  for (const LegJoints& l : legs) edited.insert(edited.end(), {l.upperLeg, l.lowerLeg, l.foot});
  std::vector<Channel> baked;
  for (int j : edited) baked.emplace_back(j, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{},
                                          std::vector<glm::vec4>{});
  std::vector<glm::mat4> world;
  for (int f = 0; f < frames; ++f) {
    const float time = ownFrameGrid(*clip).frameToTime(f);
    Pose pose = Pose::rest(s);
    sampleClip(*clip, time, pose);
    for (int side = 0; side < 2; ++side) {
      const LegJoints& leg = legs[side];
      computeWorld(s, pose, world);
      const glm::vec3 ankle(world[leg.foot][3]);
      int which = -1;
      const float w = lockWeight(*contacts[side], f, blendFrames, which);
      glm::vec3 goal = ankle;
      if (which >= 0) {
        goal.x += w * (lockAt[side][which].x - ankle.x);
        goal.z += w * (lockAt[side][which].z - ankle.z);
      }
      // The foot moves rigidly with the ankle, so the toe keeps its offset.
      float lowest = goal.y;
      if (leg.toes >= 0) lowest = std::min(lowest, goal.y + world[leg.toes][3].y - ankle.y);
      if (lowest < floorHeight) goal.y += floorHeight - lowest;
      if (goal == ankle) continue;
      IkProblem problem;
      problem.skeleton = &s;
      problem.pose = &pose;
      IkTarget target;
      target.effector = leg.foot;
      target.mid = leg.lowerLeg;
      target.root = leg.upperLeg;
      target.position = goal;
      target.hasOrientation = true;
      target.orientation = rotationOf(world[leg.foot]);
      problem.targets.push_back(target);
      solveTwoBone(problem, IkSettings{});
    }
    for (size_t k = 0; k < edited.size(); ++k) {
      glm::quat q = safeNormalize(pose.local[edited[k]].rotation);
      if (!baked[k].values.empty()) {
        const glm::vec4& v = baked[k].values.back();
        q = sameHemisphere(q, glm::quat(v.w, v.x, v.y, v.z));
      }
      baked[k].times.push_back(time);
      baked[k].values.push_back(glm::vec4(q.x, q.y, q.z, q.w));
    }
  }
  Clip out = *clip;
  out.channels.erase(std::remove_if(out.channels.begin(), out.channels.end(),
                                    [&](const Channel& c) {
                                      return (c.target == ChannelTarget::Rotation || c.target == ChannelTarget::Euler) &&
                                             std::find(edited.begin(), edited.end(), c.joint) != edited.end();
                                    }),
                     out.channels.end());
  for (Channel& c : baked) out.channels.push_back(std::move(c));
  if (out.frameTime <= 0.0) out.frameTime = ownFrameGrid(*clip).secondsPerFrame;
  *output = std::move(out);
  return true;
}

}  // namespace kinema
