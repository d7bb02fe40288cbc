// Physics in the editor (simulation_edits.h).
#include "editor/model/simulation_edits.h"

#include <algorithm>
#include <cmath>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "editor/model/document.h"
#include "editor/model/keying.h"
#include "evaluation/scene_poses.h"
#include "retarget/bone_map.h"
#include "sim/baked_keys.h"

namespace kinema {

namespace {

float restSize(const Skeleton& s) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::mat4& m : computeWorld(s, Pose::rest(s))) lo = glm::min(lo, glm::vec3(m[3])), hi = glm::max(hi, glm::vec3(m[3]));
  return s.size() > 0 ? glm::length(hi - lo) : 1.0f;
}

// Metres per file unit, guessed from the character's size.
float unitsPerMetre(const Skeleton& s) { return restSize(s) > 20.0f ? 100.0f : 1.0f; }

int firstChild(const Skeleton& s, int j) {
  for (int c = j + 1; c < s.size(); ++c)
    if (s.parents[c] == j) return c;
  return -1;
}

}  // namespace

std::vector<int> dynamicChainFrom(const Skeleton& s, const std::vector<int>& selected, int active) {
  std::vector<int> sel;
  for (int j : selected)
    if (j >= 0 && j < s.size()) sel.push_back(j);
  if (active >= 0 && active < s.size() && std::find(sel.begin(), sel.end(), active) == sel.end()) sel.push_back(active);
  std::sort(sel.begin(), sel.end());  // parents before children
  if (sel.empty()) return {};
  if (sel.size() == 1) {
    std::vector<int> chain = {sel[0]};
    for (int c = firstChild(s, sel[0]); c >= 0 && firstChild(s, c) >= 0; c = firstChild(s, c)) chain.push_back(c);
    // The last joint with a child keeps its bone; a leaf has no bone of its own to swing.
    return chain;
  }
  bool runs = true;
  for (size_t i = 1; i < sel.size() && runs; ++i) runs = s.parents[sel[i]] == sel[i - 1];
  if (runs) return sel;
  const int bottom = active >= 0 ? active : sel.back();
  std::vector<int> path;
  for (int j = bottom; j >= 0; j = s.parents[j]) {
    path.push_back(j);
    if (j == sel.front()) break;
  }
  if (path.back() != sel.front()) return {bottom};
  std::reverse(path.begin(), path.end());
  return path;
}

SpringBoneChain defaultSpringChain(const Skeleton& s, const std::vector<int>& joints) {
  SpringBoneChain c;
  c.name = joints.empty() ? std::string() : s.names[joints.front()];
  c.joints = joints;
  c.stiffness = 40.0f;
  c.damping = 3.0f;
  c.gravity = {0.0f, -9.81f * unitsPerMetre(s), 0.0f};
  c.radius = 0.01f * restSize(s);
  return c;
}

RagdollSettings defaultRagdoll(const Skeleton& s, int root, long long startFrame) {
  RagdollSettings r;
  r.name = root >= 0 && root < s.size() ? s.names[root] : std::string();
  r.root = root;
  r.startFrame = std::max(0LL, startFrame);
  r.gravity = {0.0f, -9.81f * unitsPerMetre(s), 0.0f};
  return r;
}

int characterRoot(const Skeleton& s) {
  if (Result<HumanoidReading> h = findHumanoid(s); h && h->bones.has(HumanoidBone::Hips)) return h->bones[HumanoidBone::Hips];
  for (int j = 0; j < s.size(); ++j)
    if (firstChild(s, j) >= 0) return j;
  return 0;
}

int springChainOf(const Document& doc, int joint) {
  const std::vector<SpringBoneChain>& chains = doc.scene().simulation.springChains;
  for (size_t c = 0; c < chains.size(); ++c)
    if (std::find(chains[c].joints.begin(), chains[c].joints.end(), joint) != chains[c].joints.end()) return static_cast<int>(c);
  return -1;
}

std::string addSpringChainEdit(Document& doc, const SpringBoneChain& chain) {
  if (chain.joints.empty()) return "Make chain dynamic: select the chain's first joint (or its joints) first";
  return doc.edit("Make chain " + chain.name + " dynamic", [&](DocumentEdit& e) {
    std::vector<SpringBoneChain>& chains = e.simulation.springChains;
    for (SpringBoneChain& c : chains)  // its joints leave other chains; an emptied chain goes
      c.joints.erase(std::remove_if(c.joints.begin(), c.joints.end(), [&](int j) {
                       return std::find(chain.joints.begin(), chain.joints.end(), j) != chain.joints.end();
                     }), c.joints.end());
    chains.erase(std::remove_if(chains.begin(), chains.end(), [](const SpringBoneChain& c) { return c.joints.empty(); }),
                 chains.end());
    chains.push_back(chain);
    return std::string();
  });
}

