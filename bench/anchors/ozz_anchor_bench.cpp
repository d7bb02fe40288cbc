// Kinema beside ozz-animation 0.16.0 on the same data, in one run: each row first checks that
// both sides compute the same answer, then times them in alternating rounds (CPU time,
// median; anchor_timing.h). Prints a Markdown table, ratio = Kinema / ozz (lower is faster).
//   ./build/bench/anchors/ozz_anchor_bench            (every row)
//   ./build/bench/anchors/ozz_anchor_bench sampling   (rows whose name contains "sampling")
// Instructions per 64-joint playback sample, both sides:
//   valgrind --tool=callgrind --toggle-collect='*PlaybackLoop*'
//     ./build/bench/anchors/ozz_anchor_bench callgrind-playback   (one command line)
// (kinemaPlaybackLoop: sampleClip with a SamplingCache; kinemaJobPlaybackLoop:
// PlaybackSamplingJob on a PlaybackClip; ozzPlaybackLoop: ozz's SamplingJob.)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "anchor_timing.h"
#include "anim/playback_sampling_job.h"
#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "ik/ik_solver.h"
#include "ik/two_bone_job.h"
#include "ozz/animation/offline/animation_builder.h"
#include "ozz/animation/offline/raw_animation.h"
#include "ozz/animation/offline/raw_skeleton.h"
#include "ozz/animation/offline/skeleton_builder.h"
#include "ozz/animation/runtime/animation.h"
#include "ozz/animation/runtime/ik_two_bone_job.h"
#include "ozz/animation/runtime/local_to_model_job.h"
#include "ozz/animation/runtime/sampling_job.h"
#include "ozz/animation/runtime/skeleton.h"
#include "ozz/base/maths/simd_math.h"
#include "ozz/base/maths/simd_quaternion.h"
#include "ozz/base/maths/soa_transform.h"
#include "ozz/base/span.h"
#include "ozz/geometry/runtime/skinning_job.h"
#include "skin/linear_blend_skinning.h"

namespace {

using namespace kinema;
using anchor::alternate;
using anchor::printRow;
namespace oz = ozz::animation;

int failures = 0;
void check(bool ok, const std::string& what) {
  if (!ok) {
    std::printf("MISMATCH: %s\n", what.c_str());
    ++failures;
  }
}

// ---------------------------------------------------------------- SoA and matrix access
float* lane(ozz::math::SimdFloat4& v) { return reinterpret_cast<float*>(&v); }
const float* lane(const ozz::math::SimdFloat4& v) { return reinterpret_cast<const float*>(&v); }

void setSoa(std::vector<ozz::math::SoaTransform>& soa, int j, const Transform& t) {
  ozz::math::SoaTransform& s = soa[j / 4];
  const int l = j % 4;
  lane(s.translation.x)[l] = t.translation.x;
  lane(s.translation.y)[l] = t.translation.y;
  lane(s.translation.z)[l] = t.translation.z;
  lane(s.rotation.x)[l] = t.rotation.x;
  lane(s.rotation.y)[l] = t.rotation.y;
  lane(s.rotation.z)[l] = t.rotation.z;
  lane(s.rotation.w)[l] = t.rotation.w;
  lane(s.scale.x)[l] = t.scale.x;
  lane(s.scale.y)[l] = t.scale.y;
  lane(s.scale.z)[l] = t.scale.z;
}

Transform getSoa(const std::vector<ozz::math::SoaTransform>& soa, int j) {
  const ozz::math::SoaTransform& s = soa[j / 4];
  const int l = j % 4;
  Transform t;
  t.translation = {lane(s.translation.x)[l], lane(s.translation.y)[l], lane(s.translation.z)[l]};
  t.rotation = glm::quat(lane(s.rotation.w)[l], lane(s.rotation.x)[l], lane(s.rotation.y)[l], lane(s.rotation.z)[l]);
  t.scale = {lane(s.scale.x)[l], lane(s.scale.y)[l], lane(s.scale.z)[l]};
  return t;
}

ozz::math::Float4x4 toOzz(const glm::mat4& m) {
  ozz::math::Float4x4 o;
  for (int c = 0; c < 4; ++c) o.cols[c] = ozz::math::simd_float4::Load(m[c].x, m[c].y, m[c].z, m[c].w);
  return o;
}
glm::mat4 fromOzz(const ozz::math::Float4x4& o) {
  glm::mat4 m;
  for (int c = 0; c < 4; ++c) std::memcpy(&m[c], &o.cols[c], sizeof(float) * 4);
  return m;
}
glm::quat fromOzz(const ozz::math::SimdQuaternion& q) {
  float v[4];
  std::memcpy(v, &q.xyzw, sizeof v);
  return glm::quat(v[3], v[0], v[1], v[2]);
}

float maxDiff(const glm::mat4& a, const glm::mat4& b) {
  float d = 0.0f;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  return d;
}
// Angle between two rotations (radians).
float angleBetween(const glm::quat& a, const glm::quat& b) {
  return 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(glm::normalize(a), glm::normalize(b)))));
}

