#include "editor/model/pose_edits.h"

#include <cmath>

#include "anim/clip.h"
#include "editor/model/edit_labels.h"
#include "editor/model/ik_posing.h"
#include "editor/model/mirror_names.h"
#include "editor/model/pose_clipboard.h"
#include "scene/default_character_scene.h"

namespace kinema {

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::quat& q) { return finite(glm::vec3(q.x, q.y, q.z)) && std::isfinite(q.w); }

std::string jointError(const Document& doc, int joint) {
  if (joint < 0 || joint >= doc.skeleton().size())
    return "no joint " + std::to_string(joint) + " (the skeleton has " + std::to_string(doc.skeleton().size()) + ")";
  return {};
}

std::string rotationError(const glm::quat& q) {
  if (!finite(q)) return "the rotation is not finite";
  if (!(glm::dot(q, q) > 1e-12f)) return "the rotation is a zero quaternion";
  return {};
}

// Sets the rotation, and the X-mirrored one on the mirror partner when X-mirror is on;
// each within its joint's limit.
void setRotation(DocumentEdit& e, bool xMirror, int joint, const glm::quat& q) {
  const glm::quat unit = glm::normalize(q);
  e.pose.local[joint].rotation = limitedLocalRotation(e, joint, unit);
  if (!xMirror) return;
  const std::string partnerName = mirroredJointName(e.names[joint]);
  if (partnerName.empty()) return;
  const int partner = e.skeleton.find(partnerName);
  if (partner >= 0 && partner != joint)
    e.pose.local[partner].rotation = limitedLocalRotation(e, partner, mirrorRotationX(unit));
}

const std::string& nameOf(const Document& doc, int joint) { return doc.skeleton().names[joint]; }

}  // namespace

glm::quat limitedLocalRotation(const DocumentEdit& e, int joint, const glm::quat& local) {
  if (joint < 0 || joint >= static_cast<int>(e.limits.size()) || !e.limits[joint].active()) return local;
  if (joint >= static_cast<int>(e.skeleton.rest.size())) return local;
  return applyJointLimit(e.limits[joint], e.skeleton.rest[joint].rotation, local);
}

namespace {

std::string targetError(const Document& doc, int target) {
  if (target < 0 || target >= static_cast<int>(doc.ikTargets().size()))
    return "no IK target " + std::to_string(target);
  return {};
}

// Runs an IK-target edit with `target` driven (solved first, not following its effector).
std::string drivenEdit(Document& doc, int target, const std::string& label,
                       const std::function<std::string(DocumentEdit&)>& change) {
  doc.setDrivenIkTarget(target);
  const std::string error = doc.edit(label, change);
  doc.setDrivenIkTarget(-1);
  return error;
}

}  // namespace

std::string setJointRotation(Document& doc, int joint, const glm::quat& local) {
  std::string error = jointError(doc, joint);
  if (error.empty()) error = rotationError(local);
  if (!error.empty()) return error;
  const bool mirror = doc.xMirror;
  return doc.edit("Rotate " + nameOf(doc, joint), [&](DocumentEdit& e) {
    setRotation(e, mirror, joint, local);
    return std::string();
  });
}

std::string setJointWorldRotation(Document& doc, int joint, const glm::quat& world) {
  std::string error = jointError(doc, joint);
  if (error.empty()) error = rotationError(world);
  if (!error.empty()) return error;
  glm::quat parent(1.0f, 0.0f, 0.0f, 0.0f);
  const int p = doc.skeleton().parents[joint];
  if (p >= 0) {
    const glm::mat4 m = doc.worldTransforms()[p];
    const glm::mat3 r(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])),
                      glm::normalize(glm::vec3(m[2])));
    parent = glm::normalize(glm::quat_cast(r));
  }
  return setJointRotation(doc, joint, glm::inverse(parent) * glm::normalize(world));
}

