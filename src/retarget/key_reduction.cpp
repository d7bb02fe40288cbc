#include "retarget/key_reduction.h"

#include <algorithm>
#include <cmath>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "retarget/retarget_clip.h"

namespace kinema {

namespace {

glm::quat asQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

// From the relative rotation's vector part and w: acos of a dot product near 1 loses
// all precision below ~0.03 degrees in float.
float angleBetween(const glm::quat& a, const glm::quat& b) {
  const glm::quat r = glm::conjugate(safeNormalize(a)) * safeNormalize(b);
  return 2.0f * std::atan2(glm::length(glm::vec3(r.x, r.y, r.z)), std::abs(r.w));
}

bool reducible(const Channel& c) {
  return c.keys.empty() && c.interpolation == Interpolation::Linear && c.keyCount() > 2 &&
         (c.target == ChannelTarget::Rotation || c.target == ChannelTarget::Translation);
}

// The error at `time` of the straight segment from key a to key b against the original.
float segmentError(const Channel& c, int a, int b, float time, const glm::vec4& original) {
  const float u = (time - c.times[a]) / (c.times[b] - c.times[a]);
  if (c.target == ChannelTarget::Rotation)
    return angleBetween(slerpShortest(asQuat(c.values[a]), asQuat(c.values[b]), u), asQuat(original));
  const glm::vec3 p = glm::mix(glm::vec3(c.values[a]), glm::vec3(c.values[b]), u);
  return glm::length(p - glm::vec3(original));
}

// Douglas-Peucker on one channel: the keys kept so that every check time (original keys
// and frames) stays within `budget` of the original channel.
Channel reduceChannel(const Channel& c, const std::vector<float>& frameTimes, float budget) {
  std::vector<float> checks(c.times);
  checks.insert(checks.end(), frameTimes.begin(), frameTimes.end());
  std::sort(checks.begin(), checks.end());
  checks.erase(std::unique(checks.begin(), checks.end()), checks.end());
  std::vector<glm::vec4> original;
  for (float t : checks) original.push_back(sampleChannel(c, t));
  const int n = c.keyCount();
  std::vector<char> keep(n, 0);
  keep[0] = keep[n - 1] = 1;
  std::vector<std::pair<int, int>> todo{{0, n - 1}};
  while (!todo.empty()) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    if (b - a < 2) continue;
    const auto lo = std::upper_bound(checks.begin(), checks.end(), c.times[a]) - checks.begin();
    const auto hi = std::lower_bound(checks.begin(), checks.end(), c.times[b]) - checks.begin();
    float worst = 0.0f;
    float worstTime = c.times[a];
    for (auto i = lo; i < hi; ++i) {
      const float e = segmentError(c, a, b, checks[i], original[i]);
      if (e > worst) worst = e, worstTime = checks[i];
    }
    if (worst <= budget) continue;
    // Split at the key nearest the worst point (strictly inside the segment).
    int split = static_cast<int>(std::lower_bound(c.times.begin() + a, c.times.begin() + b, worstTime) - c.times.begin());
    split = std::clamp(split, a + 1, b - 1);
    keep[split] = 1;
    todo.push_back({a, split});
    todo.push_back({split, b});
  }
  Channel out = c;
  out.times.clear();
  out.values.clear();
  for (int k = 0; k < n; ++k)
    if (keep[k]) {
      out.times.push_back(c.times[k]);
      out.values.push_back(c.values[k]);
    }
  return out;
}

// How far each joint's rest position is from its farthest descendant.
std::vector<float> restReach(const Skeleton& s) {
  const std::vector<glm::mat4> w = computeWorld(s, Pose::rest(s));
  std::vector<float> reach(s.size(), 0.0f);
  for (int j = 0; j < s.size(); ++j)
    for (int a = s.parents[j]; a >= 0; a = s.parents[a])
      reach[a] = std::max(reach[a], glm::length(glm::vec3(w[j][3]) - glm::vec3(w[a][3])));
  return reach;
}

int keyTotal(const Clip& c) {
  int n = 0;
  for (const Channel& ch : c.channels) n += ch.keyCount();
  return n;
}

}  // namespace

