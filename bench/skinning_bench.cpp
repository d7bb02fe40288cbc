// CPU skinning throughput: 50,000 vertices, 64 joints, positions + normals. "ns_per_vertex"
// is wall time per vertex. Neighbouring vertices share joints, as in real meshes. Reference
// point: ozz-animation's SkinningJob does about 4.5 ns per vertex with 4 influences,
// positions and normals, on this machine class (ozz leaves normals unnormalised: compare
// BM_LinearBlend_Unnormalized). BM_LinearBlend takes the AVX2 + FMA loop where the CPU has it;
// the *Sse2* variants force the baseline loop.
//   ./build/bench/skinning_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <vector>

#include "skin/dual_quaternion_skinning.h"
#include "skin/linear_blend_skinning.h"

namespace {

using namespace kinema;

constexpr int kVertices = 50000;
constexpr int kJoints = 64;

struct Mesh {
  std::vector<glm::vec3> positions, normals, outPositions, outNormals;
  std::vector<uint16_t> joints;
  std::vector<float> weights;
  std::vector<glm::mat4> matrices;
  int stride = 4;
};

// `rigid`: rotations and translations (the usual rig); otherwise each joint also scales
// non-uniformly, which makes linear blend use per-joint normal matrices and dual
// quaternions blend a stretch.
Mesh makeMesh(int stride, bool rigid) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.05f, 1.0f);
  Mesh m;
  m.stride = stride;
  for (int j = 0; j < kJoints; ++j) {
    glm::mat4 mat = glm::mat4_cast(glm::normalize(glm::quat(u(rng) + 2.0f, u(rng), u(rng), u(rng))));
    if (!rigid) mat = mat * glm::mat4(glm::mat3(1.0f + 0.2f * pos(rng), 0, 0, 0, 1.0f + 0.2f * pos(rng), 0, 0, 0, 1.0f));
    mat[3] = glm::vec4(u(rng), u(rng), u(rng), 1.0f);
    m.matrices.push_back(mat);
  }
  for (int v = 0; v < kVertices; ++v) {
    m.positions.emplace_back(u(rng), u(rng), u(rng));
    m.normals.push_back(glm::normalize(glm::vec3(u(rng), u(rng), u(rng) + 2.0f)));
    std::vector<float> w(stride);
    float sum = 0;
    for (int k = 0; k < stride; ++k) sum += w[k] = pos(rng);
    std::sort(w.begin(), w.end(), [](float a, float b) { return a > b; });
    const int base = v * kJoints / kVertices;
    for (int k = 0; k < stride; ++k) {
      m.joints.push_back(static_cast<uint16_t>((base + k * 3) % kJoints));
      m.weights.push_back(w[k] / sum);
    }
  }
  m.outPositions.resize(kVertices);
  m.outNormals.resize(kVertices);
  return m;
}

template <class Job>
Job makeJob(Mesh& m, bool normals) {
  Job job;
  job.positions = m.positions.data();
  job.normals = normals ? m.normals.data() : nullptr;
  job.vertexCount = kVertices;
  job.influenceJoints = m.joints.data();
  job.influenceWeights = m.weights.data();
  job.influencesPerVertex = m.stride;
  job.jointMatrices = m.matrices.data();
  job.jointCount = kJoints;
  job.outPositions = m.outPositions.data();
  job.outNormals = normals ? m.outNormals.data() : nullptr;
  return job;
}

template <class Job>
void run(benchmark::State& state, bool rigid, bool normals, void (*configure)(Job&) = nullptr) {
  Mesh m = makeMesh(static_cast<int>(state.range(0)), rigid);
  Job job = makeJob<Job>(m, normals);
  if (configure) configure(job);
  for (auto _ : state) {
    if (!job.run()) state.SkipWithError("the job refused its inputs");
    benchmark::DoNotOptimize(m.outPositions.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kVertices);
  // Seconds per vertex, printed with an SI prefix ("4.5n" = 4.5 ns).
  state.counters["ns_per_vertex"] =
      benchmark::Counter(kVertices, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_LinearBlend(benchmark::State& state) { run<LinearBlendSkinningJob>(state, true, true); }
void BM_LinearBlend_PositionsOnly(benchmark::State& state) { run<LinearBlendSkinningJob>(state, true, false); }
void BM_LinearBlend_ScaledJoints(benchmark::State& state) { run<LinearBlendSkinningJob>(state, false, true); }
// Unnormalised normals (ozz's SkinningJob leaves them so) and the SSE2 loop forced on a
// CPU with AVX2 + FMA.
void unnormalized(LinearBlendSkinningJob& job) { job.normalizeNormals = false; }
void sse2Only(LinearBlendSkinningJob& job) { job.allowAvx2 = false; }
void BM_LinearBlend_Unnormalized(benchmark::State& state) {
  run<LinearBlendSkinningJob>(state, true, true, unnormalized);
}
void BM_LinearBlend_Sse2(benchmark::State& state) { run<LinearBlendSkinningJob>(state, true, true, sse2Only); }
void BM_LinearBlend_Sse2Unnormalized(benchmark::State& state) {
  run<LinearBlendSkinningJob>(state, true, true, [](LinearBlendSkinningJob& job) {
    job.allowAvx2 = false;
    job.normalizeNormals = false;
  });
}
void BM_DualQuaternion(benchmark::State& state) { run<DualQuaternionSkinningJob>(state, true, true); }
void BM_DualQuaternion_ScaledJoints(benchmark::State& state) { run<DualQuaternionSkinningJob>(state, false, true); }

BENCHMARK(BM_LinearBlend)->Arg(4)->Arg(1)->Arg(2)->Arg(8);
BENCHMARK(BM_LinearBlend_PositionsOnly)->Arg(4);
BENCHMARK(BM_LinearBlend_ScaledJoints)->Arg(4);
BENCHMARK(BM_LinearBlend_Unnormalized)->Arg(4);
BENCHMARK(BM_LinearBlend_Sse2)->Arg(4);
BENCHMARK(BM_LinearBlend_Sse2Unnormalized)->Arg(4);
BENCHMARK(BM_DualQuaternion)->Arg(4)->Arg(1)->Arg(8);
BENCHMARK(BM_DualQuaternion_ScaledJoints)->Arg(4);

}  // namespace

BENCHMARK_MAIN();
