#include "editor/model/deformer_edits.h"

#include <algorithm>
#include <cmath>

#include "anim/scalar_property.h"
#include "core/forward_kinematics.h"
#include "editor/model/keying.h"
#include "editor/model/unique_name.h"
#include "evaluation/scene_deformation.h"

namespace kinema {
namespace {

std::string stackError(const Document& doc, int instance, int deformer) {
  const DeformerStack* stack =
      instance >= 0 ? doc.scene().deformerStack(static_cast<size_t>(instance)) : nullptr;
  if (!stack || deformer < 0 || deformer >= static_cast<int>(stack->deformers.size()))
    return "mesh instance " + std::to_string(instance) + " has no deformer " + std::to_string(deformer);
  return "";
}

// The instance's vertices at the rest pose (world space), primitive after primitive, and
// each one's heaviest skeleton joint (the instance's own joint when it is not skinned).
std::string restVertices(const Scene& scene, int instance, std::vector<glm::vec3>& points, std::vector<int>* heaviest) {
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  std::vector<DeformedPrimitive> rest;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  const std::vector<DeformerStack> none(scene.meshInstances.size());
  job.deformers = &none;
  job.out = &rest;
  if (std::string e = job.validate(); !e.empty()) return e;
  job.run();
  points.clear();
  for (const DeformedPrimitive& d : rest)
    if (d.instance == instance) points.insert(points.end(), d.positions.begin(), d.positions.end());
  if (points.empty()) return "mesh instance " + std::to_string(instance) + " has no vertices";
  if (heaviest) {
    heaviest->clear();
    const MeshInstance& mi = scene.meshInstances[static_cast<size_t>(instance)];
    const Skin* skin = mi.skin >= 0 ? &scene.skins[static_cast<size_t>(mi.skin)] : nullptr;
    for (const MeshPrimitive& p : scene.meshes[static_cast<size_t>(mi.mesh)].primitives)
      for (int v = 0; v < p.vertexCount(); ++v)
        heaviest->push_back(skin && p.skinned() ? skin->joints[p.influenceJoints[static_cast<size_t>(v) * kMaxInfluences]]
                                                : mi.joint);
  }
  return "";
}

// Replaces deformer `deformer` by `d` (same name): one undo step named `label`.
std::string replaceDeformer(Document& doc, int instance, int deformer, const Deformer& d, const std::string& label) {
  return doc.editMeshes(label, [&](Scene& s) {
    s.deformers[instance].deformers[deformer] = d;
    return std::string();
  });
}

}  // namespace

std::string setLatticeResolution(Document& doc, int instance, int deformer, const int counts[3]) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  Deformer d = doc.scene().deformers[instance].deformers[deformer];
  if (d.type != DeformerType::Lattice) return d.name + " is not a lattice";
  for (int a = 0; a < 3; ++a)
    if (counts[a] < 2 || counts[a] > 8) return d.name + ": a lattice has 2 to 8 points each way";
  d.lattice = makeLattice(counts, d.lattice.origin, d.lattice.axes);
  return replaceDeformer(doc, instance, deformer, d,
                         "Set " + d.name + " to " + std::to_string(counts[0]) + "x" + std::to_string(counts[1]) + "x" +
                             std::to_string(counts[2]));
}

std::string fitLatticeToJoints(Document& doc, int instance, int deformer, const std::vector<int>& joints) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  Deformer d = doc.scene().deformers[instance].deformers[deformer];
  if (d.type != DeformerType::Lattice) return d.name + " is not a lattice";
  std::vector<glm::vec3> points;
  std::vector<int> heaviest, selection;
  if (std::string e = restVertices(doc.scene(), instance, points, &heaviest); !e.empty()) return e;
  for (size_t v = 0; v < points.size() && !joints.empty(); ++v)
    if (std::find(joints.begin(), joints.end(), heaviest[v]) != joints.end()) selection.push_back(static_cast<int>(v));
  if (!joints.empty() && selection.empty()) return "Fit " + d.name + ": no vertex weighs most on the selected joints";
  d.lattice = fitLattice(points, selection, d.lattice.counts);
  d.parentRest = d.parentJoint >= 0 ? computeWorld(doc.skeleton(), Pose::rest(doc.skeleton()))[d.parentJoint] : glm::mat4(1.0f);
  return replaceDeformer(doc, instance, deformer, d, "Fit " + d.name + (joints.empty() ? " to the mesh" : " to the selection"));
}