// ---------------------------------------------------------------- skeletons
// A random tree of `joints` joints (each parent a random earlier joint, mostly the previous
// one), built in ozz first so that both sides use ozz's depth-first joint order.
struct TwinSkeleton {
  ozz::unique_ptr<oz::Skeleton> ozz;
  Skeleton kinema;
};

TwinSkeleton randomSkeleton(int joints, std::mt19937& rng) {
  std::uniform_real_distribution<float> coin(0.0f, 1.0f);
  std::vector<int> parent(joints, -1);
  for (int i = 1; i < joints; ++i)
    parent[i] = coin(rng) < 0.6f ? i - 1 : std::uniform_int_distribution<int>(0, i - 1)(rng);
  oz::offline::RawSkeleton raw;
  std::vector<oz::offline::RawSkeleton::Joint*> at(joints, nullptr);
  // Children lists are filled before any pointer into them is taken (reserve).
  std::vector<std::vector<int>> children(joints);
  for (int i = 1; i < joints; ++i) children[parent[i]].push_back(i);
  raw.roots.resize(1);
  std::vector<std::pair<oz::offline::RawSkeleton::Joint*, int>> stack{{&raw.roots[0], 0}};
  while (!stack.empty()) {
    auto [node, i] = stack.back();
    stack.pop_back();
    node->name = "j" + std::to_string(i);
    node->transform = ozz::math::Transform::identity();
    node->children.resize(children[i].size());
    for (size_t c = 0; c < children[i].size(); ++c) stack.push_back({&node->children[c], children[i][c]});
  }
  oz::offline::SkeletonBuilder builder;
  TwinSkeleton t;
  t.ozz = builder(raw);
  const auto parents = t.ozz->joint_parents();
  for (int i = 0; i < joints; ++i) t.kinema.addJoint("j" + std::to_string(i), parents[i], Transform());
  return t;
}

Transform randomTransform(std::mt19937& rng, bool scaled) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Transform t;
  t.translation = glm::vec3(u(rng), u(rng), u(rng));
  t.rotation = glm::normalize(glm::quat(u(rng) + 2.0f, u(rng), u(rng), u(rng)));
  if (scaled) t.scale = glm::vec3(1.0f + 0.1f * u(rng), 1.0f + 0.1f * u(rng), 1.0f + 0.1f * u(rng));
  return t;
}

