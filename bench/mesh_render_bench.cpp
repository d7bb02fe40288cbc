// GPU frame time of shaded skinned meshes on the headless EGL context (Mesa llvmpipe on a
// machine without a GPU; LIBGL_ALWAYS_SOFTWARE=1 forces it elsewhere): one 1280x800 frame,
// 4x MSAA where offered, grid + skinned mesh + bones, finished with glFinish (no read-back).
// Wall time is the figure (llvmpipe renders on its own threads, so CPU time says little).
// The pose changes every frame (60 precomputed poses over the clip), so every frame uploads
// the skinning matrices as a real animation would.
//   ./build/bench/mesh_render_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/forward_kinematics.h"
#include "render/gl_context.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"
#include "render/skeleton_renderer.h"
#include "render/skeleton_view.h"
#include "scene/default_character_scene.h"
#include "io/scene_files.h"

namespace {

using namespace kinema;

constexpr int kWidth = 1280, kHeight = 800;

void drawFrames(benchmark::State& state, const Scene& scene, const std::vector<std::vector<glm::mat4>>& worlds) {
  Result<std::unique_ptr<HeadlessContext>> context = createEglContext();
  if (!context) {
    state.SkipWithError(context.error().c_str());
    return;
  }
  SkeletonRenderer renderer;
  MeshRenderer meshes;
  OffscreenTarget target;
  std::string error = renderer.init();
  if (error.empty()) error = meshes.init();
  if (error.empty()) error = meshes.upload(scene);
  if (error.empty()) error = target.create(kWidth, kHeight);
  if (!error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
  Bounds bounds;
  for (const std::vector<glm::mat4>& w : worlds)
    for (const glm::mat4& m : w) bounds.add(glm::vec3(m[3]));
  const std::vector<char> skinJoints = skinJointMask(scene);
  size_t k = 0;
  for (auto _ : state) {
    const std::vector<glm::mat4>& world = worlds[k++ % worlds.size()];
    SkeletonDrawList list;
    SkeletonDrawJob job;
    job.parents = &scene.skeleton.parents;
    job.world = &world;
    job.shownJoints = &skinJoints;
    job.run(list);
    MeshDraw draw;
    draw.renderer = &meshes;
    draw.frame.world = &world;
    FrameDescription frame;
    frame.skeleton = &list;
    frame.meshes = &draw;
    frame.camera = defaultCamera(bounds, float(kWidth) / kHeight);
    frame.width = kWidth;
    frame.height = kHeight;
    frame.sceneRadius = bounds.radius();
    target.bind();
    renderer.draw(frame);
    glFinish();
  }
  int triangles = 0;
  for (const MeshInstance& inst : scene.meshInstances)
    for (const MeshPrimitive& p : scene.meshes[inst.mesh].primitives) triangles += static_cast<int>(p.indices.size() / 3);
  state.counters["triangles"] = triangles;
  state.SetLabel(context.value()->description());
}

std::vector<std::vector<glm::mat4>> posesOverClip(const Scene& scene, int clip) {
  std::vector<std::vector<glm::mat4>> worlds;
  const float duration = clip < static_cast<int>(scene.clips.size()) ? scene.clips[clip].duration() : 0.0f;
  for (int i = 0; i < 60; ++i) {
    Pose pose = Pose::rest(scene.skeleton);
    if (clip < static_cast<int>(scene.clips.size())) sampleClip(scene.clips[clip], duration * i / 60.0f, pose);
    worlds.push_back(computeWorld(scene.skeleton, pose));
  }
  return worlds;
}

void fileBenchmark(benchmark::State& state, const char* relative, bool dualQuaternion) {
  Result<Scene> loaded = loadScene(std::string(KINEMA_SHARED_DATA_DIR) + "/" + relative);
  if (!loaded) {
    state.SkipWithError(loaded.error().c_str());
    return;
  }
  Scene scene = loaded.value();
  for (MeshInstance& inst : scene.meshInstances)
    inst.skinning = dualQuaternion ? SkinningMethod::DualQuaternion : SkinningMethod::LinearBlend;
  drawFrames(state, scene, posesOverClip(scene, 0));
}

void BM_FoxFrame(benchmark::State& state) { fileBenchmark(state, "gltf/Fox.glb", state.range(0) != 0); }
BENCHMARK(BM_FoxFrame)->Arg(0)->Arg(1)->ArgName("dqs")->Unit(benchmark::kMillisecond)->UseRealTime();
void BM_CesiumManFrame(benchmark::State& state) { fileBenchmark(state, "gltf/CesiumMan.glb", state.range(0) != 0); }
BENCHMARK(BM_CesiumManFrame)->Arg(0)->Arg(1)->ArgName("dqs")->Unit(benchmark::kMillisecond)->UseRealTime();

// The default character (makeDefaultCharacterScene) waving: elbows and knees bend through
// 60 poses, as `kinema render` and the editor draw it.
void BM_DefaultCharacterFrame(benchmark::State& state) {
  Scene scene = makeDefaultCharacterScene();
  for (MeshInstance& inst : scene.meshInstances)
    inst.skinning = state.range(0) != 0 ? SkinningMethod::DualQuaternion : SkinningMethod::LinearBlend;
  std::vector<std::vector<glm::mat4>> worlds;
  for (int i = 0; i < 60; ++i) {
    Pose pose = Pose::rest(scene.skeleton);
    const float a = glm::radians(80.0f) * std::sin(6.2831853f * i / 60.0f);
    const std::pair<const char*, glm::vec3> bends[] = {{"LowerArm.L", glm::vec3(0, -1, 0)}, {"LowerArm.R", glm::vec3(0, 1, 0)},
                                                       {"LowerLeg.L", glm::vec3(1, 0, 0)}, {"LowerLeg.R", glm::vec3(1, 0, 0)}};
    for (const auto& [joint, axis] : bends) {
      const int j = scene.skeleton.find(joint);
      if (j >= 0) pose.local[j].rotation = glm::angleAxis(std::abs(a), axis);  // elbows forward, knees back
    }
    worlds.push_back(computeWorld(scene.skeleton, pose));
  }
  drawFrames(state, scene, worlds);
}
BENCHMARK(BM_DefaultCharacterFrame)->Arg(0)->Arg(1)->ArgName("dqs")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
