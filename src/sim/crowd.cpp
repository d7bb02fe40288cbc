#include "sim/crowd.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/quaternion.hpp>

#include "core/forward_kinematics.h"
#include "core/math.h"
#include "core/random.h"

namespace kinema {

namespace {


glm::vec3 jointCentroid(const Skeleton& skeleton, PoseSource& poses, float time) {
  Pose pose = Pose::rest(skeleton);
  poses.poseAt(time, pose);
  const std::vector<glm::mat4> world = computeWorld(skeleton, pose);
  glm::vec3 sum(0.0f);
  for (const glm::mat4& m : world) sum += glm::vec3(m[3]);
  return world.empty() ? sum : sum / static_cast<float>(world.size());
}

glm::quat yawRotation(float yaw) { return glm::angleAxis(yaw, glm::vec3(0.0f, 1.0f, 0.0f)); }

}  // namespace

CrowdClipMotion analyseCrowdClip(const Skeleton& skeleton, const Clip& clip, const CrowdSettings& settings,
                                 PoseSource* poses) {
  ClipPoses bare(skeleton, clip);
  PoseSource& source = poses ? *poses : bare;
  CrowdClipMotion m;
  m.start = 0.0f;
  m.duration = std::max(0.0f, clip.duration());
  m.forwardYaw = glm::radians(settings.forwardDegrees);
  if (m.duration > 0.0f && !skeleton.empty()) {
    glm::vec3 d = jointCentroid(skeleton, source, m.start + m.duration) - jointCentroid(skeleton, source, m.start);
    d.y = 0.0f;
    const glm::vec3 v = d / m.duration;
    if (glm::length(v) >= 1e-3f) {
      m.drift = v;
      m.forwardYaw = std::atan2(v.x, v.z);
    }
  }
  const float measured = glm::length(m.drift);
  m.naturalSpeed = settings.strideSpeed > 0.0f ? settings.strideSpeed
                   : measured > 0.0f            ? measured
                   : settings.boids.cruiseSpeed > 0.0f ? settings.boids.cruiseSpeed
                                                       : 0.5f * settings.boids.maxSpeed;
  return m;
}

std::vector<CrowdMemberState> crowdStartLayout(const CrowdSettings& s, const CrowdClipMotion& motion) {
  const int n = s.members;
  const float spacing = 2.5f * s.boids.separationDistance;
  // The n lattice points nearest the centre (ties in lattice order: deterministic).
  const int half = static_cast<int>(std::ceil(0.5 * std::sqrt(1.6 * n))) + 1;
  struct Point {
    int x, z;
    long long d2;
  };
  std::vector<Point> points;
  for (int z = -half; z <= half; ++z)
    for (int x = -half; x <= half; ++x) points.push_back({x, z, 1LL * x * x + 1LL * z * z});
  std::stable_sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.d2 < b.d2; });
  SplitMix64 random(s.seed);
  std::vector<CrowdMemberState> out(static_cast<size_t>(n));
  const float speed = s.boids.cruiseSpeed > 0.0f ? s.boids.cruiseSpeed : 0.5f * s.boids.maxSpeed;
  for (int i = 0; i < n; ++i) {
    CrowdMemberState& m = out[static_cast<size_t>(i)];
    const float jitter = 0.25f * s.boids.separationDistance;
    m.position = s.spawnCentre + glm::vec3(spacing * static_cast<float>(points[static_cast<size_t>(i)].x) +
                                               static_cast<float>(random.uniform(-jitter, jitter)),
                                           0.0f,
                                           spacing * static_cast<float>(points[static_cast<size_t>(i)].z) +
                                               static_cast<float>(random.uniform(-jitter, jitter)));
    float heading = static_cast<float>(random.uniform(-kPi, kPi));
    if (s.boids.hasGoal) {
      const glm::vec3 to = s.boids.goal - m.position;
      heading = std::atan2(to.x, to.z) + heading / 6.0f;  // within 30 degrees of the goal's direction
    }
    m.velocity = speed * glm::vec3(std::sin(heading), 0.0f, std::cos(heading));
    m.yaw = heading;
    m.clipTime = motion.start + random.uniform() * motion.duration;
  }
  return out;
}

double advanceCrowdClipTime(double clipTime, double dt, float groundSpeed, const CrowdClipMotion& motion) {
  if (!(motion.duration > 0.0f)) return motion.start;
  double t = clipTime - motion.start + dt * static_cast<double>(groundSpeed) / static_cast<double>(motion.naturalSpeed);
  t = std::fmod(t, static_cast<double>(motion.duration));
  if (t < 0.0) t += motion.duration;
  return motion.start + t;
}