// ---------------------------------------------------------------- FK
void fk() {
  constexpr int kCount = 1000, kJoints = 64;
  std::mt19937 rng(1234);
  TwinSkeleton s = randomSkeleton(kJoints, rng);
  std::vector<Pose> poses(kCount, Pose::rest(s.kinema));
  std::vector<std::vector<ozz::math::SoaTransform>> soa(kCount, std::vector<ozz::math::SoaTransform>(kJoints / 4));
  for (int i = 0; i < kCount; ++i)
    for (int j = 0; j < kJoints; ++j) {
      poses[i].local[j] = randomTransform(rng, true);
      setSoa(soa[i], j, poses[i].local[j]);
    }
  std::vector<std::vector<glm::mat4>> world(kCount, std::vector<glm::mat4>(kJoints));
  std::vector<std::vector<ozz::math::Float4x4>> models(kCount, std::vector<ozz::math::Float4x4>(kJoints));
  auto kin = [&] {
    for (int i = 0; i < kCount; ++i) {
      LocalToWorldJob job;
      job.parents = s.kinema.parents.data();
      job.local = poses[i].local.data();
      job.world = world[i].data();
      job.count = kJoints;
      job.run();
    }
  };
  auto ozzSide = [&] {
    for (int i = 0; i < kCount; ++i) {
      oz::LocalToModelJob job;
      job.skeleton = s.ozz.get();
      job.input = ozz::make_span(soa[i]);
      job.output = ozz::make_span(models[i]);
      job.Run();
    }
  };
  kin();
  ozzSide();
  float d = 0.0f;
  for (int i = 0; i < kCount; ++i)
    for (int j = 0; j < kJoints; ++j) d = std::max(d, maxDiff(world[i][j], fromOzz(models[i][j])));
  check(d < 1e-4f, "FK: world matrices differ by " + std::to_string(d));
  printRow("FK, 1,000 skeletons x 64 joints", alternate(kin, ozzSide, kCount * kJoints), "ns/joint",
           "ozz `LocalToModelJob`");
}

// ---------------------------------------------------------------- clip sampling
// 64 (or more) joints, each a translation and a rotation track of `keys` keys, 30 keys per
// second, a motion-capture-like random walk (bench/sampling_bench.cpp's clip).
struct TwinClip {
  Clip kinema;
  ozz::unique_ptr<oz::Animation> ozz;
  Skeleton skeleton;
};

// iframeInterval: seconds between ozz's seek points (0: the builder's default; < 0: no ozz
// animation, Kinema's clip only).
TwinClip makeClip(int joints, int keys, float iframeInterval) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  constexpr float kKeyStep = 1.0f / 30.0f;
  TwinClip c;
  oz::offline::RawAnimation raw;
  raw.duration = (keys - 1) * kKeyStep;
  const bool withOzz = iframeInterval >= 0.0f;
  raw.tracks.resize(withOzz ? joints : 0);
  for (int j = 0; j < joints; ++j) {
    Channel t(j, ChannelTarget::Translation, Interpolation::Linear, {}, {});
    Channel r(j, ChannelTarget::Rotation, Interpolation::Linear, {}, {});
    glm::vec3 p(u(rng), u(rng), u(rng));
    glm::quat q = glm::normalize(glm::quat(u(rng) + 2.0f, u(rng), u(rng), u(rng)));
    for (int k = 0; k < keys; ++k) {
      const float time = k * kKeyStep;
      p += 0.02f * glm::vec3(u(rng), u(rng), u(rng));
      q = glm::normalize(q * glm::quat(1.0f, 0.03f * u(rng), 0.03f * u(rng), 0.03f * u(rng)));
      t.times.push_back(time);
      r.times.push_back(time);
      t.values.emplace_back(p, 0.0f);
      r.values.emplace_back(q.x, q.y, q.z, q.w);
      if (!withOzz) continue;
      raw.tracks[j].translations.push_back({time, ozz::math::Float3(p.x, p.y, p.z)});
      raw.tracks[j].rotations.push_back({time, ozz::math::Quaternion(q.x, q.y, q.z, q.w)});
    }
    c.kinema.channels.push_back(std::move(t));
    c.kinema.channels.push_back(std::move(r));
    c.skeleton.addJoint("j" + std::to_string(j), j - 1, Transform());
  }
  if (!withOzz) return c;
  oz::offline::AnimationBuilder builder;
  if (iframeInterval > 0.0f) builder.iframe_interval = iframeInterval;
  c.ozz = builder(raw);
  return c;
}