std::string removeSpringChainEdit(Document& doc, int index) {
  const std::vector<SpringBoneChain>& chains = doc.scene().simulation.springChains;
  if (index < 0 || index >= static_cast<int>(chains.size())) return "Remove dynamic chain: no such chain";
  return doc.edit("Remove dynamic chain " + chains[index].name, [&](DocumentEdit& e) {
    e.simulation.springChains.erase(e.simulation.springChains.begin() + index);
    return std::string();
  });
}

std::string setSpringChainEdit(Document& doc, int index, const SpringBoneChain& chain) {
  if (index < 0 || index >= static_cast<int>(doc.scene().simulation.springChains.size())) return "no such chain";
  return doc.edit("Set dynamic chain " + chain.name, [&](DocumentEdit& e) {
    e.simulation.springChains[index] = chain;
    return std::string();
  });
}

SpringCollider defaultCollider(const Skeleton& s, int joint) {
  SpringCollider c;
  c.joint = joint;
  const int child = joint >= 0 && joint < s.size() ? firstChild(s, joint) : -1;
  const float length = child >= 0 ? glm::length(s.rest[child].translation) : 0.0f;
  if (child >= 0 && length > 0.0f) {
    c.b = s.rest[child].translation;
    c.radius = 0.25f * length;
  } else {
    c.radius = 0.03f * restSize(s);
  }
  return c;
}

std::string addColliderEdit(Document& doc, const SpringCollider& collider) {
  const Skeleton& s = doc.skeleton();
  if (collider.joint < -1 || collider.joint >= s.size()) return "Add collision capsule: no such joint";
  if (!(collider.radius > 0.0f) || !std::isfinite(collider.radius) || !isFinite(collider.a) || !isFinite(collider.b))
    return "Add collision capsule: the radius must be positive and the ends finite";
  const std::vector<SpringBoneChain>& chains = doc.scene().simulation.springChains;
  if (chains.empty()) return "Add collision capsule: make a chain dynamic first (Simulate > Make Chain Dynamic)";
  bool any = false;
  for (const SpringBoneChain& c : chains)
    any |= std::find(c.joints.begin(), c.joints.end(), collider.joint) == c.joints.end();
  if (!any) return "Add collision capsule: the joint belongs to the only dynamic chain (a chain does not collide with itself)";
  const std::string where = collider.joint >= 0 ? s.names[collider.joint] : std::string("the world");
  return doc.edit("Add collision capsule on " + where, [&](DocumentEdit& e) {
    for (SpringBoneChain& c : e.simulation.springChains)
      if (std::find(c.joints.begin(), c.joints.end(), collider.joint) == c.joints.end()) c.colliders.push_back(collider);
    return std::string();
  });
}

std::string removeColliderEdit(Document& doc, int chain, int collider) {
  const std::vector<SpringBoneChain>& chains = doc.scene().simulation.springChains;
  if (chain < 0 || chain >= static_cast<int>(chains.size()) || collider < 0 ||
      collider >= static_cast<int>(chains[chain].colliders.size()))
    return "Remove collision capsule: no such capsule";
  return doc.edit("Remove collision capsule", [&](DocumentEdit& e) {
    std::vector<SpringCollider>& list = e.simulation.springChains[chain].colliders;
    list.erase(list.begin() + collider);
    return std::string();
  });
}

std::string setRagdollEdit(Document& doc, int index, const RagdollSettings& ragdoll) {
  if (index < 0 || index >= static_cast<int>(doc.scene().simulation.ragdolls.size())) return "no such ragdoll";
  return doc.edit("Set ragdoll " + ragdoll.name, [&](DocumentEdit& e) {
    e.simulation.ragdolls[index] = ragdoll;
    return std::string();
  });
}

std::string removeRagdollEdit(Document& doc, int index) {
  if (index < 0 || index >= static_cast<int>(doc.scene().simulation.ragdolls.size())) return "no such ragdoll";
  return doc.edit("Remove ragdoll", [&](DocumentEdit& e) {
    e.simulation.ragdolls.erase(e.simulation.ragdolls.begin() + index);
    return std::string();
  });
}

