#include "evaluation/scene_deformation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "anim/sampling.h"
#include "anim/scalar_property.h"
#include "skin/dual_quaternion_skinning.h"
#include "skin/linear_blend_skinning.h"
#include "skin/morph_targets.h"
#include "skin/skinning_job_checks.h"
#include "skin/skinning_matrices.h"

namespace kinema {

namespace {

std::string instanceError(const Scene& scene, size_t i) {
  const MeshInstance& inst = scene.meshInstances[i];
  const std::string at = "mesh instance " + std::to_string(i) + ": ";
  if (inst.joint < 0 || inst.joint >= scene.skeleton.size()) return at + "joint " + std::to_string(inst.joint) + " does not exist";
  if (inst.mesh < 0 || inst.mesh >= static_cast<int>(scene.meshes.size()))
    return at + "mesh " + std::to_string(inst.mesh) + " does not exist";
  if (inst.skin < -1 || inst.skin >= static_cast<int>(scene.skins.size()))
    return at + "skin " + std::to_string(inst.skin) + " does not exist";
  size_t skinJoints = 0;
  if (inst.skin >= 0) {
    const Skin& skin = scene.skins[inst.skin];
    if (skin.inverseBind.size() != skin.joints.size())
      return at + "skin " + std::to_string(inst.skin) + " needs one inverse bind matrix per joint";
    for (int j : skin.joints)
      if (j < 0 || j >= scene.skeleton.size()) return at + "skin " + std::to_string(inst.skin) + " names a missing joint";
    skinJoints = skin.joints.size();
  }
  const Mesh& mesh = scene.meshes[inst.mesh];
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    const MeshPrimitive& prim = mesh.primitives[p];
    const std::string pat = at + "mesh " + std::to_string(inst.mesh) + " primitive " + std::to_string(p) + ": ";
    MorphTargetsJob morph;
    std::vector<glm::vec3> unused;
    morph.primitive = &prim;
    morph.outPositions = &unused;
    if (std::string e = morph.validate(); !e.empty()) return pat + e;
    if (!prim.skinned() || inst.skin < 0) continue;
    const size_t n = prim.positions.size() * kMaxInfluences;
    if (prim.influenceWeights.size() != n || prim.influenceJoints.size() != n)
      return pat + "expected " + std::to_string(kMaxInfluences) + " influences per vertex";
    for (size_t k = 0; k < n; ++k)
      if (prim.influenceJoints[k] >= skinJoints)
        return pat + "vertex " + std::to_string(k / kMaxInfluences) + " uses skin joint " +
               std::to_string(prim.influenceJoints[k]) + ", the skin has " + std::to_string(skinJoints);
  }
  return {};
}

// How many leading influence slots any vertex uses (the last non-zero weight's slot + 1):
// most files use 4 of the 8, and the jobs then read only those.
int usedInfluences(const MeshPrimitive& prim) {
  int used = 1;
  const size_t n = prim.positions.size();
  for (size_t v = 0; v < n && used < kMaxInfluences; ++v)
    for (int k = kMaxInfluences - 1; k >= used; --k)
      if (prim.influenceWeights[v * kMaxInfluences + k] != 0.0f) {
        used = k + 1;
        break;
      }
  return used;
}

// An unskinned primitive (or one of a node without a skin) moves rigidly with its node.
void transformRigidly(const glm::mat4& world, const std::vector<glm::vec3>& positions,
                      const std::vector<glm::vec3>& normals, DeformedPrimitive& out) {
  out.positions.resize(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) out.positions[v] = glm::vec3(world * glm::vec4(positions[v], 1.0f));
  out.normals.resize(normals.size());
  const glm::mat3 nm = normalMatrixOf(world);
  for (size_t v = 0; v < normals.size(); ++v) {
    const glm::vec3 n = nm * normals[v];
    const float len2 = glm::dot(n, n);
    out.normals[v] = len2 > 0.0f ? n / std::sqrt(len2) : glm::vec3(0.0f);
  }
}

}  // namespace

