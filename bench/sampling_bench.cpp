// Clip sampling throughput: 64 joints, each with a translation and a rotation channel of
// 1,000 keys (30 keys per second, a random walk of a few degrees per key like motion capture). "ns_per_joint" is wall time per joint per sample (both
// channels). Playback samples consecutive 60 fps frames through a SamplingCache; random
// access samples shuffled times without one (binary search). The "Job" variants sample the
// same clips through PlaybackSamplingJob on a PlaybackClip built once before timing (one
// context, in playback and at random times). Reference point: ozz-animation samples about
// 12 ns per joint in playback and 54 ns per joint at random times. The "RotationNoise" variant
// puts a noise modifier on every rotation channel (channel modifiers, anim/channel_modifier.h).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <vector>

#include "anim/playback_sampling_job.h"
#include "anim/sampling.h"

namespace {

using namespace kinema;

constexpr int kJoints = 64;
constexpr int kKeys = 1000;
constexpr float kKeyStep = 1.0f / 30.0f;

Clip makeClip(Interpolation vectorMode, Interpolation rotationMode, bool perKeySettings) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  Clip clip;
  for (int j = 0; j < kJoints; ++j) {
    Channel t(j, ChannelTarget::Translation, vectorMode, {}, {});
    Channel r(j, ChannelTarget::Rotation, rotationMode, {}, {});
    // Motion-capture-like keys: a random walk of a few degrees and centimetres per key.
    glm::vec3 p(unit(rng), unit(rng), unit(rng));
    glm::quat q = glm::normalize(glm::quat(unit(rng) + 2.0f, unit(rng), unit(rng), unit(rng)));
    for (int k = 0; k < kKeys; ++k) {
      const float time = k * kKeyStep;
      t.times.push_back(time);
      r.times.push_back(time);
      p += 0.02f * glm::vec3(unit(rng), unit(rng), unit(rng));
      q = glm::normalize(q * glm::quat(1.0f, 0.03f * unit(rng), 0.03f * unit(rng), 0.03f * unit(rng)));
      t.values.emplace_back(p, 0.0f);
      r.values.emplace_back(q.x, q.y, q.z, q.w);
    }
    if (perKeySettings) {
      KeySettings st, sr;
      st.interpolation = vectorMode;
      sr.interpolation = rotationMode;
      t.keys.assign(kKeys, st);
      r.keys.assign(kKeys, sr);
    }
    clip.channels.push_back(std::move(t));
    clip.channels.push_back(std::move(r));
  }
  return clip;
}

Skeleton makeSkeleton() {
  Skeleton s;
  for (int j = 0; j < kJoints; ++j) s.addJoint("j" + std::to_string(j), j - 1, Transform());
  return s;
}

