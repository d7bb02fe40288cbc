#include "sim/particle_system.h"

#include <algorithm>
#include <cmath>

namespace kinema {

namespace {

bool finite4(const glm::vec4& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w); }

bool anyJointEmitter(const std::vector<ParticleSystemSettings>& systems) {
  for (const ParticleSystemSettings& s : systems)
    for (const ParticleEmitter& e : s.emitters)
      if (e.shape == EmitterShape::Joint) return true;
  return false;
}

// Checkpoints hold at most this many particles in all (a 100,000-particle system keeps 20).
constexpr size_t kCheckpointParticles = 2000000;

}  // namespace

const char* toString(ParticleDrawStyle style) { return style == ParticleDrawStyle::Points ? "points" : "quads"; }

bool operator==(const RandomRange& a, const RandomRange& b) {
  return a.mean == b.mean && a.spread == b.spread && a.distribution == b.distribution;
}

bool operator==(const ParticleEmitter& a, const ParticleEmitter& b) {
  return a.shape == b.shape && a.position == b.position && a.radius == b.radius &&
         a.surfacePositions == b.surfacePositions && a.surfaceIndices == b.surfaceIndices && a.alongNormal == b.alongNormal &&
         a.joint == b.joint && a.direction == b.direction && a.coneDegrees == b.coneDegrees && a.speed == b.speed &&
         a.rate == b.rate && a.lifetime == b.lifetime;
}

bool operator==(const ParticleForces& a, const ParticleForces& b) {
  if (a.spheres.size() != b.spheres.size()) return false;
  for (size_t i = 0; i < a.spheres.size(); ++i)
    if (a.spheres[i].centre != b.spheres[i].centre || a.spheres[i].radius != b.spheres[i].radius) return false;
  return a.gravity == b.gravity && a.wind == b.wind && a.drag == b.drag && a.ground == b.ground &&
         a.groundHeight == b.groundHeight && a.restitution == b.restitution && a.friction == b.friction;
}

bool ParticleSystemSettings::operator==(const ParticleSystemSettings& o) const {
  return name == o.name && emitters == o.emitters && forces == o.forces && seed == o.seed &&
         maxParticles == o.maxParticles && style == o.style && size == o.size && colour == o.colour;
}

std::string ParticleSystemSettings::validate(const Skeleton& skeleton) const {
  const std::string which = "particle system '" + name + "': ";
  if (!(maxParticles >= 1 && maxParticles <= (1 << 22))) return which + "max_particles must be 1 to 4194304";
  if (!(size > 0.0f && size <= 1e6f)) return which + "the size must be above 0 and at most 1e6";
  if (!finite4(colour) || glm::any(glm::lessThan(colour, glm::vec4(0.0f))) || glm::any(glm::greaterThan(colour, glm::vec4(1.0f))))
    return which + "the colour's components must be 0 to 1";
  // The step job checks emitters and forces; joint emitters against placeholder matrices,
  // one per joint of the skeleton.
  std::vector<glm::mat4> joints;
  for (const ParticleEmitter& e : emitters)
    if (e.shape == EmitterShape::Joint) {
      joints.assign(static_cast<size_t>(skeleton.size()), glm::mat4(1.0f));
      break;
    }
  ParticleState state;
  ParticleStepJob job;
  job.emitters = &emitters;
  job.forces = &forces;
  job.jointWorld = &joints;
  job.state = &state;
  if (std::string bad = job.validate(); !bad.empty()) return which + bad;
  return "";
}

ParticleSystemSettings defaultParticleSystem(int joint, float height) {
  ParticleSystemSettings s;
  const float unit = height > 20.0f ? 100.0f : 1.0f;  // a character taller than 20 units is in centimetres
  const float h = height > 0.0f && std::isfinite(height) ? height : 1.8f * unit;
  ParticleEmitter e;
  e.shape = joint >= 0 ? EmitterShape::Joint : EmitterShape::Point;
  e.joint = joint;
  e.direction = glm::vec3(0.0f, 1.0f, 0.0f);
  e.coneDegrees = 25.0f;
  e.speed = {2.5f * unit, 0.8f * unit, RandomDistribution::Uniform};
  e.rate = {60.0f, 0.0f, RandomDistribution::Uniform};
  e.lifetime = {1.5f, 0.5f, RandomDistribution::Uniform};
  s.name = joint >= 0 ? "sparks" : "fountain";
  s.emitters.push_back(e);
  s.forces.gravity = glm::vec3(0.0f, -9.81f * unit, 0.0f);
  s.forces.restitution = 0.5f;
  s.forces.friction = 0.2f;
  s.size = 0.015f * h;
  return s;
}

void ParticlePlayback::reset() {
  systems_.clear();
  states_.clear();
  checkpoints_.clear();
  frameTime_ = 0.0;
  inputsKey_ = LLONG_MIN;
  frame_ = -1;
}

void ParticlePlayback::step(const JointWorldAt& jointWorldAt) {
  const long long next = frame_ + 1;
  if (jointWorldAt && anyJointEmitter(systems_)) jointWorldAt(next, world_);
  for (size_t i = 0; i < systems_.size(); ++i) {
    ParticleStepJob job;
    job.emitters = &systems_[i].emitters;
    job.forces = &systems_[i].forces;
    job.jointWorld = &world_;
    job.dt = static_cast<float>(frameTime_);
    job.maxParticles = static_cast<size_t>(systems_[i].maxParticles);
    job.state = &states_[i];
    if (!job.run()) states_[i].time += frameTime_;  // invalid settings: an empty system that keeps time
  }
  frame_ = next;
  ++stepsRun_;
  if (frame_ % kCheckpointEvery != 0 || checkpoints_.size() >= kMaxCheckpoints) return;
  if (!checkpoints_.empty() && checkpoints_.back().frame >= frame_) return;
  size_t stored = 0, now = 0;
  for (const Checkpoint& c : checkpoints_)
    for (const ParticleState& s : c.states) stored += s.positions.size();
  for (const ParticleState& s : states_) now += s.positions.size();
  if (stored + now <= kCheckpointParticles) checkpoints_.push_back({frame_, states_});
}

const std::vector<ParticleState>& ParticlePlayback::at(const std::vector<ParticleSystemSettings>& systems,
                                                       double frameTime, long long frame,
                                                       const JointWorldAt& jointWorldAt, long long inputsKey) {
  if (systems != systems_ || frameTime != frameTime_ || inputsKey != inputsKey_) {
    reset();
    systems_ = systems;
    frameTime_ = frameTime;
    inputsKey_ = inputsKey;
  }
  frame = std::max(0LL, frame);
  if (frame < frame_) {  // back to the latest checkpoint at or before it, or the start
    frame_ = -1;
    while (!checkpoints_.empty() && checkpoints_.back().frame > frame) checkpoints_.pop_back();
    if (!checkpoints_.empty()) {
      states_ = checkpoints_.back().states;
      frame_ = checkpoints_.back().frame;
    }
  }
  if (frame_ < 0) {
    states_.assign(systems_.size(), ParticleState{});
    for (size_t i = 0; i < systems_.size(); ++i) states_[i].random = systems_[i].seed;
    frame_ = 0;
  }
  while (frame_ < frame) step(jointWorldAt);
  return states_;
}

}  // namespace kinema