std::string setDeformerParent(Document& doc, int instance, int deformer, int joint) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  if (joint < -1 || joint >= doc.skeleton().size()) return "no joint " + std::to_string(joint);
  Deformer d = doc.scene().deformers[instance].deformers[deformer];
  d.parentJoint = joint;
  // Placed at the rest pose: the joint's rest matrix is where the deformer's space starts.
  d.parentRest = joint >= 0 ? computeWorld(doc.skeleton(), Pose::rest(doc.skeleton()))[joint] : glm::mat4(1.0f);
  return replaceDeformer(doc, instance, deformer, d,
                         "Parent " + d.name + " to " + (joint >= 0 ? doc.skeleton().names[joint] : std::string("the world")));
}

std::string limitDeformerToJoint(Document& doc, int instance, int deformer, int joint) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  if (joint < -1 || joint >= doc.skeleton().size()) return "no joint " + std::to_string(joint);
  const Scene& scene = doc.scene();
  Deformer d = scene.deformers[instance].deformers[deformer];
  d.weights.clear();
  if (joint >= 0) {
    const MeshInstance& mi = scene.meshInstances[static_cast<size_t>(instance)];
    const Skin* skin = mi.skin >= 0 ? &scene.skins[static_cast<size_t>(mi.skin)] : nullptr;
    bool any = false;
    for (const MeshPrimitive& p : scene.meshes[static_cast<size_t>(mi.mesh)].primitives) {
      std::vector<float> w(static_cast<size_t>(p.vertexCount()), 0.0f);
      for (int v = 0; v < p.vertexCount(); ++v) {
        if (!skin || !p.skinned()) {
          w[static_cast<size_t>(v)] = mi.joint == joint ? 1.0f : 0.0f;
          continue;
        }
        for (int k = 0; k < kMaxInfluences; ++k) {
          const size_t at = static_cast<size_t>(v) * kMaxInfluences + static_cast<size_t>(k);
          if (skin->joints[p.influenceJoints[at]] == joint) w[static_cast<size_t>(v)] += p.influenceWeights[at];
        }
      }
      any = any || std::any_of(w.begin(), w.end(), [](float x) { return x > 0.0f; });
      d.weights.push_back(std::move(w));
    }
    if (!any) return "Limit " + d.name + ": " + doc.skeleton().names[joint] + " weighs no vertex of this mesh";
  }
  return replaceDeformer(doc, instance, deformer, d,
                         "Limit " + d.name + " to " + (joint >= 0 ? doc.skeleton().names[joint] + "'s weights" : std::string("every vertex")));
}

std::string setAxisRange(Document& doc, int instance, int deformer, DeformAxis axis, float low, float high) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  Deformer d = doc.scene().deformers[instance].deformers[deformer];
  if (d.type != DeformerType::Bend && d.type != DeformerType::Twist && d.type != DeformerType::Taper)
    return d.name + " has no axis";
  d.axis.axis = axis;
  d.axis.low = low;
  d.axis.high = high;
  if (std::string e = d.axis.validate(); !e.empty()) return d.name + ": " + e;
  return replaceDeformer(doc, instance, deformer, d, "Set " + d.name + "'s axis and range");
}