std::vector<std::vector<float>> sampleMorphWeights(const Scene& scene, int clip, double time) {
  std::vector<std::vector<float>> out(scene.meshInstances.size());
  for (size_t i = 0; i < scene.meshInstances.size(); ++i) {
    const MeshInstance& inst = scene.meshInstances[i];
    if (!inst.morphWeights.empty()) out[i] = inst.morphWeights;
    else if (inst.mesh >= 0 && inst.mesh < static_cast<int>(scene.meshes.size())) out[i] = scene.meshes[inst.mesh].morphWeights;
  }
  if (clip < 0 || clip >= static_cast<int>(scene.clips.size())) return out;
  const float t = static_cast<float>(time);
  for (const Channel& ch : scene.clips[clip].channels) {
    if (ch.target != ChannelTarget::Scalar || ch.times.empty()) continue;
    const ScalarProperty property = parseScalarProperty(ch.property);
    if (property.kind != ScalarPropertyKind::MorphWeight) continue;
    const int k = property.morphTarget;
    const float value = sampleChannel(ch, t).x;  // clamped to the channel's keys
    for (size_t i = 0; i < scene.meshInstances.size(); ++i)
      if (scene.meshInstances[i].joint == ch.joint && k < static_cast<int>(out[i].size())) out[i][k] = value;
  }
  return out;
}

namespace {
bool stackActive(const std::vector<DeformerStack>& stacks, size_t i) {
  return i < stacks.size() && std::any_of(stacks[i].deformers.begin(), stacks[i].deformers.end(),
                                          [](const Deformer& d) { return d.enabled; });
}
}  // namespace

bool anyDeformerActive(const std::vector<DeformerStack>& stacks) {
  for (size_t i = 0; i < stacks.size(); ++i)
    if (stackActive(stacks, i)) return true;
  return false;
}

std::vector<DeformerStack> sampleDeformerStacks(const Scene& scene, int clip, double time) {
  std::vector<DeformerStack> out(scene.meshInstances.size());
  for (size_t i = 0; i < out.size() && i < scene.deformers.size(); ++i) out[i] = scene.deformers[i];
  if (clip < 0 || clip >= static_cast<int>(scene.clips.size()) || scene.deformers.empty()) return out;
  const float t = static_cast<float>(time);
  for (const Channel& ch : scene.clips[clip].channels) {
    if (ch.target != ChannelTarget::Scalar || ch.times.empty()) continue;
    const ScalarProperty property = parseScalarProperty(ch.property);
    if (property.kind != ScalarPropertyKind::DeformerParameter) continue;
    bool sampled = false;
    float value = 0.0f;
    for (size_t i = 0; i < out.size(); ++i) {
      if (scene.meshInstances[i].joint != ch.joint) continue;
      Deformer* d = out[i].find(property.deformer);
      if (!d) continue;
      if (!sampled) value = sampleChannel(ch, t).x;  // clamped to the channel's keys
      sampled = true;
      setDeformerParameter(*d, property.parameter, value);  // an unknown parameter changes nothing
    }
  }
  return out;
}

std::string SceneDeformationJob::validate() const {
  if (!scene) return "scene is null";
  if (!world) return "world is null";
  if (!out) return "out is null";
  if (static_cast<int>(world->size()) != scene->skeleton.size())
    return "world has " + std::to_string(world->size()) + " transforms for " + std::to_string(scene->skeleton.size()) +
           " joints";
  for (size_t j = 0; j < world->size(); ++j) {
    const float* m = glm::value_ptr((*world)[j]);
    for (int k = 0; k < 16; ++k)
      if (!std::isfinite(m[k])) return "world transform " + std::to_string(j) + " is not finite";
  }
  if (morphWeights && morphWeights->size() != scene->meshInstances.size())
    return "morphWeights has " + std::to_string(morphWeights->size()) + " entries for " +
           std::to_string(scene->meshInstances.size()) + " mesh instances";
  for (size_t i = 0; i < scene->meshInstances.size(); ++i)
    if (std::string e = instanceError(*scene, i); !e.empty()) return e;
  const std::vector<DeformerStack>& stacks = deformers ? *deformers : scene->deformers;
  if (stacks.size() > scene->meshInstances.size())
    return "deformer stacks for " + std::to_string(stacks.size()) + " mesh instances, the scene has " +
           std::to_string(scene->meshInstances.size());
  for (size_t i = 0; i < stacks.size(); ++i)
    if (std::string e = stacks[i].validate(scene->meshes[scene->meshInstances[i].mesh], scene->skeleton.size());
        !e.empty())
      return "mesh instance " + std::to_string(i) + ": " + e;
  return {};
}

