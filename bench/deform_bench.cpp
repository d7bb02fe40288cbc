// Deformer throughput (issue 22): "ns_per_vertex" is wall time per vertex.
//  BM_Ffd/N          an N x N x N lattice (every control point moved) on 50,000 vertices
//  BM_Bend/Twist/Taper  one Barr deformer on 50,000 vertices
//  BM_StackOnDefaultCharacter  a lattice, bend, twist, taper and soft pull on the default
//                    character's body (the whole stack, per frame)
//  BM_SceneDeformationWithStack  what the editor and `kinema render` run per frame for the
//                    default character with that stack: morph targets (smile at 0.5), skinning
//                    at the rest pose, the stack, and the normals recomputed (SceneDeformationJob)
//   ./build/bench/deform_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "deform/deformer_stack.h"
#include "core/forward_kinematics.h"
#include "scene/default_character_scene.h"
#include "evaluation/scene_deformation.h"

namespace {

using namespace kinema;

constexpr int kVertices = 50000;

// Wall time per vertex, in ns, as a rate counter (the other benches' "ns_per_vertex").
void countNsPerVertex(benchmark::State& state, size_t vertices) {
  state.counters["ns_per_vertex"] = benchmark::Counter(static_cast<double>(vertices) * state.iterations() * 1e-9,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

std::vector<glm::vec3> randomPoints(int n) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<glm::vec3> pts(n);
  for (glm::vec3& p : pts) p = glm::vec3(u(rng), u(rng) + 1.0f, u(rng));
  return pts;
}

FfdLattice movedLattice(const std::vector<glm::vec3>& pts, int n) {
  const int counts[3] = {n, n, n};
  FfdLattice l = fitLattice(pts, {}, counts);
  std::mt19937 rng(4);
  std::normal_distribution<float> jitter(0.0f, 0.05f);
  for (glm::vec3& p : l.points) p += glm::vec3(jitter(rng), jitter(rng), jitter(rng));
  return l;
}

void BM_Ffd(benchmark::State& state) {
  const std::vector<glm::vec3> pts = randomPoints(kVertices);
  std::vector<glm::vec3> out(pts.size());
  const FfdLattice l = movedLattice(pts, static_cast<int>(state.range(0)));
  FfdJob job;
  job.lattice = &l;
  job.positions = pts.data();
  job.count = kVertices;
  job.outPositions = out.data();
  for (auto _ : state) {
    job.run();
    benchmark::DoNotOptimize(out.data());
  }
  countNsPerVertex(state, kVertices);
}
BENCHMARK(BM_Ffd)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

void BM_Axis(benchmark::State& state, DeformerType type) {
  const std::vector<glm::vec3> pts = randomPoints(kVertices);
  std::vector<glm::vec3> out(pts.size());
  Deformer d;
  d.type = type;
  d.axis.kind = type == DeformerType::Bend ? AxisDeformerKind::Bend
                : type == DeformerType::Twist ? AxisDeformerKind::Twist
                                              : AxisDeformerKind::Taper;
  d.axis.low = 0.2f;
  d.axis.high = 1.8f;
  d.axis.amount = type == DeformerType::Taper ? 0.5f : 1.0f;
  DeformerStack stack;
  stack.deformers = {d};
  DeformerStackJob job;
  job.stack = &stack;
  job.positions = pts.data();
  job.count = kVertices;
  job.outPositions = out.data();
  for (auto _ : state) {
    job.run();
    benchmark::DoNotOptimize(out.data());
  }
  countNsPerVertex(state, kVertices);
}
BENCHMARK_CAPTURE(BM_Axis, Bend, DeformerType::Bend)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Axis, Twist, DeformerType::Twist)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Axis, Taper, DeformerType::Taper)->Unit(benchmark::kMillisecond);

void BM_StackOnDefaultCharacter(benchmark::State& state) {
  const Scene scene = makeDefaultCharacterScene();
  std::vector<glm::vec3> pts;
  for (const Mesh& m : scene.meshes)
    for (const MeshPrimitive& p : m.primitives) pts.insert(pts.end(), p.positions.begin(), p.positions.end());
  std::vector<glm::vec3> out(pts.size());
  Deformer lattice;
  lattice.type = DeformerType::Lattice;
  lattice.lattice = movedLattice(pts, 4);
  Deformer bend;
  bend.type = DeformerType::Bend;
  bend.axis.kind = AxisDeformerKind::Bend;
  bend.axis.low = 1.0f;
  bend.axis.high = 1.7f;
  bend.axis.amount = 0.4f;
  Deformer twist = bend;
  twist.type = DeformerType::Twist;
  twist.axis.kind = AxisDeformerKind::Twist;
  Deformer taper = bend;
  taper.type = DeformerType::Taper;
  taper.axis.kind = AxisDeformerKind::Taper;
  taper.axis.amount = 0.8f;
  Deformer pull;
  pull.type = DeformerType::SoftPull;
  pull.pull.center = pts[pts.size() / 2];
  pull.pull.offset = glm::vec3(0.0f, 0.05f, 0.02f);
  pull.pull.radius = 0.2f;
  DeformerStack stack;
  stack.deformers = {lattice, bend, twist, taper, pull};
  DeformerStackJob job;
  job.stack = &stack;
  job.positions = pts.data();
  job.count = static_cast<int>(pts.size());
  job.outPositions = out.data();
  for (auto _ : state) {
    job.run();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["vertices"] = static_cast<double>(pts.size());
  countNsPerVertex(state, pts.size());
}
BENCHMARK(BM_StackOnDefaultCharacter)->Unit(benchmark::kMicrosecond);

void BM_SceneDeformationWithStack(benchmark::State& state) {
  Scene scene = makeDefaultCharacterScene();
  const std::vector<glm::vec3>& pts = scene.meshes[0].primitives[0].positions;
  Deformer lattice;
  lattice.name = "lattice";
  lattice.type = DeformerType::Lattice;
  lattice.lattice = movedLattice(pts, 4);
  Deformer bend;
  bend.name = "bend";
  bend.type = DeformerType::Bend;
  bend.axis.kind = AxisDeformerKind::Bend;
  bend.axis.low = 1.0f;
  bend.axis.high = 1.7f;
  bend.axis.amount = 0.4f;
  Deformer twist = bend;
  twist.name = "twist";
  twist.type = DeformerType::Twist;
  twist.axis.kind = AxisDeformerKind::Twist;
  Deformer taper = bend;
  taper.name = "taper";
  taper.type = DeformerType::Taper;
  taper.axis.kind = AxisDeformerKind::Taper;
  taper.axis.amount = 0.8f;
  Deformer pull;
  pull.name = "pull";
  pull.type = DeformerType::SoftPull;
  pull.pull.center = pts[pts.size() / 2];
  pull.pull.offset = glm::vec3(0.0f, 0.05f, 0.02f);
  pull.pull.radius = 0.2f;
  scene.editDeformerStack(0).deformers = {lattice, bend, twist, taper, pull};
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  std::vector<std::vector<float>> weights = {{0.0f, 0.5f, 0.0f, 0.0f}};
  std::vector<DeformedPrimitive> out;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.morphWeights = &weights;
  job.out = &out;
  if (!job.validate().empty()) state.SkipWithError(job.validate().c_str());
  for (auto _ : state) {
    job.run();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["vertices"] = static_cast<double>(pts.size());
  countNsPerVertex(state, pts.size());
}
BENCHMARK(BM_SceneDeformationWithStack)->Unit(benchmark::kMicrosecond);

}  // namespace
