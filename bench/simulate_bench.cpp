// Physics for animators (issue 23):
//   spring bones: 1,000 characters, each a 10-joint chain (a tail) swinging behind a moving
//   parent, one frame (1/30 s in 4 substeps) per iteration;
//   ragdoll: one physics step (1/240 s) of a 20-body ragdoll falling onto the ground.
//   ./build/bench/simulate_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cmath>

#include "sim/ragdoll.h"
#include "sim/spring_bones.h"

namespace {

using namespace kinema;

// A root, then a chain of `joints` 0.1 m bones along -Z (a tail).
Skeleton tailSkeleton(int joints) {
  Skeleton s;
  s.addJoint("root", -1, Transform::fromTranslation({0, 1, 0}));
  for (int i = 0; i < joints; ++i) s.addJoint("tail" + std::to_string(i), s.size() - 1, Transform::fromTranslation({0, 0, -0.1f}));
  return s;
}

void BM_SpringBones1000Characters10Joints(benchmark::State& state) {
  constexpr int kCharacters = 1000, kJoints = 10;
  const Skeleton s = tailSkeleton(kJoints);
  SpringBoneChain chain;
  chain.joints.resize(kJoints);
  for (int i = 0; i < kJoints; ++i) chain.joints[i] = i + 1;
  chain.stiffness = 60.0f;
  chain.damping = 3.0f;
  chain.gravity = {0.0f, -9.81f, 0.0f};
  const std::vector<SpringBoneChain> chains = {chain};
  std::vector<SpringBoneState> states(kCharacters);
  std::vector<Pose> poses(kCharacters, Pose::rest(s));
  long long frame = 0;
  for (auto _ : state) {
    const float t = static_cast<float>(frame++) / 30.0f;
    for (int c = 0; c < kCharacters; ++c) {
      Pose& pose = poses[c];
      pose = Pose::rest(s);
      // Each character's root sways on its own phase, so the chains keep moving.
      pose.local[0].rotation = glm::angleAxis(0.5f * std::sin(2.0f * t + 0.01f * c), glm::vec3(0, 1, 0));
      SpringBoneJob job;
      job.skeleton = &s;
      job.chains = &chains;
      job.dt = 1.0f / 30.0f;
      job.pose = &pose;
      job.state = &states[c];
      job.run();
    }
    benchmark::DoNotOptimize(poses.back().local.back().rotation);
  }
  state.counters["joints/s"] = benchmark::Counter(static_cast<double>(kCharacters * kJoints), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SpringBones1000Characters10Joints)->Unit(benchmark::kMillisecond);

// A 20-body ragdoll: a root with four limbs of 6, 6, 6 and 5 joints; every joint but the
// limbs' last (leaves ride on their parent's body) is a body: 1 + 5 + 5 + 5 + 4 = 20.
void BM_Ragdoll20BodiesStep(benchmark::State& state) {
  Skeleton s;
  s.addJoint("root", -1, Transform::fromTranslation({0, 1.5f, 0}));
  const glm::vec3 dirs[4] = {{1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int limb = 0; limb < 4; ++limb) {
    int parent = 0;
    for (int i = 0; i < (limb < 3 ? 6 : 5); ++i) {
      s.addJoint("l" + std::to_string(limb) + "_" + std::to_string(i), parent,
                 Transform::fromTranslation(dirs[limb] * (i == 0 ? 0.1f : 0.2f) + glm::vec3(0, -0.02f, 0)));
      parent = s.size() - 1;
    }
  }
  const Pose pose = Pose::rest(s);
  std::vector<RagdollBody> bodies;
  RagdollBodiesJob job;
  job.skeleton = &s;
  job.pose = &pose;
  job.bodies = &bodies;
  job.run();
  RagdollSettings settings;
  Result<std::unique_ptr<Ragdoll>> r = Ragdoll::create(s, settings, bodies, ragdollJointLimits(s, {}), pose);
  if (!r) {
    state.SkipWithError(r.error().c_str());
    return;
  }
  Ragdoll& ragdoll = *r.value();
  for (auto _ : state) ragdoll.step(1.0f / kRagdollStepsPerSecond);
  if (ragdoll.bodyCount() != 20) state.SkipWithError("expected 20 bodies");
  state.counters["bodies"] = ragdoll.bodyCount();
}
BENCHMARK(BM_Ragdoll20BodiesStep)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
