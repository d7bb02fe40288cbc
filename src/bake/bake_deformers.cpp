#include "bake/bake_deformers.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "anim/sampling.h"
#include "anim/scalar_property.h"
#include "core/forward_kinematics.h"
#include "evaluation/scene_deformation.h"
#include "evaluation/scene_evaluation_job.h"
#include "skin/skinning_matrices.h"

namespace kinema {
namespace {

// One pose at which a shape is made: a clip's key time, or the rest pose (clip -1).
struct Shot {
  int clip = -1;
  float time = 0.0f;
};

// The scene through the pipeline at (clip, time), the rest pose for clip -1; the shapes are
// deltas between two evaluations of one pose, so the live chains (which would be simulated
// from the clip's start for every shot) are left out.
SceneEvaluationJob jobAt(const Scene& scene, int clip, double time, Pose& pose) {
  SceneEvaluationJob job;
  job.scene = &scene;
  job.clip = clip;
  job.time = time;
  job.stages.dynamics = false;
  job.pose = &pose;
  return job;
}

std::vector<glm::mat4> worldAt(const Scene& scene, int clip, double time) {
  Pose pose;
  std::vector<glm::mat4> world;
  SceneEvaluationJob job = jobAt(scene, clip, time, pose);
  job.world = &world;
  job.run();
  return world;
}

// Every instance x primitive of `scene` at (clip, time), with its deformers (`deform`) or
// without them; the scene's own sampled morph weights.
bool deformAt(const Scene& scene, int clip, double time, bool deform, std::vector<DeformedPrimitive>& out) {
  Pose pose;
  SceneEvaluationJob job = jobAt(scene, clip, time, pose);
  job.stages.deformers = deform;
  job.meshes = &out;
  return job.run();
}

// The linear part of vertex v's skinning at this pose (linear blend of the skin's matrices),
// or the joint's own for a rigid instance.
glm::mat3 vertexMatrix(const MeshPrimitive& prim, size_t v, bool skinned, const std::vector<glm::mat4>& skinning,
                       const glm::mat4& rigid) {
  if (!skinned) return glm::mat3(rigid);
  glm::mat3 a(0.0f);
  for (int k = 0; k < kMaxInfluences; ++k) {
    const float w = prim.influenceWeights[v * kMaxInfluences + k];
    if (w != 0.0f) a += w * glm::mat3(skinning[prim.influenceJoints[v * kMaxInfluences + k]]);
  }
  return a;
}

std::string timeText(double t) {
  std::ostringstream o;
  o << t;
  return o.str();
}

}  // namespace

std::string BakeDeformersJob::validate() const {
  if (!scene) return "BakeDeformersJob: no scene";
  if (!out) return "BakeDeformersJob: no output scene";
  if (!report) return "BakeDeformersJob: no report";
  if (maxSamplesPerClip < 1) return "BakeDeformersJob: maxSamplesPerClip must be at least 1";
  const std::vector<glm::mat4> world = worldAt(*scene, -1, 0.0);
  std::vector<DeformedPrimitive> unused;
  SceneDeformationJob job;
  job.scene = scene;
  job.world = &world;
  job.out = &unused;
  if (std::string e = job.validate(); !e.empty()) return e;
  for (size_t c = 0; c < scene->clips.size(); ++c)
    if (std::string e = scene->clips[c].validate(scene->skeleton); !e.empty()) return "clip " + std::to_string(c) + ": " + e;
  return "";
}

bool BakeDeformersJob::run() const {
  if (!validate().empty()) return false;
  const Scene& src = *scene;
  Scene baked = src;
  DeformerBakeReport rep;
  std::vector<char> bakedInstance(src.meshInstances.size(), 0);

  for (size_t i = 0; i < src.deformers.size(); ++i) {
    const DeformerStack& stack = src.deformers[i];
    if (stack.empty()) continue;
    const MeshInstance& inst = src.meshInstances[i];
    const std::string label = "mesh instance " + std::to_string(i) + " (joint '" + src.skeleton.names[inst.joint] + "')";
    if (std::none_of(stack.deformers.begin(), stack.deformers.end(), [](const Deformer& d) { return d.enabled; })) {
      rep.lines.push_back(label + ": every deformer is disabled; the stack is dropped");
      continue;
    }
    // The shots: the key times of this stack's channels, clip by clip; the rest pose when none.
    std::vector<Shot> shots;
    std::vector<std::vector<float>> keyTimes(src.clips.size());
    for (size_t c = 0; c < src.clips.size(); ++c) {
      std::vector<float>& times = keyTimes[c];
      for (const Channel& ch : src.clips[c].channels) {
        if (ch.target != ChannelTarget::Scalar || ch.joint != inst.joint) continue;
        const ScalarProperty property = parseScalarProperty(ch.property);
        if (property.kind != ScalarPropertyKind::DeformerParameter || !stack.find(property.deformer)) continue;
        times.insert(times.end(), ch.times.begin(), ch.times.end());
      }
      std::sort(times.begin(), times.end());
      times.erase(std::unique(times.begin(), times.end(), sameKeyTime), times.end());
      for (float t : times) shots.push_back({static_cast<int>(c), t});
    }
    const bool animated = !shots.empty();
    if (!animated) shots.push_back({-1, 0.0f});

    // The instance gets a mesh of its own when others show the same one.
    int m = inst.mesh;
    for (size_t j = 0; j < baked.meshInstances.size(); ++j)
      if (j != i && baked.meshInstances[j].mesh == m) {
        baked.meshes.push_back(baked.meshes[m]);
        m = static_cast<int>(baked.meshes.size()) - 1;
        baked.meshInstances[i].mesh = m;
        break;
      }
    Mesh& mesh = baked.meshes[m];
    const int before = mesh.primitives.empty() ? 0 : static_cast<int>(mesh.primitives[0].targets.size());
    if (mesh.targetNames.size() < static_cast<size_t>(before)) mesh.targetNames.resize(before);
    const Skin* skin = inst.skin >= 0 ? &src.skins[inst.skin] : nullptr;

    for (const Shot& shot : shots) {
      std::vector<DeformedPrimitive> plain, deformed;
      if (!deformAt(src, shot.clip, shot.time, false, plain) || !deformAt(src, shot.clip, shot.time, true, deformed))
        return false;
      const std::vector<glm::mat4> world = worldAt(src, shot.clip, shot.time);
      std::vector<glm::mat4> skinning;
      if (skin) computeSkinningMatrices(*skin, world, skinning);
      for (size_t k = 0; k < plain.size(); ++k) {
        if (plain[k].instance != static_cast<int>(i)) continue;
        const int p = plain[k].primitive;
        const MeshPrimitive& prim = src.meshes[inst.mesh].primitives[p];
        const bool skinned = skin && prim.skinned();
        MorphTarget target;
        const size_t n = prim.positions.size();
        target.positionDeltas.resize(n);
        const bool normals = !prim.normals.empty() && plain[k].normals.size() == n && deformed[k].normals.size() == n &&
                             std::all_of(prim.targets.begin(), prim.targets.end(),
                                         [n](const MorphTarget& t) { return t.normalDeltas.size() == n; });
        if (normals) target.normalDeltas.resize(n);
        for (size_t v = 0; v < n; ++v) {
          const glm::mat3 a = vertexMatrix(prim, v, skinned, skinning, world[inst.joint]);
          const float det = glm::determinant(a);
          const glm::mat3 back = std::abs(det) > 1e-12f ? glm::inverse(a) : glm::mat3(1.0f);
          target.positionDeltas[v] = back * (deformed[k].positions[v] - plain[k].positions[v]);
          if (normals) {
            // World normals back to bind space: n_world ~ A^-T n_bind, so n_bind ~ A^T n_world.
            const glm::vec3 n0 = glm::transpose(a) * plain[k].normals[v];
            const glm::vec3 n1 = glm::transpose(a) * deformed[k].normals[v];
            const float l0 = glm::length(n0), l1 = glm::length(n1);
            target.normalDeltas[v] = l0 > 0.0f && l1 > 0.0f ? n1 / l1 - n0 / l0 : glm::vec3(0.0f);
          }
        }
        mesh.primitives[p].targets.push_back(std::move(target));
      }
      mesh.targetNames.push_back(
          shot.clip < 0 ? "deformers"
                        : "deformers@" + (src.clips[shot.clip].name.empty() ? std::to_string(shot.clip) : src.clips[shot.clip].name) +
                              ":" + timeText(shot.time));
    }
    const int after = before + static_cast<int>(shots.size());
    const float defaultWeight = animated ? 0.0f : 1.0f;
    auto extend = [&](std::vector<float>& weights, bool always) {
      if (weights.empty() && !always) return;
      weights.resize(before, 0.0f);
      weights.resize(after, defaultWeight);
    };
    extend(mesh.morphWeights, true);
    extend(baked.meshInstances[i].morphWeights, false);
    // One weight channel per shot: 1 at its key, 0 at its neighbours' (linear in between).
    if (animated) {
      int target = before;
      for (size_t c = 0; c < src.clips.size(); ++c) {
        const std::vector<float>& times = keyTimes[c];
        for (size_t k = 0; k < times.size(); ++k, ++target) {
          std::vector<float> t;
          std::vector<glm::vec4> w;
          if (k > 0) t.push_back(times[k - 1]), w.push_back(glm::vec4(0.0f));
          t.push_back(times[k]), w.push_back(glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
          if (k + 1 < times.size()) t.push_back(times[k + 1]), w.push_back(glm::vec4(0.0f));
          Channel ch(inst.joint, ChannelTarget::Scalar, Interpolation::Linear, std::move(t), std::move(w));
          ch.property = morphWeightProperty(target);
          baked.clips[c].channels.push_back(std::move(ch));
        }
      }
    }
    rep.targets += static_cast<int>(shots.size());
    rep.lines.push_back(label + ": " + std::to_string(stack.deformers.size()) + " deformer(s) baked into " +
                        std::to_string(shots.size()) + " morph target(s)" +
                        (animated ? " at their key times" : " at the rest pose"));
    bakedInstance[i] = 1;
  }
  // The deformers and their channels are gone from the baked scene.
  baked.deformers.clear();
  for (Clip& clip : baked.clips)
    clip.channels.erase(std::remove_if(clip.channels.begin(), clip.channels.end(),
                                       [](const Channel& ch) {
                                         return ch.target == ChannelTarget::Scalar &&
                                                parseScalarProperty(ch.property).kind ==
                                                    ScalarPropertyKind::DeformerParameter;
                                       }),
                        clip.channels.end());

  // How far the baked scene strays: every frame (or an even spread), and the keys' midpoints.
  auto compare = [&](int clip, double time) {
    std::vector<DeformedPrimitive> want, got;
    if (!deformAt(src, clip, time, true, want) || !deformAt(baked, clip, time, true, got)) return false;
    ++rep.samples;
    for (size_t k = 0; k < want.size() && k < got.size(); ++k) {
      if (!bakedInstance[want[k].instance]) continue;
      for (size_t v = 0; v < want[k].positions.size(); ++v) {
        const double e = glm::length(want[k].positions[v] - got[k].positions[v]);
        if (e > rep.largestError) {
          rep.largestError = e;
          rep.errorClip = clip;
          rep.errorTime = time;
        }
      }
    }
    return true;
  };
  if (std::any_of(bakedInstance.begin(), bakedInstance.end(), [](char b) { return b != 0; })) {
    if (src.clips.empty() && !compare(-1, 0.0)) return false;
    for (size_t c = 0; c < src.clips.size(); ++c) {
      const Clip& clip = src.clips[c];
      const double end = clip.duration();
      const double frames = std::floor(end / src.frameGrid(static_cast<int>(c)).secondsPerFrame + 1e-9);
      const long long count = std::min<long long>(static_cast<long long>(frames) + 1, maxSamplesPerClip);
      std::vector<double> times;
      for (long long f = 0; f < count; ++f)
        times.push_back(count == 1 ? 0.0 : end * static_cast<double>(f) / static_cast<double>(count - 1));
      std::vector<float> keys;
      for (const Channel& ch : clip.channels)
        if (ch.target == ChannelTarget::Scalar && parseScalarProperty(ch.property).kind == ScalarPropertyKind::DeformerParameter)
          keys.insert(keys.end(), ch.times.begin(), ch.times.end());
      std::sort(keys.begin(), keys.end());
      for (size_t k = 0; k + 1 < keys.size(); ++k)
        if (!sameKeyTime(keys[k], keys[k + 1])) times.push_back(0.5 * (static_cast<double>(keys[k]) + keys[k + 1]));
      for (double t : times)
        if (!compare(static_cast<int>(c), t)) return false;
    }
  }
  *out = std::move(baked);
  *report = std::move(rep);
  return true;
}

}  // namespace kinema