std::string setJointTranslation(Document& doc, int joint, const glm::vec3& translation) {
  std::string error = jointError(doc, joint);
  if (error.empty() && !finite(translation)) error = "the translation is not finite";
  if (!error.empty()) return error;
  return doc.edit("Move " + nameOf(doc, joint), [&](DocumentEdit& e) {
    e.pose.local[joint].translation = translation;
    return std::string();
  });
}

std::string clearRotations(Document& doc, const std::vector<int>& joints) {
  for (int j : joints) {
    const std::string error = jointError(doc, j);
    if (!error.empty()) return error;
  }
  return doc.edit("Clear rotation of " + jointsPhrase(doc.skeleton(), joints), [&](DocumentEdit& e) {
    for (int j : joints) e.pose.local[j].rotation = e.skeleton.rest[j].rotation;
    return std::string();
  });
}

std::string clearTranslations(Document& doc, const std::vector<int>& joints) {
  for (int j : joints) {
    const std::string error = jointError(doc, j);
    if (!error.empty()) return error;
  }
  return doc.edit("Clear location of " + jointsPhrase(doc.skeleton(), joints), [&](DocumentEdit& e) {
    for (int j : joints) e.pose.local[j].translation = e.skeleton.rest[j].translation;
    return std::string();
  });
}

std::string resetToRestPose(Document& doc) {
  return doc.edit("Reset all joints to the rest pose", [](DocumentEdit& e) {
    e.pose = Pose::rest(e.skeleton);
    return std::string();
  });
}

std::string renameJoint(Document& doc, int joint, const std::string& name) {
  const std::string error = jointError(doc, joint);
  if (!error.empty()) return error;
  if (name.empty()) return "a joint name may not be empty";
  for (char c : name)
    if (static_cast<unsigned char>(c) < 0x20) return "a joint name may not hold control characters";
  const int other = doc.skeleton().find(name);
  if (other >= 0 && other != joint) return "joint " + std::to_string(other) + " is already named '" + name + "'";
  const std::string old = nameOf(doc, joint);
  return doc.edit("Rename " + old + " to " + name, [&](DocumentEdit& e) {
    e.names[joint] = name;
    return std::string();
  });
}

std::string setMeshSkinning(Document& doc, int instance, SkinningMethod method) {
  if (instance < 0 || instance >= static_cast<int>(doc.scene().meshInstances.size()))
    return "no mesh instance " + std::to_string(instance);
  const char* name = method == SkinningMethod::DualQuaternion ? "dual quaternion" : "linear blend";
  return doc.edit("Set skinning of mesh " + std::to_string(instance) + " to " + name, [&](DocumentEdit& e) {
    e.skinning[instance] = method;
    return std::string();
  });
}

std::string bindUnskinnedMeshes(Document& doc, AutomaticWeightsMethod method) {
  bool any = false;
  for (const MeshInstance& m : doc.scene().meshInstances) any = any || m.skin < 0;
  if (!any) return "no unskinned mesh to bind (every mesh already follows a skin)";
  return doc.editMeshes("Bind meshes to the skeleton", [&](Scene& scene) {
    for (size_t i = 0; i < scene.meshInstances.size(); ++i) {
      if (scene.meshInstances[i].skin >= 0) continue;
      std::string error;
      if (!bindMeshWithAutomaticWeights(scene, static_cast<int>(i), method, error)) return error;
    }
    return std::string();
  });
}

std::string setJointLimit(Document& doc, int joint, const JointLimit& limit) {
  std::string error = jointError(doc, joint);
  if (error.empty() && limit.active()) error = limit.validate();
  if (!error.empty()) return error;
  return doc.edit("Set joint limit of " + nameOf(doc, joint), [&](DocumentEdit& e) {
    if (e.limits.empty()) e.limits.resize(e.skeleton.size());
    e.limits[joint] = limit;
    return std::string();
  });
}