std::string KeyReductionJob::validate() const {
  if (!skeleton || !clip || !output) return "key reduction: missing input or output";
  if (!hasOwnFrameRate(*clip)) return "key reduction: the clip has no frame rate of its own";
  if (!(settings.positionTolerance > 0.0f) || !std::isfinite(settings.positionTolerance) ||
      !(settings.angleTolerance > 0.0f) || !std::isfinite(settings.angleTolerance))
    return "key reduction: tolerances must be positive and finite";
  const std::string c = clip->validate(*skeleton);
  if (!c.empty()) return "key reduction: " + c;
  return {};
}

bool KeyReductionJob::run() const {
  if (!validate().empty()) return false;
  const Skeleton& s = *skeleton;
  const int frames = clipFrameCount(*clip);
  std::vector<float> frameTimes;
  for (int f = 0; f < frames; ++f) frameTimes.push_back(ownFrameGrid(*clip).frameToTime(f));
  std::vector<std::vector<glm::vec3>> reference(frames);
  std::vector<Pose> referencePose(frames);
  std::vector<glm::mat4> world;
  for (int f = 0; f < frames; ++f) {
    referencePose[f] = Pose::rest(s);
    sampleClip(*clip, frameTimes[f], referencePose[f]);
    computeWorld(s, referencePose[f], world);
    for (const glm::mat4& m : world) reference[f].push_back(glm::vec3(m[3]));
  }
  const std::vector<float> reach = restReach(s);
  const size_t n = clip->channels.size();
  std::vector<float> factor(n, 1.0f);
  std::vector<char> dirty(n, 1);
  Clip out = *clip;
  const float pos = settings.positionTolerance, ang = settings.angleTolerance;
  KeyReductionReport r;
  for (int round = 0;; ++round) {
    for (size_t i = 0; i < n; ++i) {
      const Channel& c = clip->channels[i];
      if (!dirty[i] || !reducible(c)) continue;
      dirty[i] = 0;
      if (factor[i] < 1e-6f) {
        out.channels[i] = c;  // budget gone: every key stays
        continue;
      }
      float budget = pos;
      if (c.target == ChannelTarget::Rotation) budget = reach[c.joint] > 0.0f ? std::min(ang, pos / reach[c.joint]) : ang;
      out.channels[i] = reduceChannel(c, frameTimes, budget * factor[i]);
    }
    // Verify the whole clip through the sampler, in world space and in angle.
    r = KeyReductionReport{};
    std::vector<char> tooFar(s.size(), 0);
    bool ok = true;
    for (int f = 0; f < frames; ++f) {
      Pose pose = Pose::rest(s);
      sampleClip(out, frameTimes[f], pose);
      computeWorld(s, pose, world);
      for (int j = 0; j < s.size(); ++j) {
        const float e = glm::length(glm::vec3(world[j][3]) - reference[f][j]);
        r.maxPositionError = std::max(r.maxPositionError, e);
        if (e > pos) tooFar[j] = 1, ok = false;
      }
      for (size_t i = 0; i < n; ++i) {
        const Channel& c = clip->channels[i];
        if (!reducible(c) || c.target != ChannelTarget::Rotation) continue;
        const float e = angleBetween(pose.local[c.joint].rotation, referencePose[f].local[c.joint].rotation);
        r.maxAngleError = std::max(r.maxAngleError, e);
        if (e > ang) {
          factor[i] *= 0.5f, dirty[i] = 1;
          ok = false;
        }
      }
    }
    if (ok) break;
    if (round == 60) {  // cannot happen with exact sampling; never loop forever
      out = *clip;
      r = KeyReductionReport{};
      break;
    }
    // Tighten every channel that moves a joint that went too far.
    for (size_t i = 0; i < n; ++i) {
      const Channel& c = clip->channels[i];
      if (!reducible(c) || dirty[i]) continue;
      for (int j = 0; j < s.size() && !dirty[i]; ++j)
        if (tooFar[j] && s.isInSubtree(j, c.joint)) factor[i] *= 0.5f, dirty[i] = 1;
    }
  }
  r.keysBefore = keyTotal(*clip);
  r.keysAfter = keyTotal(out);
  *output = std::move(out);
  if (report) *report = r;
  return true;
}

}  // namespace kinema
