// Procedural groups (issue 24): "ns_per_member" is wall time per boid or particle per step.
//  BM_BoidsGrid/N    one flock step of N members (default settings, uniform hash grid)
//  BM_BoidsNaive/N   the same step with the all-pairs O(n^2) neighbour search
//  BM_Particles/N    one particle step of N live particles under gravity, wind and drag, with
//                    the ground and a sphere to bounce off (state reset every 60 steps)
//  BM_CrowdFkAndSampling/N  one frame of an N-character crowd: each member samples its own
//                    time (a phase offset) of a 2 s clip on the default character's 27 joints
//                    (a rotation channel per joint, 30 keys per second, and the root's
//                    translation) through its own SamplingCache, then runs forward kinematics
//  BM_CrowdFrame/N   one frame of an N-member crowd as kinema simulate and the editor run it
//                    (sim/crowd.h): the boids step of the whole flock (grid, planar), then each
//                    member's clip advanced by its ground speed, its pose sampled and turned to
//                    its heading (crowdMemberPose), and forward kinematics
//   ./build/bench/procedural_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "anim/sampling.h"
#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "sim/boids.h"
#include "sim/crowd.h"
#include "sim/particles.h"
#include "core/random.h"

namespace {

using namespace kinema;

void countNsPerMember(benchmark::State& state, size_t members) {
  state.counters["ns_per_member"] = benchmark::Counter(static_cast<double>(members) * state.iterations() * 1e-9,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// A flock at one density whatever its size: a jittered lattice 2 m apart (about 30 members
// within the default 4 m neighbour radius of each), flying in random directions at 2 m/s.
void makeFlock(int n, std::vector<glm::vec3>& p, std::vector<glm::vec3>& v) {
  SplitMix64 r(3);
  const int side = static_cast<int>(std::ceil(std::cbrt(double(n))));
  p.clear();
  v.clear();
  for (int i = 0; i < n; ++i) {
    const glm::vec3 cell(i % side, (i / side) % side, i / (side * side));
    p.push_back(2.0f * cell + glm::vec3(r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5)));
    v.push_back(2.0f * glm::normalize(glm::vec3(r.normal(), r.normal(), r.normal())));
  }
}

void boids(benchmark::State& state, NeighbourSearch search) {
  const int n = static_cast<int>(state.range(0));
  BoidsSettings settings;
  settings.search = search;
  std::vector<glm::vec3> p, v;
  makeFlock(n, p, v);
  BoidsStepJob job;
  job.settings = &settings;
  job.positions = &p;
  job.velocities = &v;
  for (auto _ : state) {  // the same start state each time: the cost of one step at this density
    job.run();
    benchmark::DoNotOptimize(job.outPositions.data());
  }
  countNsPerMember(state, static_cast<size_t>(n));
}

void BM_BoidsGrid(benchmark::State& state) { boids(state, NeighbourSearch::Grid); }
void BM_BoidsNaive(benchmark::State& state) { boids(state, NeighbourSearch::Naive); }
BENCHMARK(BM_BoidsGrid)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BoidsNaive)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

ParticleState particleCloud(int n) {
  ParticleState s;
  SplitMix64 r(11);
  for (int i = 0; i < n; ++i) {
    s.positions.emplace_back(r.uniform(-5, 5), r.uniform(0.5, 6), r.uniform(-5, 5));
    s.velocities.emplace_back(r.uniform(-2, 2), r.uniform(0, 5), r.uniform(-2, 2));
    s.ages.push_back(0.0f);
    s.lifetimes.push_back(1e6f);
    s.emitterOf.push_back(0);
  }
  return s;
}

void BM_Particles(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  ParticleForces forces;
  forces.wind = glm::vec3(1.5f, 0.0f, 0.0f);
  forces.drag = 0.3f;
  forces.restitution = 0.6f;
  forces.spheres.push_back({glm::vec3(0, 1, 0), 1.0f});
  const std::vector<ParticleEmitter> emitters;  // a fixed population
  const ParticleState start = particleCloud(n);
  ParticleState s = start;
  ParticleStepJob job;
  job.emitters = &emitters;
  job.forces = &forces;
  job.state = &s;
  int steps = 0;
  for (auto _ : state) {
    if (++steps % 60 == 0) {
      state.PauseTiming();
      s = start;
      state.ResumeTiming();
    }
    job.run();
    benchmark::DoNotOptimize(s.positions.data());
  }
  countNsPerMember(state, static_cast<size_t>(n));
}
BENCHMARK(BM_Particles)->Arg(100000)->Unit(benchmark::kMillisecond);

Clip walkLikeClip(const Skeleton& skeleton) {
  SplitMix64 r(5);
  Clip clip;
  for (int j = 0; j < skeleton.size(); ++j) {
    Channel rotation(j, ChannelTarget::Rotation, Interpolation::Linear, {}, {});
    for (int k = 0; k <= 60; ++k) {
      const glm::quat q = skeleton.rest[j].rotation *
                          glm::angleAxis(static_cast<float>(0.3 * std::sin(k * 0.2094 + j)), glm::vec3(1, 0, 0));
      rotation.times.push_back(k / 30.0f);
      rotation.values.emplace_back(q.x, q.y, q.z, q.w);
    }
    clip.channels.push_back(std::move(rotation));
  }
  Channel root(0, ChannelTarget::Translation, Interpolation::Linear, {}, {});
  for (int k = 0; k <= 60; ++k) {
    root.times.push_back(k / 30.0f);
    root.values.emplace_back(skeleton.rest[0].translation + glm::vec3(0.0f, 0.03f * static_cast<float>(r.uniform()), 0.05f * k), 0.0f);
  }
  clip.channels.push_back(std::move(root));
  return clip;
}

void BM_CrowdFkAndSampling(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Skeleton skeleton = makeDefaultCharacter();
  const Clip clip = walkLikeClip(skeleton);
  std::vector<Pose> poses(n, Pose::rest(skeleton));
  std::vector<SamplingCache> caches(n);
  std::vector<std::vector<glm::mat4>> world(n);
  std::vector<float> phase(n);
  SplitMix64 r(8);
  for (float& p : phase) p = static_cast<float>(r.uniform(0.0, 2.0));
  float time = 0.0f;
  for (auto _ : state) {
    time += 1.0f / 60.0f;
    for (int i = 0; i < n; ++i) {
      sampleClip(clip, std::fmod(time + phase[i], 2.0f), poses[i], caches[i]);
      computeWorld(skeleton, poses[i], world[i]);
    }
    benchmark::DoNotOptimize(world.data());
  }
  countNsPerMember(state, static_cast<size_t>(n));
  state.counters["joints"] = skeleton.size();
}
BENCHMARK(BM_CrowdFkAndSampling)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_CrowdFrame(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Skeleton skeleton = makeDefaultCharacter();
  const Clip clip = walkLikeClip(skeleton);
  CrowdSettings crowd;
  crowd.members = n;
  crowd.boids.spheres.push_back({glm::vec3(0.0f), 3.0f});
  const CrowdClipMotion motion = analyseCrowdClip(skeleton, clip, crowd);
  std::vector<CrowdMemberState> members = crowdStartLayout(crowd, motion);
  BoidsSettings boids = crowd.boids;
  boids.planar = true;
  std::vector<glm::vec3> p(n), v(n);
  BoidsStepJob step;
  step.settings = &boids;
  step.positions = &p;
  step.velocities = &v;
  step.dt = 1.0f / 30.0f;
  std::vector<Pose> poses(n);
  std::vector<std::vector<glm::mat4>> world(n);
  for (auto _ : state) {
    for (int i = 0; i < n; ++i) p[i] = members[i].position, v[i] = members[i].velocity;
    step.run();
    for (int i = 0; i < n; ++i) {
      CrowdMemberState& m = members[i];
      m.position = step.outPositions[i];
      m.velocity = step.outVelocities[i];
      const float speed = glm::length(m.velocity);
      if (speed > 1e-4f) m.yaw = std::atan2(m.velocity.x, m.velocity.z);
      m.clipTime = advanceCrowdClipTime(m.clipTime, step.dt, speed, motion);
      crowdMemberPose(skeleton, clip, motion, m, poses[i]);
      computeWorld(skeleton, poses[i], world[i]);
    }
    benchmark::DoNotOptimize(world.data());
  }
  countNsPerMember(state, static_cast<size_t>(n));
  state.counters["joints"] = skeleton.size();
}
BENCHMARK(BM_CrowdFrame)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
