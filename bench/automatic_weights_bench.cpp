// Automatic weights and the default body. Reports "time_per_vertex" for binding 50,000
// vertices (the default body's vertices repeated with small offsets) to the 27-joint
// default character, and the time to generate the whole default character scene.
#include <benchmark/benchmark.h>

#include <vector>

#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "skin/automatic_weights.h"
#include "skin/default_body_mesh.h"
#include "scene/default_character_scene.h"

namespace {

using namespace kinema;

void BM_AutomaticWeights(benchmark::State& state) {
  const Skeleton skeleton = makeDefaultCharacter();
  const std::vector<glm::mat4> world = computeWorld(skeleton, Pose::rest(skeleton));
  const MeshPrimitive body = makeDefaultBodyMesh();
  std::vector<glm::vec3> positions;
  for (int copy = 0; positions.size() < 50000; ++copy)
    for (size_t i = 0; i < body.positions.size() && positions.size() < 50000; ++i)
      positions.push_back(body.positions[i] + glm::vec3(0.0f, 0.0f, 0.001f * copy));
  std::vector<uint16_t> joints;
  std::vector<float> weights;
  AutomaticWeightsJob job;
  job.skeleton = &skeleton;
  job.bindWorld = &world;
  job.positions = &positions;
  job.method = static_cast<AutomaticWeightsMethod>(state.range(0));
  job.outJoints = &joints;
  job.outWeights = &weights;
  for (auto _ : state) {
    job.run();
    benchmark::DoNotOptimize(weights.data());
  }
  // Seconds per vertex, printed with an SI prefix (e.g. "1.1u" = 1.1 microseconds).
  state.counters["time_per_vertex"] = benchmark::Counter(
      static_cast<double>(positions.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
// 0 = Capsule, 1 = InverseDistance, 2 = Nearest
BENCHMARK(BM_AutomaticWeights)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_DefaultCharacterScene(benchmark::State& state) {
  for (auto _ : state) {
    Scene scene = makeDefaultCharacterScene();
    benchmark::DoNotOptimize(scene.meshes.data());
  }
}
BENCHMARK(BM_DefaultCharacterScene)->Unit(benchmark::kMillisecond);

}  // namespace