std::string addDeformer(Document& doc, int instance, DeformerType type) {
  const Scene& scene = doc.scene();
  if (instance < 0 || instance >= static_cast<int>(scene.meshInstances.size()))
    return "no mesh instance " + std::to_string(instance);
  // The mesh at the rest pose, world space: where the new deformer is placed.
  std::vector<glm::vec3> points;
  if (std::string e = restVertices(scene, instance, points, nullptr); !e.empty()) return e;
  glm::vec3 lo = points[0], hi = points[0];
  for (const glm::vec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  Deformer d;
  d.type = type;
  const float height = std::max(hi.y - lo.y, 1e-3f);
  switch (type) {
    case DeformerType::Lattice: {
      const int counts[3] = {3, 3, 3};
      d.lattice = fitLattice(points, {}, counts);
      break;
    }
    case DeformerType::Bend:
    case DeformerType::Twist:
    case DeformerType::Taper:
      d.axis.kind = type == DeformerType::Bend    ? AxisDeformerKind::Bend
                    : type == DeformerType::Twist ? AxisDeformerKind::Twist
                                                  : AxisDeformerKind::Taper;
      d.axis.axis = DeformAxis::Y;
      d.axis.origin = glm::vec3(0.5f * (lo.x + hi.x), lo.y, 0.5f * (lo.z + hi.z));
      d.axis.low = 0.0f;
      d.axis.high = height;
      d.axis.amount = type == DeformerType::Taper ? 1.0f : 0.0f;
      break;
    case DeformerType::SoftPull: {
      const auto top = std::max_element(points.begin(), points.end(),
                                        [](const glm::vec3& a, const glm::vec3& b) { return a.y < b.y; });
      d.pull.center = *top;
      d.pull.radius = 0.1f * height;
      break;
    }
  }
  const DeformerStack* current = scene.deformerStack(static_cast<size_t>(instance));
  d.name = uniqueName(toString(type), [&](const std::string& name) { return current && current->find(name); });
  return doc.editMeshes("Add " + d.name, [&](Scene& s) {
    s.editDeformerStack(instance).deformers.push_back(d);
    return std::string();
  });
}

std::string setSoftPullShape(Document& doc, int instance, int deformer, const glm::vec3& center, float radius,
                             Falloff falloff) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  const Deformer& d = doc.scene().deformers[instance].deformers[deformer];
  if (d.type != DeformerType::SoftPull) return d.name + " is not a soft pull";
  SoftPull pull = d.pull;
  pull.center = center;
  pull.radius = radius;
  pull.falloff = falloff;
  if (std::string e = pull.validate(); !e.empty()) return d.name + ": " + e;
  return doc.editMeshes("Set " + d.name, [&](Scene& s) {
    s.deformers[instance].deformers[deformer].pull = pull;
    return std::string();
  });
}

std::string removeDeformer(Document& doc, int instance, int deformer) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  const std::string name = doc.scene().deformers[instance].deformers[deformer].name;
  return doc.editMeshes("Remove " + name, [&](Scene& s) {
    std::vector<Deformer>& list = s.deformers[instance].deformers;
    list.erase(list.begin() + deformer);
    return std::string();
  });
}

std::string moveDeformer(Document& doc, int instance, int deformer, int step) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  const int to = deformer + (step < 0 ? -1 : 1);
  if (to < 0 || to >= static_cast<int>(doc.scene().deformers[instance].deformers.size()))
    return "the deformer is already at that end of the stack";
  return doc.editMeshes("Move " + doc.scene().deformers[instance].deformers[deformer].name, [&](Scene& s) {
    std::swap(s.deformers[instance].deformers[deformer], s.deformers[instance].deformers[to]);
    return std::string();
  });
}

std::string setDeformerEnabled(Document& doc, int instance, int deformer, bool enabled) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  const std::string name = doc.scene().deformers[instance].deformers[deformer].name;
  return doc.editMeshes((enabled ? "Enable " : "Disable ") + name, [&](Scene& s) {
    s.deformers[instance].deformers[deformer].enabled = enabled;
    return std::string();
  });
}

std::string setDeformerValue(Document& doc, int instance, int deformer, const std::string& parameter, float value) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  const std::string name = doc.scene().deformers[instance].deformers[deformer].name;
  return doc.editMeshes("Set " + name + " " + parameter, [&](Scene& s) {
    if (!setDeformerParameter(s.deformers[instance].deformers[deformer], parameter, value))
      return "'" + name + "' has no parameter '" + parameter + "' (or the value is not finite)";
    return std::string();
  });
}

float deformerValueAt(const Document& doc, int clip, double time, int instance, int deformer, const std::string& parameter) {
  if (!stackError(doc, instance, deformer).empty()) return 0.0f;
  const std::vector<DeformerStack> stacks = sampleDeformerStacks(doc.scene(), clip, time);
  float value = 0.0f;
  getDeformerParameter(stacks[instance].deformers[deformer], parameter, value);
  return value;
}

std::string keyDeformerValue(Document& doc, int& clip, int instance, int deformer, const std::string& parameter,
                             float time, float value, const KeyPreferences& preferences) {
  if (std::string e = stackError(doc, instance, deformer); !e.empty()) return e;
  const Deformer& d = doc.scene().deformers[instance].deformers[deformer];
  float unused = 0.0f;
  if (!getDeformerParameter(d, parameter, unused)) return "'" + d.name + "' has no parameter '" + parameter + "'";
  return keyScalarProperty(doc, clip, doc.scene().meshInstances[instance].joint,
                           deformerParameterProperty(d.name, parameter), time, value, preferences,
                           "Insert key on " + d.name + " " + parameter);
}

}  // namespace kinema
