#include "editor/model/shape_keys.h"

#include <algorithm>
#include <cmath>

#include "anim/scalar_property.h"
#include "editor/model/keying.h"
#include "editor/model/timeline.h"
#include "bake/bake_deformers.h"
#include "evaluation/scene_deformation.h"

namespace kinema {
namespace {

std::string targetError(const Document& doc, int instance, int target) {
  if (instance < 0 || instance >= static_cast<int>(doc.scene().meshInstances.size()))
    return "no mesh instance " + std::to_string(instance);
  if (target < 0 || target >= shapeCount(doc, instance))
    return "mesh instance " + std::to_string(instance) + " has no shape " + std::to_string(target);
  return "";
}

}  // namespace

int shapeCount(const Document& doc, int instance) {
  const Scene& s = doc.scene();
  if (instance < 0 || instance >= static_cast<int>(s.meshInstances.size())) return 0;
  const int mesh = s.meshInstances[instance].mesh;
  if (mesh < 0 || mesh >= static_cast<int>(s.meshes.size()) || s.meshes[mesh].primitives.empty()) return 0;
  return static_cast<int>(s.meshes[mesh].primitives[0].targets.size());
}

std::string shapeName(const Document& doc, int instance, int target) {
  const Scene& s = doc.scene();
  if (!targetError(doc, instance, target).empty()) return "";
  const Mesh& mesh = s.meshes[s.meshInstances[instance].mesh];
  if (target < static_cast<int>(mesh.targetNames.size()) && !mesh.targetNames[target].empty())
    return mesh.targetNames[target];
  return "Shape " + std::to_string(target);
}

float shapeWeightAt(const Document& doc, int clip, double time, int instance, int target) {
  if (!targetError(doc, instance, target).empty()) return 0.0f;
  const std::vector<std::vector<float>> w = sampleMorphWeights(doc.scene(), clip, time);
  return target < static_cast<int>(w[instance].size()) ? w[instance][target] : 0.0f;
}

std::string setShapeWeight(Document& doc, int instance, int target, float weight) {
  if (std::string e = targetError(doc, instance, target); !e.empty()) return e;
  if (!std::isfinite(weight)) return "a shape weight must be a finite number";
  return doc.editMeshes("Set " + shapeName(doc, instance, target) + " to " + std::to_string(weight), [&](Scene& s) {
    MeshInstance& inst = s.meshInstances[instance];
    if (inst.morphWeights.empty()) inst.morphWeights = s.meshes[inst.mesh].morphWeights;
    inst.morphWeights.resize(std::max<size_t>(inst.morphWeights.size(), static_cast<size_t>(target) + 1), 0.0f);
    inst.morphWeights[target] = weight;
    return std::string();
  });
}

std::string keyShapeWeight(Document& doc, int& clip, int instance, int target, float time, float weight,
                           const KeyPreferences& preferences) {
  if (std::string e = targetError(doc, instance, target); !e.empty()) return e;
  if (!std::isfinite(weight)) return "a shape weight must be a finite number";
  if (!std::isfinite(time)) return "the key time is not a finite number";
  return keyScalarProperty(doc, clip, doc.scene().meshInstances[instance].joint, morphWeightProperty(target), time, weight,
                           preferences, "Insert key on " + shapeName(doc, instance, target));
}

std::string keyAllShapeWeights(Document& doc, int& clip, float time, const KeyPreferences& preferences, int& keyed) {
  keyed = 0;
  for (int i = 0; i < static_cast<int>(doc.scene().meshInstances.size()); ++i)
    for (int t = 0; t < shapeCount(doc, i); ++t) {
      const float w = shapeWeightAt(doc, clip, time, i, t);
      if (std::string e = keyShapeWeight(doc, clip, i, t, time, w, preferences); !e.empty()) return e;
      ++keyed;
    }
  return keyed ? "" : "no mesh has shapes to key";
}

std::string applyDeformerAsShape(Document& doc, int instance, int deformer) {
  const DeformerStack* stack = doc.scene().deformerStack(static_cast<size_t>(std::max(instance, 0)));
  if (instance < 0 || !stack || deformer < 0 || deformer >= static_cast<int>(stack->deformers.size()))
    return "mesh instance " + std::to_string(instance) + " has no deformer " + std::to_string(deformer);
  const std::string name = stack->deformers[deformer].name;
  return doc.editMeshes("Apply " + name + " as shape", [&](Scene& s) {
    // The deformer alone, enabled, on a scene without animation: one shape at the rest pose.
    Scene one = s;
    one.clips.clear();
    one.deformers.assign(s.meshInstances.size(), DeformerStack());
    Deformer only = s.deformers[instance].deformers[deformer];
    only.enabled = true;
    one.deformers[instance].deformers = {only};
    Scene baked;
    DeformerBakeReport report;
    BakeDeformersJob job;
    job.scene = &one;
    job.out = &baked;
    job.report = &report;
    if (std::string e = job.validate(); !e.empty()) return e;
    if (!job.run()) return std::string("the deformer could not be applied");
    s.meshes = std::move(baked.meshes);
    s.meshInstances = std::move(baked.meshInstances);
    const int mesh = s.meshInstances[instance].mesh;
    s.meshes[mesh].targetNames.back() = name;
    s.meshes[mesh].morphWeights.back() = 0.0f;
    if (!s.meshInstances[instance].morphWeights.empty()) s.meshInstances[instance].morphWeights.back() = 0.0f;
    s.deformers[instance].deformers.erase(s.deformers[instance].deformers.begin() + deformer);
    return std::string();
  });
}

bool shapeAnimated(const Document& doc, int clip, int instance, int target) {
  const Scene& s = doc.scene();
  if (clip < 0 || clip >= static_cast<int>(s.clips.size()) || !targetError(doc, instance, target).empty()) return false;
  const int joint = s.meshInstances[instance].joint;
  const std::string property = morphWeightProperty(target);
  for (const Channel& ch : s.clips[clip].channels)
    if (ch.target == ChannelTarget::Scalar && ch.joint == joint && ch.property == property && !ch.times.empty())
      return true;
  return false;
}

std::string moveShapeSlider(EditorState& state, int instance, int target, float weight) {
  Document& doc = state.doc;
  const int clip = state.hasMotion() ? state.clip : -1;
  if (shapeAnimated(doc, clip, instance, target) || doc.autoKey.enabled) {
    const std::string error = keyShapeWeight(doc, state.clip, instance, target, static_cast<float>(state.time), weight,
                                             doc.autoKey.preferences);
    syncDocumentPlayhead(state);
    return error;
  }
  return setShapeWeight(doc, instance, target, weight);
}

std::string keyAllShapes(EditorState& state) {
  int keyed = 0;
  const std::string error =
      keyAllShapeWeights(state.doc, state.clip, static_cast<float>(state.time), state.doc.autoKey.preferences, keyed);
  syncDocumentPlayhead(state);
  return error.empty() ? "Inserted " + std::to_string(keyed) + " shape keys on frame " + std::to_string(currentFrame(state))
                       : error;
}

}  // namespace kinema