namespace {

// `clip` is scene.clips[clipIndex], or a clip not in the document yet (clipIndex -1), whose
// keys alone then drive the simulation.
Result<SimulationBake> bake(const Document& doc, int clipIndex, const Clip& clip, const SimulationSettings& settings,
                            long long first, long long last) {
  const Scene& scene = doc.scene();
  // The parts move on the clip as the editor plays it (the one pipeline), their own dynamics
  // left out: they are what is simulated.
  const IkRig rig = doc.savedRig();
  EvaluationStages stages;
  stages.dynamics = false;
  ScenePoses poses(scene, clipIndex, stages, &rig);
  SimulationBakeInput in;
  in.skeleton = &scene.skeleton;
  in.clip = &clip;
  if (clipIndex >= 0) in.poses = &poses;
  in.documentFrameRate = scene.frameRate;
  in.settings = &settings;
  in.rig = &doc.rig();
  if (!scene.meshes.empty()) {
    in.meshes = &scene.meshes;
    in.skins = &scene.skins;
    in.instances = &scene.meshInstances;
  }
  in.firstFrame = std::max(0LL, first);
  in.lastFrame = std::max(in.firstFrame, last);
  in.reduction = bakedKeyTolerances(scene.skeleton);
  return bakeSimulation(in);
}

}  // namespace

std::string bakeSimulationEdit(Document& doc, int clip, long long first, long long last, SimulationBake* result) {
  const Scene& scene = doc.scene();
  if (clip < 0 || clip >= static_cast<int>(scene.clips.size())) return "Bake simulation: the document has no clip (key a pose first)";
  if (!scene.simulation.hasBakedParts())
    return "Bake simulation: nothing to bake into keys (make a chain dynamic or add a ragdoll first)";
  Result<SimulationBake> baked = bake(doc, clip, scene.clips[clip], scene.simulation, first, last);
  if (!baked) return "Bake simulation: " + baked.error();
  const std::string error = doc.edit("Bake simulation", [&](DocumentEdit& e) {
    e.clips[clip] = baked->clip;
    return std::string();
  });
  if (error.empty() && result) *result = std::move(baked.value());
  return error;
}

std::string ragdollFromFrameEdit(Document& doc, int clip, int root, long long frame, long long last, SimulationBake* result) {
  const Scene& scene = doc.scene();
  // A character with no clip yet falls from the pose on screen: every joint keyed at the
  // start frame into a new "Action" (as a first key makes one), in the same undo step.
  const bool newClip = clip < 0 || clip >= static_cast<int>(scene.clips.size());
  std::vector<Clip> withAction;
  if (newClip) {
    int created = -1;
    std::vector<int> all(static_cast<size_t>(scene.skeleton.size()));
    for (int j = 0; j < scene.skeleton.size(); ++j) all[static_cast<size_t>(j)] = j;
    keyJoints(withAction, created, scene.skeleton, doc.pose(), all,
              scene.frameGrid(-1).frameToTime(std::max(0LL, frame)), KeyPreferences{}, scene.frameGrid(-1));
    clip = static_cast<int>(scene.clips.size());
  }
  const Clip& source = newClip ? withAction.front() : scene.clips[clip];
  const Skeleton& s = scene.skeleton;
  if (root < 0 || root >= s.size() || firstChild(s, root) < 0) return "Ragdoll: the chosen joint has no bones below it";
  SimulationSettings settings = scene.simulation;
  settings.ragdolls.erase(std::remove_if(settings.ragdolls.begin(), settings.ragdolls.end(),
                                         [&](const RagdollSettings& r) {
                                           return s.isInSubtree(r.root, root) || s.isInSubtree(root, r.root);
                                         }),
                          settings.ragdolls.end());
  settings.ragdolls.push_back(defaultRagdoll(s, root, frame));
  SimulationSettings only;
  only.ragdolls = {settings.ragdolls.back()};
  Result<SimulationBake> baked = bake(doc, newClip ? -1 : clip, source, only, frame, last);
  if (!baked) return "Ragdoll: " + baked.error();
  const std::string error = doc.edit("Ragdoll from frame " + std::to_string(frame), [&](DocumentEdit& e) {
    if (newClip) {
      e.clips.push_back(baked->clip);
      e.activeClip = clip;  // the new "Action" plays
    } else {
      e.clips[clip] = baked->clip;
    }
    e.simulation = settings;
    return std::string();
  });
  if (error.empty() && result) *result = std::move(baked.value());
  return error;
}

}  // namespace kinema
