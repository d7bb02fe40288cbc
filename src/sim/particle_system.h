#pragma once
#include <climits>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/skeleton.h"
#include "sim/particles.h"

namespace kinema {

// A particle system as a file saves it (.kinema "simulation.particles"): its emitters and
// forces (sim/particles.h), the seed, and how it is drawn. Model space, the file's units
// (metres for the default gravity), seconds.
enum class ParticleDrawStyle { Points, Quads };
const char* toString(ParticleDrawStyle style);

struct ParticleSystemSettings {
  std::string name = "particles";
  std::vector<ParticleEmitter> emitters;
  ParticleForces forces;
  uint64_t seed = 1;
  int maxParticles = 100000;  // emission stops at this many live particles, [1, 4194304]
  ParticleDrawStyle style = ParticleDrawStyle::Quads;
  // Quads: the side of a camera-facing square, in file units; Points: a dot's diameter in
  // pixels. (0, 1e6].
  float size = 0.05f;
  glm::vec4 colour{1.0f, 0.55f, 0.1f, 1.0f};  // linear RGBA in [0, 1]

  // Empty when the system fits `skeleton` (joint emitters name one of its joints) and every
  // value is in range; otherwise one sentence naming the first problem.
  std::string validate(const Skeleton& skeleton) const;
  bool operator==(const ParticleSystemSettings& o) const;
  bool operator!=(const ParticleSystemSettings& o) const { return !(*this == o); }
};

bool operator==(const RandomRange& a, const RandomRange& b);
bool operator==(const ParticleEmitter& a, const ParticleEmitter& b);
bool operator==(const ParticleForces& a, const ParticleForces& b);

// Settings for a new emitter on `joint` (or at the origin with joint -1), scaled to a
// character `height` file units tall: sparks that leave upwards in a 25° cone, fall under
// gravity (9.81 m/s^2 in the file's units) and bounce on the ground.
ParticleSystemSettings defaultParticleSystem(int joint, float height);

// The particles at any frame, deterministically: frame 0 is the empty start, frame F the
// state after F fixed steps of `frameTime` from it, each step emitting at the pose of the
// frame it ends on. Playing forwards continues from the cached frame; going backwards (or
// any change of the inputs) simulates again from the start, past checkpoints kept every
// kCheckpointEvery frames so scrubbing back stays cheap.
class ParticlePlayback {
 public:
  // Fills the model-space joint matrices at a frame (asked only when an emitter is a joint).
  using JointWorldAt = std::function<void(long long frame, std::vector<glm::mat4>& world)>;
  static constexpr long long kCheckpointEvery = 32;
  static constexpr size_t kMaxCheckpoints = 64;

  // The states of every system at `frame` (>= 0). `inputsKey` names everything else the
  // joints depend on (the editor's document change count): a new key starts again.
  const std::vector<ParticleState>& at(const std::vector<ParticleSystemSettings>& systems, double frameTime,
                                       long long frame, const JointWorldAt& jointWorldAt, long long inputsKey = 0);
  long long frame() const { return frame_; }
  long long stepsRun() const { return stepsRun_; }  // total, for tests
  void reset();

 private:
  struct Checkpoint {
    long long frame;
    std::vector<ParticleState> states;
  };
  void step(const JointWorldAt& jointWorldAt);
  std::vector<ParticleSystemSettings> systems_;
  double frameTime_ = 0.0;
  long long inputsKey_ = LLONG_MIN;
  long long frame_ = -1;
  std::vector<ParticleState> states_;
  std::vector<Checkpoint> checkpoints_;
  std::vector<glm::mat4> world_;
  long long stepsRun_ = 0;
};

}  // namespace kinema