// Both sides at the same times: translations within ozz's half-float keys, rotations within
// its 16-bit keys and nlerp (Kinema slerps).
template <class Sample>
void checkSamples(const TwinClip& c, const std::vector<float>& times, int joints, const std::string& row,
                  Sample&& sample) {
  Pose pose = Pose::rest(c.skeleton);
  std::vector<ozz::math::SoaTransform> soa((joints + 3) / 4);
  oz::SamplingJob::Context context(joints);
  float dt = 0.0f, dr = 0.0f;
  for (size_t i = 0; i < times.size() && i < 600; ++i) {
    sample(times[i], pose);
    oz::SamplingJob job;
    job.animation = c.ozz.get();
    job.context = &context;
    job.ratio = times[i] / c.ozz->duration();
    job.output = ozz::make_span(soa);
    if (!job.Run()) check(false, row + ": ozz SamplingJob refused its inputs");
    for (int j = 0; j < joints; ++j) {
      const Transform o = getSoa(soa, j);
      dt = std::max(dt, glm::length(o.translation - pose.local[j].translation));
      dr = std::max(dr, angleBetween(o.rotation, pose.local[j].rotation));
    }
  }
  check(dt < 5e-3f && dr < 2e-3f, row + ": translation differs by " + std::to_string(dt) + ", rotation by " +
                                      std::to_string(dr) + " rad");
}

double randomAt64[2] = {0.0, 0.0};  // Kinema's random-access figure at 64 joints (ns/joint), per path

// ozz builds at most 1,024 joints (Skeleton::kMaxJoints): beyond that Kinema runs alone and
// the row shows its growth from 64 joints. `viaJob`: Kinema samples through PlaybackSamplingJob
// on a PlaybackClip built once from the clip (built before timing, as ozz's Animation is);
// otherwise through sampleClip (with a SamplingCache in playback).
void sampling(int joints, bool playback, bool viaJob) {
  constexpr int kKeys = 1000;
  const bool withOzz = joints <= 1024;
  const TwinClip c = makeClip(joints, kKeys, !withOzz ? -1.0f : playback ? 0.0f : 1.0f);
  const PlaybackClip fast = viaJob ? PlaybackClip::build(c.kinema, joints) : PlaybackClip();
  const float duration = c.kinema.duration();
  std::vector<float> times;
  if (playback) {
    for (float t = 0.0f; t <= duration; t += 1.0f / 60.0f) times.push_back(t);
  } else {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> any(0.0f, duration);
    for (int i = 0; i < 4096; ++i) times.push_back(any(rng));
  }
  const std::string path = viaJob ? "`PlaybackSamplingJob`" : "`sampleClip`";
  const std::string row = playback ? "clip sampling, playback (" + std::to_string(joints) +
                                         " joints x 1,000 keys, 1/60 s steps), " + path
                                   : "clip sampling, random times, " + std::to_string(joints) + " joints x 1,000 keys, " + path;
  Pose pose = Pose::rest(c.skeleton);
  SamplingCache cache;
  PlaybackContext playbackContext;
  auto sampleKinema = [&](float time, Pose& out) {
    if (viaJob)
      samplePlayback(fast, time, out, playbackContext);
    else if (playback)
      sampleClip(c.kinema, time, out, cache);
    else
      sampleClip(c.kinema, time, out);
  };
  if (withOzz) checkSamples(c, times, joints, row, sampleKinema);
  std::vector<ozz::math::SoaTransform> soa((joints + 3) / 4);
  oz::SamplingJob::Context context(withOzz ? joints : 4);
  size_t ik = 0, io = 0;
  auto kin = [&] {
    sampleKinema(times[ik], pose);
    if (++ik == times.size()) ik = 0;
  };
  auto ozzSide = [&] {
    oz::SamplingJob job;
    job.animation = c.ozz.get();
    job.context = &context;
    job.ratio = times[io] / duration;
    job.output = ozz::make_span(soa);
    job.Run();
    if (++io == times.size()) io = 0;
  };
  if (!withOzz) {
    const anchor::SideBySide r = alternate(kin, kin, joints);
    std::printf("| %s | %.3g ns/joint | (ozz: at most 1,024 joints) | %.2fx Kinema at 64 joints |\n", row.c_str(),
                r.kinema, r.kinema / randomAt64[viaJob]);
    return;
  }
  const anchor::SideBySide r = alternate(kin, ozzSide, joints);
  if (!playback && joints == 64) randomAt64[viaJob] = r.kinema;
  printRow(row, r, "ns/joint", playback ? "ozz `SamplingJob`" : "ozz `SamplingJob`, 1 s iframes,");
}