bool SceneDeformationJob::run() const {
  if (!validate().empty()) return false;
  std::vector<DeformedPrimitive> result;
  std::vector<glm::mat4> skinning;
  std::vector<glm::vec3> morphed, morphedNormals;
  for (size_t i = 0; i < scene->meshInstances.size(); ++i) {
    const MeshInstance& inst = scene->meshInstances[i];
    if (skinnedOnly && inst.skin < 0) continue;
    const std::vector<DeformerStack>& stacks = deformers ? *deformers : scene->deformers;
    const bool deform = stackActive(stacks, i);
    if (withDeformersOnly && !deform) continue;
    const Mesh& mesh = scene->meshes[inst.mesh];
    const std::vector<float>& weights =
        morphWeights ? (*morphWeights)[i] : (!inst.morphWeights.empty() ? inst.morphWeights : mesh.morphWeights);
    if (inst.skin >= 0) computeSkinningMatrices(scene->skins[inst.skin], *world, skinning);
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const MeshPrimitive& prim = mesh.primitives[p];
      DeformedPrimitive d;
      d.instance = static_cast<int>(i);
      d.primitive = static_cast<int>(p);
      // Morph targets first (glTF), into scratch only when some weight is non-zero.
      const std::vector<glm::vec3>* positions = &prim.positions;
      const std::vector<glm::vec3>* normals = &prim.normals;
      const bool morph = !prim.targets.empty() &&
                         std::any_of(weights.begin(), weights.end(), [](float w) { return w != 0.0f; });
      if (morph) {
        MorphTargetsJob job;
        job.primitive = &prim;
        job.weights = weights.data();
        job.weightCount = static_cast<int>(weights.size());
        job.outPositions = &morphed;
        job.outNormals = &morphedNormals;
        if (!job.run()) return false;
        positions = &morphed;
        normals = &morphedNormals;
      }
      if (inst.skin < 0 || !prim.skinned()) {
        transformRigidly((*world)[inst.joint], *positions, *normals, d);
      } else {
        const int n = prim.vertexCount();
        d.positions.resize(n);
        d.normals.resize(normals->size());
        const int used = usedInfluences(prim);
        const glm::vec3* nin = normals->empty() ? nullptr : normals->data();
        glm::vec3* nout = normals->empty() ? nullptr : d.normals.data();
        // Both jobs take the same inputs; fill whichever the instance uses.
        auto fill = [&](auto& job) {
          job.positions = positions->data();
          job.normals = nin;
          job.vertexCount = n;
          job.influenceJoints = prim.influenceJoints.data();
          job.influenceWeights = prim.influenceWeights.data();
          job.influencesPerVertex = used;
          job.influenceStride = kMaxInfluences;
          job.jointMatrices = skinning.data();
          job.jointCount = static_cast<int>(skinning.size());
          job.outPositions = d.positions.data();
          job.outNormals = nout;
          return job.run();
        };
        DualQuaternionSkinningJob dq;
        LinearBlendSkinningJob lbs;
        const bool ok = inst.skinning == SkinningMethod::DualQuaternion ? fill(dq) : fill(lbs);
        if (!ok) return false;  // validate() above rules this out (non-finite world matrices aside)
      }
      // Last, the deformer stack in world space; the shading normals follow the new surface.
      if (deform) {
        DeformerStackJob job;
        job.stack = &stacks[i];
        job.primitive = static_cast<int>(p);
        job.positions = d.positions.data();
        job.count = static_cast<int>(d.positions.size());
        job.world = world;
        job.outPositions = d.positions.data();
        if (!job.run()) return false;
        if (!d.normals.empty() && !prim.indices.empty()) computeVertexNormals(d.positions, prim.indices, d.normals);
      }
      result.push_back(std::move(d));
    }
  }
  *out = std::move(result);
  return true;
}

}  // namespace kinema