std::string addIkTarget(Document& doc, const PoseIkTarget& target, int* index) {
  const std::string error = target.validate(doc.skeleton());
  if (!error.empty()) return error;
  const int at = static_cast<int>(doc.ikTargets().size());
  const std::string result = drivenEdit(doc, at, "Add IK target " + nameOf(doc, target.target.effector),
                                        [&](DocumentEdit& e) {
                                          e.targets.push_back(target);
                                          return std::string();
                                        });
  if (result.empty() && index) *index = at;
  return result;
}

std::string addIkTargetAtEffector(Document& doc, int effector, int chainLength, IkSolver solver, int* index) {
  const std::string error = jointError(doc, effector);
  if (!error.empty()) return error;
  PoseIkTarget t;
  t.target.effector = effector;
  t.target.position = effectorPosition(doc, effector);
  t.chainLength = chainLength;
  t.solver = solver;
  return addIkTarget(doc, t, index);
}

std::string removeIkTarget(Document& doc, int target) {
  const std::string error = targetError(doc, target);
  if (!error.empty()) return error;
  return doc.edit("Remove IK target of " + jointsPhrase(doc.skeleton(), {doc.ikTargets()[target].target.effector}), [&](DocumentEdit& e) {
    e.targets.erase(e.targets.begin() + target);
    return std::string();
  });
}

std::string setIkTarget(Document& doc, int target, const PoseIkTarget& settings) {
  std::string error = targetError(doc, target);
  if (error.empty()) error = settings.validate(doc.skeleton());
  if (error.empty() && !finite(settings.target.position)) error = "the target position is not finite";
  if (!error.empty()) return error;
  return drivenEdit(doc, target, "Edit IK target of " + jointsPhrase(doc.skeleton(), {doc.ikTargets()[target].target.effector}), [&](DocumentEdit& e) {
    e.targets[target] = settings;
    return std::string();
  });
}

std::string beginRotateDrag(Document& doc, int joint) {
  const std::string error = jointError(doc, joint);
  if (!error.empty()) return error;
  return doc.beginDrag("Rotate " + nameOf(doc, joint));
}

std::string updateRotateDrag(Document& doc, int joint, const glm::quat& local) {
  std::string error = jointError(doc, joint);
  if (error.empty()) error = rotationError(local);
  if (!error.empty()) return error;
  const bool mirror = doc.xMirror;
  return doc.updateDrag([&](DocumentEdit& e) {
    setRotation(e, mirror, joint, local);
    return std::string();
  });
}

std::string updateRotateDrag(Document& doc, const std::vector<int>& joints, const std::vector<glm::quat>& locals) {
  if (joints.size() != locals.size()) return "one rotation per joint expected";
  for (size_t k = 0; k < joints.size(); ++k) {
    std::string error = jointError(doc, joints[k]);
    if (error.empty()) error = rotationError(locals[k]);
    if (!error.empty()) return error;
  }
  const bool mirror = doc.xMirror;
  return doc.updateDrag([&](DocumentEdit& e) {
    for (size_t k = 0; k < joints.size(); ++k) setRotation(e, mirror, joints[k], locals[k]);
    if (mirror)  // partners set above, then the selected joints' own rotations win
      for (size_t k = 0; k < joints.size(); ++k) setRotation(e, false, joints[k], locals[k]);
    return std::string();
  });
}

std::string beginTranslateDrag(Document& doc, int joint) {
  const std::string error = jointError(doc, joint);
  if (!error.empty()) return error;
  return doc.beginDrag("Move " + nameOf(doc, joint));
}

std::string updateTranslateDrag(Document& doc, int joint, const glm::vec3& translation) {
  std::string error = jointError(doc, joint);
  if (error.empty() && !finite(translation)) error = "the translation is not finite";
  if (!error.empty()) return error;
  return doc.updateDrag([&](DocumentEdit& e) {
    e.pose.local[joint].translation = translation;
    return std::string();
  });
}

}  // namespace kinema