void report(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kJoints);
  // Seconds per joint, printed with an SI prefix ("12.3n" = 12.3 ns).
  state.counters["ns_per_joint"] =
      benchmark::Counter(kJoints, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void run(benchmark::State& state, const Clip& clip, bool playback, bool job = false) {
  const Skeleton s = makeSkeleton();
  Pose pose = Pose::rest(s);
  const float duration = clip.duration();
  std::vector<float> times;
  if (playback) {
    for (float t = 0.0f; t <= duration; t += 1.0f / 60.0f) times.push_back(t);
  } else {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> any(0.0f, duration);
    for (int i = 0; i < 4096; ++i) times.push_back(any(rng));
  }
  SamplingCache cache;
  const PlaybackClip fast = job ? PlaybackClip::build(clip, kJoints) : PlaybackClip();
  PlaybackContext context;
  size_t i = 0;
  for (auto _ : state) {
    if (job) {
      samplePlayback(fast, times[i], pose, context);
    } else if (playback) {
      sampleClip(clip, times[i], pose, cache);
    } else {
      sampleClip(clip, times[i], pose);
    }
    benchmark::DoNotOptimize(pose.local.data());
    benchmark::ClobberMemory();
    if (++i == times.size()) i = 0;
  }
  report(state);
}

void BM_Playback_Linear(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Linear, Interpolation::Linear, false);
  run(state, clip, true);
}
void BM_RandomAccess_Linear(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Linear, Interpolation::Linear, false);
  run(state, clip, false);
}
void BM_Playback_CatmullRom_Squad(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::CatmullRom, Interpolation::Squad, true);
  run(state, clip, true);
}
void BM_RandomAccess_CatmullRom_Squad(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::CatmullRom, Interpolation::Squad, true);
  run(state, clip, false);
}
void BM_Playback_Bezier_Slerp(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Bezier, Interpolation::Linear, true);
  run(state, clip, true);
}
void BM_RandomAccess_Bezier_Slerp(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Bezier, Interpolation::Linear, true);
  run(state, clip, false);
}
void BM_Playback_Linear_Job(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Linear, Interpolation::Linear, false);
  run(state, clip, true, true);
}
void BM_RandomAccess_Linear_Job(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Linear, Interpolation::Linear, false);
  run(state, clip, false, true);
}
void BM_Playback_CatmullRom_Squad_Job(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::CatmullRom, Interpolation::Squad, true);
  run(state, clip, true, true);
}
void BM_RandomAccess_CatmullRom_Squad_Job(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::CatmullRom, Interpolation::Squad, true);
  run(state, clip, false, true);
}
void BM_Playback_Bezier_Slerp_Job(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Bezier, Interpolation::Linear, true);
  run(state, clip, true, true);
}
void BM_RandomAccess_Bezier_Slerp_Job(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Bezier, Interpolation::Linear, true);
  run(state, clip, false, true);
}
// The linear clip with a two-octave noise modifier on every rotation (a procedural sway):
// what channel modifiers cost, their channels sampled one by one through the stack.
Clip withNoise(Clip clip) {
  ChannelModifier noise;
  noise.kind = ChannelModifierKind::Noise;
  noise.noise.strength = 0.05f;
  noise.noise.scale = 0.5f;
  noise.noise.octaves = 2;
  for (Channel& ch : clip.channels)
    if (ch.target == ChannelTarget::Rotation) ch.modifiers = {noise};
  return clip;
}
void BM_Playback_Linear_RotationNoise_Job(benchmark::State& state) {
  static const Clip clip = withNoise(makeClip(Interpolation::Linear, Interpolation::Linear, false));
  run(state, clip, true, true);
}
// Building the PlaybackClip of the linear clip (once per clip, and in the editor again after
// an edit made while it plays): time per build, ns_per_joint per joint.
void BM_BuildPlaybackClip_Linear(benchmark::State& state) {
  static const Clip clip = makeClip(Interpolation::Linear, Interpolation::Linear, false);
  for (auto _ : state) {
    PlaybackClip p = PlaybackClip::build(clip, kJoints);
    benchmark::DoNotOptimize(p.grids.data());
  }
  report(state);
}

BENCHMARK(BM_Playback_Linear);
BENCHMARK(BM_RandomAccess_Linear);
BENCHMARK(BM_Playback_CatmullRom_Squad);
BENCHMARK(BM_RandomAccess_CatmullRom_Squad);
BENCHMARK(BM_Playback_Bezier_Slerp);
BENCHMARK(BM_RandomAccess_Bezier_Slerp);
BENCHMARK(BM_Playback_Linear_Job);
BENCHMARK(BM_RandomAccess_Linear_Job);
BENCHMARK(BM_Playback_CatmullRom_Squad_Job);
BENCHMARK(BM_RandomAccess_CatmullRom_Squad_Job);
BENCHMARK(BM_Playback_Bezier_Slerp_Job);
BENCHMARK(BM_RandomAccess_Bezier_Slerp_Job);
BENCHMARK(BM_Playback_Linear_RotationNoise_Job);
BENCHMARK(BM_BuildPlaybackClip_Linear);

}  // namespace
