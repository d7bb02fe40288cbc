#include "retarget/foot_contacts.h"

#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "retarget/retarget_clip.h"

namespace kinema {

namespace {

float horizontal(const glm::vec3& d) { return std::sqrt(d.x * d.x + d.z * d.z); }

}  // namespace

bool LegJoints::valid(int n) const {
  auto in = [n](int j) { return j >= 0 && j < n; };
  return in(upperLeg) && in(lowerLeg) && in(foot) && (toes == -1 || in(toes));
}

void legsOf(const HumanoidMap& h, LegJoints out[2]) {
  out[0] = {h[HumanoidBone::LeftUpperLeg], h[HumanoidBone::LeftLowerLeg], h[HumanoidBone::LeftFoot], h[HumanoidBone::LeftToes]};
  out[1] = {h[HumanoidBone::RightUpperLeg], h[HumanoidBone::RightLowerLeg], h[HumanoidBone::RightFoot],
            h[HumanoidBone::RightToes]};
}

float restLegLength(const Skeleton& s, const LegJoints& leg) {
  const std::vector<glm::mat4> w = computeWorld(s, Pose::rest(s));
  auto p = [&](int j) { return glm::vec3(w[j][3]); };
  return glm::length(p(leg.lowerLeg) - p(leg.upperLeg)) + glm::length(p(leg.foot) - p(leg.lowerLeg));
}

std::vector<std::vector<glm::vec3>> jointTracks(const Skeleton& s, const Clip& clip, const std::vector<int>& joints,
                                                PoseSource* poses) {
  const int frames = clipFrameCount(clip);
  std::vector<std::vector<glm::vec3>> tracks(joints.size(), std::vector<glm::vec3>(frames));
  std::vector<glm::mat4> world;
  ClipPoses bare(s, clip);
  PoseSource& source = poses ? *poses : bare;
  Pose pose = Pose::rest(s);
  for (int f = 0; f < frames; ++f) {
    source.poseAt(ownFrameGrid(clip).frameToTime(f), pose);
    computeWorld(s, pose, world);
    for (size_t k = 0; k < joints.size(); ++k) tracks[k][f] = glm::vec3(world[joints[k]][3]);
  }
  return tracks;
}

std::string FootContactJob::validate() const {
  if (!skeleton || !clip || !output[0] || !output[1]) return "foot contacts: missing input or output";
  if (!hasOwnFrameRate(*clip)) return "foot contacts: the clip has no frame rate of its own";
  for (const LegJoints& l : legs)
    if (!l.valid(skeleton->size())) return "foot contacts: a leg joint is missing";
  const FootContactSettings& c = settings;
  if (!(c.enterHeight > 0.0f && c.exitHeight >= c.enterHeight && c.enterSpeed > 0.0f && c.exitSpeed >= c.enterSpeed))
    return "foot contacts: thresholds must be positive, exit at least enter";
  for (const LegJoints& l : legs)
    if (!(restLegLength(*skeleton, l) > 0.0f)) return "foot contacts: zero-length legs";
  return {};
}

bool FootContactJob::run() const {
  if (!validate().empty()) return false;
  const double dt = ownFrameGrid(*clip).secondsPerFrame;
  for (int side = 0; side < 2; ++side) {
    const LegJoints& leg = legs[side];
    const float length = restLegLength(*skeleton, leg);
    std::vector<int> joints{leg.foot};
    if (leg.toes >= 0) joints.push_back(leg.toes);
    const std::vector<std::vector<glm::vec3>> tracks = jointTracks(*skeleton, *clip, joints, poses);
    const int frames = static_cast<int>(tracks[0].size());
    // Height above the joint's own lowest point, and horizontal speed (central differences).
    std::vector<float> lowest;
    for (const std::vector<glm::vec3>& t : tracks) {
      float lo = t[0].y;
      for (const glm::vec3& p : t) lo = std::min(lo, p.y);
      lowest.push_back(lo);
    }
    auto height = [&](size_t k, int f) { return tracks[k][f].y - lowest[k]; };
    auto speed = [&](size_t k, int f) {
      if (frames < 2) return 0.0f;
      const int a = std::max(0, f - 1), b = std::min(frames - 1, f + 1);
      return static_cast<float>(horizontal(tracks[k][b] - tracks[k][a]) / ((b - a) * dt));
    };
    std::vector<ContactInterval> out;
    bool in = false;
    int start = 0;
    for (int f = 0; f <= frames; ++f) {
      bool enter = false, stay = false;
      for (size_t k = 0; k < tracks.size() && f < frames; ++k) {
        const float h = height(k, f) / length, v = speed(k, f) / length;
        enter = enter || (h < settings.enterHeight && v < settings.enterSpeed);
        stay = stay || (h < settings.exitHeight && v < settings.exitSpeed);
      }
      if (!in && enter) {
        in = true;
        start = f;
      } else if (in && !stay) {
        in = false;
        if (f - start >= settings.minFrames) out.push_back({start, f - 1});
      }
    }
    *output[side] = std::move(out);
  }
  return true;
}

float footSkate(const Skeleton& s, const Clip& clip, const LegJoints legs[2], const std::vector<ContactInterval> contacts[2]) {
  double slide = 0.0;
  long long count = 0;
  for (int side = 0; side < 2; ++side) {
    if (contacts[side].empty()) continue;
    const float length = restLegLength(s, legs[side]);
    const std::vector<glm::vec3> track = jointTracks(s, clip, {legs[side].foot})[0];
    for (const ContactInterval& c : contacts[side])
      for (int f = c.first + 1; f <= c.last && f < static_cast<int>(track.size()); ++f) {
        slide += horizontal(track[f] - track[f - 1]) / length;
        ++count;
      }
  }
  return count ? static_cast<float>(slide / count) : 0.0f;
}

}  // namespace kinema
