// Forward kinematics throughput. Every benchmark reports "ns_per_joint": wall time per
// joint transform written (lower is better). Reference point: ozz-animation's SIMD
// LocalToModelJob runs at about 6 ns per joint on this class of machine.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "core/forward_kinematics.h"

namespace {

using kinema::Pose;
using kinema::Skeleton;
using kinema::Transform;

// A random tree with parents listed first (parents[i] < i). `chain` is the chance that a
// joint hangs off the joint just before it, which gives limb-like chains instead of a
// bushy tree.
Skeleton randomSkeleton(int joints, std::mt19937& rng, float chain = 0.6f) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_real_distribution<float> coin(0.0f, 1.0f);
  Skeleton s;
  s.names.reserve(joints);
  for (int i = 0; i < joints; ++i) {
    int parent = -1;
    if (i > 0)
      parent = coin(rng) < chain ? i - 1 : std::uniform_int_distribution<int>(0, i - 1)(rng);
    Transform t;
    t.translation = glm::vec3(unit(rng), unit(rng), unit(rng));
    t.rotation = glm::normalize(glm::quat(unit(rng) + 2.0f, unit(rng), unit(rng), unit(rng)));
    t.scale = glm::vec3(1.0f + 0.1f * unit(rng), 1.0f + 0.1f * unit(rng), 1.0f + 0.1f * unit(rng));
    s.addJoint("j" + std::to_string(i), parent, t);
  }
  return s;
}

void setPerJoint(benchmark::State& state, double jointsPerIteration) {
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * jointsPerIteration));
  state.counters["ns_per_joint"] = benchmark::Counter(
      jointsPerIteration, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

struct Crowd {
  std::vector<Skeleton> skeletons;
  std::vector<Pose> poses;
  std::vector<std::vector<glm::mat4>> world;
  Crowd(int count, int joints) {
    std::mt19937 rng(1234);
    for (int i = 0; i < count; ++i) {
      skeletons.push_back(randomSkeleton(joints, rng));
      poses.push_back(Pose::rest(skeletons.back()));
      world.emplace_back(static_cast<size_t>(joints));
    }
  }
};

// (a) 1,000 skeletons x 64 joints, through the job with preallocated output.
void BM_Crowd1000x64_Job(benchmark::State& state) {
  Crowd crowd(1000, 64);
  for (auto _ : state) {
    for (size_t i = 0; i < crowd.skeletons.size(); ++i) {
      kinema::LocalToWorldJob job;
      job.parents = crowd.skeletons[i].parents.data();
      job.local = crowd.poses[i].local.data();
      job.world = crowd.world[i].data();
      job.count = 64;
      job.run();
    }
    benchmark::DoNotOptimize(crowd.world.back().back());
    benchmark::ClobberMemory();
  }
  setPerJoint(state, 1000.0 * 64.0);
}
BENCHMARK(BM_Crowd1000x64_Job)->Unit(benchmark::kMicrosecond);

// (a') the same through computeWorld (vector already the right size, so no allocation).
void BM_Crowd1000x64_ComputeWorld(benchmark::State& state) {
  Crowd crowd(1000, 64);
  for (auto _ : state) {
    for (size_t i = 0; i < crowd.skeletons.size(); ++i)
      kinema::computeWorld(crowd.skeletons[i], crowd.poses[i], crowd.world[i]);
    benchmark::DoNotOptimize(crowd.world.back().back());
    benchmark::ClobberMemory();
  }
  setPerJoint(state, 1000.0 * 64.0);
}
BENCHMARK(BM_Crowd1000x64_ComputeWorld)->Unit(benchmark::kMicrosecond);

// (b) one 10,000-joint skeleton.
void BM_Single10000_ComputeWorld(benchmark::State& state) {
  std::mt19937 rng(99);
  const Skeleton s = randomSkeleton(10000, rng);
  const Pose pose = Pose::rest(s);
  std::vector<glm::mat4> world(static_cast<size_t>(s.size()));
  for (auto _ : state) {
    kinema::computeWorld(s, pose, world);
    benchmark::DoNotOptimize(world.back());
    benchmark::ClobberMemory();
  }
  setPerJoint(state, s.size());
}
BENCHMARK(BM_Single10000_ComputeWorld)->Unit(benchmark::kMicrosecond);

// (c) updateSubtree on the sub-tree whose size is closest to `wanted` joints of a random
// skeleton: a mid-size one of 10,000 joints, and a limb-sized one (the arm of a 64-joint
// character). ns_per_joint counts the joints rewritten.
void runUpdateSubtree(benchmark::State& state, int joints, unsigned seed, float chaininess, int wanted) {
  std::mt19937 rng(seed);
  const Skeleton s = randomSkeleton(joints, rng, chaininess);
  const Pose pose = Pose::rest(s);
  std::vector<int> subtreeSize(static_cast<size_t>(s.size()), 1);
  for (int i = s.size() - 1; i > 0; --i)
    if (s.parents[i] >= 0) subtreeSize[s.parents[i]] += subtreeSize[i];
  int joint = 0;
  for (int i = 0; i < s.size(); ++i)
    if (std::abs(subtreeSize[i] - wanted) < std::abs(subtreeSize[joint] - wanted)) joint = i;
  std::vector<glm::mat4> world = kinema::computeWorld(s, pose);
  for (auto _ : state) {
    kinema::updateSubtree(s, pose, joint, world);
    benchmark::DoNotOptimize(world.back());
    benchmark::ClobberMemory();
  }
  state.counters["subtree_joints"] = subtreeSize[joint];
  state.counters["joints_after_root"] = s.size() - joint;
  setPerJoint(state, subtreeSize[joint]);
}

void BM_UpdateSubtree(benchmark::State& state) { runUpdateSubtree(state, 10000, 7, 0.9f, 1000); }
BENCHMARK(BM_UpdateSubtree)->Unit(benchmark::kMicrosecond);

void BM_UpdateSubtreeSmall(benchmark::State& state) { runUpdateSubtree(state, 64, 5, 0.7f, 12); }
BENCHMARK(BM_UpdateSubtreeSmall);

}  // namespace