// For callgrind (--toggle-collect='*PlaybackLoop*'): `count` playback samples of each side.
__attribute__((noinline)) void kinemaPlaybackLoop(const Clip& clip, Pose& pose, SamplingCache& cache, int count) {
  for (int i = 0; i < count; ++i) sampleClip(clip, i / 60.0f, pose, cache);
}
__attribute__((noinline)) void kinemaJobPlaybackLoop(const PlaybackClip& clip, Pose& pose, PlaybackContext& context,
                                                     int count) {
  for (int i = 0; i < count; ++i) samplePlayback(clip, i / 60.0f, pose, context);
}
__attribute__((noinline)) void ozzPlaybackLoop(const oz::Animation& animation, oz::SamplingJob::Context& context,
                                               std::vector<ozz::math::SoaTransform>& soa, int count) {
  for (int i = 0; i < count; ++i) {
    oz::SamplingJob job;
    job.animation = &animation;
    job.context = &context;
    job.ratio = i / 60.0f / animation.duration();
    job.output = ozz::make_span(soa);
    job.Run();
  }
}
// For callgrind (--toggle-collect='*twoBoneLoop*'): the whole two-bone solveIk path.
__attribute__((noinline)) void twoBoneLoop(IkProblem& problem, Pose& pose, const std::vector<Pose>& starts,
                                           const std::vector<glm::vec3>& targets) {
  IkSettings settings;
  for (size_t k = 0; k < starts.size(); ++k) {
    pose = starts[k];
    problem.pose = &pose;
    problem.targets[0].position = targets[k];
    solveIk(IkSolver::TwoBone, problem, settings);
  }
}
void callgrindTwoBone() {
  Skeleton s;
  for (int i = 0; i < 3; ++i)
    s.addJoint("j" + std::to_string(i), i - 1, Transform::fromTranslation(glm::vec3(0.0f, i == 0 ? 0.0f : 1.0f, 0.0f)));
  std::vector<Pose> starts(1000, Pose::rest(s));
  std::vector<glm::vec3> targets(1000, glm::vec3(0.5f, 1.2f, 0.3f));
  IkProblem problem;
  problem.skeleton = &s;
  problem.targets.resize(1);
  problem.targets[0].effector = 2;
  Pose pose;
  twoBoneLoop(problem, pose, starts, targets);
  std::printf("ran 1,000 two-bone solveIk calls: instructions / 1,000 = per solve\n");
}

void callgrindPlayback() {
  const TwinClip c = makeClip(64, 1000, 0.0f);
  Pose pose = Pose::rest(c.skeleton);
  SamplingCache cache;
  std::vector<ozz::math::SoaTransform> soa(16);
  oz::SamplingJob::Context context(64);
  kinemaPlaybackLoop(c.kinema, pose, cache, 1000);
  const PlaybackClip fast = PlaybackClip::build(c.kinema, 64);
  PlaybackContext playbackContext;
  kinemaJobPlaybackLoop(fast, pose, playbackContext, 1000);
  ozzPlaybackLoop(*c.ozz, context, soa, 1000);
  std::printf("ran 1,000 playback samples (64 joints) on each side (Kinema twice: sampleClip, then PlaybackSamplingJob): instructions / 1,000 = per sample\n");
}