Result<CrowdRun> runCrowd(const CrowdSettings& settings, const CrowdClipMotion& motion, double dt, long long frames) {
  if (std::string e = settings.validate(); !e.empty()) return Result<CrowdRun>::failure(e);
  if (!(dt > 0.0 && dt <= 1.0)) return Result<CrowdRun>::failure("the frame time must be in (0, 1] seconds");
  if (frames < 1 || frames * settings.members > 200000000LL)
    return Result<CrowdRun>::failure("a crowd runs 1 frame or more, and at most 200 million member frames");
  BoidsSettings boids = settings.boids;
  boids.planar = true;  // a ground crowd
  CrowdRun run;
  run.members = settings.members;
  run.frames = frames;
  run.dt = dt;
  run.states.reserve(static_cast<size_t>(frames * settings.members));
  std::vector<CrowdMemberState> now = crowdStartLayout(settings, motion);
  std::vector<glm::vec3> p(now.size()), v(now.size());
  BoidsStepJob step;
  step.settings = &boids;
  step.positions = &p;
  step.velocities = &v;
  step.dt = static_cast<float>(dt);
  step.debugBoid = settings.debugMember;
  for (long long f = 0; f < frames; ++f) {
    run.states.insert(run.states.end(), now.begin(), now.end());
    for (size_t i = 0; i < now.size(); ++i) p[i] = now[i].position, v[i] = now[i].velocity;
    if (!step.run()) return Result<CrowdRun>::failure(step.validate());
    run.debug.push_back(step.debug);  // what the debug member felt at frame f
    for (size_t i = 0; i < now.size(); ++i) {
      CrowdMemberState& m = now[i];
      m.position = step.outPositions[i];
      m.velocity = step.outVelocities[i];
      const float speed = glm::length(m.velocity);
      if (speed > 1e-4f) m.yaw = std::atan2(m.velocity.x, m.velocity.z);
      m.clipTime = advanceCrowdClipTime(m.clipTime, dt, speed, motion);
    }
  }
  return run;
}

void crowdMemberPose(const Skeleton& skeleton, const Clip& clip, const CrowdClipMotion& motion,
                     const CrowdMemberState& state, Pose& pose, PoseSource* poses) {
  if (pose.size() != skeleton.size()) pose = Pose::rest(skeleton);
  if (poses) {
    poses->poseAt(state.clipTime, pose);
  } else {
    ClipPoses(skeleton, clip).poseAt(state.clipTime, pose);
  }
  const glm::quat turn = yawRotation(state.yaw - motion.forwardYaw);
  const glm::vec3 drift = motion.drift * static_cast<float>(state.clipTime - motion.start);
  for (int j = 0; j < skeleton.size(); ++j) {
    if (skeleton.parents[j] >= 0) continue;
    Transform& t = pose.local[j];
    t.translation = state.position + turn * (t.translation - drift);
    t.rotation = glm::normalize(turn * t.rotation);
  }
}

Clip bakeCrowdMember(const Skeleton& skeleton, const Clip& clip, const CrowdClipMotion& motion, const CrowdRun& run,
                     int member, long long first, long long last, const std::string& name, PoseSource* poses) {
  const int n = skeleton.size();
  std::vector<char> moved(static_cast<size_t>(n), 0), scaled(static_cast<size_t>(n), 0);
  for (int j = 0; j < n; ++j) moved[j] = skeleton.parents[j] < 0;
  for (const Channel& c : clip.channels) {
    if (c.joint < 0 || c.joint >= n || c.target == ChannelTarget::Scalar) continue;
    moved[c.joint] = 1;
    if (c.target == ChannelTarget::Scale) scaled[c.joint] = 1;
  }
  Clip out;
  out.name = name;
  out.frameTime = run.dt;
  out.loop = false;
  std::vector<int> slot(static_cast<size_t>(n), -1);
  for (int j = 0; j < n; ++j) {
    if (!moved[j]) continue;
    slot[j] = static_cast<int>(out.channels.size());
    out.channels.emplace_back(j, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{},
                              std::vector<glm::vec4>{});
    out.channels.emplace_back(j, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{},
                              std::vector<glm::vec4>{});
    if (scaled[j])
      out.channels.emplace_back(j, ChannelTarget::Scale, Interpolation::Linear, std::vector<float>{},
                                std::vector<glm::vec4>{});
  }
  Pose pose;
  first = std::max(0LL, first);
  last = std::min(last, run.frames - 1);
  for (long long f = first; f <= last; ++f) {
    crowdMemberPose(skeleton, clip, motion, run.at(f, member), pose, poses);
    const float time = ownFrameGrid(out).frameToTime(f);
    for (int j = 0; j < n; ++j) {
      if (slot[j] < 0) continue;
      const Transform& t = pose.local[j];
      Channel* c = &out.channels[static_cast<size_t>(slot[j])];
      c[0].times.push_back(time);
      c[0].values.emplace_back(t.translation, 0.0f);
      c[1].times.push_back(time);
      glm::quat q = t.rotation;
      if (!c[1].values.empty()) {  // the sign nearest the previous key: no flips in linear keys
        const glm::vec4& prev = c[1].values.back();
        if (prev.x * q.x + prev.y * q.y + prev.z * q.z + prev.w * q.w < 0.0f) q = -q;
      }
      c[1].values.emplace_back(q.x, q.y, q.z, q.w);
      if (scaled[j]) {
        c[2].times.push_back(time);
        c[2].values.emplace_back(t.scale, 0.0f);
      }
    }
  }
  return out;
}

std::string crowdMemberName(const std::string& crowdName, int member) {
  char digits[16];
  std::snprintf(digits, sizeof digits, "%04d", member);
  return crowdName + "_" + digits;
}

}  // namespace kinema