// ---------------------------------------------------------------- skinning
void skinning() {
  constexpr int kVertices = 50000, kJoints = 64, kStride = 4;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.05f, 1.0f);
  std::vector<glm::mat4> matrices;
  std::vector<ozz::math::Float4x4> ozzMatrices;
  for (int j = 0; j < kJoints; ++j) {
    glm::mat4 m = glm::mat4_cast(glm::normalize(glm::quat(u(rng) + 2.0f, u(rng), u(rng), u(rng))));
    m[3] = glm::vec4(u(rng), u(rng), u(rng), 1.0f);
    matrices.push_back(m);
    ozzMatrices.push_back(toOzz(m));
  }
  std::vector<glm::vec3> positions, normals, outPositions(kVertices), outNormals(kVertices);
  std::vector<uint16_t> joints;
  std::vector<float> weights, ozzWeights;  // ozz: the first three of four (the last is 1 - sum)
  for (int v = 0; v < kVertices; ++v) {
    positions.emplace_back(u(rng), u(rng), u(rng));
    normals.push_back(glm::normalize(glm::vec3(u(rng), u(rng), u(rng) + 2.0f)));
    float w[kStride], sum = 0.0f;
    for (float& x : w) sum += x = pos(rng);
    std::sort(w, w + kStride, [](float a, float b) { return a > b; });
    const int base = v * kJoints / kVertices;
    for (int k = 0; k < kStride; ++k) {
      joints.push_back(static_cast<uint16_t>((base + k * 3) % kJoints));
      weights.push_back(w[k] / sum);
      if (k < kStride - 1) ozzWeights.push_back(w[k] / sum);
    }
  }
  std::vector<glm::vec3> ozzPositions(kVertices), ozzNormals(kVertices);
  LinearBlendSkinningJob job;
  job.positions = positions.data();
  job.normals = normals.data();
  job.vertexCount = kVertices;
  job.influenceJoints = joints.data();
  job.influenceWeights = weights.data();
  job.influencesPerVertex = kStride;
  job.jointMatrices = matrices.data();
  job.jointCount = kJoints;
  job.outPositions = outPositions.data();
  job.outNormals = outNormals.data();
  ozz::geometry::SkinningJob oj;
  oj.vertex_count = kVertices;
  oj.influences_count = kStride;
  oj.joint_matrices = ozz::make_span(ozzMatrices);
  oj.joint_indices = ozz::make_span(joints);
  oj.joint_indices_stride = sizeof(uint16_t) * kStride;
  oj.joint_weights = ozz::make_span(ozzWeights);
  oj.joint_weights_stride = sizeof(float) * (kStride - 1);
  oj.in_positions = {&positions[0].x, kVertices * 3};
  oj.in_positions_stride = sizeof(glm::vec3);
  oj.in_normals = {&normals[0].x, kVertices * 3};
  oj.in_normals_stride = sizeof(glm::vec3);
  oj.out_positions = {&ozzPositions[0].x, kVertices * 3};
  oj.out_positions_stride = sizeof(glm::vec3);
  oj.out_normals = {&ozzNormals[0].x, kVertices * 3};
  oj.out_normals_stride = sizeof(glm::vec3);
  check(job.run(), "skinning: Kinema's job refused its inputs");
  check(oj.Run(), "skinning: ozz's job refused its inputs");
  float dp = 0.0f, dn = 0.0f;
  for (int v = 0; v < kVertices; ++v) {
    dp = std::max(dp, glm::length(outPositions[v] - ozzPositions[v]));
    dn = std::max(dn, glm::length(outNormals[v] - glm::normalize(ozzNormals[v])));  // ozz leaves them unnormalised
  }
  check(dp < 1e-4f && dn < 1e-4f, "skinning: positions differ by " + std::to_string(dp) + ", normals by " +
                                      std::to_string(dn));
  printRow("skinning 50k vertices x 4, positions + normals", alternate([&] { job.run(); }, [&] { oj.Run(); }, kVertices),
           "ns/vertex", "ozz `SkinningJob`");
}

// ---------------------------------------------------------------- two-bone IK
// bench/ik_bench.cpp's arm: three joints along +Y (unit bones), start poses with each joint
// turned up to 0.6 rad about a random axis, reachable targets from FK of other such poses.
void twoBone() {
  constexpr int kCases = 1000;
  Skeleton s;
  for (int i = 0; i < 3; ++i)
    s.addJoint("j" + std::to_string(i), i - 1, Transform::fromTranslation(glm::vec3(0.0f, i == 0 ? 0.0f : 1.0f, 0.0f)));
  std::mt19937 rng(2011);
  auto randomPose = [&] {
    std::normal_distribution<float> g(0.0f, 1.0f);
    std::uniform_real_distribution<float> a(0.0f, 0.6f);
    Pose p = Pose::rest(s);
    for (Transform& t : p.local) t.rotation = glm::angleAxis(a(rng), glm::normalize(glm::vec3(g(rng), g(rng), g(rng))));
    return p;
  };
  std::vector<Pose> starts;
  std::vector<glm::vec3> targets;
  for (int k = 0; k < kCases; ++k) {
    starts.push_back(randomPose());
    targets.push_back(glm::vec3(computeWorld(s, randomPose())[2][3]));
  }
  glm::quat startCorrection, midCorrection;
  bool reached = false;
  std::vector<TwoBoneIkJob> jobs(kCases);
  struct OzzCase {
    ozz::math::Float4x4 start, mid, end;
    ozz::math::SimdFloat4 target, midAxis, pole;
  };
  std::vector<OzzCase> ozzCases(kCases);
  ozz::math::SimdQuaternion ozzStartCorrection, ozzMidCorrection;
  bool ozzReached = false;
  // Where the end joint lands once the local corrections are applied (model space).
  auto endAfter = [](const std::vector<glm::mat4>& w, const glm::quat& cs, const glm::quat& cm) {
    const glm::quat rs = glm::quat_cast(glm::mat3(w[0])), rm = glm::quat_cast(glm::mat3(w[1]));
    const glm::vec3 ps(w[0][3]), pm(w[1][3]), pe(w[2][3]);
    const glm::quat d1 = rs * cs * glm::conjugate(rs);
    const glm::vec3 pm2 = ps + d1 * (pm - ps);
    const glm::quat d2 = (d1 * rm * cm) * glm::conjugate(rm);
    return pm2 + d2 * (pe - pm);
  };
  float worst = 0.0f;
  int reachedBoth = 0;
  for (int k = 0; k < kCases; ++k) {
    const std::vector<glm::mat4> w = computeWorld(s, starts[k]);
    TwoBoneIkJob& job = jobs[k];
    job.startPosition = glm::vec3(w[0][3]);
    job.startRotation = glm::normalize(glm::quat_cast(glm::mat3(w[0])));
    job.midPosition = glm::vec3(w[1][3]);
    job.midRotation = glm::normalize(glm::quat_cast(glm::mat3(w[1])));
    job.endPosition = glm::vec3(w[2][3]);
    job.target = targets[k];
    job.startCorrection = &startCorrection;
    job.midCorrection = &midCorrection;
    job.reached = &reached;
    OzzCase& o = ozzCases[k];
    o.start = toOzz(w[0]);
    o.mid = toOzz(w[1]);
    o.end = toOzz(w[2]);
    o.target = ozz::math::simd_float4::Load(targets[k].x, targets[k].y, targets[k].z, 1.0f);
    // The hinge: the axis that opens the angle at the mid joint, in its local space; the
    // pole: the side the mid joint is on now (what Kinema's job does without a pole).
    const glm::vec3 a = job.midPosition - job.startPosition, b = job.endPosition - job.midPosition;
    const glm::vec3 axis = glm::inverse(job.midRotation) * glm::normalize(glm::cross(b, a));
    o.midAxis = ozz::math::simd_float4::Load(axis.x, axis.y, axis.z, 0.0f);
    const glm::vec3 toTarget = glm::normalize(targets[k] - job.startPosition);
    const glm::vec3 pole = glm::normalize(a - glm::dot(a, toTarget) * toTarget);
    o.pole = ozz::math::simd_float4::Load(pole.x, pole.y, pole.z, 0.0f);
    check(job.run(), "two-bone: Kinema's job refused case " + std::to_string(k));
    oz::IKTwoBoneJob oj;
    oj.target = o.target;
    oj.mid_axis = o.midAxis;
    oj.pole_vector = o.pole;
    oj.start_joint = &o.start;
    oj.mid_joint = &o.mid;
    oj.end_joint = &o.end;
    oj.start_joint_correction = &ozzStartCorrection;
    oj.mid_joint_correction = &ozzMidCorrection;
    oj.reached = &ozzReached;
    check(oj.Run(), "two-bone: ozz's job refused case " + std::to_string(k));
    if (reached && ozzReached) {
      ++reachedBoth;
      worst = std::max(worst, glm::length(endAfter(w, startCorrection, midCorrection) - targets[k]));
      worst = std::max(worst, glm::length(endAfter(w, fromOzz(ozzStartCorrection), fromOzz(ozzMidCorrection)) - targets[k]));
    }
  }
  check(reachedBoth > kCases * 9 / 10 && worst < 1e-3f, "two-bone: " + std::to_string(reachedBoth) +
                                                            " cases reached by both, end off target by " +
                                                            std::to_string(worst));
  int ko = 0, kk = 0, kf = 0;
  auto ozzSide = [&] {
    const OzzCase& o = ozzCases[ko];
    oz::IKTwoBoneJob oj;
    oj.target = o.target;
    oj.mid_axis = o.midAxis;
    oj.pole_vector = o.pole;
    oj.start_joint = &o.start;
    oj.mid_joint = &o.mid;
    oj.end_joint = &o.end;
    oj.start_joint_correction = &ozzStartCorrection;
    oj.mid_joint_correction = &ozzMidCorrection;
    oj.reached = &ozzReached;
    oj.Run();
    ko = (ko + 1) % kCases;
  };
  printRow("two-bone: the job", alternate([&] { jobs[kk].run(); kk = (kk + 1) % kCases; }, ozzSide, 1), "ns",
           "ozz `IKTwoBoneJob`");
  // The whole path an editor drag takes: validate, FK of the chain, the job, corrections.
  IkProblem problem;
  problem.skeleton = &s;
  problem.targets.resize(1);
  problem.targets[0].effector = 2;
  IkSettings settings;
  Pose pose;
  auto full = [&] {
    pose = starts[kf];
    problem.pose = &pose;
    problem.targets[0].position = targets[kf];
    solveIk(IkSolver::TwoBone, problem, settings);
    kf = (kf + 1) % kCases;
  };
  printRow("two-bone: the whole `solveIk` path", alternate(full, ozzSide, 1), "ns", "ozz `IKTwoBoneJob`");
}

}  // namespace

int main(int argc, char** argv) {
  const std::string only = argc > 1 ? argv[1] : "";
  if (only == "callgrind-playback") {
    callgrindPlayback();
    return 0;
  }
  if (only == "callgrind-two-bone") {
    callgrindTwoBone();
    return 0;
  }
  auto want = [&](const char* name) { return only.empty() || std::string(name).find(only) != std::string::npos; };
  anchor::printHeader("Kinema beside ozz-animation 0.16.0 (CPU time per item, median of 11 alternating rounds)");
  if (want("fk")) fk();
  // Each sampling row twice: sampleClip (the Clip as edited), then PlaybackSamplingJob.
  if (want("sampling-playback"))
    for (bool job : {false, true}) sampling(64, true, job);
  if (want("sampling-random"))
    for (int joints : {64, 1024, 10000})
      for (bool job : {false, true}) sampling(joints, false, job);
  if (want("skinning")) skinning();
  if (want("two-bone")) twoBone();
  if (failures) std::printf("%d comparison(s) did not match: the figures above are not comparable\n", failures);
  return failures ? 1 : 0;
}
